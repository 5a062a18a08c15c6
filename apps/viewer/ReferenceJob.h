#ifndef shadelab_viewer_ReferenceJob_h
#define shadelab_viewer_ReferenceJob_h
/**
 * @class   ReferenceJob
 * @brief   Runs slRadianceReference (the Monte Carlo estimate of the
 *          radiance equation) on a worker thread, with progress and cancel.
 *
 * The job works on its own copies of the mesh, scene and camera, so the user
 * can go on editing while it runs. Progress arrives as progress(percent) in
 * the GUI thread; finished() brings the output mesh (Radiance,
 * RadianceStdError, DiscreteRadiance, RadianceError, ...) or an error.
 * cancel() asks the filter to stop at its next batch (it checks after each
 * 2% of the points) and finished() then reports "cancelled".
 *
 * @warning vtkAlgorithm's abort flag is a plain int in VTK 9.1; it is only
 * written by cancel() and read by the filter, which is benign on the
 * platforms ShadeLab targets.
 */

#include "shadelab/Scene.h"

#include <vtkSmartPointer.h>

#include <QObject>
#include <QString>

#include <atomic>

class QThread;
class slRadianceReference;
class vtkCamera;
class vtkObject;
class vtkPolyData;

namespace shadelab
{
namespace viewer
{

/// What the reference is computed with.
struct ReferenceSettings
{
  int samplesPerPoint = 64;
  int strategy = 4; ///< slRadianceReference::Strategies; MIS by default
  QString environmentMap; ///< "" for none
  bool useSceneLights = true;
};

class ReferenceJob : public QObject
{
  Q_OBJECT
public:
  explicit ReferenceJob(QObject* parent = nullptr);
  ~ReferenceJob() override;

  /// Starts a job unless one is running (returns false then).
  bool start(vtkPolyData* mesh, const Scene& scene, vtkCamera* camera, const ReferenceSettings& settings);
  void cancel();
  bool running() const { return this->Running; }
  /// Blocks until the running job (if any) has finished.
  void wait();
  /// The output of the last successful job, or null.
  vtkPolyData* result() const;

signals:
  void progress(int percent);
  /// The job ended: @p error is "" on success (result() has the output),
  /// "cancelled" after cancel(), or the filter's one-line error.
  void finished(const QString& error);

private:
  void onProgress(vtkObject* caller, unsigned long event, void* data);

  vtkSmartPointer<slRadianceReference> Filter;
  vtkSmartPointer<vtkPolyData> Result;
  QThread* Thread = nullptr;
  std::atomic<bool> Running{ false };
  std::atomic<bool> Cancelled{ false };
};

} // namespace viewer
} // namespace shadelab

#endif
