#ifndef shadelab_app_BaseColourOptions_h
#define shadelab_app_BaseColourOptions_h
/**
 * @file BaseColourOptions.h
 * @brief The base colour of `shadelab light` and `shadelab reference`:
 * --diffuse-array NAME, --diffuse-texture FILE, or by default the scene's
 * material.diffuseTexture. One set of options and one way of applying them,
 * so the discrete lighting and the Monte Carlo reference are given the same
 * colour from the same command line.
 */

#include "CommandLine.h"

#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class slBaseColouredFilter;
class slScene;
class vtkImageData;
class vtkPolyData;

namespace shadelab
{
namespace app
{

/// --diffuse-array NAME and --diffuse-texture FILE.
std::vector<OptionSpec> baseColourOptions();

/// Before any work: --diffuse-array and --diffuse-texture are not both
/// given. Throws UsageError.
void checkBaseColourOptions(const CommandLine& cl);

/// The base colour the options choose, for one filter lighting one mesh
/// after another.
class BaseColour
{
public:
  /// Checks the options (checkBaseColourOptions()) and reads the texture
  /// once: --diffuse-texture FILE, or without either option the scene's
  /// material.diffuseTexture (slReadSceneTexture()). Throws UsageError or
  /// shadelab::Error naming the image.
  BaseColour(const CommandLine& cl, slScene* scene);

  /// The array name or texture onto @p filter for @p mesh: --diffuse-array
  /// and --diffuse-texture for every mesh, the scene's texture only for a mesh
  /// with texture coordinates (render draws one without them untextured).
  /// Both slRadianceFilter and slRadianceReference take it.
  void applyTo(slBaseColouredFilter* filter, vtkPolyData* mesh) const;

  /// What applyTo() gives: the array name ("" for none) and the texture for @p mesh.
  const std::string& arrayName() const { return this->ArrayName; }
  vtkImageData* textureFor(vtkPolyData* mesh) const;

private:
  std::string ArrayName;
  vtkSmartPointer<vtkImageData> Texture;
  bool SceneTexture = false; // Texture is the scene's, for meshes with texture coordinates only
};

} // namespace app
} // namespace shadelab

#endif
