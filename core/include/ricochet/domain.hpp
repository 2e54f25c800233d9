// A scene's domain: what the user says their world is (docs/scene-log.md, "Domain"). ricochet's default is the
// whole accepted range and every convention; a user's kernel may promise less: coordinates and speeds within a
// bound, no subnormal numbers, walls at least so long, or not ricochet's convention that touching is a hit. The
// generators and fuzz decoders then draw scenes inside it (fit_to_domain), the checks that rest on a waived
// convention are not run (waived_checks), and a log states its domain in `domain` lines, so that replay judges
// it the same way and the reader refuses a scene outside it.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "ricochet/check.hpp"
#include "ricochet/shapes.hpp"

namespace ricochet {

struct Scene;

/// The domain a scene is drawn from and judged in. Every bound is finite and > 0 when set.
struct Domain {
    /// `domain coordinates C`: every position, wall end, centre and rect edge, and every radius, within [−C, C].
    std::optional<double> coordinates;
    /// `domain speed V`: every velocity component within [−V, V].
    std::optional<double> speed;
    /// `domain wall-length L`: every wall at least L long (|p1 − p0| ≥ L, decided exactly), so none of zero length.
    std::optional<double> wall_length;
    /// `domain no-subnormals`: no subnormal number anywhere in the scene (zero is fine).
    bool no_subnormals = false;
    /// `domain waive touching`: the kernel does not promise that touching is a hit (a leg ending exactly on a
    /// wall, a point on a rim): the checks that judge it (boundary, oracle) are not run.
    bool waive_touching = false;
    /// True for the default: the whole accepted range and every convention.
    bool full() const { return !coordinates && !speed && !wall_length && !no_subnormals && !waive_touching; }
    friend bool operator==(const Domain&, const Domain&) = default;
};

/// The checks a domain's waived conventions switch off (boundary and oracle for `waive touching`); empty for the
/// full domain.
std::span<const Check> waived_checks(const Domain& domain);

/// True if w is at least length long: |p1 − p0| ≥ length, decided exactly (`domain wall-length`).
bool wall_at_least(const Wall& w, double length);

/// Why scene lies outside domain ("ball 0's VX 2000 is outside the domain's speed 1000"), or nothing.
std::optional<std::string> outside_domain(const Scene& scene, const Domain& domain);

/// Brings a drawn scene into domain, keeping its geometry: every length (positions, ends, centres, edges, radii and
/// velocities) scaled by one power of two until the coordinates fit, then the velocities by another until the speeds
/// fit (exact, as long as nothing underflows). Sets scene.domain. False when the scene still lies outside (a
/// subnormal, a wall too short): the case is to be discarded, not judged.
bool fit_to_domain(Scene& scene, const Domain& domain);

/// Reads a domain as RICOCHET_DOMAIN and --domain spell it: comma-separated items, the `domain` lines' words with
/// `=` before a value: "coordinates=1e6,speed=1000,wall-length=0.001,no-subnormals,waive=touching". Empty: the full
/// domain. Nothing, and *error says which item and why, for anything else.
std::optional<Domain> parse_domain_spec(std::string_view spec, std::string* error);

/// The domain as parse_domain_spec reads it back ("" for the full domain).
std::string domain_spec(const Domain& domain);

}  // namespace ricochet
