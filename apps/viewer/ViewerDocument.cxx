#include "ViewerDocument.h"

#include "slLightingPass.h"
#include "slLitFilter.h"
#include "slMeshReader.h"
#include "slPolyDataTangents.h"
#include "slScene.h"
#include "slUpdateOrThrow.h"

#include "shadelab/BrdfFile.h"
#include "shadelab/Error.h"
#include "shadelab/DefaultScene.h"

#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <QFileInfo>

namespace shadelab
{
namespace viewer
{

ViewerDocument::ViewerDocument(QObject* parent)
  : QObject(parent)
  , SceneObject(vtkSmartPointer<slScene>::New())
{
  this->SceneObject->SetScene(defaultScene());
}

ViewerDocument::~ViewerDocument() = default;

bool ViewerDocument::openMesh(const QString& path, QString& error)
{
  vtkNew<slMeshReader> reader;
  const QByteArray file = path.toLocal8Bit();
  reader->SetFileName(file.constData());
  try
  {
    slUpdateOrThrow(reader);
  }
  catch (const shadelab::Error& e)
  {
    error = QString::fromLocal8Bit(e.what());
    return false;
  }
  this->Mesh = reader->GetOutput();
  this->MeshPath = path;
  emit meshChanged();
  return true;
}

bool ViewerDocument::openScene(const QString& path, QString& error)
{
  auto read = vtkSmartPointer<slScene>::New();
  const QByteArray file = path.toLocal8Bit();
  try
  {
    slCallOrThrow(read, [&] { return read->ReadFile(file.constData()); });
    // As `shadelab render`: the pass would leave the last lights out of the picture.
    const std::string tooMany = slLightingPass::GetLightCountProblem(read->GetNumberOfLights());
    if (!tooMany.empty())
    {
      throw Error(file.toStdString() + ": " + tooMany);
    }
  }
  catch (const shadelab::Error& e)
  {
    error = QString::fromLocal8Bit(e.what());
    return false;
  }
  this->SceneObject = read;
  this->ScenePath = path;
  emit sceneChanged(EveryChange);
  return true;
}

bool ViewerDocument::openBrdf(const QString& path, QString& error)
{
  const std::string file = QFileInfo(path).absoluteFilePath().toLocal8Bit().toStdString();
  try
  {
    shadelab::readBrdfFile(file);
  }
  catch (const shadelab::Error& e)
  {
    error = QString::fromStdString(e.what());
    return false;
  }
  Scene scene = this->scene();
  scene.brdf.file = file; // absolute: the scene may be saved anywhere
  scene.brdf.parameters.clear();
  this->setScene(scene, ShadingChange);
  return true;
}

bool ViewerDocument::saveScene(const QString& path, QString& error)
{
  const QByteArray file = path.toLocal8Bit();
  try
  {
    slCallOrThrow(this->SceneObject, [&] { return this->SceneObject->WriteFile(file.constData()); });
  }
  catch (const shadelab::Error& e)
  {
    error = QString::fromLocal8Bit(e.what());
    return false;
  }
  this->ScenePath = path;
  return true;
}

const Scene& ViewerDocument::scene() const
{
  return this->SceneObject->GetScene();
}

slScene* ViewerDocument::vtkScene() const
{
  return this->SceneObject;
}

void ViewerDocument::setScene(const Scene& scene, int changes)
{
  this->SceneObject->SetScene(scene);
  emit sceneChanged(changes);
}

void ViewerDocument::recordCamera(vtkCamera* camera)
{
  this->SceneObject->SetCameraFromVTK(camera);
}

vtkPolyData* ViewerDocument::mesh() const
{
  return this->Mesh;
}

QString ViewerDocument::meshPath() const
{
  return this->MeshPath;
}

QString ViewerDocument::scenePath() const
{
  return this->ScenePath;
}

void ViewerDocument::setNormals(const NormalsSettings& settings)
{
  this->Normals = settings;
  emit normalsChanged();
}

QString ViewerDocument::tangentsProblem() const
{
  const ShadingModel model = this->scene().model;
  if (!this->Mesh || !modelNeedsTangents(model) || slLitFilter::HasTangents(this->Mesh))
  {
    return QString();
  }
  const QString mesh = QFileInfo(this->MeshPath).fileName();
  const QString line = tr("%1 is anisotropic and needs the mesh's tangents: %2 has none")
                         .arg(QString::fromUtf8(modelName(model)), mesh.isEmpty() ? tr("the mesh") : mesh);
  return this->canComputeTangents()
    ? line + tr("; compute them from its texture coordinates (shading panel)")
    : line + tr(", and no texture coordinates to compute them from; it is drawn in a fixed frame around the normal");
}

bool ViewerDocument::canComputeTangents() const
{
  return this->Mesh && this->Mesh->GetPointData()->GetTCoords();
}

bool ViewerDocument::computeTangents(QString& error)
{
  if (!this->Mesh)
  {
    error = tr("no mesh to compute tangents for");
    return false;
  }
  vtkNew<slPolyDataTangents> tangents;
  tangents->SetInputData(this->Mesh);
  try
  {
    slUpdateOrThrow(tangents);
  }
  catch (const shadelab::Error& e)
  {
    error = this->MeshPath + ": " + QString::fromLocal8Bit(e.what());
    return false;
  }
  vtkSmartPointer<vtkPolyData> out = tangents->GetOutput();
  if (!this->Mesh->GetPointData()->GetNormals() && out->GetPointData()->GetNormals())
  {
    // The filter's own normals (no splitting) would override the normals settings.
    out->GetPointData()->RemoveArray(out->GetPointData()->GetNormals()->GetName());
  }
  this->Mesh = out;
  emit tangentsChanged();
  return true;
}

} // namespace viewer
} // namespace shadelab
