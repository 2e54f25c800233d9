// Internal: a disc contact's exact entry time as integers, for a kernel that rounds its constructions itself
// (exact_disc.cpp). Apart from contact.hpp so that the code without big numbers never sees their type.
#pragma once

#include "base/bignum.hpp"
#include "kernels/disc/contact.hpp"

namespace ricochet::disc {

/// A contact's entry time t = (a + b·√c)/d exactly: integers (the leg and the obstacle relative to q, at one
/// scale, which the quotient does not depend on), d > 0, c ≥ 0 (c = 0, b = 0 for a contact at the start).
struct TimeRoot {
    bignum::Integer a, b, c, d;
};
/// The exact entry time of contact c (contact.hpp's t_f or t_c), for constructions that round it themselves.
TimeRoot contact_root(const Leg& leg, const Obstacle& o, const Contact& c);

}  // namespace ricochet::disc
