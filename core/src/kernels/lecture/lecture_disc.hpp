// Internal: the lecture kernels' disc, LectureKernel<float> and LectureKernel<double> stepping a ball of radius
// R among walls and bumpers as the lecture's method would write it, every number rounded to Real. It is the
// baseline the harness must expose: do not fix it.
//
// A leg pos → pos + d, d = v·rest, against every wall and bumper but the one just bounced off:
//   face   the lecture's t_i with n̂·P0 shifted by R toward the ball: s = the side of pos (n̂·pos ≥ n̂·P0: +1),
//          n̂·B(t_i) = n̂·P0 + s·R  ⇒  t_i = (n̂·P0 + s·R − n̂·Bs)/(n̂·v), the five tests on the shifted line,
//          the contact point B_i − s·R·n̂ inside the ends
//   cap    |Bs + v·t − P_k|² = R²: a·t² + b·t + c = 0, t = (−b − √(b² − 4ac))/(2a), the smaller root, in [0, 1]
//   bumper |B(t) − C|² = (R + r)², the same quadratic
// The earliest t wins; ties: face, cap P0, cap P1 of one wall, the lowest wall, then bumpers by index. The
// bounce reflects v about the unit contact normal, n̂ on a face, (B_i − P_k)/R at a cap, (B_i − C)/(R + r) at a
// bumper: v′ = v − 2(v·n̂)n̂; the rest of the frame from B_i, at most k_max_bounces bounces (the frame loop is
// naive_disc_frame.hpp's, which a plug-in's discs share). No tangent rule, no start-inside rule, no clearance: what
// rounding does to t_i and B_i is what the harness is there to see.
#pragma once

#include <cmath>
#include <optional>
#include <vector>

#include "kernels/naive_disc_frame.hpp"
#include "ricochet/kernel.hpp"
#include "ricochet/line.hpp"
#include "ricochet/vec2.hpp"

namespace ricochet::disc {

/// One frame of a disc (or a point ball in a scene with bumpers) the lecture's way, in Real (above).
template <class Real>
FrameStatus step_lecture_disc(Ball& ball, const Obstacles& obstacles, std::vector<HitEvent>& hits,
                              StepScratch& scratch) {
    using V = Vec2T<Real>;
    using Contact = detail::NaiveContact<Real>;
    const Real R = static_cast<Real>(ball.r);

    // u/k, component by component.
    const auto over = [](V u, Real k) { return V{u.x / k, u.y / k}; };
    // The smaller root of |pos + d·t − c|² = rho², if it lies in [0, 1].
    const auto circle_time = [](V p, V d, V c, Real rho) -> std::optional<Real> {
        const V f = p - c;
        const Real a = dot(d, d);
        const Real b = Real(2) * dot(f, d);
        const Real cc = dot(f, f) - rho * rho;
        const Real disc = b * b - Real(4) * a * cc;
        if (a == Real(0) || disc < Real(0)) return std::nullopt;
        const Real t = (-b - std::sqrt(disc)) / (Real(2) * a);
        if (!(t >= Real(0) && t <= Real(1))) return std::nullopt;
        return t;
    };
    // The face entry t_i on the line n̂·X = n̂·P0 + s·R, with the five tests; the unit normal n̂ out.
    const auto face_time = [R](V p, V d, V p0, V p1, V& n) -> std::optional<Real> {
        const V e = edge(p0, p1);
        if ((e.x == Real(0) && e.y == Real(0)) || (d.x == Real(0) && d.y == Real(0))) return std::nullopt;
        n = unit_normal(p0, p1);
        const Real s = boundary_condition(p, p0, n) >= Real(0) ? Real(1) : Real(-1);
        // The shifted line's point-normal constant: n̂·P0 + s·R.
        const Real dl = dot(n, p0) + s * R;
        const Real bc_s = dot(n, p) - dl;
        const Real bc_e = dot(n, p + d) - dl;
        if ((bc_s < Real(0) && bc_e < Real(0)) || (bc_s > Real(0) && bc_e > Real(0))) return std::nullopt;
        const Real nv = dot(n, d);
        if (nv == Real(0)) return std::nullopt;
        const Real ti = (dl - dot(n, p)) / nv;
        // The contact point on the wall's line, B_i − s·R·n̂, between the ends.
        const V ci = p + d * ti - n * (s * R);
        if (dot(ci - p0, e) < Real(0) || dot(ci - p1, e) > Real(0)) return std::nullopt;
        return ti;
    };

    // A wall: its face, then its caps; the decision traced is whether one of them became the leg's earliest so far.
    const auto wall_contacts = [&](V pos, V d, const Wall& w, const auto& offer) {
        const V p0 = vec_cast<Real>(w.p0), p1 = vec_cast<Real>(w.p1);
        bool hit = false;
        V n{};
        if (const auto t = face_time(pos, d, p0, p1, n)) hit = offer(Contact{*t, pos + d * *t, n}) || hit;
        // A point ball (R = 0, in a scene with bumpers) has no caps: the lecture's point sweep.
        if (R > Real(0))
            for (const V& pk : {p0, p1})
                if (const auto t = circle_time(pos, d, pk, R)) {
                    // (B_i − P_k)/R
                    const V bi = pos + d * *t;
                    hit = offer(Contact{*t, bi, over(bi - pk, R)}) || hit;
                }
        return hit ? Miss::none : Miss::no_reason;
    };
    const auto bumper_contacts = [&](V pos, V d, const Bumper& bumper, const auto& offer) {
        const V c = vec_cast<Real>(bumper.c);
        const Real rho = R + static_cast<Real>(bumper.r);
        // A bumper of radius 0 met by a point is never hit (as a zero-length wall).
        if (!(rho > Real(0))) return;
        if (const auto t = circle_time(pos, d, c, rho)) {
            // (B_i − C)/(R + r)
            const V bi = pos + d * *t;
            offer(Contact{*t, bi, over(bi - c, rho)});
        }
    };
    // v′ = v − 2(v·n̂)n̂, n̂ the unit contact normal.
    const auto reflect = [](V v, V n) { return v - n * (Real(2) * dot(v, n)); };
    return detail::step_naive_disc_frame<Real>(ball, obstacles, hits, scratch, wall_contacts, bumper_contacts, reflect);
}

}  // namespace ricochet::disc
