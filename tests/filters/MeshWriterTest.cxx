// slMeshWriter: every format reads back through slMeshReader; failures are clean.
#include "TestFolder.h"

#include "slMeshReader.h"
#include "slMeshWriter.h"
#include "VTKErrors.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPLYReader.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPoints.h>
#include <vtkSphereSource.h>
#include <vtkUnsignedCharArray.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <vector>

TEST(MeshWriter, EveryFormatReadsBack)
{
  const TestFolder folder;
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(10);
  sphere->SetPhiResolution(6);
  sphere->Update();
  vtkPolyData* mesh = sphere->GetOutput();
  for (const char* name : { "s.vtp", "s.vtk", "s.ply", "s.obj", "s.stl" })
  {
    vtkNew<slMeshWriter> writer;
    writer->SetInputData(mesh);
    writer->SetFileName(folder.path(name).c_str());
    ASSERT_EQ(callError(writer, [&] { return writer->Write(); }), "");
    vtkNew<slMeshReader> reader;
    reader->SetFileName(folder.path(name).c_str());
    EXPECT_EQ(updateError(reader), "") << name;
    EXPECT_EQ(reader->GetOutput()->GetNumberOfPolys(), mesh->GetNumberOfPolys()) << name;
  }
  // VTP keeps the normals array.
  vtkNew<slMeshReader> reader;
  reader->SetFileName(folder.path("s.vtp").c_str());
  reader->Update();
  EXPECT_NE(reader->GetOutput()->GetPointData()->GetNormals(), nullptr);
}

TEST(MeshWriter, EveryVTPCompressionReadsBackExactly)
{
  const TestFolder folder;
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(200);
  sphere->SetPhiResolution(100);
  sphere->Update();
  vtkPolyData* mesh = sphere->GetOutput();
  // What VTK writes in the file's header for each, and the file sizes.
  const std::pair<int, const char*> cases[] = { { slMeshWriter::NONE, nullptr },
    { slMeshWriter::LZ4, "compressor=\"vtkLZ4DataCompressor\"" },
    { slMeshWriter::ZLIB, "compressor=\"vtkZLibDataCompressor\"" } };
  std::map<int, std::uintmax_t> sizes;
  for (const auto& [compression, header] : cases)
  {
    const std::string name = slMeshWriter::GetCompressionName(compression);
    EXPECT_EQ(slMeshWriter::GetCompressionByName(name), compression);
    const std::string path = folder.path(name + ".vtp");
    vtkNew<slMeshWriter> writer;
    writer->SetCompression(compression);
    writer->SetInputData(mesh);
    writer->SetFileName(path.c_str());
    ASSERT_EQ(callError(writer, [&] { return writer->Write(); }), "");
    std::ifstream file(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    const std::string start = bytes.substr(0, 400);
    EXPECT_EQ(start.find("compressor="), header ? start.find(header) : std::string::npos) << name;
    EXPECT_NE(bytes.find("<AppendedData encoding=\"raw\">"), std::string::npos) << name << ": not raw appended data";
    sizes[compression] = std::filesystem::file_size(path);

    vtkNew<slMeshReader> reader;
    reader->SetFileName(path.c_str());
    ASSERT_EQ(updateError(reader), "") << name;
    vtkPolyData* back = reader->GetOutput();
    ASSERT_EQ(back->GetNumberOfPoints(), mesh->GetNumberOfPoints()) << name;
    for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); i += 97)
    {
      double a[3], b[3];
      mesh->GetPoint(i, a);
      back->GetPoint(i, b);
      EXPECT_EQ(a[0], b[0]);
      EXPECT_EQ(a[1], b[1]);
      EXPECT_EQ(a[2], b[2]);
    }
  }
  EXPECT_LT(sizes[slMeshWriter::ZLIB], sizes[slMeshWriter::LZ4]);
  EXPECT_LT(sizes[slMeshWriter::LZ4], sizes[slMeshWriter::NONE]);
  EXPECT_EQ(slMeshWriter::GetCompressionByName("gzip"), -1);
  EXPECT_EQ(slMeshWriter::GetCompressionName(7), nullptr);
}

TEST(MeshWriter, FailuresAreCleanAndNamed)
{
  const TestFolder folder;
  folder.write("keep.vtp", "old");
  vtkNew<vtkPolyData> empty;
  vtkNew<slMeshWriter> writer;
  writer->SetInputData(empty);
  writer->SetFileName(folder.path("keep.vtp").c_str());
  EXPECT_EQ(callError(writer, [&] { return writer->Write(); }), folder.path("keep.vtp") + ": nothing to write (empty mesh)");
  std::ifstream in(folder.path("keep.vtp"));
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "old");

  vtkNew<vtkSphereSource> sphere;
  sphere->Update();
  writer->SetInputData(sphere->GetOutput());
  writer->SetFileName(folder.path("m.gltf").c_str());
  EXPECT_EQ(callError(writer, [&] { return writer->Write(); }),
    folder.path("m.gltf") + ": unsupported mesh format \".gltf\" (supported: .vtp .vtk .ply .obj .stl)");
}

namespace
{
/// A fan of @p corners triangles around a centre as one polygon (corners
/// points on a circle), with RGB or RGBA point colours and normals, and
/// optionally a line (which only vtkPLYWriter takes).
vtkSmartPointer<vtkPolyData> colouredPolygon(int corners, int components, bool withLine)
{
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetName("RGBA");
  colours->SetNumberOfComponents(components);
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  std::vector<vtkIdType> ids;
  for (int i = 0; i < corners; ++i)
  {
    const double t = 2.0 * 3.14159265358979 * i / corners;
    points->InsertNextPoint(std::cos(t), std::sin(t), 0.0);
    const unsigned char c[4] = { static_cast<unsigned char>(i % 256), static_cast<unsigned char>(255 - i % 256),
      static_cast<unsigned char>(7 * i % 256), static_cast<unsigned char>(100 + i % 100) };
    colours->InsertNextTypedTuple(c);
    normals->InsertNextTuple3(0, 0, 1);
    ids.push_back(i);
  }
  vtkNew<vtkCellArray> polys;
  polys->InsertNextCell(corners, ids.data());
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  mesh->GetPointData()->SetScalars(colours);
  mesh->GetPointData()->SetNormals(normals);
  if (withLine)
  {
    vtkNew<vtkCellArray> lines;
    const vtkIdType line[2] = { 0, 1 };
    lines->InsertNextCell(2, line);
    mesh->SetLines(lines);
  }
  return mesh;
}
} // namespace

TEST(MeshWriter, PLYKeepsColoursAndRefusesFacesVTKCannotRead)
{
  // Read back by VTK's own reader: RGB and RGBA colours and the normals
  // (which vtkPLYWriter drops). With a line, vtkPLYWriter writes the file:
  // its colours too, and no temporary file is left (it needs a named one:
  // it appends ".ply" to any other path). A polygon of more than 255
  // corners, which VTK's PLY reader cannot read back, is refused.
  const TestFolder folder;
  for (const int components : { 3, 4 })
  {
    for (const int corners : { 5, 255, 256 })
    {
      for (const bool withLine : { false, true })
      {
        const std::string name = folder.path("c.ply");
        vtkSmartPointer<vtkPolyData> mesh = colouredPolygon(corners, components, withLine);
        vtkNew<slMeshWriter> writer;
        writer->SetInputData(mesh);
        writer->SetFileName(name.c_str());
        const std::string error = callError(writer, [&] { return writer->Write(); });
        if (corners > 255)
        {
          EXPECT_EQ(error, name + ": cannot write mesh: a polygon has 256 corners; PLY as VTK reads it takes at most "
                           "255 (write .vtp or .obj)");
          std::filesystem::remove(name);
          EXPECT_EQ(std::distance(std::filesystem::directory_iterator(folder.path("")), {}), 0) << "nothing left";
          continue;
        }
        ASSERT_EQ(error, "") << corners << " " << withLine;
        EXPECT_EQ(std::distance(std::filesystem::directory_iterator(folder.path("")), {}), 1) << "only the file";
        vtkNew<vtkPLYReader> reader;
        reader->SetFileName(name.c_str());
        reader->Update();
        vtkPolyData* back = reader->GetOutput();
        ASSERT_EQ(back->GetNumberOfPolys(), 1);
        EXPECT_EQ(back->GetPolys()->GetCellSize(0), corners);
        auto* colours = vtkUnsignedCharArray::SafeDownCast(back->GetPointData()->GetScalars());
        ASSERT_NE(colours, nullptr) << corners << " " << withLine;
        ASSERT_EQ(colours->GetNumberOfComponents(), components);
        auto* given = vtkUnsignedCharArray::SafeDownCast(mesh->GetPointData()->GetScalars());
        for (vtkIdType v = 0; v < 2 * components; ++v)
        {
          EXPECT_EQ(colours->GetValue(v), given->GetValue(v));
        }
        EXPECT_EQ(colours->GetValue(corners * components - 1), given->GetValue(corners * components - 1));
        if (!withLine)
        {
          ASSERT_NE(back->GetPointData()->GetNormals(), nullptr);
          EXPECT_EQ(back->GetPointData()->GetNormals()->GetComponent(corners - 1, 2), 1.0);
        }
      }
    }
  }
}
