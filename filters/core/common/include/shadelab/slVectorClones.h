#ifndef slVectorClones_h
#define slVectorClones_h
/**
 * @file slVectorClones.h
 * @brief SL_VECTOR_CLONES: compile a function twice, for AVX2 and for the
 * baseline x86-64 (SSE2), and pick the version at load time. C++ only.
 *
 * For loops that the compiler vectorises well only with AVX2: corner
 * weights of triangle blocks (slTriangleBlock.h), and passes over 64-bit
 * point ids, since SSE2 has no 64-bit integer compare. GCC on x86-64 ELF
 * only; elsewhere the macro is empty and the baseline version is all there is.
 */

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__ELF__)
#define SL_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define SL_VECTOR_CLONES
#endif

#endif
