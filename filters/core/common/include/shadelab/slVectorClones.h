#ifndef slVectorClones_h
#define slVectorClones_h
/**
 * @file slVectorClones.h
 * @brief A loop compiled more than once, for AVX2 (and AVX-512) and for the
 * baseline x86-64 (SSE2), and the version picked at run time. C++ only.
 *
 * For loops that the compiler vectorises well only with AVX2: corner
 * weights of triangle blocks (slTriangleBlock.h), and passes over 64-bit
 * point ids, since SSE2 has no 64-bit integer compare. The loop is written
 * once, in a function marked SL_ALWAYS_INLINE (slCompilerHints.h); a
 * second function marked SL_TARGET_AVX2 only calls it, so that the loop is
 * compiled into it for AVX2; the caller picks one with slHasAVX2():
 *
 * @code
 * SL_ALWAYS_INLINE bool loop(...) { ... }
 * SL_TARGET_AVX2 bool loopAVX2(...) { return loop(...); }
 * bool pick(...) { return slHasAVX2() ? loopAVX2(...) : loop(...); }
 * @endcode
 *
 * A loop with an AVX-512 clone too (below) asks slHasAVX512() first.
 *
 * Not GCC's target_clones: it makes an IFUNC symbol that GCC 12 exports
 * whatever its visibility or linkage, so a template instantiated in two of
 * ShadeLab's libraries was bound across them, and the dynamic linker printed
 * "Relink ... for IFUNC symbol" at every load of the Python package.
 * GCC and Clang on x86-64 only; elsewhere slHasAVX2() is false and the
 * baseline version is all there is.
 *
 * SL_TARGET_AVX512 and slHasAVX512() do the same for AVX-512 (F, VL, BW and
 * DQ), for arithmetic loops that gain from sixteen floats a vector
 * and mask registers instead of blends (the corner weights: about 1.8 times
 * as fast as AVX2 on a Zen 5). AVX-512 brings FMA, and GCC fuses a * b + c
 * by default where FMA exists, which would round differently from the other
 * versions; the clone turns fusing off (optimize("fp-contract=off")), so all
 * versions give the same bits. Clang has no such function attribute (it
 * fuses within an expression under its default -ffp-contract=on), so with
 * Clang slHasAVX512() is false and the AVX2 version runs.
 */

#include "shadelab/slCompilerHints.h"

#if (defined(__GNUC__) || defined(__clang__)) && defined(__x86_64__)
#define SL_TARGET_AVX2 __attribute__((target("avx2")))

/// Whether the CPU running the program has AVX2 (asked once).
inline bool slHasAVX2()
{
  static const bool has = (__builtin_cpu_init(), __builtin_cpu_supports("avx2") != 0);
  return has;
}
#else
#define SL_TARGET_AVX2

inline bool slHasAVX2()
{
  return false;
}
#endif

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define SL_TARGET_AVX512 __attribute__((target("avx512f,avx512vl,avx512bw,avx512dq"), optimize("fp-contract=off")))

/// Whether the CPU running the program has AVX-512 F, VL, BW and DQ (asked once).
inline bool slHasAVX512()
{
  static const bool has = (__builtin_cpu_init(), __builtin_cpu_supports("avx512f") != 0 &&
    __builtin_cpu_supports("avx512vl") != 0 && __builtin_cpu_supports("avx512bw") != 0 &&
    __builtin_cpu_supports("avx512dq") != 0);
  return has;
}
#else
#define SL_TARGET_AVX512

inline bool slHasAVX512()
{
  return false;
}
#endif

#endif
