#include "slMeshWriter.h"
#include "slCoreBoundary.h"

#include "shadelab/AtomicFile.h"
#include "shadelab/MemoryFile.h"
#include "slBinaryPLYSize.h"
#include "slErrorCapture.h"
#include "slFileExtension.h"
#include "slMeshArraysVTK.h"
#include "slOBJFormat.h"
#include "slPLYFormat.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkErrorCode.h>
#include <vtkExecutive.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkOBJWriter.h>
#include <vtkObjectFactory.h>
#include <vtkPLYWriter.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>
#include <vtkSMPTools.h>
#include <vtkSTLWriter.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLPolyDataWriter.h>

#include <fstream>
#include <optional>

vtkStandardNewMacro(slMeshWriter);

namespace
{
/// The names of slMeshWriter::Compressions, in order.
constexpr const char* kCompressionNames[] = { "none", "lz4", "zlib" };

/// A VTK writer for @p ext writing @p mesh to @p path; null if unsupported.
vtkSmartPointer<vtkAlgorithm> makeWriter(
  const std::string& ext, vtkPolyData* mesh, const std::string& path, int compression)
{
  if (ext == ".vtp")
  {
    auto w = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    w->SetInputData(mesh);
    w->SetFileName(path.c_str());
    // Raw appended data: base64 would cost more time than it saves.
    w->SetDataModeToAppended();
    w->EncodeAppendedDataOff();
    switch (compression)
    {
      case slMeshWriter::NONE:
        w->SetCompressorTypeToNone();
        break;
      case slMeshWriter::ZLIB:
        w->SetCompressorTypeToZLib();
        break;
      case slMeshWriter::LZ4:
        w->SetCompressorTypeToLZ4();
        break;
    }
    return w;
  }
  if (ext == ".vtk")
  {
    auto w = vtkSmartPointer<vtkPolyDataWriter>::New();
    w->SetInputData(mesh);
    w->SetFileName(path.c_str());
    w->SetFileTypeToBinary();
    return w;
  }
  if (ext == ".ply")
  {
    auto w = vtkSmartPointer<vtkPLYWriter>::New();
    w->SetInputData(mesh);
    w->SetFileName(path.c_str());
    w->SetFileTypeToBinary();
    // Without an array name it writes no colours at all.
    for (vtkDataSetAttributes* data : { static_cast<vtkDataSetAttributes*>(mesh->GetPointData()),
           static_cast<vtkDataSetAttributes*>(mesh->GetCellData()) })
    {
      auto* colours = vtkUnsignedCharArray::SafeDownCast(data->GetScalars());
      if (colours && colours->GetName() && colours->GetNumberOfComponents() >= 3)
      {
        w->SetArrayName(colours->GetName());
        w->SetEnableAlpha(colours->GetNumberOfComponents() == 4);
        break;
      }
    }
    return w;
  }
  if (ext == ".obj")
  {
    auto w = vtkSmartPointer<vtkOBJWriter>::New();
    w->SetInputData(mesh);
    w->SetFileName(path.c_str());
    return w;
  }
  if (ext == ".stl")
  {
    auto w = vtkSmartPointer<vtkSTLWriter>::New();
    w->SetInputData(mesh);
    w->SetFileName(path.c_str());
    w->SetFileTypeToBinary();
    return w;
  }
  return nullptr;
}
/// The size of the complete binary PLY file vtkPLYWriter wrote for @p mesh
/// at @p path, from its header (which a full disk still lets through) and
/// the polygons' corner count (vtkPLYWriter writes polygons only).
long long expectedPLYSize(const std::string& path, vtkPolyData* mesh)
{
  std::ifstream in(path, std::ios::binary);
  std::string head(65536, '\0');
  in.read(&head[0], static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(in.gcount()));
  const std::int64_t size = slBinaryPLYSize(head, mesh->GetPolys()->GetNumberOfConnectivityIds());
  if (size < 0)
  {
    // Its header never reached the file; the size check then asks the file
    // system for room for it.
    return static_cast<long long>(head.size()) + 1;
  }
  return size;
}

/// Writes @p mesh as OBJ or PLY with ShadeLab's own formatters into
/// @p output and commits it; false, writing nothing, for other formats and
/// meshes they do not write (which VTK's writers then write).
bool writeOwn(const std::string& ext, vtkPolyData* mesh, shadelab::AtomicOutput& output)
{
  slMeshView view;
  if ((ext != ".obj" && ext != ".ply") || !slViewOf(mesh, view) || (ext == ".obj" && view.colours))
  {
    return false; // (OBJ has no colours: vtkOBJWriter writes the rest)
  }
  if (ext == ".obj")
  {
    // Piece by piece, as it is formatted: the file is never whole in memory.
    slFormatOBJ(
      view, [&](const char* data, std::size_t size) { output.write(data, size); },
      vtkSMPTools::GetEstimatedNumberOfThreads());
    output.commit();
    return true;
  }
  std::string bytes;
  if (!slFormatPLY(view, bytes))
  {
    return false;
  }
  output.commit(bytes.data(), bytes.size());
  return true;
}
} // namespace

slMeshWriter::slMeshWriter()
{
  this->SetNumberOfOutputPorts(0);
}

slMeshWriter::~slMeshWriter()
{
  this->SetFileName(nullptr);
}

const char* slMeshWriter::GetSupportedExtensions()
{
  return ".vtp .vtk .ply .obj .stl";
}

bool slMeshWriter::CanWriteFile(const char* fileName)
{
  return slExtensionInList(slLowerExtension(fileName), GetSupportedExtensions());
}

int slMeshWriter::FillOutputPortInformation(int, vtkInformation*)
{
  return 1;
}

bool slMeshWriter::Write()
{
  this->Modified();
  return this->GetExecutive()->Update() != 0;
}

int slMeshWriter::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  return slRunCore(this, [&] { this->WriteMesh(vtkPolyData::GetData(inputVector[0])); }) ? 1 : 0;
}

void slMeshWriter::WriteMesh(vtkPolyData* mesh)
{
  const std::string name = this->FileName ? this->FileName : "";
  auto fail = [&](const std::string& problem) {
    return shadelab::Error((name.empty() ? std::string("(no file name)") : name) + ": " + problem);
  };
  if (name.empty())
  {
    throw fail("no output file given");
  }
  const std::string formatProblem = slFormatProblem(name.c_str(), "mesh", GetSupportedExtensions());
  if (!formatProblem.empty())
  {
    throw fail(formatProblem);
  }
  if (!mesh || mesh->GetNumberOfPoints() == 0)
  {
    throw fail("nothing to write (empty mesh)");
  }
  const std::string ext = slLowerExtension(name.c_str());
  if (ext == ".ply" && mesh->GetPolys() && mesh->GetPolys()->GetMaxCellSize() > 255)
  {
    // VTK's PLY reader keeps a face's corner count in a byte.
    throw fail("cannot write mesh: a polygon has " + std::to_string(mesh->GetPolys()->GetMaxCellSize()) +
      " corners; PLY as VTK reads it takes at most 255 (write .vtp or .obj)");
  }
  {
    // VTK's writers do not all notice a failed write (a full disk can leave a
    // truncated .vtp behind a success): they write to memory, where writing
    // cannot fail that way, and AtomicOutput writes the bytes, checking each
    // step. vtkPLYWriter cannot: it appends ".ply" to any other file name and
    // its string output is empty in VTK 9.1. It writes the temporary file
    // itself, whose size is then checked against its header.
    shadelab::AtomicOutput own(name);
    if (writeOwn(ext, mesh, own))
    {
      return;
    }
    const bool ply = ext == ".ply";
    // vtkPLYWriter appends ".ply" to a path without it: its temporary file
    // needs a name of its own from the start.
    std::optional<shadelab::AtomicOutput> named;
    if (ply)
    {
      named.emplace(name, shadelab::TemporaryKind::Named);
    }
    shadelab::AtomicOutput& output = ply ? *named : own;
    shadelab::MemoryFile memory;
    vtkSmartPointer<vtkAlgorithm> writer = makeWriter(ext, mesh, ply ? output.temporaryPath() : memory.path(), this->Compression);
    vtkNew<slErrorCapture> errors;
    errors->Watch(writer);
    writer->Update();
    const std::string bytes = ply ? std::string() : memory.contents();
    if (errors->HasError() || writer->GetErrorCode() != 0 || (!ply && bytes.empty()))
    {
      const std::string reason = errors->HasError() ? errors->GetError()
        : writer->GetErrorCode() != 0
        ? vtkErrorCode::GetStringFromErrorCode(writer->GetErrorCode())
        : std::string("the writer produced nothing");
      throw fail("cannot write mesh: " + reason);
    }
    if (ply)
    {
      output.commitWritten(expectedPLYSize(output.temporaryPath(), mesh));
    }
    else
    {
      output.commit(bytes.data(), bytes.size());
    }
  }
}

void slMeshWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "Compression: " << GetCompressionName(this->Compression) << "\n";
}

const char* slMeshWriter::GetCompressionName(int compression)
{
  return compression >= NONE && compression <= ZLIB ? kCompressionNames[compression] : nullptr;
}

int slMeshWriter::GetCompressionByName(const std::string& name)
{
  for (int c = NONE; c <= ZLIB; ++c)
  {
    if (name == kCompressionNames[c])
    {
      return c;
    }
  }
  return -1;
}
