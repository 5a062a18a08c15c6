#include "slMeshWriter.h"

#include "shadelab/AtomicFile.h"
#include "slErrorCapture.h"
#include "slFileExtension.h"

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkOBJWriter.h>
#include <vtkObjectFactory.h>
#include <vtkPLYWriter.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>
#include <vtkSTLWriter.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataWriter.h>

#include <stdexcept>

vtkStandardNewMacro(slMeshWriter);

namespace
{
/// A VTK writer for @p ext writing @p mesh to @p path; null if unsupported.
vtkSmartPointer<vtkAlgorithm> makeWriter(const std::string& ext, vtkPolyData* mesh, const std::string& path)
{
  if (ext == ".vtp")
  {
    auto w = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    w->SetInputData(mesh);
    w->SetFileName(path.c_str());
    w->SetDataModeToAppended();
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
  this->ErrorMessage.clear();
  this->Modified();
  this->Update();
  return this->ErrorMessage.empty();
}

int slMeshWriter::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  return this->WriteMesh(vtkPolyData::GetData(inputVector[0])) ? 1 : 0;
}

bool slMeshWriter::WriteMesh(vtkPolyData* mesh)
{
  const std::string name = this->FileName ? this->FileName : "";
  auto fail = [&](const std::string& problem) {
    this->ErrorMessage = (name.empty() ? std::string("(no file name)") : name) + ": " + problem;
    vtkErrorMacro(<< this->ErrorMessage);
    return false;
  };
  if (name.empty())
  {
    return fail("no output file given");
  }
  const std::string ext = slLowerExtension(name.c_str());
  if (!CanWriteFile(name.c_str()))
  {
    return fail("unsupported mesh format \"" + ext + "\" (supported: " + GetSupportedExtensions() + ")");
  }
  if (!mesh || mesh->GetNumberOfPoints() == 0)
  {
    return fail("nothing to write (empty mesh)");
  }
  try
  {
    shadelab::AtomicOutput output(name);
    vtkSmartPointer<vtkAlgorithm> writer = makeWriter(ext, mesh, output.temporaryPath());
    vtkNew<slErrorCapture> errors;
    errors->Watch(writer);
    writer->Update();
    if (errors->HasError())
    {
      return fail("cannot write mesh: " + errors->GetLastError());
    }
    output.commit();
  }
  catch (const std::runtime_error& e)
  {
    this->ErrorMessage = e.what();
    vtkErrorMacro(<< this->ErrorMessage);
    return false;
  }
  return true;
}

void slMeshWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
