// SHA-1 in hex: libFuzzer names its artifacts crash-SHA1 after their bytes, and a fuzz log's
// `from fuzz TARGET SHA1` line names its input the same way.
#pragma once

#include <string>
#include <string_view>

namespace ricochet::fuzz {

/// The 40 lowercase hex digits of SHA-1 over data.
std::string sha1_hex(std::string_view data);

}  // namespace ricochet::fuzz
