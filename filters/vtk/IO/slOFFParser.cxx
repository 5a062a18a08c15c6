#include "slOFFParser.h"

#include "shadelab/PrintableText.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

namespace
{
/// Reads the next line that has content, with '#' comments removed.
bool nextLine(std::istream& in, std::string& line, long& lineNumber)
{
  while (std::getline(in, line))
  {
    ++lineNumber;
    const size_t hash = line.find('#');
    if (hash != std::string::npos)
    {
      line.erase(hash);
    }
    if (line.find_first_not_of(" \t\r") != std::string::npos)
    {
      return true;
    }
  }
  return false;
}

/// Reads one number token; accepts "nan" and "inf" so that they can be
/// reported as non-finite coordinates rather than as syntax errors.
bool readNumber(std::istream& in, double& value)
{
  std::string token;
  if (!(in >> token))
  {
    return false;
  }
  char* end = nullptr;
  value = std::strtod(token.c_str(), &end);
  return end != token.c_str() && *end == '\0';
}

/// Whether @p token is written as an integer (digits after an optional sign).
bool integerToken(const std::string& token)
{
  const size_t digits = token[0] == '+' || token[0] == '-' ? 1 : 0;
  return digits < token.size() && token.find_first_not_of("0123456789", digits) == std::string::npos;
}

/// The error for @p problem on line @p lineNumber of @p fileName.
shadelab::Error at(const std::string& fileName, long lineNumber, const std::string& problem)
{
  return shadelab::Error(fileName + ": line " + std::to_string(lineNumber) + ": " + problem);
}
} // namespace

void slParseOFF(std::istream& in, const std::string& fileName, vtkPolyData* output)
{
  std::string line;
  long lineNumber = 0;
  if (!nextLine(in, line, lineNumber))
  {
    throw at(fileName, 1, "empty file, expected the OFF header");
  }
  std::istringstream header(line);
  std::string keyword;
  header >> keyword;
  long numPoints = -1, numFaces = -1, numEdges = 0;
  // COFF: a colour (r g b [a]) after each vertex's coordinates; NOFF: a
  // normal (nx ny nz).
  const bool colours = keyword == "COFF";
  const bool normals = keyword == "NOFF";
  if (keyword == "OFF" || colours || normals)
  {
    // The counts may follow on the same line or on the next one.
    if (!(header >> numPoints >> numFaces))
    {
      if (!nextLine(in, line, lineNumber))
      {
        throw at(fileName, lineNumber, "missing vertex and face counts");
      }
      header = std::istringstream(line);
      header >> numPoints >> numFaces >> numEdges;
    }
  }
  else if (keyword.size() > 3 && keyword.compare(keyword.size() - 3, 3, "OFF") == 0 &&
    keyword.find_first_not_of("STCN4n") == keyword.size() - 3)
  {
    throw at(fileName, lineNumber, "\"" + keyword + "\" files are not read (ShadeLab reads OFF, COFF and NOFF)");
  }
  else
  {
    throw at(fileName, lineNumber, "expected \"OFF\", found \"" + shadelab::printableText(keyword) + "\"");
  }
  if (numPoints < 0 || numFaces < 0)
  {
    throw at(fileName, lineNumber, "bad vertex/face counts");
  }

  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  // Grown point by point: the header's count is not trusted before the file
  // proves it (a huge count would otherwise allocate before failing).
  points->Allocate(std::min<long>(numPoints, 1 << 20));
  vtkNew<vtkFloatArray> normalArray;
  normalArray->SetName("Normals");
  normalArray->SetNumberOfComponents(3);
  // COFF colours as read, 4 a vertex (alpha -1 when not given), scaled
  // once the file shows whether they are 0-255 integers or 0-1 floats.
  std::vector<double> colourValues;
  bool floatColours = false, anyAlpha = false;
  long firstAboveOne = 0; // the line of the first colour value above 1
  for (long i = 0; i < numPoints; ++i)
  {
    if (!nextLine(in, line, lineNumber))
    {
      throw at(fileName, lineNumber, "file ends after " + std::to_string(i) + " of " + std::to_string(numPoints) +
          " vertices");
    }
    std::istringstream values(line);
    double x, y, z;
    if (!readNumber(values, x) || !readNumber(values, y) || !readNumber(values, z))
    {
      throw at(fileName, lineNumber, "expected three vertex coordinates");
    }
    points->InsertNextPoint(x, y, z);
    std::vector<std::string> rest;
    for (std::string token; values >> token;)
    {
      rest.push_back(token);
    }
    if (normals)
    {
      std::array<float, 3> n{};
      std::istringstream normal(rest.size() == 3 ? rest[0] + " " + rest[1] + " " + rest[2] : std::string());
      for (float& value : n)
      {
        double read = 0;
        if (!readNumber(normal, read))
        {
          throw at(fileName, lineNumber, "expected a NOFF vertex: x y z nx ny nz");
        }
        value = static_cast<float>(read);
      }
      normalArray->InsertNextTypedTuple(n.data());
    }
    else if (colours)
    {
      if (rest.size() != 3 && rest.size() != 4)
      {
        throw at(fileName, lineNumber, "expected a COFF vertex: x y z r g b [a]");
      }
      for (size_t k = 0; k < 4; ++k)
      {
        double value = -1;
        if (k < rest.size())
        {
          char* end = nullptr;
          value = std::strtod(rest[k].c_str(), &end);
          if (end == rest[k].c_str() || *end != '\0' || !(value >= 0 && value <= 255))
          {
            throw at(fileName, lineNumber, "colour value \"" + shadelab::printableText(rest[k]) +
                "\" is not a number from 0 to 255 (integers) or 0 to 1");
          }
          floatColours = floatColours || !integerToken(rest[k]);
          firstAboveOne = firstAboveOne == 0 && value > 1 ? lineNumber : firstAboveOne;
        }
        colourValues.push_back(value);
      }
      anyAlpha = anyAlpha || rest.size() == 4;
    }
    else if (!rest.empty())
    {
      throw at(fileName, lineNumber, std::to_string(3 + rest.size()) +
          " values for a vertex of plain OFF, which has 3 (x y z); a COFF header reads colours after them, NOFF "
          "normals");
    }
  }
  vtkNew<vtkUnsignedCharArray> colourArray;
  if (colours)
  {
    if (floatColours && firstAboveOne > 0)
    {
      throw at(fileName, firstAboveOne, "colour value above 1 in a file of float colours (0 to 1)");
    }
    colourArray->SetName("Colors");
    colourArray->SetNumberOfComponents(anyAlpha ? 4 : 3);
    colourArray->SetNumberOfTuples(numPoints);
    unsigned char* out = colourArray->GetPointer(0);
    for (size_t v = 0; v < colourValues.size() / 4; ++v)
    {
      for (size_t k = 0; k < (anyAlpha ? 4u : 3u); ++k)
      {
        const double value = colourValues[4 * v + k];
        *out++ = value < 0 ? 255 : static_cast<unsigned char>(floatColours ? std::lround(value * 255) : value);
      }
    }
  }

  vtkNew<vtkCellArray> polys;
  std::vector<vtkIdType> ids;
  for (long f = 0; f < numFaces; ++f)
  {
    if (!nextLine(in, line, lineNumber))
    {
      throw at(fileName, lineNumber, "file ends after " + std::to_string(f) + " of " + std::to_string(numFaces) + " faces");
    }
    std::istringstream values(line);
    long count = 0;
    if (!(values >> count) || count < 3)
    {
      throw at(fileName, lineNumber, "a face needs a vertex count of at least 3");
    }
    // Each index takes at least two characters of the line.
    if (count > static_cast<long>(line.size()) / 2)
    {
      throw at(fileName, lineNumber, "face has fewer than " + std::to_string(count) + " vertex indices");
    }
    ids.resize(static_cast<size_t>(count));
    for (long k = 0; k < count; ++k)
    {
      long id = -1;
      if (!(values >> id))
      {
        throw at(fileName, lineNumber, "face has fewer than " + std::to_string(count) + " vertex indices");
      }
      if (id < 0 || id >= numPoints)
      {
        throw at(fileName, lineNumber, "vertex index " + std::to_string(id) + " is out of range [0, " +
            std::to_string(numPoints) + ")");
      }
      ids[static_cast<size_t>(k)] = id;
    }
    polys->InsertNextCell(count, ids.data());
  }
  output->SetPoints(points);
  output->SetPolys(polys);
  if (normals)
  {
    output->GetPointData()->SetNormals(normalArray);
  }
  if (colours)
  {
    output->GetPointData()->SetScalars(colourArray);
  }
}
