#include "slLightingRenderView.h"

#include "slLightingPass.h"
#include "slScene.h"

#include <vtkObjectFactory.h>
#include <vtkPVSynchronizedRenderer.h>

vtkStandardNewMacro(slLightingRenderView);

slLightingRenderView::slLightingRenderView()
{
  // The geometry pass: ParaView keeps its camera pass and compositing around it.
  this->SynchronizedRenderers->SetRenderPass(this->Pass);
}

slLightingRenderView::~slLightingRenderView() = default;

void slLightingRenderView::SetSceneFileName(const char* fileName)
{
  const std::string name = fileName ? fileName : "";
  if (name == this->SceneFileName)
  {
    return;
  }
  // The scene sets the pass's model and frequency too: keep the view's.
  const int model = this->Pass->GetModel();
  const int frequency = this->Pass->GetFrequency();
  if (name.empty())
  {
    this->Pass->SetScene(nullptr);
  }
  else
  {
    vtkNew<slScene> scene;
    if (!scene->ReadFile(name.c_str()))
    {
      return; // the scene has reported the one-line reason through vtkErrorMacro
    }
    this->Pass->SetScene(scene);
  }
  this->Pass->SetModel(model);
  this->Pass->SetFrequency(frequency);
  this->SceneFileName = name;
  this->Modified();
}

void slLightingRenderView::SetLightingModel(int model)
{
  this->Pass->SetModel(model);
  this->Modified();
}

int slLightingRenderView::GetLightingModel()
{
  return this->Pass->GetModel();
}

void slLightingRenderView::SetShadingFrequency(int frequency)
{
  this->Pass->SetFrequency(frequency);
  this->Modified();
}

int slLightingRenderView::GetShadingFrequency()
{
  return this->Pass->GetFrequency();
}

void slLightingRenderView::SetUseSceneMaterial(bool use)
{
  this->Pass->SetUseSceneMaterial(use);
  this->Modified();
}

bool slLightingRenderView::GetUseSceneMaterial()
{
  return this->Pass->GetUseSceneMaterial();
}

void slLightingRenderView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SceneFileName: " << this->SceneFileName << "\n";
  os << indent << "Pass: " << this->Pass.GetPointer() << "\n";
}
