/**
 * @file slLightingPassQueries.cxx
 * @brief What slLightingPass reads off VTK's actors, mappers and shader
 * sources (see slLightingPassQueries.h).
 */
#include "slLightingPassQueries.h"

#include <vtkActor.h>
#include <vtkDataArray.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>

namespace slLightingPassQueries
{

bool contains(const std::string& text, const char* what)
{
  return text.find(what) != std::string::npos;
}

bool hasTangentsWithHandedness(vtkAbstractMapper* mapper)
{
  auto* polyMapper = vtkOpenGLPolyDataMapper::SafeDownCast(mapper);
  vtkPolyData* input = polyMapper ? polyMapper->GetInput() : nullptr;
  vtkDataArray* tangents = input ? input->GetPointData()->GetArray("Tangents") : nullptr;
  return tangents && tangents->GetNumberOfComponents() == 4;
}

bool isLitOpaqueActor(vtkActor* actor)
{
  return actor && actor->GetMapper() && !actor->HasTranslucentPolygonalGeometry() &&
    actor->GetProperty()->GetLighting();
}

bool isOurs(vtkAbstractMapper* mapper, vtkProp* prop)
{
  return vtkOpenGLPolyDataMapper::SafeDownCast(mapper) && isLitOpaqueActor(vtkActor::SafeDownCast(prop));
}

bool drawsScalarColours(const std::string& fragmentShader)
{
  return contains(fragmentShader, "vertexColorVSOutput") || contains(fragmentShader, "colortexture") ||
    contains(fragmentShader, "textureC");
}

bool hasActorTexture(const std::string& fragmentShader)
{
  return contains(fragmentShader, "actortexture") && contains(fragmentShader, "tcoordVCVSOutput");
}

bool textureFrontOnly(vtkProp* prop)
{
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  return actor && !actor->GetProperty()->GetShowTexturesOnBackface();
}

} // namespace slLightingPassQueries
