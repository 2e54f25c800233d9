// wall_at_least (wall_length.hpp): every double is an integer multiple of 2^−1074, so with every number written as
// that integer (at most 2^256 · 2^1074, 1331 bits), dx² + dy² ≥ L² is a comparison of integers, done here in
// base 2^32 on the magnitudes.
#include "wall_length.hpp"

#include <cmath>
#include <cstdint>
#include <vector>

namespace ricochet_grammar {
namespace {

/// A magnitude, base 2^32, least significant first, no leading zero limbs.
using Big = std::vector<std::uint32_t>;

void trim(Big& a) {
    while (!a.empty() && a.back() == 0) a.pop_back();
}

/// |x| / 2^−1074, exactly.
Big units(double x) {
    int e = 0;
    const double m = std::frexp(std::fabs(x), &e);  // |x| = m · 2^e, m in [0.5, 1)
    if (m == 0) return {};
    std::uint64_t mant = static_cast<std::uint64_t>(std::ldexp(m, 53));  // |x| = mant · 2^(e − 53)
    int shift = e - 53 + 1074;  // ≥ 0: |x| is a multiple of 2^−1074
    while (shift < 0) {  // a subnormal's mantissa has trailing zeros to give back
        mant >>= 1;
        ++shift;
    }
    Big out(static_cast<std::size_t>(shift / 32) + 3, 0);
    // mant · 2^(shift mod 32) in three limbs, from mant's 32-bit halves (no 128-bit type on 32-bit targets).
    const unsigned s = static_cast<unsigned>(shift % 32);
    const std::uint64_t a = (mant & 0xffffffffu) << s;  // < 2^63
    const std::uint64_t b = (mant >> 32) << s;          // < 2^52
    const std::uint64_t mid = (a >> 32) + (b & 0xffffffffu);
    const std::size_t at = static_cast<std::size_t>(shift / 32);
    out[at] = static_cast<std::uint32_t>(a);
    out[at + 1] = static_cast<std::uint32_t>(mid);
    out[at + 2] = static_cast<std::uint32_t>((b >> 32) + (mid >> 32));
    trim(out);
    return out;
}

int compare(const Big& a, const Big& b) {
    if (a.size() != b.size()) return a.size() < b.size() ? -1 : 1;
    for (std::size_t i = a.size(); i-- > 0;)
        if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
    return 0;
}

Big add(const Big& a, const Big& b) {
    Big out(std::max(a.size(), b.size()) + 1, 0);
    std::uint64_t carry = 0;
    for (std::size_t i = 0; i < out.size(); ++i) {
        const std::uint64_t s = carry + (i < a.size() ? a[i] : 0) + (i < b.size() ? b[i] : 0);
        out[i] = static_cast<std::uint32_t>(s);
        carry = s >> 32;
    }
    trim(out);
    return out;
}

/// a − b for a ≥ b.
Big sub(const Big& a, const Big& b) {
    Big out(a.size(), 0);
    std::int64_t borrow = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        std::int64_t d = static_cast<std::int64_t>(a[i]) - borrow - (i < b.size() ? b[i] : 0);
        borrow = d < 0;
        if (d < 0) d += std::int64_t{1} << 32;
        out[i] = static_cast<std::uint32_t>(d);
    }
    trim(out);
    return out;
}

Big mul(const Big& a, const Big& b) {
    Big out(a.size() + b.size() + 1, 0);
    for (std::size_t i = 0; i < a.size(); ++i) {
        std::uint64_t carry = 0;
        for (std::size_t j = 0; j < b.size(); ++j) {
            const std::uint64_t t = static_cast<std::uint64_t>(a[i]) * b[j] + out[i + j] + carry;
            out[i + j] = static_cast<std::uint32_t>(t);
            carry = t >> 32;
        }
        for (std::size_t k = i + b.size(); carry != 0; ++k) {
            const std::uint64_t t = out[k] + carry;
            out[k] = static_cast<std::uint32_t>(t);
            carry = t >> 32;
        }
    }
    trim(out);
    return out;
}

/// |a − b| in units of 2^−1074.
Big distance(double a, double b) {
    const bool same_sign = std::signbit(a) == std::signbit(b);
    const Big ua = units(a), ub = units(b);
    if (!same_sign) return add(ua, ub);
    return compare(ua, ub) >= 0 ? sub(ua, ub) : sub(ub, ua);
}

}  // namespace

bool wall_at_least(double x0, double y0, double x1, double y1, double length) {
    const Big dx = distance(x1, x0), dy = distance(y1, y0), l = units(length);
    return compare(add(mul(dx, dx), mul(dy, dy)), mul(l, l)) >= 0;
}

}  // namespace ricochet_grammar
