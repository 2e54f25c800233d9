#include "methods.hpp"

#include <vector>

namespace ricochet::bench {
namespace {

class KernelMethod final : public Method {
public:
    explicit KernelMethod(KernelId k) : k_(k) {}
    std::string name() const override { return std::string(kernel_name(k_)); }
    const KernelId* kernel() const override { return &k_; }

    SweepAnswer sweep_one(const SweepQuery& q) const override {
        const Sweep s = sweep(k_, q.bs, q.v, q.wall);
        return {s.hit(), true, s.t, s.point};
    }
    void sweep_all(std::span<const SweepQuery> qs, std::span<SweepAnswer> out) const override {
        for (std::size_t i = 0; i < qs.size(); ++i) {
            const Sweep s = sweep(k_, qs[i].bs, qs[i].v, qs[i].wall);
            out[i] = {s.hit(), true, s.t, s.point};
        }
    }
    bool has_disc() const override { return true; }
    void disc_all(std::span<const DiscQuery> qs, std::span<DiscAnswer> out) const override {
        // What a user calls: one frame of step_ball for the disc among the query's obstacles (the kernel's
        // step_disc: its decisions, the contact point, the bounce and the rest of the frame); the first hit is the
        // answer.
        std::vector<HitEvent> hits;
        StepScratch scratch;
        for (std::size_t i = 0; i < qs.size(); ++i) {
            const DiscQuery& q = qs[i];
            Ball b{q.bs, q.v, q.R};
            BallMemory memory;
            hits.clear();
            step_ball(k_, b, memory, Obstacles{q.wall_span(), q.bumper_span(), nullptr}, hits, scratch);
            out[i] = hits.empty() ? DiscAnswer{} : DiscAnswer{true, hits[0].bumper, hits[0].wall, hits[0].point};
        }
    }
    void static_all(std::span<const StaticQuery> qs, std::span<unsigned char> out) const override {
        for (std::size_t i = 0; i < qs.size(); ++i) {
            const StaticQuery& q = qs[i];
            bool r = false;
            switch (q.kind) {
                case StaticKind::point_circle: r = point_in_circle(k_, q.p, q.a); break;
                case StaticKind::circle_circle: r = circles_overlap(k_, q.a, q.b); break;
                case StaticKind::point_rect: r = point_in_rect(k_, q.p, q.ra); break;
                case StaticKind::rect_rect: r = rects_overlap(k_, q.ra, q.rb); break;
            }
            out[i] = r;
        }
    }

private:
    KernelId k_;
};

}  // namespace

std::vector<std::unique_ptr<Method>> kernel_methods() {
    std::vector<std::unique_ptr<Method>> out;
    for (KernelId k : k_all_kernels) out.push_back(std::make_unique<KernelMethod>(k));
    return out;
}

std::vector<std::unique_ptr<Method>> peer_methods(std::vector<std::string>& skipped) {
    std::vector<std::unique_ptr<Method>> out;
    (void)skipped;
#ifdef RICOCHET_HAVE_BOX2D
    out.push_back(make_box2d());
#else
    skipped.emplace_back("box2d: skipped, libbox2d-dev (find_package(box2d)) was not found at build time");
#endif
#ifdef RICOCHET_HAVE_CHIPMUNK
    out.push_back(make_chipmunk());
#else
    skipped.emplace_back("chipmunk: skipped, libchipmunk-dev (libchipmunk + chipmunk/chipmunk.h) was not found at build time");
#endif
#ifdef RICOCHET_HAVE_CGAL
    out.push_back(make_cgal());
#else
    skipped.emplace_back("cgal: skipped, libcgal-dev (find_package(CGAL)) was not found at build time");
#endif
    return out;
}

}  // namespace ricochet::bench
