#include "slSceneTexture.h"

#include "slScene.h"
#include "slUpdateOrThrow.h"

#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

vtkSmartPointer<vtkImageData> slReadSceneTexture(slScene* scene)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  slCallOrThrow(scene, [&] { return scene->ReadDiffuseTexture(image); });
  // ReadDiffuseTexture() leaves the image empty when the scene has no texture.
  return image->GetPointData()->GetScalars() ? image : nullptr;
}

vtkImageData* slSceneTextureFor(vtkImageData* texture, vtkPolyData* mesh)
{
  return texture && mesh->GetPointData()->GetTCoords() ? texture : nullptr;
}
