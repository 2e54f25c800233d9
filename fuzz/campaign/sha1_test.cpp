// sha1_hex (sha1.hpp) against FIPS 180 test vectors and against the name libFuzzer gave an artifact.
#include <gtest/gtest.h>

#include <string>

#include "sha1.hpp"

namespace ricochet::fuzz {
namespace {

TEST(Sha1Hex, FipsVectors) {
    EXPECT_EQ(sha1_hex(""), "da39a3ee5e6b4b0d3255bfef95601890afd80709");
    EXPECT_EQ(sha1_hex("abc"), "a9993e364706816aba3e25717850c26c9cd0d89d");
    EXPECT_EQ(sha1_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
              "84983e441c3bd26ebaae4aa1f95129e5e54670f1");
    EXPECT_EQ(sha1_hex(std::string(1'000'000, 'a')), "34aa973cd4c4daa4f61eeb2bdbad27316534016f");
}

TEST(Sha1Hex, BinaryBytes) {
    // NUL and high bytes count like any other (a fuzz input is arbitrary bytes).
    const std::string bytes("\x00\xff\x80\x01", 4);
    EXPECT_EQ(sha1_hex(bytes), "f83fa0e751b27c7e5c0c8e68757cca55606dc0e4");  // printf '\x00\xff\x80\x01' | sha1sum
}

TEST(Sha1Hex, LibFuzzerArtifactName) {
    // A 16-byte input that fuzz_sweep (lecture-double, -seed=1) saved as
    // crash-8de3e5b670a8ed9209280e089f1375153b7a5174: libFuzzer names an artifact by the SHA-1 of its bytes.
    const unsigned char input[] = {0x04, 0x04, 0xff, 0xd3, 0x14, 0xd8, 0x04, 0x1c,
                                   0x1c, 0x1c, 0x1c, 0x11, 0x04, 0xff, 0xd3, 0x2c};
    const std::string bytes(reinterpret_cast<const char*>(input), sizeof input);
    EXPECT_EQ(sha1_hex(bytes), "8de3e5b670a8ed9209280e089f1375153b7a5174");
}

}  // namespace
}  // namespace ricochet::fuzz
