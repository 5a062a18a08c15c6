// slMeshReader: every format, and every kind of bad input.
#include "TestFolder.h"

#include "slMeshReader.h"
#include "VTKErrors.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPLYWriter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>
#include <vtkSTLWriter.h>
#include <vtkSphereSource.h>
#include <vtkTriangleFilter.h>
#include <vtkXMLPolyDataWriter.h>

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

namespace
{
vtkSmartPointer<vtkPolyData> sphere()
{
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(12);
  source->SetPhiResolution(8);
  source->Update();
  vtkSmartPointer<vtkPolyData> out = source->GetOutput();
  return out;
}

struct ReadResult
{
  vtkSmartPointer<vtkPolyData> mesh;
  std::string error;
};

ReadResult read(const std::string& path)
{
  vtkNew<slMeshReader> reader;
  reader->SetFileName(path.c_str());
  ReadResult r;
  r.error = updateError(reader);
  r.mesh = reader->GetOutput();
  return r;
}
} // namespace

TEST(MeshReader, ReadsVTKWrittenFormats)
{
  const TestFolder folder;
  vtkSmartPointer<vtkPolyData> input = sphere();
  const vtkIdType expectedPoints = input->GetNumberOfPoints();
  const vtkIdType expectedCells = input->GetNumberOfPolys();

  vtkNew<vtkXMLPolyDataWriter> vtp;
  vtp->SetInputData(input);
  vtp->SetFileName(folder.path("s.vtp").c_str());
  vtp->Write();
  vtkNew<vtkPolyDataWriter> legacy;
  legacy->SetInputData(input);
  legacy->SetFileName(folder.path("s.VTK").c_str()); // extensions are case insensitive
  legacy->Write();
  vtkNew<vtkPLYWriter> ply;
  ply->SetInputData(input);
  ply->SetFileName(folder.path("s.ply").c_str());
  ply->Write();

  for (const char* name : { "s.vtp", "s.VTK", "s.ply" })
  {
    const ReadResult r = read(folder.path(name));
    EXPECT_EQ(r.error, "") << name;
    EXPECT_EQ(r.mesh->GetNumberOfPoints(), expectedPoints) << name;
    EXPECT_EQ(r.mesh->GetNumberOfPolys(), expectedCells) << name;
  }

  vtkNew<vtkSTLWriter> stl;
  stl->SetInputData(input);
  stl->SetFileName(folder.path("s.stl").c_str());
  stl->Write();
  const ReadResult r = read(folder.path("s.stl"));
  EXPECT_EQ(r.error, "");
  EXPECT_EQ(r.mesh->GetNumberOfPolys(), expectedCells); // STL merges points itself
}

// The VTP check reads the markup as expat does: a tag inside a comment or a
// processing instruction is text, and a valid file holding one reads.
TEST(MeshReader, VTPTagsInCommentsAreText)
{
  const TestFolder folder;
  vtkSmartPointer<vtkPolyData> input = sphere();
  vtkNew<vtkXMLPolyDataWriter> vtp;
  vtp->SetInputData(input);
  vtp->SetFileName(folder.path("plain.vtp").c_str());
  vtp->Write();
  std::ifstream in(folder.path("plain.vtp"), std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_NE(text.find(" compressor="), std::string::npos) << "the header check applies";
  // As arrays, each would declare 4294967295 blocks or a negative offset.
  const std::string lookalikes = "<!-- <DataArray Name=\"a\" format=\"binary\">////////////////</DataArray> -->"
                                 "<?note <DataArray Name=\"b\" offset=\"-1\"/> ?>";
  text.insert(text.find("<PolyData>") + std::strlen("<PolyData>"), lookalikes);
  std::ofstream(folder.path("commented.vtp"), std::ios::binary) << text;

  const ReadResult r = read(folder.path("commented.vtp"));
  EXPECT_EQ(r.error, "");
  EXPECT_EQ(r.mesh->GetNumberOfPoints(), input->GetNumberOfPoints());
  EXPECT_EQ(r.mesh->GetNumberOfPolys(), input->GetNumberOfPolys());
}

TEST(MeshReader, ObjCornersAreMergedButUVSeamsStay)
{
  // Two triangles sharing an edge; one shared corner has two different UVs.
  const TestFolder folder;
  folder.write("quad.obj",
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\n"
    "f 1/1 2/2 3/3\nf 1/5 3/3 4/4\n");
  const ReadResult r = read(folder.path("quad.obj"));
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.mesh->GetNumberOfPolys(), 2);
  // Corners: 6. Vertex 3 (same UV twice) merges; vertex 1 keeps two UVs.
  EXPECT_EQ(r.mesh->GetNumberOfPoints(), 5);
  EXPECT_NE(r.mesh->GetPointData()->GetTCoords(), nullptr);
}

TEST(MeshReader, OBJLinesPointsAndFacesWithoutNormalsKeepEveryCell)
{
  // vtkOBJReader 9.1 labels only faces in its "GroupIds" array and drops the
  // faces without vn beside faces with one; every cell is read here.
  const TestFolder folder;
  const auto cell = [](vtkCellArray* cells, vtkIdType c) {
    vtkNew<vtkIdList> ids;
    cells->GetCellAtId(c, ids);
    return std::vector<vtkIdType>(ids->begin(), ids->end());
  };
  const auto arraysFit = [](vtkPolyData* mesh) {
    for (int a = 0; a < mesh->GetCellData()->GetNumberOfArrays(); ++a)
    {
      EXPECT_EQ(mesh->GetCellData()->GetArray(a)->GetNumberOfTuples(), mesh->GetNumberOfCells());
    }
  };
  folder.write("lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nl 1 2\np 3\n");
  ReadResult r = read(folder.path("lines.obj"));
  ASSERT_EQ(r.error, "");
  ASSERT_EQ(r.mesh->GetNumberOfPoints(), 3);
  ASSERT_EQ(r.mesh->GetNumberOfCells(), 3);
  EXPECT_EQ(cell(r.mesh->GetPolys(), 0), std::vector<vtkIdType>({ 0, 1, 2 }));
  EXPECT_EQ(cell(r.mesh->GetLines(), 0), std::vector<vtkIdType>({ 0, 1 }));
  EXPECT_EQ(cell(r.mesh->GetVerts(), 0), std::vector<vtkIdType>({ 2 }));
  arraysFit(r.mesh);

  folder.write("mixed.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 1\nf 1//1 2//1 3//1\nf 1 2 4\n");
  r = read(folder.path("mixed.obj"));
  ASSERT_EQ(r.error, "");
  ASSERT_EQ(r.mesh->GetNumberOfPolys(), 2);
  EXPECT_EQ(r.mesh->GetNumberOfPoints(), 4);
  EXPECT_EQ(cell(r.mesh->GetPolys(), 0), std::vector<vtkIdType>({ 0, 1, 2 }));
  EXPECT_EQ(cell(r.mesh->GetPolys(), 1), std::vector<vtkIdType>({ 0, 1, 3 }));
  // The second face's points have no normal in the file: none is made up.
  EXPECT_EQ(r.mesh->GetPointData()->GetNormals(), nullptr);
  arraysFit(r.mesh);

  // With groups, GroupIds has a value per cell: vtkOBJReader gives one per
  // face only, and the lines and points get the group -1.
  folder.write("groups.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\ng a\nf 1 2 3\nl 1 2\ng b\nf 1 2 4\np 3\n");
  r = read(folder.path("groups.obj"));
  ASSERT_EQ(r.error, "");
  ASSERT_EQ(r.mesh->GetNumberOfPolys(), 2);
  ASSERT_EQ(r.mesh->GetNumberOfLines(), 1);
  ASSERT_EQ(r.mesh->GetNumberOfVerts(), 1);
  vtkDataArray* groups = r.mesh->GetCellData()->GetArray("GroupIds");
  ASSERT_NE(groups, nullptr);
  std::vector<double> groupOfCell;
  for (vtkIdType c = 0; c < groups->GetNumberOfTuples(); ++c)
  {
    groupOfCell.push_back(groups->GetTuple1(c));
  }
  // VTK's cell order: the vertex cell, the line, then the faces of a and b.
  EXPECT_EQ(groupOfCell, std::vector<double>({ -1, -1, 0, 1 }));
  arraysFit(r.mesh);
}

TEST(MeshReader, OBJByteOrderMarkIsSkippedOrNamed)
{
  // A UTF-8 byte order mark made the first keyword "\xEF\xBB\xBFv": the
  // first vertex was dropped and every index shifted.
  const TestFolder folder;
  const auto triangle = [](vtkPolyData* mesh) {
    std::vector<double> coordinates;
    vtkNew<vtkIdList> ids;
    mesh->GetPolys()->GetCellAtId(0, ids);
    for (vtkIdType id : *ids)
    {
      double p[3];
      mesh->GetPoint(id, p);
      coordinates.insert(coordinates.end(), p, p + 3);
    }
    return coordinates;
  };
  const std::vector<double> expected({ 0, 0, 0, 1, 0, 0, 0, 1, 0 });
  folder.write("bom.obj", "\xEF\xBB\xBFv 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\nf 1 2 3\n");
  ReadResult r = read(folder.path("bom.obj"));
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.mesh->GetNumberOfPoints(), 4);
  EXPECT_EQ(triangle(r.mesh), expected);

  // Through vtkOBJReader (negative indices): a comment after the mark is
  // skipped either way; anything else is refused, as VTK would skip it.
  folder.write("bomcomment.obj", "\xEF\xBB\xBF# made on Windows\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\nf -4 -3 -2\n");
  r = read(folder.path("bomcomment.obj"));
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.mesh->GetNumberOfPoints(), 4);
  EXPECT_EQ(triangle(r.mesh), expected);
  folder.write("bomvertex.obj", "\xEF\xBB\xBFv 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\nf -4 -3 -2\n");
  r = read(folder.path("bomvertex.obj"));
  EXPECT_EQ(r.error, folder.path("bomvertex.obj") +
      ": line 1: \"v\" follows a UTF-8 byte order mark, which VTK's OBJ reader would read as part of it and "
      "skip the line; save the file without the mark");
  EXPECT_EQ(r.mesh->GetNumberOfPoints(), 0);
}

TEST(MeshReader, ReadsOFFWithNgonsAndComments)
{
  const TestFolder folder;
  folder.write("m.off",
    "OFF\n# a pyramid with a square base\n5 5 0\n"
    "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 1\n"
    "4 3 2 1 0\n3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4 255 0 0\n");
  const ReadResult r = read(folder.path("m.off"));
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.mesh->GetNumberOfPoints(), 5);
  EXPECT_EQ(r.mesh->GetNumberOfPolys(), 5);
  EXPECT_EQ(r.mesh->GetPolys()->GetMaxCellSize(), 4);
}

TEST(MeshReader, ReadsCOFFColoursAndNOFFNormals)
{
  const TestFolder folder;
  const auto values = [](vtkDataArray* array) {
    std::vector<double> v;
    for (vtkIdType t = 0; array && t < array->GetNumberOfTuples(); ++t)
    {
      for (int c = 0; c < array->GetNumberOfComponents(); ++c)
      {
        v.push_back(array->GetComponent(t, c));
      }
    }
    return v;
  };
  // Integers are 0-255; alpha, where some vertex gives one, defaults to 255.
  folder.write("ints.off", "COFF\n3 1 0\n0 0 0 255 0 0 128\n1 0 0 0 255 0\n0 1 0 0 0 255 0\n3 0 1 2\n");
  ReadResult r = read(folder.path("ints.off"));
  ASSERT_EQ(r.error, "");
  vtkDataArray* colours = r.mesh->GetPointData()->GetScalars();
  ASSERT_NE(colours, nullptr);
  EXPECT_STREQ(colours->GetName(), "Colors");
  EXPECT_EQ(colours->GetDataType(), VTK_UNSIGNED_CHAR);
  EXPECT_EQ(values(colours), std::vector<double>({ 255, 0, 0, 128, 0, 255, 0, 255, 0, 0, 255, 0 }));
  // A value written with a point (as MeshLab writes floats): 0-1.
  folder.write("floats.off", "COFF\n3 1 0\n0 0 0 1 0 0\n1 0 0 0 0.5 0\n0 1 0 0 0 1.0\n3 0 1 2\n");
  r = read(folder.path("floats.off"));
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(values(r.mesh->GetPointData()->GetScalars()), std::vector<double>({ 255, 0, 0, 0, 128, 0, 0, 0, 255 }));
  folder.write("n.off", "NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0.6 0.8\n0 1 0 0 1 0\n3 0 1 2\n");
  r = read(folder.path("n.off"));
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(values(r.mesh->GetPointData()->GetNormals()),
    std::vector<double>({ 0, 0, 1, 0, 0.6f, 0.8f, 0, 1, 0 }));
  // Values after a plain OFF vertex were ignored.
  folder.write("plain.off", "OFF\n3 1 0\n0 0 0 255 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(read(folder.path("plain.off")).error, folder.path("plain.off") +
      ": line 3: 6 values for a vertex of plain OFF, which has 3 (x y z); a COFF header reads colours after them, "
      "NOFF normals");
}

TEST(MeshReader, BadOFFNamesTheLine)
{
  const TestFolder folder;
  folder.write("bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
  EXPECT_EQ(read(folder.path("bad.off")).error, folder.path("bad.off") + ": line 6: vertex index 7 is out of range [0, 3)");
  folder.write("short.off", "OFF\n3 1 0\n0 0 0\n1 0\n");
  EXPECT_EQ(read(folder.path("short.off")).error, folder.path("short.off") + ": line 4: expected three vertex coordinates");
  folder.write("noheader.off", "3 1 0\n");
  EXPECT_EQ(read(folder.path("noheader.off")).error, folder.path("noheader.off") + ": line 1: expected \"OFF\", found \"3\"");
}

TEST(MeshReader, MissingFile)
{
  const ReadResult r = read("/nonexistent/bunny.obj");
  EXPECT_EQ(r.error, "/nonexistent/bunny.obj: cannot open file: No such file or directory");
  EXPECT_EQ(r.mesh->GetNumberOfPoints(), 0);
}

TEST(MeshReader, PathThroughAFileSaysWhy)
{
  // The system's reason, not a bare "cannot open": here a file stands
  // where the path needs a folder.
  const TestFolder folder;
  folder.write("plain.off", "OFF\n0 0 0\n");
  const std::string path = folder.path("plain.off") + "/m.obj";
  EXPECT_EQ(read(path).error, path + ": cannot open file: Not a directory");
}

TEST(MeshReader, UnsupportedExtension)
{
  EXPECT_EQ(read("mesh.xyz").error,
    "mesh.xyz: unsupported mesh format \".xyz\" (supported: .obj .ply .stl .vtp .vtk .off .gltf .glb)");
}

TEST(MeshReader, GarbageGivesAnErrorAndEmptyOutput)
{
  const TestFolder folder;
  for (const char* name : { "junk.obj", "junk.ply", "junk.vtp", "junk.vtk", "junk.stl", "junk.gltf", "junk.glb" })
  {
    folder.write(name, "this is not a mesh at all\n\x01\x02\x03");
    const ReadResult r = read(folder.path(name));
    EXPECT_EQ(r.error.rfind(folder.path(name) + ": ", 0), 0u) << name << ": " << r.error;
    EXPECT_EQ(r.error.find('\n'), std::string::npos) << "one line: " << r.error;
    EXPECT_EQ(r.mesh->GetNumberOfPoints(), 0) << name;
  }
}

TEST(MeshReader, NonFiniteCoordinates)
{
  const TestFolder folder;
  folder.write("nan.off", "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n");
  const ReadResult r = read(folder.path("nan.off"));
  EXPECT_EQ(r.error, folder.path("nan.off") + ": point 1 has a NaN or infinite coordinate");
  EXPECT_EQ(r.mesh->GetNumberOfPoints(), 0);
}

TEST(MeshReader, ObjMaterialNamesUpToVTKsLimitRead)
{
  const TestFolder folder;
  // ShadeLab's own parser takes the name of 99 bytes; the longer one goes to
  // the file check, which refuses it.
  const std::string name(99, 'm');
  folder.write("named.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl " + name + "\nf 1 2 3\n");
  const ReadResult r = read(folder.path("named.obj"));
  EXPECT_EQ(r.error, "");
  EXPECT_EQ(r.mesh->GetNumberOfPolys(), 1);
  folder.write("long.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl " + name + "m\nf 1 2 3\n");
  EXPECT_EQ(read(folder.path("long.obj")).error,
    folder.path("long.obj") + ": line 4: usemtl name of 100 bytes is longer than the 99 that VTK's OBJ reader holds");
}

TEST(MeshReader, NoPolygons)
{
  const TestFolder folder;
  folder.write("points.obj", "v 0 0 0\nv 1 0 0\n");
  const ReadResult r = read(folder.path("points.obj"));
  EXPECT_NE(r.error, "");
  EXPECT_EQ(r.mesh->GetNumberOfPoints(), 0);
}

TEST(MeshReader, SharedDataMeshes)
{
  struct Expected
  {
    const char* name;
    vtkIdType faces;
  };
  for (const Expected& e : { Expected{ "spot.obj", 5856 }, Expected{ "fandisk.obj", 12946 },
         Expected{ "teapot.obj", 6320 } })
  {
    const ReadResult r = read(std::string(SHADELAB_DATA_DIR) + "/meshes/" + e.name);
    EXPECT_EQ(r.error, "") << e.name;
    EXPECT_EQ(r.mesh->GetNumberOfPolys(), e.faces) << e.name;
  }
  // Spot: 2930 positions, 3225 (position, UV) pairs.
  EXPECT_EQ(read(std::string(SHADELAB_DATA_DIR) + "/meshes/spot.obj").mesh->GetNumberOfPoints(), 3225);
}

TEST(MeshReader, ReadsGLTFWithNodeTransforms)
{
  // One triangle mesh used by two nodes, the second moved by +5 in x: the
  // reader must append both primitives with their node transforms applied.
  const TestFolder folder;
  const float positions[9] = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
  const unsigned short indices[4] = { 0, 1, 2, 0 }; // padded to 4-byte alignment
  {
    std::ofstream bin(folder.path("tri.bin"), std::ios::binary);
    bin.write(reinterpret_cast<const char*>(positions), sizeof positions);
    bin.write(reinterpret_cast<const char*>(indices), sizeof indices);
  }
  folder.write("two.gltf", R"({
  "asset": { "version": "2.0" },
  "scene": 0,
  "scenes": [ { "nodes": [0, 1] } ],
  "nodes": [ { "mesh": 0 }, { "mesh": 0, "translation": [5, 0, 0] } ],
  "meshes": [ { "primitives": [ { "attributes": { "POSITION": 0 }, "indices": 1 } ] } ],
  "buffers": [ { "uri": "tri.bin", "byteLength": 44 } ],
  "bufferViews": [ { "buffer": 0, "byteOffset": 0, "byteLength": 36 },
                   { "buffer": 0, "byteOffset": 36, "byteLength": 6 } ],
  "accessors": [
    { "bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0] },
    { "bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR" } ]
})");
  const ReadResult r = read(folder.path("two.gltf"));
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.mesh->GetNumberOfPolys(), 2);
  EXPECT_EQ(r.mesh->GetNumberOfPoints(), 6);
  double bounds[6];
  r.mesh->GetBounds(bounds);
  EXPECT_DOUBLE_EQ(bounds[0], 0.0);
  EXPECT_DOUBLE_EQ(bounds[1], 6.0);
  EXPECT_DOUBLE_EQ(bounds[3], 1.0);
}

TEST(MeshReader, BrokenGLTFGivesOneLineNamingTheFile)
{
  const TestFolder folder;
  folder.write("broken.gltf", "{ \"asset\": { \"version\": \"2.0\" }, \"meshes\": [ { \"primitives\": [ ");
  const std::string error = read(folder.path("broken.gltf")).error;
  EXPECT_EQ(error.rfind(folder.path("broken.gltf") + ": ", 0), 0u) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
}
