// Programs started at fixed addresses (fixed_addresses.hpp).
#include "fixed_addresses.hpp"

#if defined(__linux__) && !defined(__EMSCRIPTEN__)
#include <sys/personality.h>

#include <cerrno>
#include <cstring>
#endif

namespace ricochet::fuzz {

#if defined(__linux__) && !defined(__EMSCRIPTEN__)
FixedAddresses::FixedAddresses() {
    // 0xffffffff asks for the personality without changing it.
    const int now = personality(0xffffffff);
    if (now == -1 || personality(static_cast<unsigned long>(now) | ADDR_NO_RANDOMIZE) == -1) {
        error_ = std::strerror(errno);
        return;
    }
    before_ = now;
}

FixedAddresses::~FixedAddresses() {
    if (before_ != -1) personality(static_cast<unsigned long>(before_));
}
#else
FixedAddresses::FixedAddresses() : error_("this system has no Linux personality to turn address randomization off") {}
FixedAddresses::~FixedAddresses() = default;
#endif

}  // namespace ricochet::fuzz
