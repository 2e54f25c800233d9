// Expectations: what a scene log's `expect` lines say its run must give.
#pragma once

#include <cstdint>

#include "ricochet/check.hpp"
#include "ricochet/shapes.hpp"

namespace ricochet {

/// `expect state F I X Y VX VY`: ball I's state at the end of frame F.
struct ExpectState {
    std::int64_t frame = 0;
    std::uint32_t ball = 0;
    Ball state;
    friend bool operator==(const ExpectState&, const ExpectState&) = default;
};
/// `expect failure CHECK F`: the run must break CHECK first at frame F.
struct ExpectFailure {
    Check check = Check::no_tunnel;
    std::int64_t frame = 0;
    friend bool operator==(const ExpectFailure&, const ExpectFailure&) = default;
};
/// `found CHECK F BALL`: the run that saved this log broke CHECK first at frame F for ball BALL. A record,
/// not an expectation: replay's verdict does not depend on it, its message says when the run differs.
struct Found {
    Check check = Check::no_tunnel;
    std::int64_t frame = 0;
    std::uint32_t ball = 0;
    friend bool operator==(const Found&, const Found&) = default;
};

}  // namespace ricochet
