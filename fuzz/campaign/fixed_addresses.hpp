// Programs started without address-space randomization, for reproducible campaigns. libFuzzer's coverage
// follows addresses in a few places (comparison tracing records pointer values and splices them into new
// inputs; docs/fuzzing.md, "Reproducible campaigns"), so with ASLR two runs of the same seed and run count can
// part after a few thousand inputs. Linux keeps the choice in the process's personality, which exec inherits.
#pragma once

#include <string>

namespace ricochet::fuzz {

/// While alive, every program this process starts runs with ADDR_NO_RANDOMIZE (what `setarch -R` does); the
/// personality before it comes back on destruction. This process's own addresses do not change.
class FixedAddresses {
public:
    FixedAddresses();
    ~FixedAddresses();
    FixedAddresses(const FixedAddresses&) = delete;
    FixedAddresses& operator=(const FixedAddresses&) = delete;
    /// Empty if the programs started now run at fixed addresses; else why not (a system without Linux's
    /// personality, or one that refuses it, as a container's seccomp filter may).
    const std::string& error() const { return error_; }

private:
    int before_ = -1;  ///< the personality to restore, or -1: nothing changed
    std::string error_;
};

}  // namespace ricochet::fuzz
