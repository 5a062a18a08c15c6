#include "slOFFParser.h"

#include "shadelab/PrintableText.h"

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
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
  if (keyword == "OFF")
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
}
