#ifndef slLightingRenderView_h
#define slLightingRenderView_h
/**
 * @class   slLightingRenderView
 * @brief   ParaView's render view with ShadeLab's lighting: opaque geometry is
 *          drawn through slLightingPass.
 *
 * A vtkPVRenderView whose geometry pass (vtkPVSynchronizedRenderer::
 * SetRenderPass(), inside ParaView's camera and compositing passes) is an
 * slLightingPass, so every representation's opaque surfaces are lit by
 * ShadeLab's lighting equation: every model, light type and shading
 * frequency, on one process or composited over MPI ranks like any render
 * view.
 *
 * Without a scene file the pass lights with the view's own lights (ParaView's
 * light kit and headlight, and lights added in the Lights panel) and each
 * representation's material (its vtkProperty); with SetSceneFileName() the
 * scene's lights replace them and, with UseSceneMaterial, its material too.
 * A scene file that cannot be read is reported with vtkErrorMacro (the file,
 * the place and the reason) and the view keeps its previous lighting.
 *
 * @warning Translucent geometry, volumes and ParaView's own special passes
 * (OSPRay, SSAO, tone mapping) keep VTK's lighting, as they do under
 * slLightingPass anywhere. Only in ParaView: it builds against ParaView's
 * RemotingViews module.
 *
 * @sa slLightingPass vtkPVRenderView
 */

#include "ShadeLabParaViewViewsModule.h"

#include <vtkNew.h>
#include <vtkPVRenderView.h>

#include <string>

class slLightingPass;

class SHADELABPARAVIEWVIEWS_EXPORT slLightingRenderView : public vtkPVRenderView
{
public:
  static slLightingRenderView* New();
  vtkTypeMacro(slLightingRenderView, vtkPVRenderView);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// A ShadeLab JSON scene whose lights (and, with UseSceneMaterial, whose
  /// material) light the view; "" or null (default): the view's own lights.
  void SetSceneFileName(const char* fileName);
  const char* GetSceneFileName() const { return this->SceneFileName.c_str(); }
  ///@}

  ///@{
  /// Lighting model: a row of the model table (shadelab/LightingTables.h,
  /// the values of slLighting.glsl's SL_MODEL_* constants); another value is
  /// reported and ignored. Blinn-Phong (2) by default.
  void SetLightingModel(int model);
  int GetLightingModel();
  ///@}

  ///@{
  /// Shading frequency: slLightingPass::FLAT (0), GOURAUD (1), PHONG (2, default).
  void SetShadingFrequency(int frequency);
  int GetShadingFrequency();
  ///@}

  ///@{
  /// With a scene file: its material (on, default) or each representation's
  /// (off).
  void SetUseSceneMaterial(bool use);
  bool GetUseSceneMaterial();
  ///@}

protected:
  slLightingRenderView();
  ~slLightingRenderView() override;

private:
  slLightingRenderView(const slLightingRenderView&) = delete;
  void operator=(const slLightingRenderView&) = delete;

  vtkNew<slLightingPass> Pass;
  std::string SceneFileName;
};

#endif
