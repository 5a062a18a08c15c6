// slRunCore() and slUpdateOrThrow(): an error of the VTK-free code becomes a
// failed VTK request with VTK's error message, and comes back to the caller
// as the same one-line shadelab::Error.
#include "slCoreBoundary.h"
#include "slUpdateOrThrow.h"

#include "shadelab/SceneFile.h"

#include <vtkCallbackCommand.h>
#include <vtkExecutive.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataAlgorithm.h>

#include <gtest/gtest.h>

#include <string>

namespace
{
const std::string kMissingScene = "/nonexistent-shadelab-folder/scene.json";

/// A source that makes one point, then reads a scene file through the core.
class CoreProbe : public vtkPolyDataAlgorithm
{
public:
  static CoreProbe* New();
  vtkTypeMacro(CoreProbe, vtkPolyDataAlgorithm);
  std::string SceneFile;

protected:
  CoreProbe() { this->SetNumberOfInputPorts(0); }
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector) override
  {
    vtkPolyData* output = vtkPolyData::GetData(outputVector);
    vtkNew<vtkPoints> points;
    points->InsertNextPoint(0.0, 0.0, 0.0);
    output->SetPoints(points);
    return slRunCore(this, output, [this] { shadelab::readSceneFile(this->SceneFile); });
  }
};
vtkStandardNewMacro(CoreProbe);

/// Text of the last ErrorEvent of the object observed.
void keepMessage(vtkObject*, unsigned long, void* clientData, void* callData)
{
  *static_cast<std::string*>(clientData) = static_cast<const char*>(callData);
}
} // namespace

TEST(CoreBoundary, CoreErrorFailsTheUpdateWithItsMessage)
{
  vtkNew<CoreProbe> probe;
  probe->SceneFile = kMissingScene;
  std::string message;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetCallback(keepMessage);
  observer->SetClientData(&message);
  probe->AddObserver(vtkCommand::ErrorEvent, observer);

  EXPECT_EQ(probe->GetExecutive()->Update(), 0) << "the request must fail";
  EXPECT_EQ(probe->GetOutput()->GetNumberOfPoints(), 0) << "the output must be empty";
  // VTK's own message, heard through the filter's ErrorEvent.
  EXPECT_NE(message.find("CoreProbe"), std::string::npos) << message;
  EXPECT_NE(message.find(kMissingScene + ": cannot open scene file: No such file or directory"), std::string::npos) << message;
}

TEST(CoreBoundary, UpdateOrThrowGivesBackTheOneLine)
{
  vtkNew<CoreProbe> probe;
  probe->SceneFile = kMissingScene;
  try
  {
    slUpdateOrThrow(probe);
    ADD_FAILURE() << "slUpdateOrThrow must throw";
  }
  catch (const shadelab::Error& error)
  {
    EXPECT_EQ(std::string(error.what()), kMissingScene + ": cannot open scene file: No such file or directory");
  }
  EXPECT_FALSE(probe->HasObserver(vtkCommand::ErrorEvent)) << "the capture must stop watching";
}

TEST(CoreBoundary, SuccessPassesTheOutputOn)
{
  vtkNew<CoreProbe> probe;
  probe->SceneFile = std::string(SHADELAB_DATA_DIR) + "/scenes/default.json";
  EXPECT_NO_THROW(slUpdateOrThrow(probe));
  EXPECT_EQ(probe->GetOutput()->GetNumberOfPoints(), 1);
}

TEST(CoreBoundary, CallOrThrowTakesAFailedCall)
{
  vtkNew<CoreProbe> probe;
  try
  {
    slCallOrThrow(probe, [&] { return slRunCore(probe, [] { throw shadelab::Error("a.json: lights[2]: bad"); }); });
    ADD_FAILURE() << "slCallOrThrow must throw";
  }
  catch (const shadelab::Error& error)
  {
    EXPECT_EQ(std::string(error.what()), "a.json: lights[2]: bad");
  }
  EXPECT_NO_THROW(slCallOrThrow(probe, [] { return true; }));
}
