// slMeshReader on any bytes as a file of one extension (SL_FUZZ_EXTENSION):
// either an error message and an empty output, or a mesh that every
// ShadeLab filter and VTK writer may follow (finite points, cells naming
// existing points, polygons of 3 points or more, arrays as long as the mesh).
// For OBJ and PLY, bytes that ShadeLab's own parser takes must also read to
// exactly what VTK's reader gives, where VTK 9.1 keeps every element: for
// OBJ also the groups' and materials' arrays, and the texture coordinates'
// array of each material; for PLY also the colours.
#include "FuzzInputFile.h"
#include "FuzzToolOutput.h"

#include "slConnectivityCheck.h"
#include "slMeshReader.h"
#include "slOBJFormat.h"
#include "slPLYFormat.h"
#include "slUpdateOrThrow.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkUnsignedCharArray.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace
{
/// Equal values, NaN equal to NaN (slMeshReader rejects those meshes later).
bool equal(double a, double b)
{
  return a == b || (std::isnan(a) && std::isnan(b));
}

/// True if @p mesh holds exactly @p arrays' points, normals, texture
/// coordinates (or, if given, @p activeTCoords as its active ones) and
/// polygons.
bool same(vtkPolyData* mesh, const slMeshArrays& arrays, const std::vector<float>* activeTCoords = nullptr)
{
  const vtkIdType n = static_cast<vtkIdType>(arrays.points.size() / 3);
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  vtkDataArray* tcoords = mesh->GetPointData()->GetTCoords();
  const std::vector<float>& uv = activeTCoords ? *activeTCoords : arrays.tcoords;
  if (mesh->GetNumberOfPoints() != n || (normals != nullptr) != !arrays.normals.empty() ||
    (tcoords != nullptr) != !uv.empty() ||
    mesh->GetPolys()->GetNumberOfCells() != static_cast<vtkIdType>(arrays.offsets.size()) - 1)
  {
    return false;
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      const size_t k = static_cast<size_t>(3 * i + c);
      if (!equal(mesh->GetPoints()->GetData()->GetComponent(i, c), arrays.points[k]) ||
        (normals && !equal(normals->GetComponent(i, c), arrays.normals[k])) ||
        (tcoords && c < 2 && !equal(tcoords->GetComponent(i, c), uv[static_cast<size_t>(2 * i + c)])))
      {
        return false;
      }
    }
  }
  vtkNew<vtkIdList> ids;
  for (vtkIdType f = 0; f < mesh->GetPolys()->GetNumberOfCells(); ++f)
  {
    mesh->GetPolys()->GetCellAtId(f, ids);
    const std::int64_t first = arrays.offsets[static_cast<size_t>(f)];
    if (ids->GetNumberOfIds() != arrays.offsets[static_cast<size_t>(f + 1)] - first)
    {
      return false;
    }
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      if (ids->GetId(k) != arrays.connectivity[static_cast<size_t>(first + k)])
      {
        return false;
      }
    }
  }
  return true;
}

/// True if the arrays of @p data are exactly those named @p names, in order.
bool named(vtkFieldData* data, const std::vector<std::string>& names)
{
  if (data->GetNumberOfArrays() != static_cast<int>(names.size()))
  {
    return false;
  }
  for (int a = 0; a < data->GetNumberOfArrays(); ++a)
  {
    const char* name = data->GetAbstractArray(a)->GetName();
    if (!name || names[static_cast<size_t>(a)] != name)
    {
      return false;
    }
  }
  return true;
}

/// True if the @p Array named @p name in @p data holds exactly @p values.
template <typename Array, typename T>
bool holds(vtkFieldData* data, const char* name, const std::vector<T>& values)
{
  Array* array = Array::SafeDownCast(data->GetAbstractArray(name));
  if (!array || array->GetNumberOfComponents() != 1 ||
    array->GetNumberOfValues() != static_cast<vtkIdType>(values.size()))
  {
    return false;
  }
  for (size_t k = 0; k < values.size(); ++k)
  {
    if (!(array->GetValue(static_cast<vtkIdType>(k)) == values[k]))
    {
      return false;
    }
  }
  return true;
}

/// Texture coordinate array @p a of those @p attributes name, for the mesh
/// @p arrays that came with them.
std::vector<float> tcoordsArray(const slOBJAttributes& attributes, size_t a, const slMeshArrays& arrays)
{
  std::vector<float> values(arrays.tcoords.size());
  slOBJTCoordsArray(attributes, a, arrays.tcoords.data(), arrays.tcoords.size() / 2, values.data());
  return values;
}

/// True if @p mesh, read by vtkOBJReader, has exactly the arrays besides
/// points and normals that @p attributes describe for @p arrays: the
/// texture coordinates' arrays (names, order, values, the first active);
/// the cell arrays "MaterialIds" (with materials) and "GroupIds" (0 for
/// every face where @p attributes has none); the field data
/// "MaterialNames" and "MaterialLibraries".
bool sameAttributes(vtkPolyData* mesh, const slMeshArrays& arrays, const slOBJAttributes& attributes)
{
  vtkPointData* pd = mesh->GetPointData();
  vtkDataArray* tcoords = pd->GetTCoords();
  std::vector<std::string> pointArrays = tcoords ? attributes.tcoordsNames : std::vector<std::string>();
  if (pd->GetNormals())
  {
    pointArrays.emplace_back("Normals");
  }
  if (!named(pd, pointArrays) || (tcoords && tcoords != pd->GetArray(0)))
  {
    return false;
  }
  for (size_t a = 0; tcoords && a < attributes.tcoordsNames.size(); ++a)
  {
    vtkDataArray* array = pd->GetArray(static_cast<int>(a));
    const std::vector<float> values = tcoordsArray(attributes, a, arrays);
    if (array->GetNumberOfComponents() != 2 || static_cast<size_t>(array->GetNumberOfValues()) != values.size())
    {
      return false;
    }
    for (size_t k = 0; k < values.size(); ++k)
    {
      if (!equal(array->GetComponent(static_cast<vtkIdType>(k / 2), static_cast<int>(k % 2)), values[k]))
      {
        return false;
      }
    }
  }
  const bool materials = !attributes.materialIds.empty();
  std::vector<std::string> cellArrays{ "GroupIds" }, fieldArrays;
  if (materials)
  {
    cellArrays.insert(cellArrays.begin(), "MaterialIds");
    fieldArrays.emplace_back("MaterialNames");
    if (!attributes.materialLibraries.empty())
    {
      fieldArrays.emplace_back("MaterialLibraries");
    }
  }
  const std::vector<float> groups = !attributes.groupIds.empty()
    ? attributes.groupIds
    : std::vector<float>(static_cast<size_t>(mesh->GetNumberOfPolys()), 0.0f);
  return named(mesh->GetCellData(), cellArrays) && named(mesh->GetFieldData(), fieldArrays) &&
    holds<vtkFloatArray>(mesh->GetCellData(), "GroupIds", groups) &&
    (!materials ||
      (holds<vtkIntArray>(mesh->GetCellData(), "MaterialIds", attributes.materialIds) &&
        holds<vtkStringArray>(mesh->GetFieldData(), "MaterialNames", attributes.materialNames) &&
        (attributes.materialLibraries.empty() ||
          holds<vtkStringArray>(mesh->GetFieldData(), "MaterialLibraries", attributes.materialLibraries))));
}

/// True if vtkOBJReader 9.1 kept every element of a file that gave
/// @p arrays: it drops the faces without vn beside faces with one, and the
/// "l" and "p" elements when it makes a point per corner (where ShadeLab's
/// parser keeps them and leaves the normals out).
bool keptEveryElement(vtkPolyData* mesh, const slMeshArrays& arrays)
{
  return mesh->GetNumberOfPolys() == static_cast<vtkIdType>(arrays.offsets.size()) - 1 &&
    mesh->GetNumberOfLines() == static_cast<vtkIdType>(arrays.lineSizes.size()) &&
    mesh->GetNumberOfVerts() == static_cast<vtkIdType>(arrays.vertexSizes.size());
}

/// True if @p mesh, read by vtkPLYReader, has exactly the colours @p arrays
/// holds (an unsigned char array "RGB" or "RGBA", the active scalars, the
/// first point array) and no point arrays but those, normals and texture
/// coordinates.
bool sameColours(vtkPolyData* mesh, const slMeshArrays& arrays)
{
  vtkPointData* pd = mesh->GetPointData();
  auto* colours = vtkUnsignedCharArray::SafeDownCast(pd->GetScalars());
  const bool given = !arrays.colours.empty();
  if ((pd->GetScalars() != nullptr) != given ||
    pd->GetNumberOfArrays() != (given ? 1 : 0) + (pd->GetNormals() ? 1 : 0) + (pd->GetTCoords() ? 1 : 0))
  {
    return false;
  }
  return !given ||
    (colours && colours == pd->GetArray(0) && colours->GetNumberOfComponents() == arrays.colourComponents &&
      colours->GetName() && std::string(colours->GetName()) == (arrays.colourComponents == 4 ? "RGBA" : "RGB") &&
      static_cast<size_t>(colours->GetNumberOfValues()) == arrays.colours.size() &&
      std::memcmp(colours->GetPointer(0), arrays.colours.data(), arrays.colours.size()) == 0);
}

/// What VTK's reader gives for a file ShadeLab's parser takes, against it.
void compareWithVTK(const std::string& path, const uint8_t* data, size_t size)
{
  const std::string ext = SL_FUZZ_EXTENSION;
  const char* text = reinterpret_cast<const char*>(data);
  slMeshArrays arrays;
  slOBJAttributes attributes;
  if (ext == ".obj" && slParseOBJ(text, size, false, arrays, attributes, 1))
  {
    // ShadeLab's parser skips a UTF-8 byte order mark, which vtkOBJReader
    // reads as part of the first keyword (dropping that line): it reads
    // the text after the mark.
    const bool mark = size >= 3 && std::memcmp(text, "\xEF\xBB\xBF", 3) == 0;
    const std::string vtkPath = mark ? fuzzInputFile(data + 3, size - 3, SL_FUZZ_EXTENSION) : path;
    vtkNew<vtkOBJReader> reader;
    reader->SetFileName(vtkPath.c_str());
    reader->Update();
    // The active texture coordinates: the first of vtkOBJReader's arrays.
    const std::vector<float> active =
      attributes.tcoordsNames.empty() ? std::vector<float>() : tcoordsArray(attributes, 0, arrays);
    if (keptEveryElement(reader->GetOutput(), arrays) &&
      (!same(reader->GetOutput(), arrays, &active) || !sameAttributes(reader->GetOutput(), arrays, attributes)))
    {
      std::abort();
    }
  }
  if (ext == ".ply" && slParsePLY(text, size, arrays, 1))
  {
    vtkNew<vtkPLYReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    if (!same(reader->GetOutput(), arrays) || !sameColours(reader->GetOutput(), arrays))
    {
      std::abort();
    }
  }
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  const std::string path = fuzzInputFile(data, size, SL_FUZZ_EXTENSION);
  vtkNew<slMeshReader> reader;
  reader->SetFileName(path.c_str());
  bool failed = false;
  try
  {
    slUpdateOrThrow(reader);
  }
  catch (const shadelab::Error&)
  {
    failed = true;
  }
  vtkPolyData* mesh = reader->GetOutput();
  if (failed != (mesh->GetNumberOfPoints() == 0) || !slConnectivityProblem(mesh).empty())
  {
    std::abort();
  }
  // Every polygon has 3 points or more (VTK builds no cell types around a
  // shorter one, and its writers crash), and every array a tuple per point
  // or cell.
  for (vtkIdType f = 0; f < mesh->GetPolys()->GetNumberOfCells(); ++f)
  {
    if (mesh->GetPolys()->GetCellSize(f) < 3)
    {
      std::abort();
    }
  }
  const auto expectTuples = [](vtkDataSetAttributes* data, vtkIdType expected) {
    for (int a = 0; a < data->GetNumberOfArrays(); ++a)
    {
      if (data->GetAbstractArray(a)->GetNumberOfTuples() != expected)
      {
        std::abort();
      }
    }
  };
  expectTuples(mesh->GetPointData(), mesh->GetNumberOfPoints());
  expectTuples(mesh->GetCellData(), mesh->GetNumberOfCells());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    if (!std::isfinite(p[0] + p[1] + p[2]))
    {
      std::abort();
    }
  }
  compareWithVTK(path, data, size);
  return 0;
}
