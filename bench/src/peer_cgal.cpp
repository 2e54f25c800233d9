// CGAL 5.5 through its own API, with Exact_predicates_inexact_constructions_kernel: do_intersect of
// the leg's Segment_2 with the wall's Segment_2 for the decision, intersection() for the point (no leg
// parameter: CGAL constructs the point only); bounded_side for points against Circle_2 and
// Iso_rectangle_2, compare_squared_distance for two circles, do_intersect for two rectangles.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include "methods.hpp"

namespace ricochet::bench {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
using Segment = K::Segment_2;

Point to_cgal(Vec2 p) { return {p.x, p.y}; }

class CgalMethod final : public Method {
public:
    std::string name() const override { return "cgal"; }

    SweepAnswer sweep_one(const SweepQuery& q) const override {
        const Segment leg(to_cgal(q.bs), to_cgal(q.bs + q.v));
        const Segment wall(to_cgal(q.wall.p0), to_cgal(q.wall.p1));
        if (!CGAL::do_intersect(leg, wall)) return {};
        SweepAnswer a{true, false, 0.0, {}};
        if (const auto x = CGAL::intersection(leg, wall)) {
            if (const Point* p = boost::get<Point>(&*x)) a.point = {p->x(), p->y()};
            // Collinear overlap: CGAL answers a segment; its first point is where the leg meets it.
            else if (const Segment* s = boost::get<Segment>(&*x)) a.point = {s->source().x(), s->source().y()};
        }
        return a;
    }
    void sweep_all(std::span<const SweepQuery> qs, std::span<SweepAnswer> out) const override {
        for (std::size_t i = 0; i < qs.size(); ++i) out[i] = sweep_one(qs[i]);
    }
    void static_all(std::span<const StaticQuery> qs, std::span<unsigned char> out) const override {
        for (std::size_t i = 0; i < qs.size(); ++i) {
            const StaticQuery& q = qs[i];
            bool r = false;
            switch (q.kind) {
                case StaticKind::point_circle:
                    // Circle_2 takes the squared radius, rounded as a user computes it.
                    r = K::Circle_2(to_cgal(q.a.c), q.a.r * q.a.r).bounded_side(to_cgal(q.p)) != CGAL::ON_UNBOUNDED_SIDE;
                    break;
                case StaticKind::circle_circle: {
                    const double rs = q.a.r + q.b.r;
                    r = CGAL::compare_squared_distance(to_cgal(q.a.c), to_cgal(q.b.c), rs * rs) != CGAL::LARGER;
                    break;
                }
                case StaticKind::point_rect:
                    r = K::Iso_rectangle_2(q.ra.left, q.ra.bottom, q.ra.right, q.ra.top).bounded_side(to_cgal(q.p)) !=
                        CGAL::ON_UNBOUNDED_SIDE;
                    break;
                case StaticKind::rect_rect:
                    r = CGAL::do_intersect(K::Iso_rectangle_2(q.ra.left, q.ra.bottom, q.ra.right, q.ra.top),
                                           K::Iso_rectangle_2(q.rb.left, q.rb.bottom, q.rb.right, q.rb.top));
                    break;
            }
            out[i] = r;
        }
    }
};

}  // namespace

std::unique_ptr<Method> make_cgal() { return std::make_unique<CgalMethod>(); }

}  // namespace ricochet::bench
