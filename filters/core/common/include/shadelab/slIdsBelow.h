#ifndef slIdsBelow_h
#define slIdsBelow_h
/**
 * @file slIdsBelow.h
 * @brief slIdsWithin() and slIdsBelow(): whether point ids lie in
 * [lo, hi) or [0, limit), in a loop the compiler vectorises. The one test of
 * an id against a mesh's points, used by the connectivity check and by the
 * normals' scatter (which also asks whether a block's ids lie in the range
 * of points its chunk owns). C++ only.
 */

#include "shadelab/slVectorClones.h"

#include <cstdint>
#include <limits>
#include <type_traits>

/// Whether the @p n ids at @p ids all lie in [@p lo, @p hi) and none is
/// negative (a negative id names no point, whatever @p lo); inline, for a
/// few ids at a time in a hot loop (slIdsWithin() first picks a version).
///
/// Each id is compared once, as unsigned and less @p lo: an id below lo
/// (a negative one too) then becomes a huge one. Bounds beyond the ids'
/// range (more points than 32-bit ids can name) become the first value past
/// it, so that no negative id passes. The result of each compare, a mask, is
/// or-ed into an integer of the ids' width: GCC vectorises that (-O3), where
/// it does not vectorise a bool |=.
template <typename Id>
SL_ALWAYS_INLINE bool slIdsWithinInline(const Id* ids, int64_t n, int64_t lo, int64_t hi)
{
  using U = std::make_unsigned_t<Id>;
  constexpr auto largest = static_cast<uint64_t>(std::numeric_limits<Id>::max());
  const auto bound = [](int64_t v) {
    return v < 0 ? U(0) : static_cast<uint64_t>(v) > largest ? static_cast<U>(largest + 1) : static_cast<U>(v);
  };
  const U l = bound(lo), h = bound(hi);
  const U width = h > l ? static_cast<U>(h - l) : U(0);
  U bad = 0;
  for (int64_t i = 0; i < n; ++i)
  {
    bad |= static_cast<U>(static_cast<U>(ids[i]) - l) >= width ? ~U(0) : U(0);
  }
  return bad == 0;
}

/// slIdsWithinInline() compiled for AVX2 (see slIdsWithin()).
template <typename Id>
SL_TARGET_AVX2 bool slIdsWithinAVX2(const Id* ids, int64_t n, int64_t lo, int64_t hi)
{
  return slIdsWithinInline(ids, n, lo, hi);
}

/// slIdsWithinInline() for long runs of ids: in its AVX2 version where the
/// CPU has it, since SSE2 has no 64-bit compare and its version of 64-bit
/// ids runs one id at a time.
template <typename Id>
bool slIdsWithin(const Id* ids, int64_t n, int64_t lo, int64_t hi)
{
  return slHasAVX2() ? slIdsWithinAVX2(ids, n, lo, hi) : slIdsWithinInline(ids, n, lo, hi);
}

/// Whether the @p n ids at @p ids all lie in [0, @p limit): slIdsWithinInline().
template <typename Id>
SL_ALWAYS_INLINE bool slIdsBelowInline(const Id* ids, int64_t n, int64_t limit)
{
  return slIdsWithinInline(ids, n, 0, limit);
}

/// slIdsBelowInline() compiled for AVX2 (see slIdsBelow()).
template <typename Id>
SL_TARGET_AVX2 bool slIdsBelowAVX2(const Id* ids, int64_t n, int64_t limit)
{
  return slIdsWithinInline(ids, n, 0, limit);
}

/// Whether the @p n ids at @p ids all lie in [0, @p limit): slIdsWithin().
template <typename Id>
bool slIdsBelow(const Id* ids, int64_t n, int64_t limit)
{
  return slIdsWithin(ids, n, 0, limit);
}

#endif
