#ifndef slTextParsing_h
#define slTextParsing_h
/**
 * @file slTextParsing.h
 * @brief What ShadeLab's text parsers (OBJ, ASCII PLY) share: a cursor that
 * reads a line's words as numbers, and the splitting of a text into
 * stretches of whole lines parsed on threads of their own. Internal to
 * ShadeLab::IO.
 *
 * Every read function returns false on anything outside the plain decimal
 * forms: the parsers then decline the file, which goes to VTK's reader.
 */

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <system_error>
#include <vector>

/// One line's cursor: words parted by spaces and tabs.
struct slTextCursor
{
  const char* at;
  const char* end; ///< the line's end, a '\r' before its '\n' excluded

  void skipBlanks()
  {
    while (this->at < this->end && (*this->at == ' ' || *this->at == '\t'))
    {
      ++this->at;
    }
  }
  bool atSeparator() const { return this->at == this->end || *this->at == ' ' || *this->at == '\t'; }

  /// The next word as a finite float, the nearest to its decimal value (as
  /// strtof reads it).
  bool number(float& value)
  {
    this->skipBlanks();
    const auto r = std::from_chars(this->at, this->end, value, std::chars_format::general);
    if (r.ec != std::errc() || !std::isfinite(value))
    {
      return false;
    }
    this->at = r.ptr;
    return this->atSeparator();
  }

  /// The next word as a double, the nearest to its decimal value (as strtod
  /// reads it): finite, and 0 or at least 1e-300 in size (strtod reports a
  /// range error below 2.2e-308, which from_chars does not).
  bool number(double& value)
  {
    this->skipBlanks();
    const auto r = std::from_chars(this->at, this->end, value, std::chars_format::general);
    if (r.ec != std::errc() || !std::isfinite(value) || (value != 0 && std::fabs(value) < 1e-300))
    {
      return false;
    }
    this->at = r.ptr;
    return this->atSeparator();
  }

  /// The next word read as a double and then converted to a float, which
  /// must be finite: how VTK's PLY code reads a float (atof and a cast). A
  /// value half-way between two floats once rounded to a double rounds to
  /// the even one of them, where strtof may give the other.
  bool numberViaDouble(float& value)
  {
    double read;
    if (!this->number(read))
    {
      return false;
    }
    value = static_cast<float>(read);
    return std::isfinite(value);
  }

  /// The next word as a decimal integer of at most @p max (below 10^18),
  /// digits only.
  bool unsignedInteger(std::uint64_t& value, std::uint64_t max)
  {
    this->skipBlanks();
    const char* start = this->at;
    value = 0;
    for (; this->at < this->end && *this->at >= '0' && *this->at <= '9'; ++this->at)
    {
      value = value * 10 + static_cast<std::uint64_t>(*this->at - '0');
      if (value > max) // long before it could overflow
      {
        return false;
      }
    }
    return this->at > start && this->atSeparator();
  }

  /// The next word as a 64-bit decimal integer (an optional '-', digits).
  bool integer(std::int64_t& value)
  {
    this->skipBlanks();
    const auto r = std::from_chars(this->at, this->end, value);
    if (r.ec != std::errc())
    {
      return false;
    }
    this->at = r.ptr;
    return this->atSeparator();
  }

  /// An OBJ index where the cursor is: a decimal integer in [1, INT_MAX].
  bool index(std::int64_t& value)
  {
    const auto r = std::from_chars(this->at, this->end, value);
    if (r.ec != std::errc() || value <= 0 || value > std::numeric_limits<int>::max())
    {
      return false;
    }
    this->at = r.ptr;
    return true;
  }

  /// True if nothing but blanks is left.
  bool done()
  {
    this->skipBlanks();
    return this->at == this->end;
  }
};

/// The newlines in [@p begin, @p end).
std::size_t slCountLines(const char* begin, const char* end);

/// The stretches to parse @p size bytes of text in on @p threads threads:
/// one below 1 MiB (a thread would cost more than it saves), else one per
/// thread, at most 64.
std::size_t slTextStretchCount(std::size_t size, int threads);

/// The bounds of @p parts stretches of whole lines that cover the @p size
/// bytes at @p text: parts + 1 pointers in order, the first @p text, the
/// last text + size, each other the start of a line (or text + size), near
/// an equal share of the bytes.
std::vector<const char*> slLineStretches(const char* text, std::size_t size, std::size_t parts);

/// Calls @p work(k) for every k in [0, @p count): 0 on this thread, the
/// others on threads of their own (on this one where a thread cannot
/// start). After every call has returned, rethrows the first exception a
/// call threw (std::bad_alloc, say: out of a thread it would end the
/// process).
void slRunEach(std::size_t count, const std::function<void(std::size_t)>& work);

#endif
