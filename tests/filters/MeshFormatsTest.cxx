// ShadeLab's own OBJ and PLY parsers and formatters: the files they take give
// exactly what VTK's readers give (for OBJ, followed by the merging of equal
// corners, computed here on its own); the files they decline go to VTK; and
// what slMeshWriter writes reads back bit for bit, in ShadeLab and in VTK.
#include "TestFolder.h"

#include "VTKErrors.h"
#include "slMeshReader.h"
#include "slMeshWriter.h"
#include "slOBJFormat.h"
#include "slPLYFormat.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPLYWriter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkPolyDataWriter.h>
#include <vtkSphereSource.h>
#include <vtkStringArray.h>
#include <vtkUnsignedCharArray.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
std::string contents(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

vtkSmartPointer<vtkPolyData> readShadeLab(const std::string& path)
{
  vtkNew<slMeshReader> reader;
  reader->SetFileName(path.c_str());
  EXPECT_EQ(updateError(reader), "") << path;
  vtkSmartPointer<vtkPolyData> out = reader->GetOutput();
  return out;
}

template <typename Reader>
vtkSmartPointer<vtkPolyData> readVTK(const std::string& path)
{
  vtkNew<Reader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkSmartPointer<vtkPolyData> out = reader->GetOutput();
  return out;
}

/// A point's position and every point-data value, in array order.
std::vector<double> row(vtkPolyData* mesh, vtkIdType id)
{
  std::vector<double> r(3);
  mesh->GetPoint(id, r.data());
  for (int a = 0; a < mesh->GetPointData()->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = mesh->GetPointData()->GetArray(a);
    for (int c = 0; c < array->GetNumberOfComponents(); ++c)
    {
      r.push_back(array->GetComponent(id, c));
    }
  }
  return r;
}

/// @p mesh with points equal in every value merged (bit for bit: 0 and -0
/// stay apart), first occurrence first, as a list of distinct rows and
/// polygons naming them.
struct Merged
{
  std::vector<std::vector<double>> rows;
  std::vector<std::vector<vtkIdType>> polygons;
};
Merged merged(vtkPolyData* mesh)
{
  Merged m;
  std::map<std::string, vtkIdType> seen;
  std::vector<vtkIdType> newId(static_cast<size_t>(mesh->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    const std::vector<double> r = row(mesh, i);
    const std::string bytes(reinterpret_cast<const char*>(r.data()), r.size() * sizeof(double));
    auto inserted = seen.emplace(bytes, static_cast<vtkIdType>(m.rows.size()));
    if (inserted.second)
    {
      m.rows.push_back(r);
    }
    newId[static_cast<size_t>(i)] = inserted.first->second;
  }
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < mesh->GetPolys()->GetNumberOfCells(); ++c)
  {
    mesh->GetPolys()->GetCellAtId(c, ids);
    std::vector<vtkIdType> polygon;
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      polygon.push_back(newId[static_cast<size_t>(ids->GetId(k))]);
    }
    m.polygons.push_back(polygon);
  }
  return m;
}

std::vector<std::string> arrayNames(vtkPolyData* mesh)
{
  std::vector<std::string> names;
  for (int a = 0; a < mesh->GetPointData()->GetNumberOfArrays(); ++a)
  {
    names.emplace_back(mesh->GetPointData()->GetArrayName(a));
  }
  return names;
}

/// Every point, array value and polygon of @p ours equals @p theirs, in order.
void expectIdentical(vtkPolyData* ours, vtkPolyData* theirs, const std::string& what)
{
  ASSERT_EQ(ours->GetNumberOfPoints(), theirs->GetNumberOfPoints()) << what;
  EXPECT_EQ(ours->GetPoints()->GetDataType(), theirs->GetPoints()->GetDataType()) << what;
  EXPECT_EQ(arrayNames(ours), arrayNames(theirs)) << what;
  EXPECT_EQ(ours->GetPointData()->GetNormals() != nullptr, theirs->GetPointData()->GetNormals() != nullptr) << what;
  EXPECT_EQ(ours->GetPointData()->GetTCoords() != nullptr, theirs->GetPointData()->GetTCoords() != nullptr) << what;
  const Merged a = merged(ours), b = merged(theirs);
  for (vtkIdType i = 0; i < ours->GetNumberOfPoints(); ++i)
  {
    ASSERT_EQ(row(ours, i), row(theirs, i)) << what << ": point " << i;
  }
  EXPECT_EQ(a.polygons, b.polygons) << what;
  EXPECT_EQ(ours->GetNumberOfVerts() + ours->GetNumberOfLines() + ours->GetNumberOfStrips(), 0) << what;
}

/// One cell or field data array: its name, class and every value.
struct ArrayValues
{
  std::string name, type;
  std::vector<double> numbers;
  std::vector<std::string> strings;
  bool operator==(const ArrayValues& o) const
  {
    // Bit for bit, as the points are compared.
    return name == o.name && type == o.type && strings == o.strings && numbers.size() == o.numbers.size() &&
      std::equal(numbers.begin(), numbers.end(), o.numbers.begin(),
        [](double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; });
  }
};
std::ostream& operator<<(std::ostream& out, const ArrayValues& a)
{
  out << a.name << " (" << a.type << "):";
  for (double v : a.numbers)
  {
    out << " " << v;
  }
  for (const std::string& v : a.strings)
  {
    out << " \"" << v << "\"";
  }
  return out;
}

/// Every array of @p data, in order.
std::vector<ArrayValues> arraysOf(vtkFieldData* data)
{
  std::vector<ArrayValues> arrays;
  for (int a = 0; a < data->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = data->GetAbstractArray(a);
    ArrayValues values{ array->GetName() ? array->GetName() : "", array->GetClassName(), {}, {} };
    auto* strings = vtkStringArray::SafeDownCast(array);
    auto* numbers = vtkDataArray::SafeDownCast(array);
    for (vtkIdType k = 0; k < array->GetNumberOfValues(); ++k)
    {
      if (strings)
      {
        values.strings.push_back(strings->GetValue(k));
      }
      else if (numbers)
      {
        values.numbers.push_back(numbers->GetComponent(k / numbers->GetNumberOfComponents(),
          static_cast<int>(k % numbers->GetNumberOfComponents())));
      }
    }
    arrays.push_back(values);
  }
  return arrays;
}

/// The cell and field data of @p ours, read by slMeshReader, equal
/// vtkOBJReader's in @p theirs (names, classes, order, values), but for
/// "GroupIds" where VTK gives every face 0: ShadeLab's parser leaves it out.
void expectSameCellAndFieldData(vtkPolyData* ours, vtkPolyData* theirs, const std::string& what)
{
  std::vector<ArrayValues> cells = arraysOf(theirs->GetCellData());
  cells.erase(std::remove_if(cells.begin(), cells.end(),
                [](const ArrayValues& a) {
                  return a.name == "GroupIds" &&
                    std::all_of(a.numbers.begin(), a.numbers.end(), [](double v) { return v == 0; });
                }),
    cells.end());
  EXPECT_EQ(arraysOf(ours->GetCellData()), cells) << what;
  EXPECT_EQ(arraysOf(ours->GetFieldData()), arraysOf(theirs->GetFieldData())) << what;
}

/// A sphere with normals and texture coordinates @p uv(point id).
vtkSmartPointer<vtkPolyData> texturedSphere(int resolution, std::array<double, 2> (*uv)(double))
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(resolution);
  sphere->SetPhiResolution(resolution - 2);
  sphere->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->DeepCopy(sphere->GetOutput());
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetName("TCoords");
  tcoords->SetNumberOfComponents(2);
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    tcoords->InsertNextTuple(uv(static_cast<double>(i)).data());
  }
  mesh->GetPointData()->SetTCoords(tcoords);
  return mesh;
}

/// OBJ files of every form slParseOBJ takes.
const std::map<std::string, std::string>& objFiles()
{
  static const std::map<std::string, std::string> files = {
    { "plain", "# a comment\nv 0 0 0\nv 1 0 0\nv 1 1 0\r\nv 0 1 0\n\nf 1 2 3\nf 1 3 4\n" },
    { "quad and scientific", "v -1e-3 2.5E+2 .5\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 1 0 0\nf 1 2 3 4\nf 5 3 2\n" },
    { "same index", "v 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\n"
                    "f 1/1/1 2/2/2 3/3/3\n" },
    { "normals by corner", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nvn 0 0 -1\n"
                           "f 1//1 2//1 3//1\nf 1//2 3//2 4//2\n" },
    { "uv seam", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\n"
                 "f 1/1 2/2 3/3\nf 1/5 3/3 4/4\n" },
    { "all three, forward references", "f 1/2/1 2/1/1 3/3/1\t\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                                       "vn 0 0 1\n" },
    { "negative zero", "v 0 0 0\nv -0 0 0\nv 1 0 0\nv 0 1 0\nf 1 3 4\nf 2 3 4\n" },
    // Faces of several forms: (-1, -1) for the corners, or the points, no
    // vt is given for; the normals of the v list, where every vn index is
    // its v index.
    { "faces with and without vt", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1\nf 1 2 3\n" },
    { "faces with and without vt, of the v list", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvt 1 0\nvt 0 1\n"
                                                  "vt 1 1\nf 1/1 2/2 3/3\nf 1 2 4\n" },
    { "faces with and without vn", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 1 0\n"
                                   "f 1//1 2//2 3//3\nf 1 2 4\n" },
    // Objects, smoothing groups, groups and materials, as exporters write
    // them: the groups' and materials' arrays as vtkOBJReader gives them.
    { "Blender-style header", "# Blender v2.93.0 OBJ File: ''\n# www.blender.org\nmtllib untitled.mtl\no Plane\n"
                              "v -1.000000 0.000000 1.000000\nv 1.000000 0.000000 1.000000\n"
                              "v -1.000000 0.000000 -1.000000\nv 1.000000 0.000000 -1.000000\n"
                              "vt 1.000000 0.000000\nvt 0.000000 1.000000\nvt 0.000000 0.000000\n"
                              "vt 1.000000 1.000000\nvn 0.0000 1.0000 0.0000\nusemtl Material\ns off\n"
                              "f 2/1/1 3/2/1 1/3/1\nf 2/1/1 4/4/1 3/2/1\n" },
    { "objects, smoothing groups and libraries anywhere",
      "mtllib a.mtl b.mtl\no first\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\ns 1\nf 1 2 3\no second object\ns off\n"
      "f 1 3 4\nmtllib\n" },
    { "several groups", "g\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\ng first\nf 1 2 3\ng second part\ng\nf 1 3 4\n"
                        "f 2 3 4\ng last\n" },
    { "a face before the first group", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\ng a\nf 1 3 2\n" },
    { "one group", "v 0 0 0\nv 1 0 0\nv 1 1 0\ng a\nf 1 2 3\nf 1 3 2\n" },
    { "material with vt", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                          "usemtl wood\nf 1/1 2/2 3/3\nusemtl wood\nf 1/1 3/3 4/4\n" },
    { "material with vt by corner", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0.5 0.5\n"
                                    "f 1/1 2/2 3/3\nusemtl wood extra words\nf 1/4 3/3 4/1\nf 1 2 4\n" },
    { "material with vn", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nvn 0 0 -1\nmtllib m.mtl\nusemtl steel\n"
                          "f 1//1 2//1 3//1\nf 1//2 3//2 4//2\n" },
    { "material with neither", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl steel\nf 1 2 3\nf 1 3 2\n" },
    { "material named NO_MATERIAL", "v 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nusemtl NO_MATERIAL\n"
                                    "f 1/1 2/2 3/3\n" },
    { "materials without vt", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\n"
                              "f 1//1 2//2 3//3\nusemtl a\nf 1//1 3//3 4//4\nusemtl b\nusemtl c\nf 1 2 4\nf 1 2 3\n"
                              "usemtl a\nf 2 3 4\nusemtl d\n" },
    { "mixed", "# mixed\nmtllib x.mtl\no thing\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\n"
               "vt 1 1\nvt 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\ng top\nusemtl paint\ns 1\n"
               "f 1/1/1 2/2/2 3/3/3\ng side\nf 1/1 3/3 4/4\nf 1 2 4\no other\ng\nusemtl paint\nf 2//2 3//3 4//4\n" },
    // Texture coordinates under several material names: vtkOBJReader's
    // array per name, in its hash table's order, holding the vt of the
    // faces of that material and (-1, -1) elsewhere; the faces before the
    // first "usemtl" line count as the last one's.
    { "materials with vt", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl a\nf 1/1 2/2 3/3\n"
                           "usemtl b\nf 1/1 3/3 2/2\n" },
    { "materials with vt, of the v list", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvt 1 0\nvt 1 1\n"
                                          "vt 0 1\nvt 0.5 0.5\nusemtl a\nf 1/1 2/2 3/3\nusemtl b\nf 1/1 3/3 4/4\n"
                                          "f 1 2 4\n" },
    // A face before the first "usemtl" line (the last one's, "c"), a
    // material without faces, a face without vt, a vt (-1, -1) at a corner
    // of it (one point: every array holds (-1, -1) for both), and vt of
    // equal values: (0, 0) under other materials (two points), (0.5, 0.5)
    // under the same (one point).
    { "materials with vt by corner", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0.5 0.5\n"
                                     "vt -1 -1\nvt 0 0\nvt 0.5 0.5\nf 1/1 2/2 3/3\nusemtl a\nf 1/4 3/3 4/1\nf 1 3 4\n"
                                     "usemtl b\nf 2/2 3/5 4/6\nusemtl unused\nusemtl a\nf 1/6 2/2 4/4\nf 1/7 3/3 2/2\n"
                                     "usemtl c\n" },
    // Vertex colours (r g b, r g b a) and weights (w), which vtkOBJReader
    // ignores, as the parser does.
    { "vertex colours and weights", "v 0 0 0 1 0 0\nv 1 0 0 0.5 0.25 0.125 1\nv 0 1 0 2\nv 1 1 0\t0 1e-3 1\t\n"
                                    "f 1 2 3\nf 2 4 3\n" },
    { "materials with vt and vn by corner", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 0\nvn 0 0 1\n"
                                            "vn 0 0 -1\nf 1/1/1 2/2/1 3/1/1\nusemtl b\nf 1/3/1 3/3/1 4/3/2\nusemtl a\n"
                                            "f 1/1/2 2/2/1 4/2/2\n" },
  };
  return files;
}

/// The name of the active texture coordinates, "" without.
std::string activeTCoordsName(vtkPolyData* mesh)
{
  vtkDataArray* tcoords = mesh->GetPointData()->GetTCoords();
  return tcoords && tcoords->GetName() ? tcoords->GetName() : "";
}

/// slMeshReader reads the OBJ file @p path to what vtkOBJReader gives,
/// merged here: every point array (names, order, the active texture
/// coordinates, values), cell and field data and polygon.
void expectOBJAsVTKReadsIt(const std::string& path, const std::string& what)
{
  vtkSmartPointer<vtkPolyData> ours = readShadeLab(path);
  vtkSmartPointer<vtkPolyData> theirs = readVTK<vtkOBJReader>(path);
  const Merged a = merged(ours), b = merged(theirs);
  expectSameCellAndFieldData(ours, theirs, what);
  // Merging leaves nothing to merge, and gives VTK's points merged.
  EXPECT_EQ(static_cast<size_t>(ours->GetNumberOfPoints()), a.rows.size()) << what;
  EXPECT_EQ(a.rows, b.rows) << what;
  EXPECT_EQ(a.polygons, b.polygons) << what;
  EXPECT_EQ(arrayNames(ours), arrayNames(theirs)) << what;
  EXPECT_EQ(activeTCoordsName(ours), activeTCoordsName(theirs)) << what;
  EXPECT_EQ(ours->GetPoints()->GetDataType(), theirs->GetPoints()->GetDataType()) << what;

  // Without merging: VTK's points, one for one.
  vtkNew<slMeshReader> unmerged;
  unmerged->SetFileName(path.c_str());
  unmerged->MergeDuplicatePointsOff();
  unmerged->Update();
  expectIdentical(unmerged->GetOutput(), theirs, what + ", unmerged");
  EXPECT_EQ(activeTCoordsName(unmerged->GetOutput()), activeTCoordsName(theirs)) << what << ", unmerged";
  expectSameCellAndFieldData(unmerged->GetOutput(), theirs, what + ", unmerged");
}
} // namespace

TEST(MeshFormats, OBJAsVTKReadsItWithCornersMerged)
{
  const TestFolder folder;
  for (const auto& file : objFiles())
  {
    folder.write("m.obj", file.second);
    slMeshArrays arrays;
    slOBJAttributes attributes;
    EXPECT_TRUE(slParseOBJ(file.second.data(), file.second.size(), true, arrays, attributes, 2)) << file.first;
    expectOBJAsVTKReadsIt(folder.path("m.obj"), file.first);
  }
}

TEST(MeshFormats, OBJOutsideTheCommonFormGoesToVTK)
{
  const TestFolder folder;
  const std::map<std::string, std::string> declined = {
    // vtkOBJReader gives a texture coordinate array per material, one
    // named "Normals", which its normals then replace.
    { "material named Normals", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl Normals\n"
                                "f 1/1 2/2 3/3\n" },
    { "materials with vt, one named Normals", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl a\n"
                                              "f 1/1 2/2 3/3\nusemtl Normals\nf 1/1 3/3 2/2\n" },
    // ... "MaterialIds" for the faces only, which slMeshReader refuses.
    { "material and a line", "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\nl 1 2\n" },
    { "material without a name", "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl \nf 1 2 3\n" },
    { "material name of 100 bytes", "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl " + std::string(100, 'm') + "\nf 1 2 3\n" },
    { "form feed in a material name", "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\fb\nf 1 2 3\n" },
    { "vertical tab after a group", "v 0 0 0\nv 1 0 0\nv 0 1 0\ng\va\nf 1 2 3\ng\nf 1 3 2\n" },
    { "negative index", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n" },
    { "vertex colour not a number", "v 0 0 0 1 0 0\nv 1 0 0 1 0 red\nv 0 1 0 1 0 0\nf 1 2 3\n" },
    { "line naming a normal", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nl 1//1 2\n" },
    { "continued line", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 \\\n3\n" },
  };
  for (const auto& file : declined)
  {
    slMeshArrays arrays;
    slOBJAttributes attributes;
    EXPECT_FALSE(slParseOBJ(file.second.data(), file.second.size(), true, arrays, attributes, 1)) << file.first;
  }
  // Declined, it reads as before: through vtkOBJReader, with its array of
  // texture coordinates per material.
  folder.write("m.obj", declined.at("materials with vt, one named Normals"));
  vtkSmartPointer<vtkPolyData> read = readShadeLab(folder.path("m.obj"));
  EXPECT_EQ(read->GetNumberOfPolys(), 2);
  EXPECT_EQ(read->GetPointData()->GetNumberOfArrays(), 2);
}

TEST(MeshFormats, PLYAsVTKReadsIt)
{
  const TestFolder folder;
  vtkSmartPointer<vtkPolyData> mesh =
    texturedSphere(9, [](double i) { return std::array<double, 2>{ 0.1 * i, 1.0 / (i + 1) }; });
  // As VTK writes it (points and texture coordinates), and as ShadeLab does
  // (with normals).
  vtkNew<vtkPLYWriter> writer;
  writer->SetInputData(mesh);
  writer->SetFileName(folder.path("vtk.ply").c_str());
  writer->SetFileTypeToBinary();
  writer->Write();
  vtkNew<slMeshWriter> ours;
  ours->SetInputData(mesh);
  ours->SetFileName(folder.path("shadelab.ply").c_str());
  ASSERT_EQ(callError(ours, [&] { return ours->Write(); }), "");
  for (const char* name : { "vtk.ply", "shadelab.ply" })
  {
    const std::string bytes = contents(folder.path(name));
    slMeshArrays arrays;
    EXPECT_TRUE(slParsePLY(bytes.data(), bytes.size(), arrays, 1)) << name;
    expectIdentical(readShadeLab(folder.path(name)), readVTK<vtkPLYReader>(folder.path(name)), name);
  }
  // VTK's PLY code takes "\fv" for one word, not a texture coordinate "v";
  // ShadeLab's parser declines a header with a control byte, and the file
  // check refuses it.
  std::string formFeed = contents(folder.path("shadelab.ply"));
  const size_t v = formFeed.find("property float v\n");
  ASSERT_NE(v, std::string::npos);
  formFeed.insert(v + 15, "\f");
  slMeshArrays arrays;
  EXPECT_FALSE(slParsePLY(formFeed.data(), formFeed.size(), arrays, 1));
  folder.write("formfeed.ply", formFeed);
  vtkNew<slMeshReader> reader;
  reader->SetFileName(folder.path("formfeed.ply").c_str());
  EXPECT_NE(updateError(reader).find("a control byte in the header"), std::string::npos);
  vtkSmartPointer<vtkPolyData> back = readVTK<vtkPLYReader>(folder.path("shadelab.ply"));
  ASSERT_NE(back->GetPointData()->GetNormals(), nullptr);
  EXPECT_EQ(back->GetPointData()->GetNormals()->GetTuple3(5)[2], mesh->GetPointData()->GetNormals()->GetTuple3(5)[2]);
}

namespace
{
/// The point arrays of @p mesh: each one's name, class and components, and
/// whether it is the active scalars, normals or texture coordinates.
std::vector<std::string> pointArrayKinds(vtkPolyData* mesh)
{
  std::vector<std::string> kinds;
  vtkPointData* pd = mesh->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pd->GetArray(a);
    std::string kind = std::string(array->GetName() ? array->GetName() : "(no name)") + " " + array->GetClassName() +
      " x" + std::to_string(array->GetNumberOfComponents());
    kind += array == pd->GetScalars() ? " scalars" : "";
    kind += array == pd->GetNormals() ? " normals" : "";
    kind += array == pd->GetTCoords() ? " tcoords" : "";
    kinds.push_back(kind);
  }
  return kinds;
}

/// @p ours, read by slMeshReader, and @p theirs, read by vtkPLYReader, hold
/// the same points, point arrays and polygons: every value bit for bit (0
/// and -0 apart), every array of the same name, class, components and
/// attribute.
void expectSamePLYMesh(vtkPolyData* ours, vtkPolyData* theirs, const std::string& what)
{
  expectIdentical(ours, theirs, what);
  EXPECT_EQ(pointArrayKinds(ours), pointArrayKinds(theirs)) << what;
  for (vtkIdType i = 0; i < std::min(ours->GetNumberOfPoints(), theirs->GetNumberOfPoints()); ++i)
  {
    const std::vector<double> a = row(ours, i), b = row(theirs, i);
    ASSERT_TRUE(a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0)
      << what << ": point " << i << " differs in its bits";
  }
}

/// Parses @p bytes (file @p name in @p folder) with ShadeLab's PLY parser on
/// 1 and 2 threads, expects it to take them, and compares what slMeshReader
/// reads with what vtkPLYReader reads.
void expectTakenAsVTKReadsIt(const TestFolder& folder, const std::string& name, const std::string& bytes)
{
  folder.write(name, bytes);
  for (int threads : { 1, 2 })
  {
    slMeshArrays arrays;
    EXPECT_TRUE(slParsePLY(bytes.data(), bytes.size(), arrays, threads)) << name;
  }
  expectSamePLYMesh(readShadeLab(folder.path(name)), readVTK<vtkPLYReader>(folder.path(name)), name);
}

/// A vertex property of plyFile: its type, name and its value at each of
/// the five vertices, as text.
struct PLYColumn
{
  std::string type, name;
  std::array<const char*, 5> values;
};

/// The bytes of one value of @p type, read from @p text as VTK's PLY code
/// reads ASCII (strtod, strtoul or strtol, then converted to the type).
std::string binaryValue(const std::string& type, const char* text)
{
  const auto bytes = [](auto value) { return std::string(reinterpret_cast<const char*>(&value), sizeof(value)); };
  const long long integer = std::strtoll(text, nullptr, 10);
  if (type == "float" || type == "float32")
  {
    return bytes(static_cast<float>(std::strtod(text, nullptr)));
  }
  if (type == "double" || type == "float64")
  {
    return bytes(std::strtod(text, nullptr));
  }
  if (type == "char" || type == "int8" || type == "uchar" || type == "uint8")
  {
    return bytes(static_cast<unsigned char>(integer));
  }
  if (type == "short" || type == "int16" || type == "ushort" || type == "uint16")
  {
    return bytes(static_cast<std::uint16_t>(integer));
  }
  return bytes(static_cast<std::uint32_t>(integer)); // int, int32, uint, uint32
}

/// A pyramid of five vertices with the vertex properties @p columns, as
/// PLY of @p format ("ascii", "binary_little_endian" or "binary_big_endian";
/// the test host is little-endian) with lines ending in @p eol, its faces'
/// indices declared by @p faceProperty.
std::string plyFile(const std::vector<PLYColumn>& columns, const std::string& format, const std::string& eol = "\n",
  const std::string& faceProperty = "property list uchar int vertex_indices")
{
  const bool ascii = format == "ascii";
  // Values in the file's byte order.
  const auto ordered = [&](std::string bytes) {
    if (format == "binary_big_endian")
    {
      std::reverse(bytes.begin(), bytes.end());
    }
    return bytes;
  };
  std::string out = "ply" + eol + "format " + format + " 1.0" + eol + "comment written by hand" + eol +
    "element vertex 5" + eol;
  for (const PLYColumn& c : columns)
  {
    out += "property " + c.type + " " + c.name + eol;
  }
  out += "element face 3" + eol + faceProperty + eol + "end_header" + eol;
  for (size_t i = 0; i < 5; ++i)
  {
    for (size_t k = 0; k < columns.size(); ++k)
    {
      out += ascii ? std::string(k ? " " : "") + columns[k].values[i]
                   : ordered(binaryValue(columns[k].type, columns[k].values[i]));
    }
    out += ascii ? eol : "";
  }
  const std::vector<std::vector<std::int32_t>> faces = { { 0, 1, 4 }, { 1, 2, 4 }, { 0, 1, 2, 3 } };
  for (const auto& face : faces)
  {
    out += ascii ? std::to_string(face.size()) : std::string(1, static_cast<char>(face.size()));
    for (std::int32_t index : face)
    {
      out += ascii ? " " + std::to_string(index) : ordered(std::string(reinterpret_cast<const char*>(&index), 4));
    }
    out += ascii ? eol : "";
  }
  return out;
}

const PLYColumn plyX{ "float", "x", { "0", "1", "1", "0", "0.5" } };
const PLYColumn plyY{ "float", "y", { "0", "0", "1", "1", "0.5" } };
const PLYColumn plyZ{ "float", "z", { "0", "-0", "0", "1e-3", "0.70710678118654752440" } };

/// The vertex layouts slParsePLY takes, by name: positions, colours, normals
/// and texture coordinates in any order, and properties vtkPLYReader
/// ignores, of every scalar type.
const std::map<std::string, std::vector<PLYColumn>>& plyLayouts()
{
  static const PLYColumn red{ "uchar", "red", { "0", "255", "17", "128", "64" } },
    green{ "uchar", "green", { "255", "0", "34", "1", "2" } }, blue{ "uchar", "blue", { "9", "8", "7", "6", "250" } },
    alpha{ "uchar", "alpha", { "255", "128", "0", "1", "77" } },
    nx{ "float", "nx", { "0", "-0", "0.6", "-0.6", "1" } }, ny{ "float", "ny", { "0", "1", "0.8", "0", "0" } },
    nz{ "float", "nz", { "1", "0", "0", "0.8", "-0" } },
    u{ "float32", "u", { "0", "0.333333333333333333", "1", "1e-7", "-2.5" } },
    v{ "float", "v", { "1", "0.25", "0", "3e-8", "7" } };
  const auto skipped = [](const char* type, const char* name, bool isSigned) {
    return PLYColumn{ type, name,
      isSigned ? std::array<const char*, 5>{ "0", "-1", "100", "-7", "42" }
               : std::array<const char*, 5>{ "0", "1", "100", "7", "42" } };
  };
  static const std::map<std::string, std::vector<PLYColumn>> layouts = {
    { "positions", { plyX, plyY, plyZ } },
    { "RGB", { plyX, plyY, plyZ, red, green, blue } },
    { "RGBA", { plyX, plyY, plyZ, red, green, blue, alpha } },
    { "RGBA of uint8, float32", { PLYColumn{ "float32", "x", plyX.values }, plyY, plyZ,
                                  PLYColumn{ "uint8", "red", red.values }, green,
                                  PLYColumn{ "uint8", "blue", blue.values }, PLYColumn{ "uint8", "alpha", alpha.values } } },
    { "double coordinates, normals and texture coordinates",
      { PLYColumn{ "double", "x", { "0.1", "1", "16777217", "0", "0.5" } }, PLYColumn{ "float64", "y", plyY.values },
        PLYColumn{ "double", "z", { "0", "-0", "1e-40", "1e-3", "0.70710678118654752440" } },
        PLYColumn{ "double", "nx", nx.values }, ny, PLYColumn{ "float64", "nz", nz.values },
        PLYColumn{ "double", "u", u.values }, PLYColumn{ "double", "v", { "1", "0.25", "3.4028234e38", "3e-8", "7" } } } },
    { "everything, mixed up", { nx, alpha, plyX, skipped("float", "quality", true), plyY, plyZ, ny, nz, green, red,
                                blue, u, v, skipped("double", "confidence", true), skipped("float", "intensity", true) } },
    { "ignored properties of every type",
      { skipped("char", "a", true), plyX, skipped("int8", "b", true), skipped("uchar", "c", false),
        skipped("uint8", "d", false), skipped("short", "e", true), plyY, skipped("int16", "f", true),
        skipped("ushort", "g", false), skipped("uint16", "h", false), skipped("int", "i", true),
        skipped("int32", "j", true), plyZ, skipped("uint", "k", false), skipped("uint32", "l", false),
        skipped("float", "m", true), skipped("float32", "n", true), skipped("double", "o", true),
        skipped("float64", "p", true) } },
  };
  return layouts;
}
} // namespace

TEST(MeshFormats, PLYLayoutsBinaryAndASCIIAsVTKReadsThem)
{
  const TestFolder folder;
  for (const auto& layout : plyLayouts())
  {
    expectTakenAsVTKReadsIt(folder, "b.ply", plyFile(layout.second, "binary_little_endian"));
    expectTakenAsVTKReadsIt(folder, "big.ply", plyFile(layout.second, "binary_big_endian"));
    expectTakenAsVTKReadsIt(folder, "a.ply", plyFile(layout.second, "ascii"));
    expectTakenAsVTKReadsIt(folder, "crlf.ply", plyFile(layout.second, "ascii", "\r\n"));
    expectTakenAsVTKReadsIt(folder, "index.ply",
      plyFile(layout.second, "ascii", "\n", "property list uint8 uint32 vertex_index"));
  }
  // Colours as vtkPLYReader gives them: unsigned chars, "RGB" or "RGBA",
  // the active scalars, before the normals and texture coordinates.
  folder.write("m.ply", plyFile(plyLayouts().at("everything, mixed up"), "ascii"));
  EXPECT_EQ(pointArrayKinds(readShadeLab(folder.path("m.ply"))),
    (std::vector<std::string>{ "RGBA vtkUnsignedCharArray x4 scalars", "Normals vtkFloatArray x3 normals",
      "TCoords vtkFloatArray x2 tcoords" }));
}

TEST(MeshFormats, PLYWrittenByVTKAndShadeLabWithColoursAsVTKReadsIt)
{
  const TestFolder folder;
  vtkSmartPointer<vtkPolyData> mesh =
    texturedSphere(12, [](double i) { return std::array<double, 2>{ 0.1 * i, 1.0 / (i + 1) }; });
  for (int components : { 3, 4 })
  {
    vtkNew<vtkUnsignedCharArray> colours;
    colours->SetName(components == 3 ? "RGB" : "RGBA");
    colours->SetNumberOfComponents(components);
    colours->SetNumberOfTuples(mesh->GetNumberOfPoints());
    for (vtkIdType k = 0; k < colours->GetNumberOfValues(); ++k)
    {
      colours->SetValue(k, static_cast<unsigned char>((37 * k + 11) % 256));
    }
    mesh->GetPointData()->SetScalars(colours);
    for (bool binary : { true, false })
    {
      // vtkPLYWriter writes points, colours and texture coordinates.
      vtkNew<vtkPLYWriter> writer;
      writer->SetInputData(mesh);
      writer->SetFileName(folder.path("vtk.ply").c_str());
      binary ? writer->SetFileTypeToBinary() : writer->SetFileTypeToASCII();
      writer->SetArrayName(colours->GetName());
      writer->SetEnableAlpha(components == 4);
      writer->Write();
      const std::string what = std::to_string(components) + (binary ? " binary" : " ASCII");
      expectTakenAsVTKReadsIt(folder, "vtk.ply", contents(folder.path("vtk.ply")));
      EXPECT_NE(readShadeLab(folder.path("vtk.ply"))->GetPointData()->GetScalars(), nullptr) << what;
    }
    // ShadeLab writes normals too.
    vtkNew<slMeshWriter> ours;
    ours->SetInputData(mesh);
    ours->SetFileName(folder.path("shadelab.ply").c_str());
    ASSERT_EQ(callError(ours, [&] { return ours->Write(); }), "");
    expectTakenAsVTKReadsIt(folder, "shadelab.ply", contents(folder.path("shadelab.ply")));
    vtkSmartPointer<vtkPolyData> back = readShadeLab(folder.path("shadelab.ply"));
    ASSERT_NE(back->GetPointData()->GetScalars(), nullptr);
    EXPECT_EQ(back->GetPointData()->GetScalars()->GetTuple(7)[components - 1], colours->GetTuple(7)[components - 1]);
  }
}

namespace
{
/// An ASCII PLY file with the text forms vtkPLYReader reads alike: blanks
/// and tabs anywhere, CRLF and LF line ends, exponents, -0, a float
/// subnormal, a value on either side of which double and float rounding
/// part (x of vertex 2), trailing blank lines.
const char* const oddPLY = "ply\r\n"
                           "format ascii 1.0\r\n"
                           "comment odd but fine\r\n"
                           "element vertex 5\r\n"
                           "property float x\r\n"
                           "property float\ty\r\n"
                           "property float z\n"
                           "property uchar red\r\n"
                           "property uchar green\r\n"
                           "property uchar blue\r\n"
                           "property float quality\r\n"
                           "element face 3\r\n"
                           "property list uchar int vertex_indices\r\n"
                           "end_header\r\n"
                           "0 -0 0 255 0 0 1e300\r\n"
                           "  \t 2.5E+2\t-1e-3   .5 0 255 0 -7\t \r\n"
                           "1.00000005960464477539062500000001 1 0 0 0 255 0.5\n"
                           "5. 0001.5 1e-40 10 20 30 -0\r\n"
                           "3.4028235e38 -2.5e-300 0.1 40 50 60 3\r\n"
                           "3 0 1 4\r\n"
                           "3\t1 2 4 \r\n"
                           " 4 0 1 2 3\r\n"
                           "\r\n"
                           "  \n";
} // namespace

TEST(MeshFormats, PLYASCIITextFormsAsVTKReadsThem)
{
  const TestFolder folder;
  expectTakenAsVTKReadsIt(folder, "odd.ply", oddPLY);
  // VTK reads a float through a double: the text just above the float
  // midway between 1 and the next float rounds to that midway double, then
  // to the even float, 1; read straight to float it rounds up.
  vtkSmartPointer<vtkPolyData> vtk = readVTK<vtkPLYReader>(folder.path("odd.ply"));
  EXPECT_EQ(vtk->GetPoint(2)[0], 1.0);
  EXPECT_NE(std::strtof("1.00000005960464477539062500000001", nullptr), 1.0f);
  EXPECT_TRUE(std::signbit(vtk->GetPoint(0)[1]));
  EXPECT_EQ(vtk->GetPoint(3)[2], static_cast<double>(static_cast<float>(1e-40)));
  EXPECT_TRUE(std::signbit(vtk->GetPoint(4)[1]));
}

TEST(MeshFormats, PLYASCIIOnAnyThreadCountAsVTKReadsIt)
{
  // Over 1 MiB: parsed in stretches of lines, one per thread.
  const TestFolder folder;
  vtkSmartPointer<vtkPolyData> mesh =
    texturedSphere(150, [](double i) { return std::array<double, 2>{ 1.0 / (i + 3), 1e-3 * i }; });
  vtkNew<vtkPLYWriter> writer;
  writer->SetInputData(mesh);
  writer->SetFileName(folder.path("big.ply").c_str());
  writer->SetFileTypeToASCII();
  writer->Write();
  const std::string bytes = contents(folder.path("big.ply"));
  ASSERT_GT(bytes.size(), size_t(1) << 20);
  slMeshArrays one;
  ASSERT_TRUE(slParsePLY(bytes.data(), bytes.size(), one, 1));
  for (int threads : { 2, 3, 8 })
  {
    slMeshArrays more;
    ASSERT_TRUE(slParsePLY(bytes.data(), bytes.size(), more, threads)) << threads;
    EXPECT_TRUE(more.points == one.points && more.tcoords == one.tcoords && more.offsets == one.offsets &&
      more.connectivity == one.connectivity)
      << threads;
  }
  expectSamePLYMesh(readShadeLab(folder.path("big.ply")), readVTK<vtkPLYReader>(folder.path("big.ply")), "big");
}

TEST(MeshFormats, PLYOutsideTheCommonFormGoesToVTK)
{
  const TestFolder folder;
  const std::string good = "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\n"
                           "property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
                           "property float quality\nelement face 3\nproperty list uchar int vertex_indices\n"
                           "end_header\n"
                           "0 0 0 255 0 0 0.5\n"
                           "1 0 0 0 255 0 1.5\n"
                           "1 1 0 0 0 255 2.5\n"
                           "0 1 0 10 20 30 3.5\n"
                           "0.5 0.5 0.7 40 50 60 4.5\n"
                           "3 0 1 4\n"
                           "3 1 2 4\n"
                           "4 0 1 2 3\n";
  expectTakenAsVTKReadsIt(folder, "good.ply", good);
  // Each change of the good file it is declined for, and the first words of
  // slMeshReader's problem with it ("" if VTK reads it whole).
  struct Change
  {
    const char *what, *from, *to, *problem;
  };
  const std::string longRow = "1 0 0 0 255 0 1.5" + std::string(4000, ' ') + "\n";
  const Change changes[] = {
    { "missing value", "1 0 0 0 255 0 1.5\n", "1 0 0 0 255 0\n", "line 15 (element \"vertex\" row 2 of 5): fewer" },
    { "extra value", "1 0 0 0 255 0 1.5\n", "1 0 0 0 255 0 1.5 9\n", "" },
    { "extra index", "3 1 2 4\n", "3 1 2 4 0\n", "" },
    { "missing index", "4 0 1 2 3\n", "4 0 1 2\n", "line 21 (element \"face\" row 3 of 3): fewer" },
    { "fewer than 3 indices", "3 0 1 4\n", "2 0 1\n", "polygon 0 has fewer than 3 points" },
    { "index out of range", "3 1 2 4\n", "3 1 2 5\n", "line 20 (element \"face\" row 2 of 3): vertex index 5 is" },
    { "negative index", "3 1 2 4\n", "3 1 2 -4\n", "line 20 (element \"face\" row 2 of 3): vertex index -4 is" },
    { "index with an exponent", "3 1 2 4\n", "3 1 2 4e0\n", "line 20 (element \"face\" row 2 of 3): \"4e0\" is not" },
    { "letters after a number", "1 0 0 0 255 0 1.5\n", "1 0 0 0 255 0 1.5x\n", "line 15 (element \"vertex\" row 2 of 5): \"1.5x\"" },
    { "hexadecimal", "0.5 0.5 0.7", "0x1p-1 0.5 0.7", "" },
    { "plus sign", "0.5 0.5 0.7", "+0.5 0.5 0.7", "" },
    { "decimal comma", "0.5 0.5 0.7", "0,5 0.5 0.7", "line 18 (element \"vertex\" row 5 of 5): \"0,5\"" },
    { "exponent without digits", "0.5 0.5 0.7", "0.5 0.5 7e", "line 18 (element \"vertex\" row 5 of 5): \"7e\"" },
    { "not a number", "0.5 0.5 0.7", "nan 0.5 0.7", "point 4 has a NaN" },
    { "infinite", "0.5 0.5 0.7", "0.5 -inf 0.7", "point 4 has a NaN or infinite" },
    { "too large for a float", "0.5 0.5 0.7", "0.5 0.5 1e39", "point 4 has a NaN or infinite" },
    { "too small for a double", "0.5 0.5 0.7", "0.5 0.5 1e-320", "line 18 (element \"vertex\" row 5 of 5): \"1e-320\"" },
    { "colour of 256", "40 50 60", "40 256 60", "" },
    { "negative colour", "40 50 60", "40 -1 60", "" },
    { "fractional colour", "40 50 60", "40 50.0 60", "line 18 (element \"vertex\" row 5 of 5): \"50.0\" is not" },
    { "skipped value not a number", "4.5\n", "four\n", "line 18 (element \"vertex\" row 5 of 5): \"four\"" },
    { "skipped value infinite", "4.5\n", "inf\n", "" },
    { "blank line between rows", "1 1 0 0 0 255 2.5\n", "\n1 1 0 0 0 255 2.5\n", "line 16 (element \"vertex\" row 3 of 5): fewer" },
    { "no newline at the end", "4 0 1 2 3\n", "4 0 1 2 3", "line 21 (element \"face\" row 3 of 3): no newline" },
    { "form feed between values", "1 1 0 0 0 255 2.5\n", "1\f1 0 0 0 255 2.5\n", "line 16 (element \"vertex\" row 3 of 5): \"1\\x0C1\" is not" },
    { "carriage return within a row", "1 1 0 0 0 255 2.5\n", "1\r1 0 0 0 255 2.5\n", "" },
    { "row of 4017 bytes", "1 0 0 0 255 0 1.5\n", longRow.c_str(), "line 15 (element \"vertex\" row 2 of 5): longer" },
    { "text after the last row", "4 0 1 2 3\n", "4 0 1 2 3\nend\n", "" },
    { "fewer rows than the header says", "element face 3", "element face 4", "line 22: the file ends before" },
    { "a colour of another type", "property uchar green", "property float green", "" },
    { "colours in part", "property uchar blue", "property uchar quality2", "" },
    { "colours from diffuse_red ...", "uchar red\nproperty uchar green\nproperty uchar blue",
      "uchar diffuse_red\nproperty uchar diffuse_green\nproperty uchar diffuse_blue", "" },
    { "integer coordinates", "property float x", "property int x", "line 18 (element \"vertex\" row 5 of 5): \"0.5\"" },
    { "a list among the vertex properties", "property float quality", "property list uchar float quality",
      "line 14 (element \"vertex\" row 1 of 5): list count \"0.5\"" },
    { "a face property besides the indices", "vertex_indices\n", "vertex_indices\nproperty uchar red\n",
      "line 20 (element \"face\" row 1 of 3): fewer values than \"red\"" },
  };
  for (const Change& change : changes)
  {
    std::string bytes = good;
    const size_t at = bytes.find(change.from);
    ASSERT_NE(at, std::string::npos) << change.what;
    bytes.replace(at, std::strlen(change.from), change.to);
    slMeshArrays arrays;
    EXPECT_FALSE(slParsePLY(bytes.data(), bytes.size(), arrays, 1)) << change.what;
    // As before: through the file check and vtkPLYReader.
    folder.write("changed.ply", bytes);
    vtkNew<slMeshReader> reader;
    reader->SetFileName(folder.path("changed.ply").c_str());
    const std::string problem = updateError(reader);
    if (*change.problem)
    {
      EXPECT_NE(problem.find(change.problem), std::string::npos) << change.what << ": " << problem;
    }
    else
    {
      EXPECT_EQ(problem, "") << change.what;
      expectSamePLYMesh(reader->GetOutput(), readVTK<vtkPLYReader>(folder.path("changed.ply")), change.what);
    }
  }
}

TEST(MeshFormats, PLYBinaryDoublesWithoutAFloatGoToVTK)
{
  // A double beyond the largest float, or NaN, has no float C++ converts it
  // to: the parser declines the file, and the point check reports it after
  // vtkPLYReader, which stores infinity or NaN.
  const TestFolder folder;
  for (const char* format : { "binary_little_endian", "binary_big_endian" })
  {
    for (const char* value : { "1e39", "-1e300", "inf", "nan" })
    {
      const std::string bytes =
        plyFile({ PLYColumn{ "double", "x", { "0", "1", "1", "0", value } }, plyY, plyZ }, format);
      slMeshArrays arrays;
      EXPECT_FALSE(slParsePLY(bytes.data(), bytes.size(), arrays, 1)) << format << " " << value;
      folder.write("wide.ply", bytes);
      vtkNew<slMeshReader> reader;
      reader->SetFileName(folder.path("wide.ply").c_str());
      const std::string problem = updateError(reader);
      EXPECT_NE(problem.find("point 4 has a NaN or infinite"), std::string::npos)
        << format << " " << value << ": " << problem;
    }
  }
}

TEST(MeshFormats, WrittenOBJAndPLYReadBackBitForBit)
{
  const TestFolder folder;
  vtkSmartPointer<vtkPolyData> mesh =
    texturedSphere(11, [](double i) { return std::array<double, 2>{ 1.0 / 3.0 + i, 1e-7 * i }; });
  vtkDataArray* uv = mesh->GetPointData()->GetTCoords();
  for (const char* name : { "m.obj", "m.ply" })
  {
    vtkNew<slMeshWriter> writer;
    writer->SetInputData(mesh);
    writer->SetFileName(folder.path(name).c_str());
    ASSERT_EQ(callError(writer, [&] { return writer->Write(); }), "");
    const std::string bytes = contents(folder.path(name));
    slMeshArrays arrays;
    slOBJAttributes attributes;
    EXPECT_TRUE(std::string(name) == "m.obj" ? slParseOBJ(bytes.data(), bytes.size(), false, arrays, attributes, 1)
                                             : slParsePLY(bytes.data(), bytes.size(), arrays, 1));
    vtkNew<slMeshReader> reader;
    reader->SetFileName(folder.path(name).c_str());
    reader->MergeDuplicatePointsOff();
    reader->Update();
    vtkPolyData* back = reader->GetOutput();
    ASSERT_EQ(back->GetNumberOfPoints(), mesh->GetNumberOfPoints()) << name;
    for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    {
      double a[3], b[3];
      mesh->GetPoint(i, a);
      back->GetPoint(i, b);
      ASSERT_EQ(std::vector<double>(a, a + 3), std::vector<double>(b, b + 3)) << name << " point " << i;
      ASSERT_EQ(back->GetPointData()->GetNormals()->GetTuple3(i)[1], mesh->GetPointData()->GetNormals()->GetTuple3(i)[1]);
      ASSERT_EQ(back->GetPointData()->GetTCoords()->GetTuple2(i)[0], uv->GetTuple2(i)[0]) << name;
      ASSERT_EQ(back->GetPointData()->GetTCoords()->GetTuple2(i)[1], uv->GetTuple2(i)[1]) << name;
    }
    EXPECT_EQ(merged(back).polygons, merged(mesh).polygons) << name;
  }
  // VTK reads ShadeLab's OBJ to the same values.
  const Merged vtk = merged(readVTK<vtkOBJReader>(folder.path("m.obj")));
  const Merged own = merged(readShadeLab(folder.path("m.obj")));
  EXPECT_EQ(vtk.rows, own.rows);
}

namespace
{
/// A grid of @p n x @p n points in the plane z = 0, with normals, as
/// triangles, viewed for slFormatOBJ (the arrays live in @p storage).
slMeshView gridView(int n, slMeshArrays& storage)
{
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      storage.points.insert(storage.points.end(), { i / 7.0f, j / 3.0f, 0.0f });
      storage.normals.insert(storage.normals.end(), { 0.0f, 0.0f, 1.0f });
    }
  }
  storage.offsets.push_back(0);
  for (int j = 0; j + 1 < n; ++j)
  {
    for (int i = 0; i + 1 < n; ++i)
    {
      const std::int64_t p = j * n + i;
      for (std::int64_t corner : { p, p + 1, p + n + 1, p, p + n + 1, p + n })
      {
        storage.connectivity.push_back(corner);
      }
      storage.offsets.push_back(static_cast<std::int64_t>(storage.connectivity.size()) - 3);
      storage.offsets.push_back(static_cast<std::int64_t>(storage.connectivity.size()));
    }
  }
  slMeshView view;
  view.numberOfPoints = static_cast<std::int64_t>(storage.points.size() / 3);
  view.numberOfPolygons = static_cast<std::int64_t>(storage.offsets.size()) - 1;
  view.points.data = storage.points.data();
  view.normals.data = storage.normals.data();
  view.offsets.data = storage.offsets.data();
  view.connectivity.data = storage.connectivity.data();
  return view;
}
} // namespace

TEST(MeshFormats, OBJIsWrittenInOrderPieceByPiece)
{
  // 360k points: their v and vn lines, and the faces, each take more than
  // one piece (256k lines).
  slMeshArrays storage;
  const slMeshView mesh = gridView(600, storage);
  std::map<int, std::vector<std::string>> calls;
  for (int threads : { 1, 2, 4 })
  {
    slFormatOBJ(
      mesh, [&](const char* data, std::size_t size) { calls[threads].emplace_back(data, size); }, threads);
  }
  ASSERT_GE(calls[1].size(), 6u);
  EXPECT_EQ(calls[2], calls[1]);
  EXPECT_EQ(calls[4], calls[1]);
  std::string text;
  for (const std::string& piece : calls[1])
  {
    ASSERT_FALSE(piece.empty());
    ASSERT_EQ(piece.back(), '\n');
    text += piece;
  }
  // The joined text reads back to the mesh, line for line.
  slMeshArrays back;
  slOBJAttributes attributes;
  ASSERT_TRUE(slParseOBJ(text.data(), text.size(), false, back, attributes, 1));
  EXPECT_EQ(back.points, storage.points);
  EXPECT_EQ(back.normals, storage.normals);
  EXPECT_EQ(back.offsets, storage.offsets);
  EXPECT_EQ(back.connectivity, storage.connectivity);
  EXPECT_EQ(text.rfind("v ", 0), 0u);
  EXPECT_EQ(text.substr(text.rfind('\n', text.size() - 2) + 1), "f 359399//359399 360000//360000 359999//359999\n");
}

TEST(MeshFormats, OBJStopsAtTheFirstFailedPieceAndSaysWhy)
{
  slMeshArrays storage;
  const slMeshView mesh = gridView(600, storage);
  for (int threads : { 1, 2, 4 })
  {
    int calls = 0;
    const auto failThird = [&](const char*, std::size_t) {
      if (++calls == 3)
      {
        throw std::runtime_error("disk full");
      }
    };
    try
    {
      slFormatOBJ(mesh, failThird, threads);
      ADD_FAILURE() << "no exception on " << threads << " threads";
    }
    catch (const std::runtime_error& e)
    {
      EXPECT_STREQ(e.what(), "disk full");
    }
    EXPECT_EQ(calls, 3) << threads << " threads";
  }
}

namespace
{
/// An OBJ grid of n x n points over 1 MiB (so that 2 and 4 threads parse it
/// in stretches): "v" and "vn" lines in @p points, and in @p faces a
/// triangle per grid cell whose corners name one index for v and vn.
/// Returns the number of faces.
int objGrid(int n, std::string& points, std::string& faces)
{
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      points += "v " + std::to_string(i) + " " + std::to_string(j) + " 0.125\n";
      points += "vn 0 " + std::to_string(0.5 + i % 3) + " 1\n";
    }
  }
  int faceCount = 0;
  for (int j = 0; j + 1 < n; ++j)
  {
    for (int i = 0; i + 1 < n; ++i, ++faceCount)
    {
      const std::string a = std::to_string(j * n + i + 1), b = std::to_string(j * n + i + 2),
                        c = std::to_string(j * n + i + n + 2);
      faces += "f " + a + "//" + a + " " + b + "//" + b + " " + c + "//" + c + "\n";
    }
  }
  return faceCount;
}

/// Parses @p text on 2 and 4 threads and expects every array as @p one
/// (parsed on 1 thread) has it.
void expectSameOnMoreThreads(const std::string& text, const slMeshArrays& one, const char* what)
{
  for (int threads : { 2, 4 })
  {
    slMeshArrays many;
    slOBJAttributes attributes;
    ASSERT_TRUE(slParseOBJ(text.data(), text.size(), false, many, attributes, threads)) << what;
    EXPECT_EQ(many.points, one.points) << what << ", " << threads << " threads";
    EXPECT_EQ(many.normals, one.normals) << what << ", " << threads << " threads";
    EXPECT_EQ(many.offsets, one.offsets) << what << ", " << threads << " threads";
    EXPECT_EQ(many.connectivity, one.connectivity) << what << ", " << threads << " threads";
    EXPECT_EQ(many.lineSizes, one.lineSizes) << what << ", " << threads << " threads";
    EXPECT_EQ(many.vertexSizes, one.vertexSizes) << what << ", " << threads << " threads";
  }
}
} // namespace

TEST(MeshFormats, OBJLinesPointsAndFacesOfSeveralFormsReadAlikeOnAnyThreadCount)
{
  // Over 1 MiB, so that 2 and 4 threads parse it in stretches: a grid whose
  // faces name one index for v and vn, an "l" and a "p" element, and a face
  // without vn first or last, with or without a face whose corner takes
  // another point's normal.
  const int n = 150;
  std::string points, faces;
  objGrid(n, points, faces);
  const std::string elements = "l 1 2 3\np 4 5\n", bare = "f 1 2 152\n", odd = "f 1//2 2//2 152//152\n";
  struct Case
  {
    const char* what;
    std::string text;
    bool normals; // kept: the v list's, or none (a point per corner would lack one)
  };
  const Case cases[] = { { "bare face last", points + elements + faces + bare, true },
    { "bare face first", points + bare + faces + elements, true },
    { "bare and odd faces", points + odd + faces + elements + bare, false } };
  for (const Case& c : cases)
  {
    ASSERT_GT(c.text.size(), size_t(1) << 20);
    slMeshArrays one;
    slOBJAttributes attributes;
    ASSERT_TRUE(slParseOBJ(c.text.data(), c.text.size(), false, one, attributes, 1)) << c.what;
    // The v list's points, lines and vertex cells naming them after the faces.
    ASSERT_EQ(one.points.size(), size_t(3 * n * n)) << c.what;
    EXPECT_EQ(one.normals.size(), c.normals ? one.points.size() : 0u) << c.what;
    EXPECT_EQ(one.lineSizes, std::vector<std::int64_t>({ 3 })) << c.what;
    EXPECT_EQ(one.vertexSizes, std::vector<std::int64_t>({ 2 })) << c.what;
    const std::vector<std::int64_t> elementIds(one.connectivity.end() - 5, one.connectivity.end());
    EXPECT_EQ(elementIds, std::vector<std::int64_t>({ 0, 1, 2, 3, 4 })) << c.what;
    EXPECT_EQ(static_cast<size_t>(one.offsets.back()) + 5, one.connectivity.size()) << c.what;
    expectSameOnMoreThreads(c.text, one, c.what);
  }
}

TEST(MeshFormats, OBJCornersNamingOtherNormalsReadAlikeOnAnyThreadCount)
{
  // Over 1 MiB, so that 2 and 4 threads parse it in stretches. Every face
  // names one index for v and vn, except, in some cases, the first or the
  // last face, whose first corner takes the second point's normal.
  const int n = 150;
  std::string points, faces;
  const int faceCount = objGrid(n, points, faces);
  const std::string odd = "f 1//2 2//2 152//152\n"; // point 1 with point 2's normal (0, 1.5, 1)
  const std::pair<const char*, std::string> cases[] = { { "same everywhere", points + faces },
    { "odd first face", points + odd + faces }, { "odd last face", points + faces + odd } };
  for (const auto& [what, text] : cases)
  {
    ASSERT_GT(text.size(), size_t(1) << 20);
    slMeshArrays one;
    slOBJAttributes attributes;
    ASSERT_TRUE(slParseOBJ(text.data(), text.size(), false, one, attributes, 1)) << what;
    const bool odd = std::string(what) != "same everywhere";
    const size_t corners = 3 * static_cast<size_t>(faceCount + (odd ? 1 : 0));
    // vtkOBJReader's points: the v list when every corner names one index,
    // else one point per corner.
    ASSERT_EQ(one.points.size(), odd ? 3 * corners : size_t(3 * n * n)) << what;
    ASSERT_EQ(one.normals.size(), one.points.size()) << what;
    if (odd)
    {
      const size_t k = std::string(what) == "odd first face" ? 0 : corners - 3;
      EXPECT_EQ(std::vector<float>(one.points.begin() + 3 * k, one.points.begin() + 3 * k + 3),
        std::vector<float>({ 0.0f, 0.0f, 0.125f })) << what;
      EXPECT_EQ(std::vector<float>(one.normals.begin() + 3 * k, one.normals.begin() + 3 * k + 3),
        std::vector<float>({ 0.0f, 1.5f, 1.0f })) << what;
      // The next corner names point 2 and its own normal.
      EXPECT_EQ(one.normals[3 * k + 4], 1.5f) << what;
    }
    expectSameOnMoreThreads(text, one, what);
  }
}

TEST(MeshFormats, OBJGroupsAndMaterialsReadAlikeOnAnyThreadCount)
{
  // Over 1 MiB, so that 2 and 4 threads parse it in stretches, which then
  // begin and end between "g" and "usemtl" lines and the faces they apply
  // to: a group every 1000 faces (the first before the first face), a
  // material every 1500 faces, of three names in turn, and halfway a face of
  // plain "v" corners (vtkOBJReader's material NO_MATERIAL from there on).
  const int n = 150;
  std::string points, faces;
  const int faceCount = objGrid(n, points, faces);
  std::istringstream lines(faces);
  std::string text = "mtllib grid.mtl\no grid\n" + points, line;
  for (int face = 0; std::getline(lines, line); ++face)
  {
    if (face % 1000 == 0)
    {
      text += "g part " + std::to_string(face / 1000) + "\n";
    }
    if (face % 1500 == 700)
    {
      text += std::string("usemtl ") + "abc"[(face / 1500) % 3] + "\n";
    }
    if (face == faceCount / 2)
    {
      text += "f 1 2 152\n";
    }
    text += line + "\ns 1\n";
  }
  text += "mtllib more.mtl\n";
  ASSERT_GT(text.size(), size_t(1) << 20);
  slMeshArrays one;
  slOBJAttributes attributes;
  ASSERT_TRUE(slParseOBJ(text.data(), text.size(), false, one, attributes, 1));
  ASSERT_EQ(attributes.groupIds.size(), size_t(faceCount + 1));
  ASSERT_EQ(attributes.materialIds.size(), size_t(faceCount + 1));
  // A face's group: the "g" lines before it, less the one before the first
  // face; its material: id 0 before the first "usemtl" line, then a, b, c
  // numbered in order of appearance.
  for (const int face : { 0, 999, 1000, 2500, 10999 })
  {
    EXPECT_EQ(attributes.groupIds[static_cast<size_t>(face)], static_cast<float>(face / 1000)) << face;
  }
  for (const auto& [face, id] : std::map<int, std::int32_t>{ { 0, 0 }, { 699, 0 }, { 700, 0 }, { 2199, 0 },
         { 2200, 1 }, { 3700, 2 }, { 5200, 0 }, { 6700, 1 } })
  {
    EXPECT_EQ(attributes.materialIds[static_cast<size_t>(face)], id) << face;
  }
  EXPECT_EQ(std::vector<std::string>(attributes.materialNames.begin(), attributes.materialNames.begin() + 4),
    std::vector<std::string>({ "a", "b", "c", "NO_MATERIAL" }));
  EXPECT_EQ(attributes.materialLibraries, std::vector<std::string>({ "grid.mtl", "more.mtl" }));
  for (int threads : { 2, 4 })
  {
    slMeshArrays many;
    slOBJAttributes more;
    ASSERT_TRUE(slParseOBJ(text.data(), text.size(), false, many, more, threads));
    EXPECT_EQ(more.groupIds, attributes.groupIds) << threads << " threads";
    EXPECT_EQ(more.materialIds, attributes.materialIds) << threads << " threads";
    EXPECT_EQ(more.materialNames, attributes.materialNames) << threads << " threads";
    EXPECT_EQ(more.materialLibraries, attributes.materialLibraries) << threads << " threads";
    EXPECT_EQ(many.connectivity, one.connectivity) << threads << " threads";
  }
  // Every value as vtkOBJReader gives it.
  const TestFolder folder;
  folder.write("grid.obj", text);
  expectSameCellAndFieldData(readShadeLab(folder.path("grid.obj")), readVTK<vtkOBJReader>(folder.path("grid.obj")),
    "grid");
}

namespace
{
/// An OBJ grid of @p n x @p n points, each with a vt and a vn, and a
/// triangle per grid cell whose corners name one index for v, vt and vn,
/// or, if @p byCorner, whose first corner names the next point's vt (then
/// vtkOBJReader makes a point per corner). The faces take @p materials
/// names (m0, m1, ...) in turn: a "usemtl" line every @p run faces from
/// face run / 2 on, the first after a material without faces ("empty");
/// the file ends in "usemtl last", which the faces before the first
/// "usemtl" line then take in vtkOBJReader.
std::string texturedGrid(int n, int materials, int run, bool byCorner)
{
  std::string points, faces;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      points += "v " + std::to_string(i) + " " + std::to_string(j) + " 0\n";
      points += "vt " + std::to_string(i * 0.125) + " " + std::to_string(j * 0.25) + "\n";
      points += "vn 0 " + std::to_string(i % 2) + " 1\n";
    }
  }
  for (int j = 0, face = 0; j + 1 < n; ++j)
  {
    for (int i = 0; i + 1 < n; ++i, ++face)
    {
      if (face % run == run / 2)
      {
        faces += std::string(face == run / 2 ? "usemtl empty\n" : "") + "usemtl m" +
          std::to_string(face / run % materials) + "\n";
      }
      const std::string a = std::to_string(j * n + i + 1), b = std::to_string(j * n + i + 2),
                        c = std::to_string(j * n + i + n + 2);
      faces += "f " + a + "/" + (byCorner ? b : a) + "/" + a + " " + b + "/" + b + "/" + b + " " + c + "/" + c + "/" +
        c + "\n";
    }
  }
  return points + faces + "usemtl last\n";
}
} // namespace

TEST(MeshFormats, OBJTextureCoordinatesOfManyMaterialsAsVTKReadsThem)
{
  // vtkOBJReader's array of texture coordinates per material name, in the
  // order of its hash table: not that in which the names appear, nor its
  // reverse, from ten names on.
  const TestFolder folder;
  for (const int materials : { 2, 3, 10, 50 })
  {
    std::vector<std::string> appearance{ "empty" };
    for (int m = 0; m < materials; ++m)
    {
      appearance.push_back("m" + std::to_string(m));
    }
    appearance.emplace_back("last");
    for (const bool byCorner : { false, true })
    {
      const std::string what = std::to_string(materials) + " materials" + (byCorner ? ", by corner" : "");
      const std::string text = texturedGrid(12, materials, 2, byCorner);
      folder.write("m.obj", text);
      std::vector<std::string> names = arrayNames(readVTK<vtkOBJReader>(folder.path("m.obj")));
      ASSERT_EQ(names.size(), appearance.size() + 1) << what;
      EXPECT_EQ(names.back(), "Normals") << what;
      names.pop_back();
      if (materials >= 10)
      {
        EXPECT_NE(names, appearance) << what;
        EXPECT_NE(names, std::vector<std::string>(appearance.rbegin(), appearance.rend())) << what;
      }
      slMeshArrays arrays;
      slOBJAttributes attributes;
      ASSERT_TRUE(slParseOBJ(text.data(), text.size(), true, arrays, attributes, 1)) << what;
      EXPECT_EQ(attributes.tcoordsNames, names) << what;
      expectOBJAsVTKReadsIt(folder.path("m.obj"), what);
    }
  }
}

TEST(MeshFormats, OBJTextureCoordinatesOfSeveralMaterialsReadAlikeOnAnyThreadCount)
{
  // Over 1 MiB, so that 2 and 4 threads parse it in stretches, which then
  // begin and end between "usemtl" lines and the faces they apply to: three
  // materials in turn every 1500 faces, whose arrays hold the points of
  // one material's faces, or of two where they meet.
  const TestFolder folder;
  for (const bool byCorner : { false, true })
  {
    const std::string what = byCorner ? "by corner" : "of the v list";
    const std::string text = texturedGrid(150, 3, 1500, byCorner);
    ASSERT_GT(text.size(), size_t(1) << 20);
    slMeshArrays one;
    slOBJAttributes attributes;
    ASSERT_TRUE(slParseOBJ(text.data(), text.size(), true, one, attributes, 1)) << what;
    EXPECT_EQ(attributes.tcoordsNames.size(), 5u) << what;
    EXPECT_GT(attributes.tcoordsSets.size(), 2u) << what;
    EXPECT_EQ(attributes.pointTCoordsSets.size(), one.points.size() / 3) << what;
    for (int threads : { 2, 4 })
    {
      slMeshArrays many;
      slOBJAttributes more;
      ASSERT_TRUE(slParseOBJ(text.data(), text.size(), true, many, more, threads)) << what;
      EXPECT_EQ(many.points, one.points) << what << ", " << threads << " threads";
      EXPECT_EQ(many.tcoords, one.tcoords) << what << ", " << threads << " threads";
      EXPECT_EQ(many.normals, one.normals) << what << ", " << threads << " threads";
      EXPECT_EQ(many.connectivity, one.connectivity) << what << ", " << threads << " threads";
      EXPECT_EQ(more.tcoordsNames, attributes.tcoordsNames) << what << ", " << threads << " threads";
      EXPECT_EQ(more.tcoordsSets, attributes.tcoordsSets) << what << ", " << threads << " threads";
      EXPECT_EQ(more.pointTCoordsSets, attributes.pointTCoordsSets) << what << ", " << threads << " threads";
      EXPECT_EQ(more.materialIds, attributes.materialIds) << what << ", " << threads << " threads";
    }
    folder.write("grid.obj", text);
    expectOBJAsVTKReadsIt(folder.path("grid.obj"), what);
  }
}

TEST(MeshFormats, OBJGroupsOfLinesAndPointsAreTheOnesVTKsReaderIsGiven)
{
  // vtkOBJReader 9.1 gives the faces only a group; slMeshReader gives the
  // lines and vertex cells, which VTK orders first, the group -1, whichever
  // parser reads the file.
  const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\ng a\nf 1 2 3\nl 1 2\ng b\nf 1 2 4\np 3\nl 2 3\n";
  slMeshArrays arrays;
  slOBJAttributes attributes;
  ASSERT_TRUE(slParseOBJ(text.data(), text.size(), true, arrays, attributes, 1));
  const TestFolder folder;
  folder.write("g.obj", text);
  vtkSmartPointer<vtkPolyData> theirs = readVTK<vtkOBJReader>(folder.path("g.obj"));
  vtkDataArray* faceGroups = theirs->GetCellData()->GetArray("GroupIds");
  ASSERT_NE(faceGroups, nullptr);
  ASSERT_EQ(faceGroups->GetNumberOfTuples(), 2);
  std::vector<double> expected(3, -1.0);
  expected.push_back(faceGroups->GetTuple1(0));
  expected.push_back(faceGroups->GetTuple1(1));
  vtkSmartPointer<vtkPolyData> ours = readShadeLab(folder.path("g.obj"));
  vtkDataArray* groups = ours->GetCellData()->GetArray("GroupIds");
  ASSERT_NE(groups, nullptr);
  std::vector<double> got;
  for (vtkIdType c = 0; c < groups->GetNumberOfTuples(); ++c)
  {
    got.push_back(groups->GetTuple1(c));
  }
  EXPECT_EQ(got, expected);
  EXPECT_EQ(expected, std::vector<double>({ -1, -1, -1, 0, 1 }));
}

TEST(MeshFormats, LegacyVTKIdAndStringArraysReadAsVTKReadsThem)
{
  // vtkDataWriter writes vtkIdType as 32-bit int, and binary strings each
  // after a length of 1, 2, 4 or 8 bytes: ShadeLab's check refused both.
  const TestFolder folder;
  vtkNew<vtkSphereSource> source;
  source->Update();
  vtkNew<vtkPolyData> mesh;
  mesh->DeepCopy(source->GetOutput());
  const vtkIdType points = mesh->GetNumberOfPoints(), cells = mesh->GetNumberOfCells();
  vtkNew<vtkIdTypeArray> ids;
  ids->SetName("ids");
  for (vtkIdType i = 0; i < points; ++i)
  {
    ids->InsertNextValue(i * 1000 - 7);
  }
  mesh->GetPointData()->AddArray(ids);
  {
    vtkNew<slMeshWriter> idsOnly;
    idsOnly->SetInputData(mesh);
    idsOnly->SetFileName(folder.path("ids.vtk").c_str());
    ASSERT_EQ(callError(idsOnly, [&] { return idsOnly->Write(); }), "");
    vtkSmartPointer<vtkPolyData> read = readShadeLab(folder.path("ids.vtk"));
    auto* readIds = vtkIdTypeArray::SafeDownCast(read->GetPointData()->GetAbstractArray("ids"));
    ASSERT_NE(readIds, nullptr);
    ASSERT_EQ(readIds->GetNumberOfValues(), points);
    EXPECT_EQ(readIds->GetValue(points - 1), (points - 1) * 1000 - 7);
  }
  vtkNew<vtkStringArray> names;
  names->SetName("names");
  for (vtkIdType c = 0; c < cells; ++c)
  {
    // Empty, short, and past the 1-byte (63) and 2-byte (16383) lengths.
    const size_t length = c == 1 ? 70 : c == 2 ? 17000 : static_cast<size_t>(c % 5);
    names->InsertNextValue(std::string(length, static_cast<char>('a' + c % 26)));
  }
  mesh->GetCellData()->AddArray(names);
  vtkNew<vtkStringArray> notes;
  notes->SetName("notes");
  notes->SetNumberOfComponents(2);
  for (const char* note : { "first note", "100% sure", "x", "" })
  {
    notes->InsertNextValue(note);
  }
  mesh->GetFieldData()->AddArray(notes);
  vtkNew<slMeshWriter> ours;
  ours->SetInputData(mesh);
  ours->SetFileName(folder.path("b.vtk").c_str());
  ASSERT_EQ(callError(ours, [&] { return ours->Write(); }), "");
  vtkNew<vtkPolyDataWriter> ascii;
  ascii->SetInputData(mesh);
  ascii->SetFileName(folder.path("a.vtk").c_str());
  ascii->SetFileTypeToASCII();
  ASSERT_EQ(ascii->Write(), 1);
  for (const char* name : { "b.vtk", "a.vtk" })
  {
    vtkSmartPointer<vtkPolyData> read = readShadeLab(folder.path(name));
    vtkSmartPointer<vtkPolyData> expected = readVTK<vtkPolyDataReader>(folder.path(name));
    ASSERT_EQ(read->GetNumberOfPoints(), points) << name;
    auto* readIds = vtkIdTypeArray::SafeDownCast(read->GetPointData()->GetAbstractArray("ids"));
    auto* readNames = vtkStringArray::SafeDownCast(read->GetCellData()->GetAbstractArray("names"));
    auto* readNotes = vtkStringArray::SafeDownCast(read->GetFieldData()->GetAbstractArray("notes"));
    ASSERT_TRUE(readIds && readNames && readNotes) << name;
    for (vtkIdType i = 0; i < points; ++i)
    {
      EXPECT_EQ(readIds->GetValue(i), ids->GetValue(i)) << name;
    }
    ASSERT_EQ(readNames->GetNumberOfValues(), cells) << name;
    for (vtkIdType c = 0; c < cells; ++c)
    {
      EXPECT_EQ(readNames->GetValue(c), names->GetValue(c)) << name << " cell " << c;
    }
    ASSERT_EQ(readNotes->GetNumberOfComponents(), 2) << name;
    ASSERT_EQ(readNotes->GetNumberOfValues(), 4) << name;
    for (vtkIdType v = 0; v < 4; ++v)
    {
      EXPECT_EQ(readNotes->GetValue(v), notes->GetValue(v)) << name;
      EXPECT_EQ(readNotes->GetValue(v),
        vtkStringArray::SafeDownCast(expected->GetFieldData()->GetAbstractArray("notes"))->GetValue(v))
        << name;
    }
  }
}
