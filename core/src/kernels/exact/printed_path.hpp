// The exact kernel's rules for its printed path (kernel.hpp, "No tunnelling"), written on its own
// exact signs (filter.hpp): each rounded piece is checked before it is accepted, and walked back towards
// its start if rounding carried it across a wall, exactly as the rules state. Independent on purpose of
// the robust kernel's implementation of the same rules, which this kernel exists to check.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>

#include "kernels/exact/filter.hpp"
#include "ricochet/kernel.hpp"

namespace ricochet::exact_kernel::printed {

/// sign of BC = n·(p − P0), n = (e_y, −e_x): e_y(p_x − P0_x) − e_x(p_y − P0_y).
inline int side(Vec2 p, const Wall& w) {
    return num::det_sign(w.p1.y, w.p0.y, p.x, w.p0.x, w.p1.x, w.p0.x, p.y, w.p0.y);
}
/// sign((b − a) × (c − a)).
inline int orient(Vec2 a, Vec2 b, Vec2 c) { return num::det_sign(b.x, a.x, c.y, a.y, b.y, a.y, c.x, a.x); }
/// sign of n·d = e_y·d_x − e_x·d_y.
inline int direction_side(Vec2 d, const Wall& w) {
    return num::det_sign(w.p1.y, w.p0.y, d.x, 0.0, w.p1.x, w.p0.x, d.y, 0.0);
}

/// p, known to lie on w's line, lies on its closed segment: on the line the segment is its bounding box.
inline bool on_closed_segment(Vec2 p, const Wall& w) {
    return std::min(w.p0.x, w.p1.x) <= p.x && p.x <= std::max(w.p0.x, w.p1.x) && std::min(w.p0.y, w.p1.y) <= p.y &&
           p.y <= std::max(w.p0.y, w.p1.y);
}

/// The contacts after the piece q → r (kernel.hpp's BallMemory): each wall whose closed segment holds r and
/// whose line q is off, with q's side; a wall whose line q is on too only if it was a contact already (the
/// ball slid along it), with its old side. Walls in index order; false (with the first four kept) when
/// more walls meet at r than BallMemory holds. r = q leaves before unchanged.
inline bool arrive(Vec2 q, Vec2 r, const BallMemory& before, std::span<const Wall> walls, BallMemory& out) {
    if (q == r) {
        out = before;
        return true;
    }
    out.count = 0;
    for (std::uint32_t i = 0; i < walls.size(); ++i) {
        const Wall& w = walls[i];
        if (side(r, w) != 0 || !on_closed_segment(r, w)) continue;
        const int from = side(q, w);
        Contact c{i, static_cast<std::int8_t>(from)};
        if (from == 0) {
            const auto* kept = std::find_if(before.contacts.begin(), before.contacts.begin() + before.count,
                                            [i](const Contact& k) { return k.wall == i; });
            if (kept == before.contacts.begin() + before.count) continue;
            c = *kept;
        }
        if (out.count == out.contacts.size()) return false;
        out.contacts[out.count++] = c;
    }
    return true;
}

/// The piece q → r may be printed: it leaves no contact wall to the side it did not come from, passes
/// through no wall's closed segment from one open side to the other, and arrives where BallMemory can
/// remember every wall it meets.
inline bool piece_allowed(Vec2 q, Vec2 r, const BallMemory& memory, std::span<const Wall> walls) {
    if (q == r) return true;
    for (std::uint8_t k = 0; k < memory.count; ++k)
        if (side(r, walls[memory.contacts[k].wall]) == -memory.contacts[k].side) return false;
    for (const Wall& w : walls) {
        // Strictly opposite sides: the piece crosses the line, inside the segment unless P0 and P1 lie
        // strictly on one side of the piece's line.
        if (side(q, w) * side(r, w) >= 0) continue;
        if (orient(q, r, w.p0) * orient(q, r, w.p1) <= 0) return false;
    }
    BallMemory arrived;
    return arrive(q, r, memory, walls, arrived);
}

/// A wall bounced off and the side it was met from: until the next bounce no printed point may lie on
/// its far side, even beyond its ends.
struct Kept {
    const Wall* wall = nullptr;
    int from = 0;
};

/// r if the piece q → r is allowed and r lies on no kept wall's far side; else the first such point on a
/// fixed walk back towards q (q itself at worst, where the ball already is).
inline Vec2 make_safe(Vec2 q, Vec2 r, const BallMemory& memory, std::span<const Wall> walls, Kept a, Kept b) {
    const auto ok = [&](Vec2 c) {
        for (const Kept& k : {a, b})
            if (k.wall != nullptr && k.from != 0 && side(c, *k.wall) == -k.from) return false;
        return piece_allowed(q, c, memory, walls);
    };
    if (ok(r)) return r;
    // A rounding error of a few ulps is undone by the first steps; f = 0 is q, which passed ok when it was
    // printed (with the memory the kernel left), so the loop always returns and the last line is a guard.
    const Vec2 d = r - q;
    for (double f : {1 - 0x1p-50, 1 - 0x1p-46, 1 - 0x1p-40, 1 - 0x1p-30, 1 - 0x1p-20, 1 - 0x1p-10, 0.5, 0.0}) {
        const Vec2 c = f == 0.0 ? q : q + f * d;
        if (ok(c)) return c;
    }
    return q;
}

}  // namespace ricochet::exact_kernel::printed
