// The disc gate of `ricochet bench` (disc_score.hpp): the truth on hand-made legs (a tangent, a leg ending on the
// capsule moving in or along it), robust and exact clean on every disc workload, and answers made wrong on
// purpose (a missed hit, an invented one, a ghost bounce at a joint, a contact point inside) each failing it.
#include <gtest/gtest.h>

#include "disc_score.hpp"
#include "disc_workloads.hpp"
#include "methods.hpp"

namespace ricochet::bench {
namespace {

DiscQuery wall_query(Vec2 bs, Vec2 be, double R) {
    DiscQuery q;
    q.bs = bs;
    q.v = be - bs;
    q.R = R;
    q.walls[0] = {{0, 0}, {4, 0}};
    q.nwalls = 1;
    return q;
}

TEST(DiscTruth, HandCases) {
    // Sliding along the face at exactly R: a tangent, no hit; a hair closer at the end: a hit.
    EXPECT_FALSE(truth_hit(wall_query({1, 0.5}, {3, 0.5}, 0.5)));
    EXPECT_TRUE(truth_hit(wall_query({1, 0.5}, {3, std::nextafter(0.5, 0.0)}, 0.5)));
    // Ending exactly at R while moving in: an entry at t = 1, a hit; moving out to R from inside the leg: none.
    EXPECT_TRUE(truth_hit(wall_query({1, 2}, {1, 0.5}, 0.5)));
    EXPECT_FALSE(truth_hit(wall_query({1, 2}, {1, 0.75}, 0.5)));
    // A grazing leg (from disc-grazing) ending exactly at R on the face, 4.6e-18 closer than it started per unit
    // of n: an entry at t = 1, although the rounded v = fl(Be − Bs) runs exactly parallel to the wall.
    DiscQuery g = wall_query({-0.171875, 0.05468750000000001}, {0.078125, -0.4140625}, 0.06640625);
    g.walls[0] = {{-0.41796875, 0.375}, {0.23828125, -0.85546875}};
    EXPECT_TRUE(truth_hit(g));
    // A cap: passing P1 = (4, 0) tangentially at (4, 0.5) (no hit), ending on its circle moving in (a hit).
    EXPECT_FALSE(truth_hit(wall_query({5, 0.5}, {3.5, 0.5}, 0.5)));
    EXPECT_TRUE(truth_hit(wall_query({6, 0}, {4.5, 0}, 0.5)));
    // A bumper of radius 1 at the origin met by a disc of radius 0.5: tangent at 1.5, and through it.
    DiscQuery b;
    b.R = 0.5;
    b.has_bumper = true;
    b.bumper = {{0, 0}, 1.0};
    b.bs = {-2, 1.5};
    b.v = {4, 0};
    EXPECT_FALSE(truth_hit(b));
    b.v = {4, -0.25};
    EXPECT_TRUE(truth_hit(b));
}

struct Scored {
    DiscWorkload wl;
    std::vector<bool> hits;
    std::vector<DiscAnswer> exact, robust;
};

std::vector<Scored> scored_workloads() {
    std::vector<Scored> out;
    std::unique_ptr<Method> robust, exact;
    for (auto& m : kernel_methods()) {
        if (m->name() == "robust") robust = std::move(m);
        else if (m->name() == "exact") exact = std::move(m);
    }
    for (DiscWorkload& wl : disc_workloads(300, 11)) {
        Scored s{std::move(wl), {}, {}, {}};
        const std::size_t n = s.wl.queries.size();
        s.exact.resize(n);
        s.robust.resize(n);
        exact->disc_all(s.wl.queries, s.exact);
        robust->disc_all(s.wl.queries, s.robust);
        for (const DiscQuery& q : s.wl.queries) s.hits.push_back(truth_hit(q));
        out.push_back(std::move(s));
    }
    return out;
}

TEST(DiscWorkloads, NamesInOrder) {
    const std::vector<DiscWorkload> w = disc_workloads(2, 1);
    const auto names = disc_workload_names();
    ASSERT_EQ(w.size(), names.size());
    for (std::size_t i = 0; i < w.size(); ++i) EXPECT_EQ(w[i].name, names[i]);
}

TEST(DiscGate, RobustAndExactAreClean) {
    for (const Scored& s : scored_workloads()) {
        const DiscScore r = score_discs(s.wl.queries, s.robust, s.exact, s.hits, s.wl.joint);
        const DiscScore e = score_discs(s.wl.queries, s.exact, s.exact, s.hits, s.wl.joint);
        EXPECT_TRUE(disc_score_clean(r)) << s.wl.name << ": robust FN " << r.fn << " FP " << r.fp << " ghosts " << r.ghosts
                                         << " inside " << r.inside;
        EXPECT_TRUE(disc_score_clean(e)) << s.wl.name << ": exact FN " << e.fn << " FP " << e.fp << " inside " << e.inside;
        EXPECT_EQ(e.part, 0) << s.wl.name;
    }
}

TEST(DiscGate, WrongAnswersFailIt) {
    for (Scored& s : scored_workloads()) {
        const auto score = [&](const std::vector<DiscAnswer>& a) {
            return score_discs(s.wl.queries, a, s.exact, s.hits, s.wl.joint);
        };
        std::size_t hit = s.hits.size(), miss = s.hits.size();
        for (std::size_t i = 0; i < s.hits.size(); ++i) (s.hits[i] ? hit : miss) = i;
        if (hit < s.hits.size()) {
            // A missed hit.
            std::vector<DiscAnswer> a = s.robust;
            a[hit] = {};
            const DiscScore d = score(a);
            EXPECT_EQ(d.fn, 1) << s.wl.name;
            EXPECT_FALSE(disc_score_clean(d)) << s.wl.name;
            // A contact point moved onto the wall's end (or the bumper's centre): inside by R (R + r).
            a = s.robust;
            const DiscQuery& q = s.wl.queries[hit];
            a[hit].point = q.has_bumper ? q.bumper.c : q.walls[a[hit].index].p0;
            const DiscScore p = score(a);
            EXPECT_EQ(p.inside, 1) << s.wl.name;
            EXPECT_GT(p.depth, 0.0) << s.wl.name;
            EXPECT_FALSE(disc_score_clean(p)) << s.wl.name;
        }
        if (miss < s.hits.size()) {
            // An invented hit (at the joint workload: a ghost bounce) at the leg's start.
            std::vector<DiscAnswer> a = s.robust;
            a[miss] = {true, s.wl.queries[miss].has_bumper, 0, s.wl.queries[miss].bs};
            const DiscScore d = score(a);
            EXPECT_EQ(d.fp, 1) << s.wl.name;
            EXPECT_EQ(d.ghosts, s.wl.joint ? 1 : -1) << s.wl.name;
            EXPECT_FALSE(disc_score_clean(d)) << s.wl.name;
        }
        // Every workload but the joint has both; the joint none with a hit.
        EXPECT_EQ(hit < s.hits.size(), !s.wl.joint) << s.wl.name;
        EXPECT_LT(miss, s.hits.size()) << s.wl.name;
    }
}

}  // namespace
}  // namespace ricochet::bench
