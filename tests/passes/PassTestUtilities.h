#ifndef shadelab_tests_PassTestUtilities_h
#define shadelab_tests_PassTestUtilities_h
// Offscreen rendering helpers for the render-pass tests: fixed window size,
// fixed camera, multisampling off.

#include "shadelab/Scene.h"

#include <vtkSmartPointer.h>

#include <functional>
#include <vector>

class slLightingPass;
class vtkActor;
class vtkImageData;
class vtkPolyData;
class vtkRenderer;
class vtkRenderWindow;

namespace passtest
{

/// An RGB image as floats in [0, 1], row 0 at the bottom.
struct Image
{
  int width = 0;
  int height = 0;
  std::vector<float> rgb;
  const float* at(int x, int y) const { return &rgb[3 * (static_cast<size_t>(y) * width + x)]; }
  float luminance(int x, int y) const;
};

/// A window, renderer and actor for @p mesh, with the scene's camera (which
/// must give a position) and background, at @p width x @p height.
struct Stage
{
  vtkSmartPointer<vtkRenderWindow> window;
  vtkSmartPointer<vtkRenderer> renderer;
  vtkSmartPointer<vtkActor> actor;
  vtkSmartPointer<slLightingPass> pass; ///< null for unlit stages

  Image render();
  /// Display coordinates (pixels) of a world point.
  void toDisplay(const double world[3], double display[2]);
};

/// Renders through an slLightingPass configured from @p scene.
Stage litStage(vtkPolyData* mesh, const shadelab::Scene& scene, int width, int height);

/// Renders @p mesh unlit with its RGB point (or cell) scalars as colours.
Stage unlitStage(vtkPolyData* mesh, const shadelab::Scene& scene, int width, int height, bool cellScalars);

/// The CPU lighting of every point of @p mesh (which must have point
/// normals): slRadianceFilter's Radiance, as unsigned char RGB scalars.
void colourPointsOnCPU(vtkPolyData* mesh, const shadelab::Scene& scene);

/// Pixels covered in @p image (differing from @p background) whose 8
/// neighbours are covered too: the pixels away from silhouettes.
std::vector<bool> interiorMask(const Image& image, const glm::vec3& background);

/// How two images of the same size agree on the pixels of @p mask: how many
/// there are, how many differ by at most 2/255 in every channel, and the
/// largest difference.
struct Agreement
{
  long covered = 0;
  long agreeing = 0;
  float worst = 0.0f;
};
Agreement agreement(const Image& a, const Image& b, const std::vector<bool>& mask);

} // namespace passtest

#endif
