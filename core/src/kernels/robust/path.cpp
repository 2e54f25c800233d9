// The rules that keep a printed path from tunnelling (path.hpp).
#include "kernels/robust/path.hpp"

#include <algorithm>
#include <cmath>

#include "kernels/candidates.hpp"
#include "predicates/orient_filter.hpp"
#include "ricochet/line.hpp"
#include "ricochet/predicates.hpp"

namespace ricochet::detail {

const Contact* find_contact(const BallMemory& memory, std::uint32_t w) {
    for (std::uint8_t i = 0; i < memory.count; ++i)
        if (memory.contacts[i].wall == w) return &memory.contacts[i];
    return nullptr;
}

namespace {

/// The arrival rule for one wall w (index i), given the sides sq and sr of q and r: a wall whose closed
/// segment holds r and whose line q is off becomes a contact with q's side; a wall q → r runs along keeps
/// the contact before had on it (sliding along it), if any. False if out is full.
bool arrive_at(std::uint32_t i, const Wall& w, Vec2 r, int sq, int sr, const BallMemory& before, BallMemory& out) {
    if (sr != 0 || !in_segment_box(r, w)) return true;
    // Arriving along the wall's line: keep the side it had come from if it was lying on this wall
    // already (sliding along it), else there is nothing to remember.
    Contact c{i, static_cast<std::int8_t>(sq)};
    if (sq == 0) {
        const Contact* kept = find_contact(before, i);
        if (kept == nullptr) return true;
        c = *kept;
    }
    if (out.count == out.contacts.size()) return false;
    out.contacts[out.count++] = c;
    return true;
}

}  // namespace

bool piece_allowed(Vec2 q, Vec2 r, const BallMemory& memory, std::span<const Wall> walls, const WallIndex* index,
                   StepScratch& scratch, BallMemory& arrived) {
    if (q == r) {
        arrived = memory;
        return true;
    }
    // The walls' plan picks the cheapest exact side test (wall_plan.hpp); the same sign either way.
    const bool axis = planned(scratch, walls).axis_aligned != 0;
    const auto side = [axis](Vec2 p, const Wall& w) {
        return axis ? exact::detail::side_planned(p, w) : exact::detail::side(p, w);
    };
    for (std::uint8_t k = 0; k < memory.count; ++k) {
        const Contact& c = memory.contacts[k];
        if (side(r, walls[c.wall]) == -c.side) return false;
    }
    arrived = BallMemory{};
    for (std::uint32_t i : candidates(walls, index, q, r, scratch.candidates, scratch.all_walls)) {
        const Wall& w = walls[i];
        const int sq = side(q, w);
        const int sr = side(r, w);
        if (sq * sr < 0) {
            // Strictly opposite sides: the piece crosses the line; it tunnels if P0 and P1 are not
            // strictly on one side of the line q → r.
            if (exact::orient(q, r, w.p0) * exact::orient(q, r, w.p1) <= 0) return false;
            continue;
        }
        if (!arrive_at(i, w, r, sq, sr, memory, arrived)) return false;
    }
    // Deterministic order, whatever order the index answered in.
    std::sort(arrived.contacts.begin(), arrived.contacts.begin() + arrived.count,
              [](const Contact& a, const Contact& b) { return a.wall < b.wall; });
    return true;
}

SafePoint make_safe(const SafePiece& piece) {
    const Vec2 q = piece.q, r = piece.r;
    SafePoint out{r, {}};
    const auto ok = [&](Vec2 c) {
        // A nearly parallel leg can round a point just past a line while the piece to it passes the line
        // beyond the wall's end: no tunnel, but the ball would sit on a wall's far side after bouncing off it.
        for (const Keep& k : piece.keep)
            if (k.wall != nullptr && k.from != 0 && exact::side(c, *k.wall) == -k.from) return false;
        if (!piece_allowed(q, c, piece.memory, piece.walls, piece.index, piece.scratch, out.arrived)) return false;
        out.x = c;
        return true;
    };
    if (ok(r)) return out;
    // Walk back from r towards q: first by 1, 2, 4, … ulps of the piece's largest coordinate M, as
    // fractions g of the piece (one ulp of M is about g = 2^-52·M / |d|∞ of it), so a point rounded a few
    // ulps across a line comes back within a few ulps (the `accuracy` check holds robust's hit points to
    // 256·ε·M), and the doubling steps up to a quarter of the piece cover a point rounded across several
    // lines at once (after 256 ulps, the first fractions once more, measured from r: below); then half the
    // piece, then q itself, where the ball already is. Fixed fractions of the
    // piece (2^-50, 2^-46, …, 2^-10, as before) moved a short piece far from the origin by 2^-20 of its
    // length, hundreds of ulps of M, before the first that was not a no-op.
    const Vec2 d = r - q;
    const double m = std::max({std::fabs(q.x), std::fabs(q.y), std::fabs(r.x), std::fabs(r.y)});
    const double d_inf = std::max(std::fabs(d.x), std::fabs(d.y));
    // An ulp of M that underflows (M subnormal) starts the walk at 2^-60 of the piece; g doubles, so the
    // loop runs at most 60 times.
    const double g0 = std::max(m * 0x1p-52 / d_inf, 0x1p-60);
    for (double g = g0; g < 0.5; g *= 2.0) {
        if (g == g0 * 0x1p9) {
            // 256 ulps of M and no point allowed: q + (1 − g)·d carries an error of an ulp of M wherever q is far
            // from r, so next to a wall nearly parallel to the piece each point may round across it. The same
            // fractions again from r's end, r − g·d, each within an ulp of r's own size of the piece's line
            // (found by the sweep target: a leg from 5e20 to the origin beside a wall from (1, 1) to 4e18).
            for (double h = g0; h < g; h *= 2.0) {
                const Vec2 c = r - h * d;
                if (c != r && ok(c)) return out;
            }
        }
        const Vec2 c = q + (1.0 - g) * d;
        if (c != r && ok(c)) return out;
    }
    if (ok(q + 0.5 * d)) return out;
    // q itself, where the ball already is: the piece q → q arrives with the contacts it has.
    return {q, piece.memory};
}

}  // namespace ricochet::detail
