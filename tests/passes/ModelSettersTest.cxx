// Every VTK setter that takes a lighting model as a number rejects one that
// is not a row of LightingTables.h: one error naming the valid models, and
// the model stays as it was (never clamped to another model).
#include "shadelab/LightingTables.h"
#include "shadelab/Scene.h"
#include "slBRDFLobeSource.h"
#include "slComparisonRenderer.h"
#include "slLightingPass.h"
#include "slRadianceFilter.h"
#include "slScene.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkNew.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace
{
/// The error messages @p object reports during @p call.
template <typename Call>
std::vector<std::string> errorsDuring(vtkObject* object, Call&& call)
{
  std::vector<std::string> errors;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetClientData(&errors);
  observer->SetCallback([](vtkObject*, unsigned long, void* list, void* message) {
    static_cast<std::vector<std::string>*>(list)->push_back(static_cast<const char*>(message));
  });
  const unsigned long tag = object->AddObserver(vtkCommand::ErrorEvent, observer);
  call();
  object->RemoveObserver(tag);
  return errors;
}

/// The error messages @p object reports while @p model is set.
template <typename T>
std::vector<std::string> errorsSettingModel(T* object, int model)
{
  return errorsDuring(object, [&] { object->SetModel(model); });
}

/// Expects @p call to return false with one error that holds @p text.
template <typename Call>
void expectOneError(vtkObject* object, Call&& call, const std::string& text)
{
  bool result = true;
  const std::vector<std::string> errors = errorsDuring(object, [&] { result = call(); });
  EXPECT_FALSE(result) << text;
  ASSERT_EQ(errors.size(), 1u) << text;
  EXPECT_NE(errors[0].find(text), std::string::npos) << errors[0];
}

template <typename T>
void expectRejected(T* object, int model, int kept)
{
  const std::vector<std::string> errors = errorsSettingModel(object, model);
  ASSERT_EQ(errors.size(), 1u) << object->GetClassName() << " accepted model " << model;
  EXPECT_NE(errors[0].find("SetModel: " + std::to_string(model) + " is not a lighting model (0 lambert, 1 phong"),
    std::string::npos)
    << errors[0];
  EXPECT_EQ(object->GetModel(), kept) << object->GetClassName();
}

template <typename T>
void expectAccepted(T* object, int model)
{
  EXPECT_TRUE(errorsSettingModel(object, model).empty()) << object->GetClassName() << " model " << model;
  EXPECT_EQ(object->GetModel(), model) << object->GetClassName();
}
} // namespace

TEST(ModelSetters, AcceptEveryRowAndRejectEverythingElse)
{
  vtkNew<slLightingPass> pass;
  vtkNew<slBRDFLobeSource> lobe;
  vtkNew<slRadianceFilter> radiance;
  for (const shadelab::LightingModelInfo& m : shadelab::kLightingModels)
  {
    expectAccepted(pass.Get(), static_cast<int>(m.model));
    expectAccepted(lobe.Get(), static_cast<int>(m.model));
    expectAccepted(radiance.Get(), static_cast<int>(m.model));
  }
  const int last = shadelab::kLightingModelCount - 1;
  for (int bad : { shadelab::kLightingModelCount, 99, -2 })
  {
    expectRejected(pass.Get(), bad, last);
    expectRejected(lobe.Get(), bad, last);
    expectRejected(radiance.Get(), bad, last);
  }
  expectRejected(pass.Get(), -1, last);
  expectRejected(lobe.Get(), -1, last);
  expectAccepted(radiance.Get(), -1); // the lighting filters' "the scene's own"
}

TEST(ModelSetters, ByNameAsInSceneFiles)
{
  // Each row's scene-file name sets its number and reads back; other names
  // change nothing.
  vtkNew<slLightingPass> pass;
  vtkNew<slBRDFLobeSource> lobe;
  vtkNew<slRadianceFilter> radiance;
  EXPECT_EQ(radiance->GetModelName(), "") << "the scene's own model has no name of its own";
  for (const shadelab::LightingModelInfo& m : shadelab::kLightingModels)
  {
    EXPECT_TRUE(pass->SetModelName(m.name)) << m.name;
    EXPECT_TRUE(lobe->SetModelName(m.name)) << m.name;
    EXPECT_TRUE(radiance->SetModelName(m.name)) << m.name;
    EXPECT_EQ(pass->GetModel(), static_cast<int>(m.model)) << m.name;
    EXPECT_EQ(lobe->GetModel(), static_cast<int>(m.model)) << m.name;
    EXPECT_EQ(radiance->GetModel(), static_cast<int>(m.model)) << m.name;
    EXPECT_EQ(lobe->GetModelName(), m.name);
    EXPECT_EQ(radiance->GetModelName(), m.name);
  }
  const int last = static_cast<int>(shadelab::kLightingModels[shadelab::kLightingModelCount - 1].model);
  for (const char* bad : { "Phong", "blinn phong", "", "6" })
  {
    // One error naming the models, as scene files spell them.
    const std::string text = std::string("SetModelName: \"") + bad + "\" is not a lighting model (lambert, phong,";
    expectOneError(lobe, [&] { return lobe->SetModelName(bad); }, text);
    expectOneError(radiance, [&] { return radiance->SetModelName(bad); }, text);
    expectOneError(pass, [&] { return pass->SetModelName(bad); }, text);
  }
  expectOneError(radiance, [&] { return radiance->SetModelName(nullptr); }, "SetModelName: (null) is not a lighting model");
  EXPECT_EQ(lobe->GetModel(), last);
  EXPECT_EQ(radiance->GetModel(), last);
  EXPECT_EQ(pass->GetModel(), last);
}

TEST(ModelSetters, SceneFrequencyAndComparisonPanelsByName)
{
  // The scene, the pass's frequency and a comparison's panels take names too,
  // and say which there are when one is not.
  vtkNew<slScene> scene;
  vtkNew<slLightingPass> pass;
  vtkNew<slComparisonRenderer> comparison;
  EXPECT_TRUE(scene->SetModelName("ward"));
  EXPECT_TRUE(scene->SetFrequencyName("flat"));
  EXPECT_TRUE(pass->SetFrequencyName("gouraud"));
  expectOneError(scene, [&] { return scene->SetModelName("Ward"); },
    "SetModelName: \"Ward\" is not a lighting model (lambert, phong,");
  expectOneError(scene, [&] { return scene->SetFrequencyName("smooth"); },
    "SetFrequencyName: \"smooth\" is not a shading frequency (flat, gouraud, phong)");
  expectOneError(pass, [&] { return pass->SetFrequencyName(nullptr); },
    "SetFrequencyName: (null) is not a shading frequency (flat, gouraud, phong)");
  EXPECT_EQ(scene->GetModelName(), "ward");
  EXPECT_EQ(scene->GetFrequencyName(), "flat");
  EXPECT_EQ(pass->GetFrequency(), static_cast<int>(shadelab::ShadingFrequency::Gouraud));
  expectOneError(comparison, [&] { return comparison->AddPanel("a", "toon", "phong"); },
    "AddPanel: \"toon\" is not a lighting model (lambert, phong,");
  expectOneError(comparison, [&] { return comparison->AddPanel("a", "phong", "smooth"); },
    "AddPanel: \"smooth\" is not a shading frequency (flat, gouraud, phong)");
  EXPECT_EQ(comparison->GetNumberOfPanels(), 0);
  EXPECT_TRUE(comparison->AddPanel("a", "phong", "flat"));
}
