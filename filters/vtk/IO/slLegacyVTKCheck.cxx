// Legacy VTK polydata (.vtk, ASCII or BINARY), read as vtkDataReader reads
// it: every section holds the values its keyword line announces, within the
// file, each legacy cell list adds up to its size, and METADATA blocks hold
// what VTK reads without looping for ever. vtkPolyDataReader reads past the
// end of a short section (and crashes there).
//
// This file holds the sections' grammar; the cursor that reads their words
// and values is sllegacyvtk::Walker (slLegacyVTKWalker.h), METADATA blocks
// are read in slLegacyVTKMetadata.cxx.
#include "slLegacyVTKWalker.h"
#include "slMeshFileCheck.h"

#include "shadelab/PrintableText.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace
{
using sllegacyvtk::fail;
using sllegacyvtk::upper;
using sllegacyvtk::Walker;

/// Whether VTK takes @p word for the start of a METADATA block: it peeks 8
/// characters and compares them case-insensitively.
bool isMetadata(const std::string& word)
{
  if (word.size() < 8)
  {
    return false;
  }
  std::string head = word.substr(0, 8);
  std::transform(head.begin(), head.end(), head.begin(), [](unsigned char c) { return std::tolower(c); });
  return head == "metadata";
}

/// The arrays after FIELD (@p section names them in problems): the field's
/// name and array count, then per array its name, components, tuples, type
/// and values, each array's METADATA block after it.
void fieldArrays(Walker& w, const std::string& section)
{
  w.word("the field name");
  const long long arrays = w.count("the number of field arrays");
  for (long long a = 0; a < arrays; ++a)
  {
    // VTK decodes an array name (DecodeString); the block after an array
    // is its METADATA.
    const std::string name = w.word("a field array name");
    if (isMetadata(name))
    {
      w.skipMetadata();
      --a;
      continue;
    }
    const long long components = w.count("the number of components");
    const long long tuples = w.count("the number of tuples");
    const std::string type = w.word("the data type");
    const std::string array = section + " array \"" + shadelab::printableText(name) + "\"";
    w.checkName(name, array);
    w.values(tuples, components, type, array);
  }
}

/// The attribute sections after POINT_DATA n or CELL_DATA n.
void attributes(Walker& w, long long n, const std::string& keyword, bool binary)
{
  const std::string section = keyword;
  if (keyword == "SCALARS")
  {
    w.name("the scalars name", section);
    const std::string type = w.word("the scalars type");
    // An optional component count, then LOOKUP_TABLE and its name.
    long long components = 1;
    std::string next = w.word("LOOKUP_TABLE or the component count");
    if (upper(next) != "LOOKUP_TABLE")
    {
      char* end = nullptr;
      components = std::strtoll(next.c_str(), &end, 10);
      if (*end != '\0' || components < 1 || components > 4)
      {
        fail("line " + std::to_string(w.line()) + ": SCALARS: \"" + shadelab::printableText(next) +
          "\" is not a component count (1 to 4)");
      }
      next = w.word("LOOKUP_TABLE");
    }
    if (upper(next) != "LOOKUP_TABLE")
    {
      fail("line " + std::to_string(w.line()) + ": SCALARS: expected LOOKUP_TABLE");
    }
    w.word("the lookup table name");
    w.values(n, components, type, section);
  }
  else if (keyword == "LOOKUP_TABLE")
  {
    w.word("the lookup table name");
    w.values(w.count("the lookup table size"), 4, binary ? "unsigned_char" : "float", section);
  }
  else if (keyword == "VECTORS" || keyword == "NORMALS")
  {
    w.name("the array name", section);
    w.values(n, 3, w.word("the data type"), section);
  }
  else if (keyword == "TEXTURE_COORDINATES")
  {
    w.name("the array name", section);
    const long long dim = w.count("the dimension");
    w.values(n, dim, w.word("the data type"), section);
  }
  else if (keyword == "TENSORS" || keyword == "TENSORS6")
  {
    w.name("the array name", section);
    w.values(n, keyword == "TENSORS" ? 9 : 6, w.word("the data type"), section);
  }
  else if (keyword == "COLOR_SCALARS")
  {
    w.name("the array name", section);
    const long long m = w.count("the number of values");
    w.values(n, m, binary ? "unsigned_char" : "float", section);
  }
  else if (keyword == "GLOBAL_IDS" || keyword == "PEDIGREE_IDS")
  {
    w.name("the array name", section);
    w.values(n, 1, w.word("the data type"), section);
  }
  else if (keyword == "FIELD")
  {
    fieldArrays(w, section);
  }
  else
  {
    fail("line " + std::to_string(w.line()) + ": unknown keyword \"" + shadelab::printableText(keyword) + "\"");
  }
}

/// Checks the whole legacy file @p bytes (fails with its first problem):
/// the three header lines, then the sections of a polydata dataset. A
/// dataset of another type is left to VTK, which reads nothing and says so.
void walk(const std::string& bytes)
{
  // Three header lines: identification, title, ASCII or BINARY.
  size_t end = 0;
  std::string lines[3];
  for (std::string& l : lines)
  {
    const size_t newline = bytes.find('\n', end);
    if (newline == std::string::npos)
    {
      fail("the file ends within its three header lines");
    }
    l = bytes.substr(end, newline - end);
    end = newline + 1;
  }
  // VTK reads each header line into a 256-byte C string, then parses the
  // version from line 1: a NUL byte or a missing version derails it.
  for (int i = 0; i < 3; ++i)
  {
    if (lines[i].size() > 255 || lines[i].find('\0') != std::string::npos)
    {
      fail("line " + std::to_string(i + 1) + ": a header line longer than 255 bytes or holding a NUL byte");
    }
  }
  // The version as VTK reads it: from 5.0 on, cell lists are OFFSETS and
  // CONNECTIVITY; before, one list of counts and ids. Without both numbers
  // VTK assumes 3.0 whatever the file holds.
  int major = 0, minor = 0;
  if (std::sscanf(lines[0].c_str(), "# vtk DataFile Version %d.%d", &major, &minor) != 2)
  {
    fail("line 1: expected \"# vtk DataFile Version N.N\", found \"" + shadelab::printableText(lines[0]) + "\"");
  }
  const std::string kind = upper(lines[2].substr(0, 6));
  const bool binary = kind.rfind("BINARY", 0) == 0;
  if (!binary && kind.rfind("ASCII", 0) != 0)
  {
    fail("line 3: expected ASCII or BINARY, found \"" + shadelab::printableText(lines[2]) + "\"");
  }
  if (!binary && bytes.find('\0') != std::string::npos)
  {
    fail("an ASCII file holding a NUL byte (at byte " + std::to_string(bytes.find('\0')) + ")");
  }
  // VTK reads the file type as one word (ReadString), and the rest of
  // line 3 is the start of the file's content.
  const size_t typeEnd = lines[2].find_first_of(" \t\r\v\f");
  Walker w(bytes, binary, typeEnd == std::string::npos ? end : end - lines[2].size() - 1 + typeEnd);
  const bool offsetCells = major >= 5;
  long long points = -1;
  long long cells = 0;
  while (!w.atEnd())
  {
    const std::string keyword = upper(w.word("a keyword"));
    if (keyword == "DATASET")
    {
      // vtkPolyDataReader compares the first 8 characters only.
      const std::string type = upper(w.word("the dataset type"));
      if (type.compare(0, 8, "POLYDATA") != 0)
      {
        // vtkPolyDataReader would read nothing and say only "Cannot read
        // dataset type".
        fail("line " + std::to_string(w.line()) + ": the dataset is " + shadelab::printableText(type) +
          ", not a surface (POLYDATA): " + kExtractSurfaceFirst);
      }
      if (type != "POLYDATA")
      {
        fail("line " + std::to_string(w.line()) + ": dataset type \"" + shadelab::printableText(type) +
          "\" is not POLYDATA, though VTK would read it as POLYDATA");
      }
    }
    else if (keyword == "FIELD")
    {
      fieldArrays(w, "FIELD");
    }
    else if (isMetadata(keyword))
    {
      w.skipMetadata();
    }
    else if (keyword == "POINTS")
    {
      points = w.count("the number of points");
      w.values(points, 3, w.word("the points' data type"), "POINTS");
    }
    else if (keyword == "VERTICES" || keyword == "LINES" || keyword == "POLYGONS" || keyword == "TRIANGLE_STRIPS")
    {
      const long long n = w.count("the number of cells");
      const long long size = w.count("the cell list size");
      if (offsetCells)
      {
        // Version 5: OFFSETS type (n values), CONNECTIVITY type (size values).
        if (upper(w.word("OFFSETS")) != "OFFSETS")
        {
          fail("line " + std::to_string(w.line()) + ": " + keyword + ": expected OFFSETS (file version " +
            std::to_string(major) + "." + std::to_string(minor) + ")");
        }
        w.values(n, 1, w.word("the offsets' type"), keyword + " OFFSETS");
        if (upper(w.word("CONNECTIVITY")) != "CONNECTIVITY")
        {
          fail("line " + std::to_string(w.line()) + ": " + keyword + ": expected CONNECTIVITY after the offsets");
        }
        w.values(size, 1, w.word("the connectivity type"), keyword + " CONNECTIVITY");
        cells += n > 0 ? n - 1 : 0;
        continue;
      }
      // Legacy: per cell a point count and the ids, adding up to size.
      std::vector<long long> list;
      w.values(size, 1, "int", keyword, &list);
      size_t at = 0;
      for (long long c = 0; c < n; ++c)
      {
        if (at >= list.size() || list[at] < 0 || static_cast<unsigned long long>(list[at]) > list.size() - at - 1)
        {
          fail(keyword + ": cell " + std::to_string(c) + " of " + std::to_string(n) + " reaches beyond the list of " +
            std::to_string(size) + " values");
        }
        at += static_cast<size_t>(list[at]) + 1;
      }
      if (at != list.size())
      {
        fail(keyword + ": " + std::to_string(n) + " cells use " + std::to_string(at) + " of the list's " +
          std::to_string(size) + " values");
      }
      cells += n;
    }
    else if (keyword == "POINT_DATA" || keyword == "CELL_DATA")
    {
      const long long n = w.count("the number of values");
      if ((keyword == "POINT_DATA" && n != points) || (keyword == "CELL_DATA" && n != cells))
      {
        fail("line " + std::to_string(w.line()) + ": " + keyword + " " + std::to_string(n) + " does not match the " +
          (keyword == "POINT_DATA" ? std::to_string(points) + " points" : std::to_string(cells) + " cells"));
      }
      while (!w.atEnd())
      {
        Walker probe = w;
        const std::string next = upper(probe.word("a keyword"));
        if (next == "POINT_DATA" || next == "CELL_DATA")
        {
          break;
        }
        w.word("a keyword");
        if (isMetadata(next)) // an array's information keys
        {
          w.skipMetadata();
          continue;
        }
        attributes(w, n, next, binary);
      }
    }
    else
    {
      fail("line " + std::to_string(w.line()) + ": unknown keyword \"" + shadelab::printableText(keyword) + "\"");
    }
  }
}
} // namespace

std::string slLegacyVTKProblem(const std::string& fileName)
{
  const std::string bytes = slReadWholeFile(fileName);
  try
  {
    walk(bytes);
  }
  catch (const sllegacyvtk::Problem& p)
  {
    return p.text;
  }
  return std::string();
}
