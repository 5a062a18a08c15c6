#ifndef slSceneTexture_h
#define slSceneTexture_h
/**
 * @file slSceneTexture.h
 * @brief A scene's material.diffuseTexture for the CPU lighting filters
 * (slRadianceFilter, slRadianceReference), mesh by mesh, as
 * `shadelab render` draws it. Not wrapped.
 *
 * `shadelab light`, `shadelab reference` and the viewer's reference job all
 * go through these two functions, so the discrete lighting and the Monte
 * Carlo reference see the same base colour at every point: the texture is
 * read once, and a mesh without point texture coordinates gets none (render
 * draws such a mesh untextured). The filters sample the texture per point
 * with the same code (slDiffuseColors.h).
 */

#include "ShadeLabLightingModule.h"

#include <vtkSmartPointer.h>

class slScene;
class vtkImageData;
class vtkPolyData;

/// @p scene's material.diffuseTexture as stored (slScene::ReadDiffuseTexture()),
/// or null when the scene has none. Throws shadelab::Error with the one-line
/// reason ("IMAGE: cannot read image: ... (material.diffuseTexture of SCENE)")
/// if it cannot be read.
SHADELABLIGHTING_EXPORT vtkSmartPointer<vtkImageData> slReadSceneTexture(slScene* scene);

/// What a lighting filter takes as its diffuse texture for @p mesh:
/// @p texture, or null if @p texture is null or @p mesh has no point texture
/// coordinates.
SHADELABLIGHTING_EXPORT vtkImageData* slSceneTextureFor(vtkImageData* texture, vtkPolyData* mesh);

#endif
