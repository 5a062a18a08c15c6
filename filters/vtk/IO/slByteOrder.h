#ifndef slByteOrder_h
#define slByteOrder_h
/**
 * @file slByteOrder.h
 * @brief The host's byte order, and unsigned values loaded from bytes of
 * either order. Internal to ShadeLab::IO (the PLY check and parser).
 */

#include <cstdint>
#include <cstring>

/// True on a little-endian host.
inline bool slHostIsLittleEndian()
{
  const std::uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

/// The 4- or 8-byte unsigned value at @p at (any alignment), its bytes
/// reversed if @p Swap: a file of the other byte order than the host's.
template <bool Swap, typename Unsigned>
Unsigned slLoadUnsigned(const char* at)
{
  static_assert(sizeof(Unsigned) == 4 || sizeof(Unsigned) == 8, "a 4- or 8-byte value");
  Unsigned value;
  std::memcpy(&value, at, sizeof(value));
  if constexpr (Swap && sizeof(Unsigned) == 4)
  {
    value = __builtin_bswap32(value);
  }
  else if constexpr (Swap)
  {
    value = __builtin_bswap64(value);
  }
  return value;
}

#endif
