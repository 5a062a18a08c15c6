#ifndef slIdsBelow_h
#define slIdsBelow_h
/**
 * @file slIdsBelow.h
 * @brief slIdsBelow() and slIdsBelowInline(): whether point ids lie in
 * [0, limit), in a loop the compiler vectorises. The one test of an id
 * against a mesh's points, used by the connectivity check and by the
 * normals' scatter. C++ only.
 */

#include "shadelab/slVectorClones.h"

#include <cstdint>
#include <limits>
#include <type_traits>

/// Whether the @p n ids at @p ids all lie in [0, @p limit); inline, for a
/// few ids at a time in a hot loop (slIdsBelow() first picks a version).
///
/// Each id is compared once, as unsigned: a negative id is then a huge one.
/// A limit beyond the ids' range (more points than 32-bit ids can name)
/// becomes the first value past it, so that no negative id passes. The
/// result of each compare, a mask, is or-ed into an integer of the ids'
/// width: GCC vectorises that (-O3), where it does not vectorise a bool |=.
template <typename Id>
SL_ALWAYS_INLINE bool slIdsBelowInline(const Id* ids, int64_t n, int64_t limit)
{
  using U = std::make_unsigned_t<Id>;
  constexpr auto largest = static_cast<uint64_t>(std::numeric_limits<Id>::max());
  const U l = limit < 0 ? U(0)
    : static_cast<uint64_t>(limit) > largest ? static_cast<U>(largest + 1)
                                             : static_cast<U>(limit);
  U bad = 0;
  for (int64_t i = 0; i < n; ++i)
  {
    bad |= static_cast<U>(ids[i]) >= l ? ~U(0) : U(0);
  }
  return bad == 0;
}

/// slIdsBelowInline() compiled for AVX2 (see slIdsBelow()).
template <typename Id>
SL_TARGET_AVX2 bool slIdsBelowAVX2(const Id* ids, int64_t n, int64_t limit)
{
  return slIdsBelowInline(ids, n, limit);
}

/// slIdsBelowInline() for long runs of ids: in its AVX2 version where the
/// CPU has it, since SSE2 has no 64-bit compare and its version of 64-bit
/// ids runs one id at a time.
template <typename Id>
bool slIdsBelow(const Id* ids, int64_t n, int64_t limit)
{
  return slHasAVX2() ? slIdsBelowAVX2(ids, n, limit) : slIdsBelowInline(ids, n, limit);
}

#endif
