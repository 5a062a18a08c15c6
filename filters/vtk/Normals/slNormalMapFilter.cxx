#include "slNormalMapFilter.h"

#include "slDetailInputs.h"

#include "shadelab/LightingGLSLDouble.h"

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>

namespace glsld = shadelab::glsld;

vtkStandardNewMacro(slNormalMapFilter);

slNormalMapFilter::slNormalMapFilter() = default;

slNormalMapFilter::~slNormalMapFilter() = default;

int slNormalMapFilter::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  slSurfaceFrames frames;
  slnormals::Texture map;
  if (!this->PrepareDetail(input, output, "Strength", this->Strength, true, 3, frames, map))
  {
    return 0;
  }
  if (map.channels < 3)
  {
    return this->Fail(std::string(this->FileName) + ": a normal map needs 3 channels (RGB), the image has " + std::to_string(map.channels), output);
  }
  std::vector<glm::dvec3> normals(frames.normal.size());
  vtkSMPTools::For(0, static_cast<vtkIdType>(normals.size()), 4096, [&](vtkIdType b, vtkIdType e) {
    for (vtkIdType i = b; i < e; ++i)
    {
      const size_t s = static_cast<size_t>(i);
      const glm::dvec2 uv = frames.uv[s];
      const glm::dvec3 rgb(map.sample(uv.x, uv.y, 0), map.sample(uv.x, uv.y, 1), map.sample(uv.x, uv.y, 2));
      const glm::dvec3 ts = glsld::slDecodeNormal(rgb, this->GreenDown ? -1.0 : 1.0, this->Strength);
      normals[s] = glsld::slTangentToSurface(ts, frames.normal[s], frames.tangent[s], frames.handedness[s]);
    }
  });
  slOutputWithNormals(output, frames.mesh, normals);
  return 1;
}

void slNormalMapFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Strength: " << this->Strength << "\n";
  os << indent << "GreenDown: " << this->GreenDown << "\n";
}
