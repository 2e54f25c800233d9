// Methods under test: the four kernels through ricochet's API, and the peers through their own APIs.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "disc_workloads.hpp"
#include "workloads.hpp"

namespace ricochet::bench {

/// One method's answer to a sweep query.
struct SweepAnswer {
    bool hit = false;
    bool has_t = false;  ///< false where the method gives no leg parameter (CGAL's intersection point)
    double t = 0.0;
    Vec2 point;
};

/// One method's first contact on a disc query: the obstacle (a wall of the query, or its bumper) and the disc's
/// centre where the method puts the contact.
struct DiscAnswer {
    bool hit = false;
    bool bumper = false;
    std::uint32_t index = 0;  ///< the wall (into DiscQuery::walls) when not bumper
    Vec2 point;
};

/// A way of answering the queries. Each method runs its own throughput loop, so that a per-query
/// virtual call is not part of what is timed.
class Method {
public:
    virtual ~Method() = default;
    /// The name in the table.
    virtual std::string name() const = 0;
    /// Untimed set-up for a batch of queries (a peer's shapes that a game would keep in its world).
    virtual void prepare(std::span<const SweepQuery>) const {}
    /// Frees what prepare made.
    virtual void release() const {}
    /// Answers every sweep query.
    virtual void sweep_all(std::span<const SweepQuery> qs, std::span<SweepAnswer> out) const = 0;
    /// Answers one sweep query (the naive closed-box stepper uses it).
    virtual SweepAnswer sweep_one(const SweepQuery& q) const = 0;
    /// Whether the method has an answer for this static test.
    virtual bool has_static(StaticKind) const { return true; }
    /// Answers every static query (1 = collide), all of the same kind.
    virtual void static_all(std::span<const StaticQuery> qs, std::span<unsigned char> out) const = 0;
    /// Whether the method answers disc queries (CGAL has no moving disc).
    virtual bool has_disc() const { return false; }
    /// Untimed set-up for a batch of disc queries (a peer's shapes), and its release.
    virtual void prepare_discs(std::span<const DiscQuery>) const {}
    virtual void release_discs() const {}
    /// Answers every disc query: the first contact of the disc's leg, or no hit.
    virtual void disc_all(std::span<const DiscQuery>, std::span<DiscAnswer>) const {}
    /// The kernel behind it, if it is one of ricochet's (closed-box runs then use step_ball).
    virtual const KernelId* kernel() const { return nullptr; }
};

/// The four kernels, in k_all_kernels order.
std::vector<std::unique_ptr<Method>> kernel_methods();
/// The peers that were found at build time; a line for each one skipped is appended to skipped.
std::vector<std::unique_ptr<Method>> peer_methods(std::vector<std::string>& skipped);

/// Peer factories, each defined only when its library was found (see bench/CMakeLists.txt).
std::unique_ptr<Method> make_box2d();
std::unique_ptr<Method> make_chipmunk();
std::unique_ptr<Method> make_cgal();

}  // namespace ricochet::bench
