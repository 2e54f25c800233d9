// Kernel names and the run-time dispatch to the four implementations.
#include "ricochet/kernel.hpp"

#include <cmath>

#include "kernel_impl.hpp"
#include "kernel_lecture.hpp"

namespace ricochet {

std::string_view kernel_name(KernelId k) {
    switch (k) {
        case KernelId::lecture_float: return "lecture-float";
        case KernelId::lecture_double: return "lecture-double";
        case KernelId::robust: return "robust";
        case KernelId::exact: return "exact";
    }
    return "?";
}

std::optional<KernelId> parse_kernel(std::string_view name) {
    for (KernelId k : k_all_kernels)
        if (kernel_name(k) == name) return k;
    return std::nullopt;
}

bool in_range(double x) { return std::isfinite(x) && std::fabs(x) <= k_coordinate_limit; }

std::string_view miss_name(Miss m) {
    switch (m) {
        case Miss::none: return "hit";
        case Miss::both_inside: return "both-inside";
        case Miss::both_outside: return "both-outside";
        case Miss::parallel: return "parallel";
        case Miss::before_p0: return "before-p0";
        case Miss::past_p1: return "past-p1";
        case Miss::degenerate: return "degenerate";
        case Miss::leaving: return "leaving";
    }
    return "?";
}

Side classify(KernelId k, Vec2 p, const Wall& w) {
    switch (k) {
        case KernelId::lecture_float: return lecture::classify<float>(p, w);
        case KernelId::lecture_double: return lecture::classify<double>(p, w);
        case KernelId::robust: return robust::classify(p, w);
        case KernelId::exact: return exact_kernel::classify(p, w);
    }
    return Side::On;
}

bool point_in_circle(KernelId k, Vec2 p, const Circle& c) {
    switch (k) {
        case KernelId::lecture_float: return lecture::point_in_circle<float>(p, c);
        case KernelId::lecture_double: return lecture::point_in_circle<double>(p, c);
        case KernelId::robust: return robust::point_in_circle(p, c);
        case KernelId::exact: return exact_kernel::point_in_circle(p, c);
    }
    return false;
}

bool circles_overlap(KernelId k, const Circle& a, const Circle& b) {
    switch (k) {
        case KernelId::lecture_float: return lecture::circles_overlap<float>(a, b);
        case KernelId::lecture_double: return lecture::circles_overlap<double>(a, b);
        case KernelId::robust: return robust::circles_overlap(a, b);
        case KernelId::exact: return exact_kernel::circles_overlap(a, b);
    }
    return false;
}

bool point_in_rect(KernelId k, Vec2 p, const Rect& r) {
    // Comparisons of doubles are exact: robust and exact share lecture-double's test.
    return k == KernelId::lecture_float ? lecture::point_in_rect<float>(p, r) : lecture::point_in_rect<double>(p, r);
}

bool rects_overlap(KernelId k, const Rect& a, const Rect& b) {
    return k == KernelId::lecture_float ? lecture::rects_overlap<float>(a, b) : lecture::rects_overlap<double>(a, b);
}

Sweep sweep(KernelId k, Vec2 bs, Vec2 v, const Wall& w) {
    switch (k) {
        case KernelId::lecture_float: return lecture::sweep<float>(bs, v, w);
        case KernelId::lecture_double: return lecture::sweep<double>(bs, v, w);
        case KernelId::robust: return robust::sweep(bs, v, w);
        case KernelId::exact: return exact_kernel::sweep(bs, v, w);
    }
    return {};
}

Vec2 reflect(KernelId k, Vec2 v, const Wall& w) {
    switch (k) {
        case KernelId::lecture_float: {
            const auto r = lecture::reflect<float>(lecture::to<float>(v), w);
            return {static_cast<double>(r.x), static_cast<double>(r.y)};
        }
        case KernelId::lecture_double: {
            const auto r = lecture::reflect<double>(lecture::to<double>(v), w);
            return {r.x, r.y};
        }
        case KernelId::robust: return robust::reflect(v, w);
        case KernelId::exact: return exact_kernel::reflect(v, w);
    }
    return v;
}

FrameStatus step_ball(KernelId k, Ball& ball, BallMemory& memory, std::span<const Wall> walls,
                      std::vector<HitEvent>& hits, StepScratch& scratch, const WallIndex* index) {
    const auto ok = [](const Ball& b) {
        return in_range(b.pos.x) && in_range(b.pos.y) && in_range(b.vel.x) && in_range(b.vel.y);
    };
    if (!ok(ball)) return FrameStatus::out_of_range;
    // Work on copies so that a frame which leaves the range changes nothing.
    Ball next = ball;
    BallMemory next_memory = memory;
    const std::size_t first_hit = hits.size();
    FrameStatus status = FrameStatus::ok;
    switch (k) {
        case KernelId::lecture_float: status = lecture::step_ball<float>(next, walls, hits, scratch, index); break;
        case KernelId::lecture_double: status = lecture::step_ball<double>(next, walls, hits, scratch, index); break;
        case KernelId::robust: status = robust::step_ball(next, next_memory, walls, hits, scratch, index); break;
        case KernelId::exact: status = exact_kernel::step_ball(next, next_memory, walls, hits, scratch); break;
    }
    if (!ok(next)) {
        hits.resize(first_hit);
        return FrameStatus::out_of_range;
    }
    ball = next;
    memory = next_memory;
    return status;
}

}  // namespace ricochet
