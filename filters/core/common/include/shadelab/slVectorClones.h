#ifndef slVectorClones_h
#define slVectorClones_h
/**
 * @file slVectorClones.h
 * @brief A loop compiled twice, for AVX2 and for the baseline x86-64 (SSE2),
 * and the version picked at run time. C++ only.
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
 * Not GCC's target_clones: it makes an IFUNC symbol that GCC 12 exports
 * whatever its visibility or linkage, so a template instantiated in two of
 * ShadeLab's libraries was bound across them, and the dynamic linker printed
 * "Relink ... for IFUNC symbol" at every load of the Python package.
 * GCC and Clang on x86-64 only; elsewhere slHasAVX2() is false and the
 * baseline version is all there is.
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

#endif
