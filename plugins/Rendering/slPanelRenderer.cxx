#include "slPanelRenderer.h"

#include <vtkImageData.h>

slPanelRenderer::slPanelRenderer() = default;
slPanelRenderer::~slPanelRenderer() = default;

vtkImageData* slPanelRenderer::GetImage()
{
  return this->Image;
}

void slPanelRenderer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PanelSize: " << this->PanelWidth << " x " << this->PanelHeight << "\n";
}
