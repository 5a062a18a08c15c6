#include "ViewerDocument.h"

#include "slMeshReader.h"
#include "slScene.h"
#include "slUpdateOrThrow.h"

#include "shadelab/DefaultScene.h"

#include <vtkNew.h>
#include <vtkPolyData.h>

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

} // namespace viewer
} // namespace shadelab
