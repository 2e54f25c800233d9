// The floating-point model the determinism contract needs, refused at compile time where the
// preprocessor can see it: the same bits on every machine need IEEE-754 double arithmetic, each
// operation rounded once. ricochet::core's compile options carry the flags (-ffp-contract=off
// -fno-fast-math; -mfpmath=sse on x86-64, -msse2 -mfpmath=sse on 32-bit x86, where Debian's gcc
// defaults to x87); this catches a build that overrides them.
// Contraction into FMA (-ffp-contract=fast, GCC's default under GNU dialects) leaves no macro, so it
// cannot be detected here: the flag on the target is the only guard (examples/package_test.sh tests it).
#pragma once

#include <cfloat>

#if defined(__FAST_MATH__)
#error "ricochet: -ffast-math (or -Ofast) breaks the determinism contract; compile with -fno-fast-math -ffp-contract=off"
#endif

#if defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__
#error "ricochet: -ffinite-math-only drops the NaN and infinity checks the kernels rely on; compile with -fno-fast-math"
#endif

// FLT_EVAL_METHOD 0: float and double expressions are evaluated in their own type (1, 2: excess
// precision as on x87; -1: unknown).
#if !defined(FLT_EVAL_METHOD) || FLT_EVAL_METHOD != 0
#error "ricochet: excess precision (FLT_EVAL_METHOD != 0, e.g. x87) breaks the determinism contract; compile with -mfpmath=sse -msse2 -ffp-contract=off"
#endif
