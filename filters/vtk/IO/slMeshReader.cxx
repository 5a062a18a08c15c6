#include "slMeshReader.h"

#include "slConnectivityCheck.h"
#include "slCoreBoundary.h"
#include "slErrorCapture.h"
#include "slFileExtension.h"
#include "slMeshArraysVTK.h"
#include "slMeshAttributeCheck.h"
#include "slMeshFileCheck.h"
#include "slOBJFormat.h"
#include "slOFFParser.h"
#include "slPLYFormat.h"
#include "slPointWelding.h"

#include "shadelab/InputFile.h"
#include "shadelab/OutOfMemory.h"
#include "shadelab/PrintableText.h"

#include <vtkAlgorithm.h>
#include <vtkAppendPolyData.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCompositeDataIterator.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkGLTFReader.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkObjectFactory.h>
#include <vtkPLYReader.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkSMPTools.h>
#include <vtkSTLReader.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <memory>
#include <new>
#include <string>
#include <vector>

vtkStandardNewMacro(slMeshReader);

namespace
{
/// The VTK reader for an extension, or null for OFF and unknown extensions.
vtkSmartPointer<vtkAlgorithm> makeVTKReader(const std::string& ext, const char* fileName)
{
  if (ext == ".obj")
  {
    auto r = vtkSmartPointer<vtkOBJReader>::New();
    r->SetFileName(fileName);
    return r;
  }
  if (ext == ".gltf" || ext == ".glb")
  {
    auto r = vtkSmartPointer<vtkGLTFReader>::New();
    r->SetFileName(fileName);
    return r;
  }
  if (ext == ".ply")
  {
    auto r = vtkSmartPointer<vtkPLYReader>::New();
    r->SetFileName(fileName);
    return r;
  }
  if (ext == ".stl")
  {
    auto r = vtkSmartPointer<vtkSTLReader>::New();
    r->SetFileName(fileName);
    return r;
  }
  if (ext == ".vtp")
  {
    auto r = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    r->SetFileName(fileName);
    return r;
  }
  if (ext == ".vtk")
  {
    auto r = vtkSmartPointer<vtkPolyDataReader>::New();
    r->SetFileName(fileName);
    return r;
  }
  return nullptr;
}

/// The first polygon of fewer than three points in @p offsets (one more
/// than the polygons), or -1.
template <typename Offset>
vtkIdType firstShortPolygon(const Offset* offsets, vtkIdType numberOfOffsets)
{
  for (vtkIdType c = 0; c + 1 < numberOfOffsets; ++c)
  {
    if (offsets[c + 1] - offsets[c] < 3)
    {
      return c;
    }
  }
  return -1;
}

/// "" unless a polygon of @p polys has fewer than three points: vtkPolyData
/// then builds no cell types for the mesh ("Invalid cell size for polys"),
/// and VTK's writers and cell queries follow the missing table (the VTP
/// writer crashes). The connectivity must be checked (slConnectivityProblem).
std::string shortPolygonProblem(vtkCellArray* polys)
{
  const vtkIdType first = polys->IsStorage64Bit()
    ? firstShortPolygon(polys->GetOffsetsArray64()->GetPointer(0), polys->GetOffsetsArray64()->GetNumberOfValues())
    : firstShortPolygon(polys->GetOffsetsArray32()->GetPointer(0), polys->GetOffsetsArray32()->GetNumberOfValues());
  if (first < 0)
  {
    return std::string();
  }
  return "polygon " + std::to_string(first) + " has fewer than 3 points (" +
    std::to_string(polys->GetCellSize(first)) + ")";
}

/// vtkOBJReader 9.1 gives its cell array "GroupIds" a value per face only,
/// although VTK orders a mesh's vertex and line cells (OBJ "p" and "l")
/// before its faces. Gives those cells the group -1 (the reader records none
/// for them), so that the array has a value per cell again.
void completeOBJGroupIds(vtkPolyData* mesh)
{
  vtkDataArray* groups = mesh->GetCellData()->GetArray("GroupIds");
  const vtkIdType others = mesh->GetNumberOfVerts() + mesh->GetNumberOfLines();
  if (!groups || others == 0 || groups->GetNumberOfComponents() != 1 ||
    groups->GetNumberOfTuples() != mesh->GetNumberOfPolys() + mesh->GetNumberOfStrips())
  {
    return;
  }
  vtkSmartPointer<vtkDataArray> complete;
  complete.TakeReference(groups->NewInstance());
  complete->SetName(groups->GetName());
  complete->SetNumberOfTuples(others + groups->GetNumberOfTuples());
  for (vtkIdType c = 0; c < others; ++c)
  {
    complete->SetTuple1(c, -1.0);
  }
  for (vtkIdType f = 0; f < groups->GetNumberOfTuples(); ++f)
  {
    complete->SetTuple1(others + f, groups->GetTuple1(f));
  }
  mesh->GetCellData()->RemoveArray("GroupIds");
  mesh->GetCellData()->AddArray(complete);
}

/// A one-component VTK array named @p name holding @p values.
template <typename Array, typename T>
vtkSmartPointer<Array> namedArray(const char* name, const std::vector<T>& values)
{
  auto array = vtkSmartPointer<Array>::New();
  array->SetName(name);
  slSetNumberOfTuplesOrThrow(array, static_cast<vtkIdType>(values.size()));
  for (std::size_t k = 0; k < values.size(); ++k)
  {
    array->SetValue(static_cast<vtkIdType>(k), values[k]);
  }
  return array;
}

/// Gives @p mesh, read by ShadeLab's OBJ parser, vtkOBJReader 9.1's arrays
/// of texture coordinates, one per material name, in its order and before
/// the normals, the first one active, in place of the parser's one.
void addOBJTCoords(const slOBJAttributes& attributes, vtkPolyData* mesh)
{
  vtkPointData* pd = mesh->GetPointData();
  vtkSmartPointer<vtkFloatArray> given = vtkFloatArray::SafeDownCast(pd->GetTCoords());
  if (!given || attributes.tcoordsNames.empty())
  {
    return;
  }
  const vtkIdType points = given->GetNumberOfTuples();
  std::vector<vtkSmartPointer<vtkFloatArray>> arrays{ given };
  for (std::size_t a = 1; a < attributes.tcoordsNames.size(); ++a)
  {
    arrays.push_back(vtkSmartPointer<vtkFloatArray>::New());
    arrays[a]->SetNumberOfComponents(2);
    slSetNumberOfTuplesOrThrow(arrays[a], points);
    slOBJTCoordsArray(
      attributes, a, given->GetPointer(0), static_cast<std::size_t>(points), arrays[a]->GetPointer(0));
  }
  // The first array in place, once the others have their values from it.
  slOBJTCoordsArray(attributes, 0, given->GetPointer(0), static_cast<std::size_t>(points), given->GetPointer(0));
  vtkSmartPointer<vtkDataArray> normals = pd->GetNormals();
  pd->RemoveArray(given->GetName());
  if (normals)
  {
    pd->RemoveArray(normals->GetName());
  }
  for (std::size_t a = 0; a < arrays.size(); ++a)
  {
    arrays[a]->SetName(attributes.tcoordsNames[a].c_str());
    pd->AddArray(arrays[a]);
  }
  pd->SetActiveTCoords(attributes.tcoordsNames[0].c_str());
  if (normals)
  {
    pd->SetNormals(normals);
  }
}

/// Adds to @p mesh, read by ShadeLab's OBJ parser, what vtkOBJReader 9.1
/// makes of groups and materials, as it names and orders them: the texture
/// coordinates' arrays, the cell arrays "MaterialIds" and "GroupIds" (the
/// latter, as for VTK's reader, completed for the lines and vertex cells),
/// the field data "MaterialNames" and "MaterialLibraries".
void addOBJAttributes(const slOBJAttributes& attributes, vtkPolyData* mesh)
{
  addOBJTCoords(attributes, mesh);
  if (!attributes.materialIds.empty())
  {
    mesh->GetCellData()->AddArray(namedArray<vtkIntArray>("MaterialIds", attributes.materialIds));
    mesh->GetFieldData()->AddArray(namedArray<vtkStringArray>("MaterialNames", attributes.materialNames));
    if (!attributes.materialLibraries.empty())
    {
      mesh->GetFieldData()->AddArray(namedArray<vtkStringArray>("MaterialLibraries", attributes.materialLibraries));
    }
  }
  if (!attributes.groupIds.empty())
  {
    mesh->GetCellData()->AddArray(namedArray<vtkFloatArray>("GroupIds", attributes.groupIds));
    completeOBJGroupIds(mesh);
  }
}

/// All polygonal leaves of a composite dataset (glTF meshes and primitives)
/// appended into one polydata; null when it has none.
vtkSmartPointer<vtkPolyData> appendLeaves(vtkCompositeDataSet* composite)
{
  vtkNew<vtkAppendPolyData> append;
  vtkSmartPointer<vtkCompositeDataIterator> it;
  it.TakeReference(composite->NewIterator());
  int leaves = 0;
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    if (vtkPolyData* leaf = vtkPolyData::SafeDownCast(it->GetCurrentDataObject()))
    {
      append->AddInputData(leaf);
      ++leaves;
    }
  }
  if (leaves == 0)
  {
    return nullptr;
  }
  append->Update();
  return append->GetOutput();
}

/// Reads an OBJ or PLY file through ShadeLab's own parsers into @p mesh.
/// False for other formats and for files those parsers decline, which go to
/// the file checks and VTK's readers.
bool readOwnFormat(const char* fileName, const std::string& ext, bool merge, vtkPolyData* mesh)
{
  if (ext != ".obj" && ext != ".ply")
  {
    return false;
  }
  try
  {
    std::ifstream in(fileName, std::ios::binary | std::ios::ate);
    const std::streamoff size = in ? static_cast<std::streamoff>(in.tellg()) : -1;
    if (size <= 0)
    {
      return false;
    }
    // Not zero-filled first: the read writes every byte (a pass over the
    // whole file less, on one thread).
    const auto length = static_cast<std::size_t>(size);
    std::unique_ptr<char[]> bytes(new char[length]);
    in.seekg(0);
    if (!in.read(bytes.get(), size))
    {
      return false;
    }
    slMeshArrays arrays;
    slOBJAttributes attributes;
    const bool parsed = ext == ".obj"
      ? slParseOBJ(bytes.get(), length, merge, arrays, attributes, vtkSMPTools::GetEstimatedNumberOfThreads())
      : slParsePLY(bytes.get(), length, arrays, vtkSMPTools::GetEstimatedNumberOfThreads());
    if (!parsed)
    {
      return false;
    }
    bytes.reset();
    // vtkOBJReader adds texture coordinates before normals.
    slToPolyData(arrays, ext == ".obj", mesh);
    if (ext == ".obj")
    {
      addOBJAttributes(attributes, mesh);
    }
    return true;
  }
  catch (const std::exception& e)
  {
    if (!shadelab::isOutOfMemory(e))
    {
      throw;
    }
    return false; // VTK's path then says what the file needs
  }
}

/// Index of the first point with a NaN or infinite coordinate, or -1.
vtkIdType firstNonFinitePoint(vtkPoints* points)
{
  const vtkIdType n = points ? points->GetNumberOfPoints() : 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      return i;
    }
  }
  return -1;
}
} // namespace

slMeshReader::slMeshReader()
{
  this->SetNumberOfInputPorts(0);
}

slMeshReader::~slMeshReader()
{
  this->SetFileName(nullptr);
}

const char* slMeshReader::GetSupportedExtensions()
{
  return ".obj .ply .stl .vtp .vtk .off .gltf .glb";
}

bool slMeshReader::CanReadFile(const char* fileName)
{
  return slExtensionInList(slLowerExtension(fileName), GetSupportedExtensions());
}

bool slMeshReader::Fail(const std::string& problem)
{
  vtkErrorMacro(<< (this->FileName ? this->FileName : "(no file name)") << ": " << problem);
  return false;
}

int slMeshReader::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->Initialize();

  if (!this->FileName || !*this->FileName)
  {
    return this->Fail("no file name given");
  }
  // Before the extension: a folder or a device is no mesh whatever its name.
  const std::string fileProblem = shadelab::inputFileProblem(this->FileName, "a mesh file");
  if (!fileProblem.empty())
  {
    return this->Fail(fileProblem);
  }
  const std::string ext = slLowerExtension(this->FileName);
  if (!CanReadFile(this->FileName))
  {
    // VTK's XML formats of datasets other than polydata, serial and parallel.
    static const char* const notSurfaces[] = { ".vtu", ".vts", ".vtr", ".vti", ".vtm", ".pvtu", ".pvts", ".pvtr",
      ".pvti" };
    const bool dataset = std::find(std::begin(notSurfaces), std::end(notSurfaces), ext) != std::end(notSurfaces);
    return this->Fail("unsupported mesh format \"" + ext + "\" (supported: " + GetSupportedExtensions() + ")" +
      (dataset ? std::string(": a VTK dataset that is not a surface; ") + kExtractSurfaceFirst : std::string()));
  }
  std::ifstream probe(this->FileName, std::ios::binary);
  if (!probe)
  {
    return this->Fail("cannot open file: " + shadelab::openFailureReason(this->FileName));
  }

  vtkNew<vtkPolyData> mesh;
  if (ext == ".off")
  {
    if (!slRunCore(this, [&] { slParseOFF(probe, this->FileName, mesh); }))
    {
      return 0;
    }
  }
  else if (!readOwnFormat(this->FileName, ext, this->MergeDuplicatePoints, mesh))
  {
    probe.close();
    // VTK's readers trust the file; what would make them crash, allocate
    // without bound or read part of it is rejected first.
    const std::string problem = slMeshFileProblem(this->FileName, ext);
    if (!problem.empty())
    {
      return this->Fail(problem);
    }
    vtkSmartPointer<vtkAlgorithm> reader = makeVTKReader(ext, this->FileName);
    vtkNew<slErrorCapture> errors;
    errors->Watch(reader);
    try
    {
      reader->Update();
    }
    catch (const std::exception& e)
    {
      return this->Fail(shadelab::isOutOfMemory(e) ? "out of memory (reading)" : shadelab::printableText(e.what(), 200));
    }
    if (errors->HasError())
    {
      // VTK's compressors say that data did not uncompress, not which: the
      // VTP check finds the array and block.
      const std::string dataProblem = ext == ".vtp" ? slVTPDataProblem(this->FileName) : std::string();
      // VTK's messages may quote bytes of the file.
      return this->Fail(!dataProblem.empty() ? dataProblem : shadelab::printableText(errors->GetError(), 200));
    }
    vtkSmartPointer<vtkPolyData> read = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
    if (auto* composite = vtkCompositeDataSet::SafeDownCast(reader->GetOutputDataObject(0)))
    {
      read = appendLeaves(composite);
    }
    if (!read)
    {
      return this->Fail("the file does not hold polygonal data (vtkPolyData)");
    }
    mesh->DeepCopy(read);
    if (ext == ".obj")
    {
      completeOBJGroupIds(mesh);
    }
    // Before anything follows the cells (point merging, the filters).
    std::string cellProblem = slConnectivityProblem(mesh);
    if (cellProblem.empty())
    {
      cellProblem = shortPolygonProblem(mesh->GetPolys());
    }
    if (cellProblem.empty())
    {
      // vtkOBJReader attaches the listed normals or texture coordinates as
      // they are when every face names the same index for v, vt and vn,
      // also when fewer are listed than points; point merging and the
      // filters index them by point or cell.
      cellProblem = slArrayLengthProblem(mesh->GetPointData(), mesh->GetNumberOfPoints(), "point", true);
    }
    if (cellProblem.empty())
    {
      cellProblem = slArrayLengthProblem(mesh->GetCellData(), mesh->GetNumberOfCells(), "cell", true);
    }
    if (!cellProblem.empty())
    {
      return this->Fail(cellProblem);
    }
    if (ext == ".obj" && this->MergeDuplicatePoints)
    {
      slMergeIdenticalPoints(mesh);
    }
  }

  if (mesh->GetNumberOfPoints() == 0)
  {
    return this->Fail("no points: empty, truncated or not a " + ext.substr(1) + " file");
  }
  if (mesh->GetNumberOfPolys() == 0 && mesh->GetNumberOfStrips() == 0)
  {
    return this->Fail("no polygons among its " + std::to_string(mesh->GetNumberOfCells()) + " cells");
  }
  const vtkIdType bad = firstNonFinitePoint(mesh->GetPoints());
  if (bad >= 0)
  {
    return this->Fail("point " + std::to_string(bad) + " has a NaN or infinite coordinate");
  }
  // Every format's normals, texture coordinates and tangents, as the filters
  // would carry a NaN into their output.
  const std::string attributeProblem = slNonFiniteAttributeProblem(mesh);
  if (!attributeProblem.empty())
  {
    return this->Fail(attributeProblem);
  }
  output->ShallowCopy(mesh);
  return 1;
}

void slMeshReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "MergeDuplicatePoints: " << this->MergeDuplicatePoints << "\n";
}
