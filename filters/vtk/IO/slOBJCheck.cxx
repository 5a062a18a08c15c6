// OBJ: every index of an f, l or p line names an existing v, vt or vn,
// every v, vt and vn value is a finite number, and nothing in the file makes
// vtkOBJReader read or write out of bounds.
#include "slMeshAttributeCheck.h"
#include "slMeshFileCheck.h"

#include "shadelab/PrintableText.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

namespace
{
struct Counts
{
  long long v = 0, vt = 0, vn = 0;
};

/// Whether vtkOBJReader reads the line after @p part as part of the logical
/// line that starts with @p head: only an f, l or p line continues, when its
/// last token is a lone backslash right before the newline ("\\\n"; not
/// "\\\r\n"), after any white space isspace() knows, as VTK's. A backslash
/// ending any other line, a comment included, is text, and the next line is
/// a line of its own.
bool continues(const std::string& head, const std::string& part)
{
  std::istringstream words(head);
  std::string command;
  words >> command;
  if (command != "f" && command != "l" && command != "p")
  {
    return false;
  }
  const size_t n = part.size();
  return n >= 1 && part[n - 1] == '\\' && (n == 1 || std::isspace(static_cast<unsigned char>(part[n - 2])));
}

/// Reads one logical line as vtkOBJReader does (see continues()).
bool nextLine(std::istream& in, std::string& line, long& lineNumber)
{
  line.clear();
  std::string part;
  bool any = false;
  while (std::getline(in, part))
  {
    ++lineNumber;
    any = true;
    const bool crlf = !part.empty() && part.back() == '\r';
    if (crlf)
    {
      part.pop_back();
    }
    if (!crlf && continues(line.empty() ? part : line, part))
    {
      part.back() = ' ';
      line += part;
      continue;
    }
    line += part;
    return true;
  }
  return any;
}

std::string at(long lineNumber, const std::string& problem)
{
  return "line " + std::to_string(lineNumber) + ": " + problem;
}

/// The problem with one value token of a v, vt or vn line, or "".
std::string numberProblem(const std::string& token)
{
  errno = 0;
  char* end = nullptr;
  std::strtod(token.c_str(), &end);
  const bool decimal = token.find_first_of("xXpP") == std::string::npos;
  if (end == token.c_str() || *end != '\0' || !decimal)
  {
    return "\"" + shadelab::printableText(token) + "\" is not a number";
  }
  // vtkOBJReader reads values into floats with a stream, which fails on a
  // value beyond float range and leaves the line's other values unset.
  const std::string finite = slNonFiniteTextProblem(token, true);
  return finite.empty() ? finite : "coordinate " + finite;
}

/// Resolves one index of kind @p what (1-based, or negative: relative to the
/// @p before values defined so far) against the @p total in the file.
std::string indexProblem(const std::string& text, const char* what, long long before, long long total)
{
  errno = 0;
  char* end = nullptr;
  const long long index = std::strtoll(text.c_str(), &end, 10);
  if (end == text.c_str() || *end != '\0')
  {
    return std::string(what) + " index \"" + shadelab::printableText(text) + "\" is not an integer";
  }
  if (index == 0)
  {
    return std::string(what) + " index 0 is invalid (OBJ indices start at 1)";
  }
  if (index < 0 && (errno == ERANGE || -index > before))
  {
    return std::string(what) + " index " + shadelab::printableText(text) + " reaches before the first " + what +
      " (" + std::to_string(before) + " precede the line)";
  }
  if (index > 0 && (errno == ERANGE || index > total))
  {
    return std::string(what) + " index " + shadelab::printableText(text) + " is out of range [1, " +
      std::to_string(total) + "]";
  }
  return std::string();
}
} // namespace

std::string slOBJProblem(const std::string& fileName)
{
  std::ifstream in(fileName, std::ios::binary);
  // ShadeLab's parser skips a UTF-8 byte order mark; vtkOBJReader reads it
  // as part of the first line's keyword and ignores that line, which is
  // harmless only when it is blank or a comment.
  {
    std::string first;
    long firstNumber = 0;
    if (nextLine(in, first, firstNumber) && first.compare(0, 3, "\xEF\xBB\xBF") == 0)
    {
      std::istringstream words(first.substr(3));
      std::string keyword;
      if (words >> keyword && keyword[0] != '#')
      {
        return at(1, "\"" + shadelab::printableText(keyword) +
            "\" follows a UTF-8 byte order mark, which VTK's OBJ reader would read as part of it and skip the line; "
            "save the file without the mark");
      }
    }
    in.clear();
    in.seekg(0);
  }
  // Pass 1: how many of each; indices may name values defined later.
  Counts total;
  std::string line, keyword;
  long lineNumber = 0;
  while (nextLine(in, line, lineNumber))
  {
    std::istringstream words(line);
    if (words >> keyword)
    {
      total.v += keyword == "v";
      total.vt += keyword == "vt";
      total.vn += keyword == "vn";
    }
  }
  in.clear();
  in.seekg(0);
  Counts seen;
  lineNumber = 0;
  std::string token;
  while (nextLine(in, line, lineNumber))
  {
    std::istringstream words(line);
    if (!(words >> keyword))
    {
      continue;
    }
    if (keyword == "v" || keyword == "vt" || keyword == "vn")
    {
      // vtkOBJReader reads two values of every vt line (u and v).
      const int needed = keyword == "vt" ? 2 : 3;
      int count = 0;
      while (words >> token)
      {
        const std::string problem = numberProblem(token);
        if (!problem.empty())
        {
          return at(lineNumber, keyword + " " + problem);
        }
        ++count;
      }
      if (count < needed)
      {
        return at(lineNumber, keyword + " needs at least " + std::to_string(needed) + " values, it has " +
            std::to_string(count));
      }
      (keyword == "v" ? seen.v : keyword == "vt" ? seen.vt : seen.vn) += 1;
    }
    else if (keyword == "usemtl")
    {
      // vtkOBJReader copies the name into a char[100] with sscanf("%s").
      constexpr size_t longestName = 99;
      if (words >> token && token.size() > longestName)
      {
        return at(lineNumber, "usemtl name of " + std::to_string(token.size()) + " bytes is longer than the " +
            std::to_string(longestName) + " that VTK's OBJ reader holds");
      }
    }
    else if (keyword == "f" || keyword == "l" || keyword == "p")
    {
      int corners = 0;
      while (words >> token)
      {
        ++corners;
        // v, v/vt, v//vn or v/vt/vn.
        std::vector<std::string> parts(1);
        for (char c : token)
        {
          if (c == '/')
          {
            parts.emplace_back();
          }
          else
          {
            parts.back() += c;
          }
        }
        if (parts.size() > 3)
        {
          return at(lineNumber, "\"" + shadelab::printableText(token) + "\" is not an index triple");
        }
        // vtkOBJReader reads a corner with sscanf("%d/%d"), which skips white
        // space after the slash: "2/ 3" would take the next corner's 3 as
        // 2's texture coordinate, unchecked.
        if (token.back() == '/')
        {
          return at(lineNumber,
            "\"" + shadelab::printableText(token) + "\" ends in a slash, without the index after it");
        }
        static const char* const kinds[3] = { "vertex", "texture coordinate", "normal" };
        const long long before[3] = { seen.v, seen.vt, seen.vn };
        const long long all[3] = { total.v, total.vt, total.vn };
        for (size_t k = 0; k < parts.size(); ++k)
        {
          if (k > 0 && parts[k].empty())
          {
            continue; // v//vn
          }
          const std::string problem = indexProblem(parts[k], kinds[k], before[k], all[k]);
          if (!problem.empty())
          {
            return at(lineNumber, problem);
          }
        }
      }
      const int needed = keyword == "f" ? 3 : keyword == "l" ? 2 : 1;
      if (corners < needed)
      {
        return at(lineNumber, keyword + " needs at least " + std::to_string(needed) + " vertices, it has " +
            std::to_string(corners));
      }
    }
  }
  return std::string();
}
