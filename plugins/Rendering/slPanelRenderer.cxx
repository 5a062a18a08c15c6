#include "slPanelRenderer.h"

#include "shadelab/SceneLimits.h"

#include <vtkImageData.h>

#include <algorithm>

slPanelRenderer::slPanelRenderer() = default;
slPanelRenderer::~slPanelRenderer() = default;

void slPanelRenderer::SetPanelWidth(int width)
{
  width = std::max(shadelab::kMinImageSize, std::min(width, shadelab::kMaxImageSize));
  if (width != this->PanelWidth)
  {
    this->PanelWidth = width;
    this->Modified();
  }
}

void slPanelRenderer::SetPanelHeight(int height)
{
  height = std::max(shadelab::kMinImageSize, std::min(height, shadelab::kMaxImageSize));
  if (height != this->PanelHeight)
  {
    this->PanelHeight = height;
    this->Modified();
  }
}

vtkImageData* slPanelRenderer::GetImage()
{
  return this->Image;
}

void slPanelRenderer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PanelSize: " << this->PanelWidth << " x " << this->PanelHeight << "\n";
}
