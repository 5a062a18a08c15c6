#include "ReferenceJob.h"

#include "slRadianceReference.h"
#include "slScene.h"
#include "slSceneTexture.h"
#include "slUpdateOrThrow.h"

#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkImageData.h>
#include <vtkPolyData.h>

#include <QMetaObject>
#include <QThread>

namespace shadelab
{
namespace viewer
{

ReferenceJob::ReferenceJob(QObject* parent)
  : QObject(parent)
{
}

ReferenceJob::~ReferenceJob()
{
  this->cancel();
  this->wait();
}

bool ReferenceJob::start(vtkPolyData* mesh, const Scene& scene, vtkCamera* camera, const ReferenceSettings& settings)
{
  if (this->Running)
  {
    return false;
  }
  this->wait(); // join the previous, finished thread
  auto input = vtkSmartPointer<vtkPolyData>::New();
  input->DeepCopy(mesh);
  auto sceneCopy = vtkSmartPointer<slScene>::New();
  sceneCopy->SetScene(scene);
  auto cameraCopy = vtkSmartPointer<vtkCamera>::New();
  cameraCopy->DeepCopy(camera);

  this->Filter = vtkSmartPointer<slRadianceReference>::New();
  this->Filter->SetInputData(input);
  this->Filter->SetScene(sceneCopy);
  this->Filter->SetCamera(cameraCopy);
  this->Filter->SetSamplesPerPoint(settings.samplesPerPoint);
  this->Filter->SetStrategy(settings.strategy);
  this->Filter->SetUseSceneLights(settings.useSceneLights);
  this->Filter->ZeroNormalsAreErrorsOff(); // isolated points have no normal; they get L_e + ambient
  const QByteArray environment = settings.environmentMap.toLocal8Bit();
  this->Filter->SetEnvironmentFileName(environment.isEmpty() ? nullptr : environment.constData());
  this->Filter->AddObserver(vtkCommand::ProgressEvent, this, &ReferenceJob::onProgress);

  this->Running = true;
  this->Cancelled = false;
  vtkSmartPointer<slRadianceReference> filter = this->Filter;
  this->Thread = QThread::create([this, filter, sceneCopy, input] {
    QString error;
    try
    {
      // The scene's diffuse texture, as the view draws it and
      // `shadelab light` and `shadelab reference` apply it; read here, off
      // the GUI thread.
      filter->SetDiffuseTexture(slSceneTextureFor(slReadSceneTexture(sceneCopy), input));
      slUpdateOrThrow(filter);
    }
    catch (const shadelab::Error& e)
    {
      error = QString::fromUtf8(e.what());
    }
    vtkSmartPointer<vtkPolyData> result = filter->GetOutput();
    if (this->Cancelled)
    {
      error = tr("cancelled");
    }
    if (!error.isEmpty())
    {
      result = nullptr;
    }
    QMetaObject::invokeMethod(
      this,
      [this, result, error] {
        this->Running = false;
        this->Result = result;
        emit finished(error);
      },
      Qt::QueuedConnection);
  });
  this->Thread->start();
  return true;
}

void ReferenceJob::onProgress(vtkObject*, unsigned long, void* data)
{
  // Called on the worker thread: hand the figure to the GUI thread.
  const int percent = static_cast<int>(100.0 * *static_cast<double*>(data));
  QMetaObject::invokeMethod(this, [this, percent] { emit progress(percent); }, Qt::QueuedConnection);
}

void ReferenceJob::cancel()
{
  if (this->Running && this->Filter)
  {
    this->Cancelled = true;
    this->Filter->AbortExecuteOn();
  }
}

vtkPolyData* ReferenceJob::result() const
{
  return this->Result;
}

void ReferenceJob::wait()
{
  if (this->Thread)
  {
    this->Thread->wait();
    delete this->Thread;
    this->Thread = nullptr;
  }
}

} // namespace viewer
} // namespace shadelab
