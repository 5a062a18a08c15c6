// slMeshWriter: every format reads back through slMeshReader; failures are clean.
#include "TestFolder.h"

#include "slMeshReader.h"
#include "slMeshWriter.h"
#include "VTKErrors.h"

#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSphereSource.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

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
