// slMeshWriter: every format reads back through slMeshReader; failures are clean.
#include "TestFolder.h"

#include "slMeshReader.h"
#include "slMeshWriter.h"

#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSphereSource.h>

#include <gtest/gtest.h>

#include <fstream>
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
    ASSERT_TRUE(writer->Write()) << writer->GetErrorMessage();
    vtkNew<slMeshReader> reader;
    reader->SetFileName(folder.path(name).c_str());
    reader->Update();
    EXPECT_STREQ(reader->GetErrorMessage(), "") << name;
    EXPECT_EQ(reader->GetOutput()->GetNumberOfPolys(), mesh->GetNumberOfPolys()) << name;
  }
  // VTP keeps the normals array.
  vtkNew<slMeshReader> reader;
  reader->SetFileName(folder.path("s.vtp").c_str());
  reader->Update();
  EXPECT_NE(reader->GetOutput()->GetPointData()->GetNormals(), nullptr);
}

TEST(MeshWriter, FailuresAreCleanAndNamed)
{
  const TestFolder folder;
  folder.write("keep.vtp", "old");
  vtkNew<vtkPolyData> empty;
  vtkNew<slMeshWriter> writer;
  writer->SetInputData(empty);
  writer->SetFileName(folder.path("keep.vtp").c_str());
  EXPECT_FALSE(writer->Write());
  EXPECT_EQ(std::string(writer->GetErrorMessage()), folder.path("keep.vtp") + ": nothing to write (empty mesh)");
  std::ifstream in(folder.path("keep.vtp"));
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "old");

  vtkNew<vtkSphereSource> sphere;
  sphere->Update();
  writer->SetInputData(sphere->GetOutput());
  writer->SetFileName(folder.path("m.gltf").c_str());
  EXPECT_FALSE(writer->Write());
  EXPECT_EQ(std::string(writer->GetErrorMessage()),
    folder.path("m.gltf") + ": unsupported mesh format \".gltf\" (supported: .vtp .vtk .ply .obj .stl)");
}
