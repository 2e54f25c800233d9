// 64-bit integers into and out of GMP where `long` may have 32 bits (i386): mpz_set_si and mpz_get_ui
// take and give a long, which would cut a 53-bit mantissa. Through limbs instead, on every platform.
#pragma once

#include <cstdint>

#include <gmp.h>

namespace ricochet::exact_kernel::num {

/// out = v, exactly.
inline void set_int64(mpz_t out, std::int64_t v) {
    // |v| as unsigned: exact even for INT64_MIN.
    const std::uint64_t m = v < 0 ? std::uint64_t{0} - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v);
    // One 64-bit word, least significant first, native byte order.
    mpz_import(out, 1, -1, sizeof m, 0, 0, &m);
    if (v < 0) mpz_neg(out, out);
}

/// The low 64 bits of |z|.
inline std::uint64_t low_uint64(mpz_srcptr z) {
    std::uint64_t r = 0;
    const auto limbs = static_cast<int>(mpz_size(z));
    for (int i = 0; i < limbs && i * GMP_NUMB_BITS < 64; ++i)
        r |= static_cast<std::uint64_t>(mpz_getlimbn(z, i)) << (i * GMP_NUMB_BITS);
    return r;
}

}  // namespace ricochet::exact_kernel::num
