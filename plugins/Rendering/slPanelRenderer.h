#ifndef slPanelRenderer_h
#define slPanelRenderer_h
/**
 * @class   slPanelRenderer
 * @brief   Base of ShadeLab's composite-image renderers: panels of a fixed
 *          size, one offscreen render, the image, and a one-line error.
 *
 * Subclasses lay out their panels in Render(), which returns false and sets
 * the error message on failure; GetImage() then holds the last good image.
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
  /// Size of one panel in pixels.
  vtkSetClampMacro(PanelWidth, int, 16, 4096);
  vtkGetMacro(PanelWidth, int);
  vtkSetClampMacro(PanelHeight, int, 16, 4096);
  vtkGetMacro(PanelHeight, int);
  ///@}

  /// Renders all panels. False, with GetErrorMessage(), on failure.
  virtual bool Render() = 0;

  /// The composite image (RGB, unsigned char, row 0 at the bottom).
  vtkImageData* GetImage();

  /// Why the last Render() failed, or "".
  const char* GetErrorMessage() const { return this->ErrorMessage.c_str(); }

protected:
  slPanelRenderer();
  ~slPanelRenderer() override;

  vtkSmartPointer<vtkImageData> Image;
  std::string ErrorMessage;
  int PanelWidth = 400;
  int PanelHeight = 300;

private:
  slPanelRenderer(const slPanelRenderer&) = delete;
  void operator=(const slPanelRenderer&) = delete;
};

#endif
