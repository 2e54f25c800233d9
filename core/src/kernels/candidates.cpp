// The walls a leg tries (candidates.hpp).
#include "kernels/candidates.hpp"

#include <algorithm>
#include <numeric>

namespace ricochet::detail {

std::span<const std::uint32_t> candidates(std::span<const Wall> walls, const WallIndex* index, Vec2 a, Vec2 b,
                                          std::vector<std::uint32_t>& out, std::vector<std::uint32_t>& all) {
    if (index != nullptr) {
        out.clear();
        index->query(a, b, out);
        return out;
    }
    // Every wall: the list 0..n−1 is built once per scratch, not once per leg.
    if (all.size() != walls.size()) {
        all.resize(walls.size());
        std::iota(all.begin(), all.end(), std::uint32_t{0});
    }
    return all;
}

std::span<const std::uint32_t> candidates_near(std::size_t count, const WallIndex* index, Vec2 a, Vec2 b, double r,
                                               std::vector<std::uint32_t>& out, std::vector<std::uint32_t>& all) {
    if (index != nullptr) {
        out.clear();
        index->query_near(a, b, r, out);
        // In index order, as trying every wall visits them: the frame's ties and corners depend on the order.
        std::sort(out.begin(), out.end());
        return out;
    }
    if (all.size() != count) {
        all.resize(count);
        std::iota(all.begin(), all.end(), std::uint32_t{0});
    }
    return all;
}

}  // namespace ricochet::detail
