#ifndef slLegacyVTKWalker_h
#define slLegacyVTKWalker_h
/**
 * @file slLegacyVTKWalker.h
 * @brief The legacy VTK check's cursor over a file (sllegacyvtk::Walker),
 * and the few helpers its files share. Internal to ShadeLab::IO.
 *
 * The check (slLegacyVTKProblem()) is in three files, one concept each:
 * slLegacyVTKCheck.cxx, the sections' grammar (header, keywords, cells,
 * attributes); slLegacyVTKWalker.cxx, the cursor's words, counts, names,
 * values and string arrays; slLegacyVTKMetadata.cxx, the METADATA blocks
 * and their information keys, which VTK reads line by line rather than word
 * by word. A problem is thrown (fail()) where it is found and caught once,
 * in slLegacyVTKProblem().
 */

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <string>
#include <vector>

namespace sllegacyvtk
{
/// What fail() throws: the problem's text, as slLegacyVTKProblem() returns it.
struct Problem
{
  std::string text;
};

/// Ends the check with the problem @p text (throws Problem).
[[noreturn]] inline void fail(const std::string& text)
{
  throw Problem{ text };
}

/// @p s in upper case (ASCII letters only), as VTK compares keywords.
inline std::string upper(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::toupper(c); });
  return s;
}

/// The problem with @p text as vtkDataReader::DecodeString decodes it, or "".
/// It decodes "%XX" escapes, and for a '%' in a string shorter than 3
/// characters its bound (length - 3, unsigned) wraps: it reads past the end.
std::string encodedProblem(const std::string& text);

/// A cursor over the bytes of a legacy file, from just after its file type
/// (ASCII or BINARY) to its end, that reads what the keywords announce as
/// vtkDataReader reads it. Each read that finds what VTK would misread
/// fails (fail()), naming the line where it can. A copy reads ahead without
/// moving the original (the grammar's look at the next keyword).
class Walker
{
public:
  /// A cursor at byte @p start of @p bytes (kept by reference: it must
  /// outlive the cursor), a file whose values are BINARY when @p binary.
  Walker(const std::string& bytes, bool binary, size_t start)
    : Bytes(bytes)
    , Binary(binary)
    , Position(start)
  {
  }

  /// Whether nothing but white space is left; skips it.
  bool atEnd();

  /// The next whitespace-separated word; @p what names it in the problem
  /// when the file ends before it.
  std::string word(const char* what);

  /// A count: a whole number in [0, 2^40].
  long long count(const char* what);

  /// A name as VTK reads it with ReadString and decodes with DecodeString.
  std::string name(const char* what, const std::string& section);

  /// Fails, at the current line, if VTK cannot decode the name @p text of
  /// @p section (encodedProblem()).
  void checkName(const std::string& text, const std::string& section);

  /// Skips @p tuples tuples of @p components values of @p type after a
  /// keyword line; integers are returned through @p keep when given (legacy
  /// cell lists).
  void values(long long tuples, long long components, const std::string& type, const std::string& section,
    std::vector<long long>* keep = nullptr);

  /// Skips a METADATA block as vtkDataReader::ReadArray reads it: the
  /// METADATA line, then lines up to an empty one (after a trailing CR; a
  /// line of spaces is not empty to VTK). It compares each line's start
  /// case-insensitively: COMPONENT_NAMES is followed by one name line per
  /// component of the array before, "information" by a count as sscanf's
  /// "%d" reads it (any white space), then information keys
  /// (information()); other lines it ignores. In slLegacyVTKMetadata.cxx.
  void skipMetadata();

  /// The line number at the current position. Counted on from the last
  /// call (the position only moves forward): a METADATA block asks at each
  /// of its lines, and counting from the start each time cost a pass over
  /// the whole file per line.
  long line() const;

private:
  /// Skips the @p n values of a string array, as vtkDataReader::ReadArray
  /// reads them after the keyword line. ASCII: one line per value, decoded
  /// with DecodeString. Binary: per value a big-endian length, whose first
  /// byte's top two bits give its size (3: 1 byte, 2: 2, 1: 4, less those
  /// two bits; 0: 8 bytes), then that many bytes; VTK allocates the length
  /// before it reads, so it must lie within the file.
  void strings(long long n, const std::string& section);

  /// The @p keys information keys after an "information" line (line @p at),
  /// as vtkDataReader::ReadInformation reads them: each key skips empty
  /// lines, then takes one line; a line starting "NAME " (case-sensitive)
  /// names a key, others are ignored. A key known to this process
  /// (vtkInformationKeyLookup, as VTK looks it up) of a type VTK reads takes
  /// its DATA next (metadataDataProblem()); a string key the next line,
  /// whose word after DATA VTK decodes; a string vector key as many lines
  /// as its DATA gives, each decoded. In slLegacyVTKMetadata.cxx.
  void information(long long keys, long at);

  /// The next line of a METADATA block into @p text, as vtkDataReader's
  /// ReadLine reads it (a trailing CR removed); returns its line number.
  /// In slLegacyVTKMetadata.cxx.
  long nextLine(std::string& text);

  void skipSpace();

  const std::string& Bytes;
  bool Binary;
  size_t Position;
  long long Components = 1; // of the array before, for a METADATA block's COMPONENT_NAMES
  mutable size_t CountedTo = 0;      // line(): where the newlines were counted up to
  mutable std::ptrdiff_t LinesBefore = 0; // and how many there were
};
} // namespace sllegacyvtk

#endif
