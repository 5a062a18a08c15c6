#ifndef slPanelRenderer_h
#define slPanelRenderer_h
/**
 * @class   slPanelRenderer
 * @brief   Base of ShadeLab's composite-image renderers: panels of a fixed
 *          size, one offscreen render and the image.
 *
 * Subclasses lay out their panels in Render(), which on failure reports one
 * line through vtkErrorMacro and returns false (slCallOrThrow() gives the
 * line back); GetImage() then holds the last good image.
 *
 * @sa slComparisonRenderer slFieldImageRenderer slLobeImageRenderer
 */

#include "ShadeLabRenderPassesModule.h"

#include <vtkObject.h>
#include <vtkSmartPointer.h>

#include <string>

class vtkImageData;

class SHADELABRENDERPASSES_EXPORT slPanelRenderer : public vtkObject
{
public:
  vtkTypeMacro(slPanelRenderer, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Size of one panel in pixels, clamped to the image sizes of a scene
  /// (shadelab::kMinImageSize to kMaxImageSize, SceneLimits.h; `shadelab
  /// --size` takes the same). A composite of several panels must still fit
  /// slMaximumWindowSize (slOffscreen.h): Render() refuses a larger one.
  void SetPanelWidth(int width);
  vtkGetMacro(PanelWidth, int);
  void SetPanelHeight(int height);
  vtkGetMacro(PanelHeight, int);
  ///@}

  /// Renders all panels. False, after vtkErrorMacro, on failure.
  virtual bool Render() = 0;

  /// The composite image (RGB, unsigned char, row 0 at the bottom).
  vtkImageData* GetImage();

protected:
  slPanelRenderer();
  ~slPanelRenderer() override;

  vtkSmartPointer<vtkImageData> Image;
  int PanelWidth = 400;
  int PanelHeight = 300;

private:
  slPanelRenderer(const slPanelRenderer&) = delete;
  void operator=(const slPanelRenderer&) = delete;
};

#endif
