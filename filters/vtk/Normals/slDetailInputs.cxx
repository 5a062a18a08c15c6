#include "slDetailInputs.h"

#include "slConnectivityCheck.h"
#include "slCoreBoundary.h"
#include "slImageReader.h"
#include "slNormalsVTKBridge.h"
#include "slPolyDataNormals.h"
#include "slPolyDataTangents.h"
#include "slUpdateOrThrow.h"

#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>

void slLoadTexture(const char* fileName, slnormals::Texture& texture)
{
  if (!fileName || !*fileName)
  {
    throw shadelab::Error("no image file name given");
  }
  vtkNew<slImageReader> reader;
  reader->SetFileName(fileName);
  reader->OutputFloatOn();
  slUpdateOrThrow(reader);
  vtkImageData* image = reader->GetOutput();
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  int dims[3];
  image->GetDimensions(dims);
  if (!scalars || dims[0] < 1 || dims[1] < 1)
  {
    throw shadelab::Error(std::string(fileName) + ": the image is empty");
  }
  texture.width = dims[0];
  texture.height = dims[1];
  texture.channels = scalars->GetNumberOfComponents();
  texture.texels.resize(static_cast<size_t>(scalars->GetNumberOfValues()));
  for (vtkIdType i = 0; i < scalars->GetNumberOfValues(); ++i)
  {
    texture.texels[static_cast<size_t>(i)] = static_cast<float>(scalars->GetVariantValue(i).ToDouble());
  }
}

void slCheckFiniteChannel(const slnormals::Texture& texture, int channel, const char* fileName)
{
  // Rows are stored bottom-up: the top row first, so that the pixel named is
  // the first one an image viewer shows.
  for (int row = 0; row < texture.height; ++row)
  {
    for (int x = 0; x < texture.width; ++x)
    {
      const float value = texture.texel(x, texture.height - 1 - row, channel);
      if (!std::isfinite(value))
      {
        throw shadelab::Error(std::string(fileName) + ": pixel x " + std::to_string(x) + ", y " + std::to_string(row) +
          " (from the top left), channel " + std::to_string(channel) + ": " +
          (std::isnan(value) ? "nan" : value > 0 ? "inf" : "-inf") + " is not a finite number");
      }
    }
  }
}

void slGetSurfaceFrames(vtkPolyData* input, bool needTangents, slSurfaceFrames& frames)
{
  const vtkIdType bad = slFirstNonFinitePoint(input->GetPoints());
  if (bad >= 0)
  {
    throw shadelab::Error("point " + std::to_string(bad) + " has a NaN or infinite coordinate");
  }
  const std::string cellProblem = slConnectivityProblem(input);
  if (!cellProblem.empty())
  {
    throw shadelab::Error(cellProblem);
  }
  vtkDataArray* tc = input->GetPointData()->GetTCoords();
  if (!tc || tc->GetNumberOfComponents() < 2)
  {
    throw shadelab::Error("no texture coordinates (UVs): surface detail needs a 2-component point TCoords array");
  }
  vtkSmartPointer<vtkPolyData> mesh = input;
  if (!mesh->GetPointData()->GetNormals())
  {
    vtkNew<slPolyDataNormals> normals;
    normals->SetInputData(mesh);
    normals->SplittingOff();
    normals->ConsistencyOff();
    slUpdateOrThrow(normals);
    mesh = normals->GetOutput();
  }
  if (needTangents && !mesh->GetPointData()->GetArray("Tangents"))
  {
    vtkNew<slPolyDataTangents> tangents;
    tangents->SetInputData(mesh);
    slUpdateOrThrow(tangents);
    mesh = tangents->GetOutput();
  }
  frames.mesh = mesh;
  const vtkIdType n = mesh->GetNumberOfPoints();
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  vtkDataArray* tangents = mesh->GetPointData()->GetArray("Tangents");
  tc = mesh->GetPointData()->GetTCoords();
  frames.normal.resize(static_cast<size_t>(n));
  frames.uv.resize(static_cast<size_t>(n));
  frames.tangent.assign(static_cast<size_t>(n), glm::dvec3(1, 0, 0));
  frames.handedness.assign(static_cast<size_t>(n), 1.0);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double v[4];
    normals->GetTuple(i, v);
    const glm::dvec3 nv(v[0], v[1], v[2]);
    frames.normal[static_cast<size_t>(i)] = glm::length(nv) > 0 ? glm::normalize(nv) : glm::dvec3(0, 0, 1);
    frames.uv[static_cast<size_t>(i)] = glm::dvec2(tc->GetComponent(i, 0), tc->GetComponent(i, 1));
    if (tangents && needTangents)
    {
      tangents->GetTuple(i, v);
      frames.tangent[static_cast<size_t>(i)] = glm::dvec3(v[0], v[1], v[2]);
      frames.handedness[static_cast<size_t>(i)] = tangents->GetNumberOfComponents() >= 4 && v[3] < 0 ? -1.0 : 1.0;
    }
  }
}

void slPrepareDetail(vtkPolyData* input, const char* fileName, bool needTangents, int channelsRead,
  slSurfaceFrames& frames, slnormals::Texture& texture)
{
  slGetSurfaceFrames(input, needTangents, frames);
  slLoadTexture(fileName, texture);
  for (int channel = 0; channel < std::min(channelsRead, texture.channels); ++channel)
  {
    slCheckFiniteChannel(texture, channel, fileName);
  }
}

void slOutputWithNormals(vtkPolyData* output, vtkPolyData* mesh, const std::vector<glm::dvec3>& normals)
{
  output->ShallowCopy(mesh);
  vtkNew<vtkFloatArray> array;
  array->SetName("Normals");
  array->SetNumberOfComponents(3);
  slSetNumberOfTuplesOrThrow(array, static_cast<vtkIdType>(normals.size()));
  for (size_t i = 0; i < normals.size(); ++i)
  {
    array->SetTuple3(static_cast<vtkIdType>(i), normals[i].x, normals[i].y, normals[i].z);
  }
  output->GetPointData()->RemoveArray("Normals");
  output->GetPointData()->SetNormals(array);
}
