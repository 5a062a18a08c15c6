#include "slBumpMapFilter.h"

#include "slDetailInputs.h"

#include "shadelab/LightingGLSLDouble.h"

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>

namespace glsld = shadelab::glsld;

vtkStandardNewMacro(slBumpMapFilter);

slBumpMapFilter::slBumpMapFilter() = default;

slBumpMapFilter::~slBumpMapFilter() = default;

int slBumpMapFilter::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  slSurfaceFrames frames;
  slnormals::Texture height;
  if (!this->PrepareDetail(input, output, "Scale", this->Scale, true, 1, frames, height))
  {
    return 0;
  }
  // 1 − h has the gradient of h negated: invert through the scale's sign.
  const double scale = this->InvertHeight ? -this->Scale : this->Scale;
  std::vector<glm::dvec3> normals(frames.normal.size());
  vtkSMPTools::For(0, static_cast<vtkIdType>(normals.size()), 4096, [&](vtkIdType b, vtkIdType e) {
    for (vtkIdType i = b; i < e; ++i)
    {
      const size_t s = static_cast<size_t>(i);
      const glm::dvec3 ts = slnormals::bumpNormal(height, frames.uv[s].x, frames.uv[s].y, scale);
      normals[s] = glsld::slTangentToSurface(ts, frames.normal[s], frames.tangent[s], frames.handedness[s]);
    }
  });
  slOutputWithNormals(output, frames.mesh, normals);
  return 1;
}

void slBumpMapFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scale: " << this->Scale << "\n";
  os << indent << "InvertHeight: " << this->InvertHeight << "\n";
}
