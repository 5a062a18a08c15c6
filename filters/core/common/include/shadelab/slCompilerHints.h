#ifndef slCompilerHints_h
#define slCompilerHints_h
/**
 * @file slCompilerHints.h
 * @brief Inlining, branch and cache hints for the hot loops of the geometry core.
 * C++ only; on compilers other than GCC and Clang each hint is a no-op.
 *
 * - SL_ALWAYS_INLINE: the function's body is compiled into each caller, so
 *   that a caller marked SL_TARGET_AVX2 (slVectorClones.h) compiles it for
 *   AVX2.
 * - SL_NOINLINE: kept out of its callers, for a rare path whose code would
 *   otherwise take registers from a hot loop.
 * - SL_LIKELY(condition): the condition is almost always true; the compiler
 *   lays out its branch as the straight path.
 * - slPrefetch<ForWriting>(address): asks the cache for the line at address,
 *   to be read or written soon; it never reads the address and never
 *   faults. GCC takes a function whose only effect is such a hint for one
 *   without effects and deletes calls to it that it has not inlined, so
 *   slPrefetch() and any function made only of calls to it are always
 *   inlined.
 * - slPrefetchBytes(address, bytes): slPrefetch() for every cache line of
 *   [address, address + bytes); the address is only hinted, so it may lie
 *   anywhere.
 */

#include <cstddef>
#include <cstdint>

#if defined(__GNUC__) || defined(__clang__)
#define SL_ALWAYS_INLINE inline __attribute__((always_inline))
#define SL_NOINLINE __attribute__((noinline))
#define SL_LIKELY(condition) __builtin_expect(static_cast<bool>(condition), 1)
#else
#define SL_ALWAYS_INLINE inline
#define SL_NOINLINE
#define SL_LIKELY(condition) (condition)
#endif

template <bool ForWriting = false>
SL_ALWAYS_INLINE void slPrefetch(const void* address)
{
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(address, ForWriting ? 1 : 0);
#else
  (void)address;
#endif
}

SL_ALWAYS_INLINE void slPrefetchBytes(const void* address, size_t bytes)
{
  constexpr uintptr_t line = 64;
  const uintptr_t end = reinterpret_cast<uintptr_t>(address) + bytes;
  for (uintptr_t a = reinterpret_cast<uintptr_t>(address) & ~(line - 1); a < end; a += line)
  {
    slPrefetch(reinterpret_cast<const void*>(a));
  }
}

#endif
