// The wall BVH (bvh.hpp; its margin is the wall grid's, wall_grid.hpp).
#include "ricochet/bvh.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "world/index_math.hpp"

namespace ricochet {

using detail::finite;
using detail::max_abs;

WallBvh::WallBvh(std::span<const Wall> walls, double margin) : margin_(margin) {
    items_.resize(walls.size());
    std::iota(items_.begin(), items_.end(), std::uint32_t{0});
    if (walls.empty()) return;
    nodes_.reserve(walls.size() / 2 + 2);
    nodes_.push_back({});
    build(walls, 0, 0, static_cast<std::uint32_t>(walls.size()));
}

void WallBvh::build(std::span<const Wall> walls, std::uint32_t slot, std::uint32_t first, std::uint32_t count) {
    Node node{};
    node.lo_x = node.lo_y = INFINITY;
    node.hi_x = node.hi_y = -INFINITY;
    double clo_x = INFINITY, clo_y = INFINITY, chi_x = -INFINITY, chi_y = -INFINITY;
    for (std::uint32_t k = first; k < first + count; ++k) {
        const Wall& w = walls[items_[k]];
        node.lo_x = std::min({node.lo_x, w.p0.x, w.p1.x});
        node.lo_y = std::min({node.lo_y, w.p0.y, w.p1.y});
        node.hi_x = std::max({node.hi_x, w.p0.x, w.p1.x});
        node.hi_y = std::max({node.hi_y, w.p0.y, w.p1.y});
        const double cx = 0.5 * w.p0.x + 0.5 * w.p1.x, cy = 0.5 * w.p0.y + 0.5 * w.p1.y;
        clo_x = std::min(clo_x, cx);
        chi_x = std::max(chi_x, cx);
        clo_y = std::min(clo_y, cy);
        chi_y = std::max(chi_y, cy);
    }
    if (count <= 4) {
        node.first = first;
        node.count = count;
        nodes_[slot] = node;
        return;
    }
    // Median split of the centres along the longer axis of their box (ties by index: deterministic).
    const bool split_x = chi_x - clo_x >= chi_y - clo_y;
    const auto key = [&](std::uint32_t i) {
        const Wall& w = walls[i];
        return split_x ? 0.5 * w.p0.x + 0.5 * w.p1.x : 0.5 * w.p0.y + 0.5 * w.p1.y;
    };
    const std::uint32_t half = count / 2;
    const auto at = [&](std::uint32_t k) { return items_.begin() + static_cast<std::ptrdiff_t>(k); };
    std::nth_element(at(first), at(first + half), at(first + count),
                     [&](std::uint32_t l, std::uint32_t r) { return key(l) < key(r) || (key(l) == key(r) && l < r); });
    // The children sit side by side: left at node.first, right at node.first + 1.
    node.first = static_cast<std::uint32_t>(nodes_.size());
    node.count = 0;
    nodes_[slot] = node;
    nodes_.push_back({});
    nodes_.push_back({});
    build(walls, node.first, first, half);
    build(walls, node.first + 1, first + half, count - half);
}

void WallBvh::query(Vec2 a, Vec2 b, std::vector<std::uint32_t>& out) const { query_near(a, b, 0.0, out); }

void WallBvh::query_near(Vec2 a, Vec2 b, double r, std::vector<std::uint32_t>& out) const {
    if (nodes_.empty()) return;
    // A wall within r of the segment has its box within r of it: the boxes grow by r (widened by 2^-40 for
    // the sum's rounding) beside the margin.
    const double m = margin_ * (1.0 + max_abs(a) + max_abs(b)) + r * (1.0 + 0x1p-40);
    if (!finite(a) || !finite(b) || !std::isfinite(m)) {
        out.insert(out.end(), items_.begin(), items_.end());
        return;
    }
    const double sx_lo = std::min(a.x, b.x) - m, sx_hi = std::max(a.x, b.x) + m;
    const double sy_lo = std::min(a.y, b.y) - m, sy_hi = std::max(a.y, b.y) + m;
    const Vec2 d = b - a;
    const double adx = std::fabs(d.x), ady = std::fabs(d.y);
    std::uint32_t stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& n = nodes_[stack[--top]];
        // Boxes of doubles against the segment's box: exact comparisons.
        if (n.hi_x < sx_lo || n.lo_x > sx_hi || n.hi_y < sy_lo || n.lo_y > sy_hi) continue;
        // The segment's line misses the box if |d × (c − a)| > |d_x|·h_y + |d_y|·h_x (c the centre, h
        // the half sizes, inflated by m); tol bounds the rounding of both sides, 2^13 times over.
        const double hx = 0.5 * (n.hi_x - n.lo_x) + m, hy = 0.5 * (n.hi_y - n.lo_y) + m;
        const double cx = 0.5 * n.lo_x + 0.5 * n.hi_x - a.x, cy = 0.5 * n.lo_y + 0.5 * n.hi_y - a.y;
        const double tol = 0x1p-40 * (adx + ady) * (std::fabs(cx) + std::fabs(cy) + hx + hy);
        if (std::fabs(d.x * cy - d.y * cx) > adx * hy + ady * hx + tol) continue;
        if (n.count > 0) {
            out.insert(out.end(), items_.begin() + n.first, items_.begin() + n.first + n.count);
        } else {
            stack[top++] = n.first;
            stack[top++] = n.first + 1;
        }
    }
}

}  // namespace ricochet
