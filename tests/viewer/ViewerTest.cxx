// shadelab-viewer driven with QtTest under Xvfb: what the user does (open,
// drag a slider, switch the frequency, save and load, drop a file, pick a
// point, run the reference) and what the image must do in answer. Images are
// compared with `shadelab render`'s own renderer (slSceneRenderer) with the
// regression harness's metric: at most 0.2% of pixels off by more than 2/255.
#include "BrdfFilePanel.h"
#include "BrdfPanel.h"
#include "FieldsPanel.h"
#include "LightPanel.h"
#include "LightWidgets.h"
#include "MainWindow.h"
#include "MaterialPanel.h"
#include "NormalsPanel.h"
#include "NumberControl.h"
#include "ReferenceJob.h"
#include "SceneView.h"
#include "ShadingPanel.h"
#include "ViewerDocument.h"
#include "ColorButton.h"

#include "ImageComparison.h"

#include "slImageReader.h"
#include "slLitFilter.h"
#include "slMeshReader.h"
#include "slLightingPass.h"
#include "slRenderNormals.h"
#include "slScene.h"
#include "slSceneRenderer.h"
#include "VTKErrors.h"

#include "shadelab/SceneKeys.h"

#include <vtkActorCollection.h>
#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkLightRepresentation.h>
#include <vtkLightWidget.h>
#include <vtkMath.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPLYWriter.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkPlaneSource.h>
#include <vtkSphereSource.h>
#include <vtkActor2DCollection.h>

#include <QCheckBox>
#include <QComboBox>
#include <QFile>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMimeData>
#include <QDir>
#include <QDockWidget>
#include <QPair>
#include <QProcess>
#include <QProcessEnvironment>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QStatusBar>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QUrl>
#include <QVTKOpenGLNativeWidget.h>
#include <QtTest>

#include <cmath>

using namespace shadelab;
using namespace shadelab::viewer;

namespace
{
const char* const kSpot = SHADELAB_DATA_DIR "/meshes/spot.obj";

/// A small scene with every light type, camera lights among them.
const char* const kSceneText = R"({
  "imageSize": [320, 240],
  "background": [0.1, 0.1, 0.12],
  "shading": { "model": "blinn-phong", "frequency": "phong" },
  "material": { "ambient": [0.1, 0.1, 0.1], "diffuse": [0.7, 0.6, 0.5], "specular": [0.6, 0.6, 0.6], "shininess": 16 },
  "camera": { "azimuth": 140, "elevation": 12 },
  "lights": [
    { "name": "key", "type": "directional", "space": "camera", "direction": [0.5, -0.5, -1] },
    { "name": "rim", "type": "spot", "space": "camera", "position": [0, 0.9, -0.8], "direction": [0, -0.9, 0.8],
      "cutoff": 35, "edge": 5 },
    { "name": "bulb", "type": "point", "position": [1, 1, 1], "diffuse": [0.4, 0.4, 0.4] },
    { "name": "sky", "type": "ambient", "ambient": [0.1, 0.1, 0.1] }
  ]
})";

struct Rgb
{
  int width = 0;
  int height = 0;
  std::vector<unsigned char> pixels;
};

Rgb toRgb(vtkImageData* image)
{
  Rgb out;
  int dims[3];
  image->GetDimensions(dims);
  out.width = dims[0];
  out.height = dims[1];
  const auto* p = static_cast<const unsigned char*>(image->GetScalarPointer());
  out.pixels.assign(p, p + 3 * static_cast<size_t>(dims[0]) * dims[1]);
  return out;
}

/// Fraction of pixels whose largest channel difference exceeds @p tolerance (of 255).
double fractionDiffering(const Rgb& a, const Rgb& b, int tolerance = 2)
{
  if (a.width != b.width || a.height != b.height)
  {
    return 1.0;
  }
  size_t differing = 0;
  for (size_t i = 0; i < a.pixels.size(); i += 3)
  {
    int worst = 0;
    for (int c = 0; c < 3; ++c)
    {
      worst = std::max(worst, std::abs(int(a.pixels[i + c]) - int(b.pixels[i + c])));
    }
    differing += worst > tolerance ? 1 : 0;
  }
  return static_cast<double>(differing) / (a.pixels.size() / 3);
}

/// What `shadelab render` draws for @p scene on @p mesh (default: spot.obj).
Rgb renderOffscreen(const Scene& scene, vtkPolyData* mesh = nullptr)
{
  vtkNew<slMeshReader> reader;
  reader->SetFileName(kSpot);
  reader->Update();
  vtkNew<slScene> sceneObject;
  sceneObject->SetScene(scene);
  vtkNew<slSceneRenderer> renderer;
  renderer->SetScene(sceneObject);
  renderer->SetMesh(mesh ? mesh : reader->GetOutput());
  const std::string error = callError(renderer, [&] { return renderer->Render(); });
  if (!error.empty())
  {
    qFatal("offscreen render failed: %s", error.c_str());
  }
  return toRgb(renderer->GetImage());
}

vtkActor2D* findScalarBar(vtkRenderer* renderer)
{
  vtkActor2DCollection* actors = renderer->GetActors2D();
  actors->InitTraversal();
  while (vtkActor2D* actor = actors->GetNextActor2D())
  {
    if (vtkScalarBarActor::SafeDownCast(actor))
    {
      return actor;
    }
  }
  return nullptr;
}
} // namespace

class ViewerTest : public QObject
{
  Q_OBJECT

private:
  // Made by the first test run, not by the constructor: test discovery
  // (-functions) ends the program with exit(), which would leave it behind.
  std::unique_ptr<QTemporaryDir> Folder;
  std::unique_ptr<MainWindow> Window;

  QString path(const QString& name) const { return this->Folder->filePath(name); }
  Rgb grab() { return toRgb(this->Window->view()->grabImage()); }

private slots:


  void lightEditWritesOnlyThatValue()
  {
    // A light with values the panel shows rounded, or that lie beyond what a
    // hand-picked spin box range would hold, and no attenuation (all zero).
    QFile file(this->path("precise.json"));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({ "imageSize": [320, 240], "lights": [ { "name": "lamp", "type": "spot",
      "position": [0.123456, 1.234567, 2.5], "direction": [-0.1, -0.4, -1], "intensity": 20000, "cutoff": 22.25,
      "edge": 2.125, "exponent": 5000, "attenuation": [0, 0, 0], "diffuse": [1, 1, 1], "specular": [0.3, 0.3, 0.3] } ] })");
    file.close();
    QString error;
    QVERIFY2(this->Window->openFile(this->path("precise.json"), &error), qPrintable(error));
    LightPanel* panel = this->Window->lightPanel();
    QCOMPARE(panel->list()->currentRow(), 0);
    const SceneLight original = this->Window->document()->scene().lights[0];

    // Every number's control takes the scene format's range (lightKeys()).
    for (const SceneKey<SceneLight>& key : lightKeys())
    {
      if (key.number)
      {
        QDoubleSpinBox* box = panel->numberBox(key.name);
        QVERIFY2(box != nullptr, key.name);
        QCOMPARE(box->maximum(), keyUpperLimit(key, original));
        QVERIFY2(key.openLo ? box->minimum() > key.lo && box->minimum() < key.lo + 1e-3 : box->minimum() == key.lo,
          key.name);
        QVERIFY2(std::abs(box->value() - original.*(key.number)) < 1e-3, key.name);
      }
    }

    // Halve the light's diffuse colour: that, and only that, changes.
    panel->colourButton("diffuse")->slider()->setValue(500);
    Scene expected = this->Window->document()->scene();
    expected.lights[0] = original;
    expected.lights[0].diffuse = glm::vec3(0.5f);
    vtkNew<slScene> expectedScene;
    expectedScene->SetScene(expected);
    QCOMPARE(this->Window->document()->vtkScene()->ToJSON(), expectedScene->ToJSON());
    // So does a new name.
    auto* name = qobject_cast<QLineEdit*>(panel->editor("name"));
    QVERIFY(name != nullptr);
    name->setText("key");
    emit name->editingFinished();
    expected.lights[0].name = "key";
    expectedScene->SetScene(expected);
    QCOMPARE(this->Window->document()->vtkScene()->ToJSON(), expectedScene->ToJSON());
  }

  void lightControlsReachThePicture()
  {
    // k_a = (0.2, 0.4, 0.6), k_d = 1, nothing else; one directional light on
    // a blue background: a mesh pixel is 255 * (light) * N.L, exactly.
    QFile file(this->path("one-light.json"));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({ "imageSize": [320, 240], "background": [0, 0, 1],
      "shading": { "model": "lambert", "frequency": "phong" },
      "material": { "ambient": [0.2, 0.4, 0.6], "diffuse": [1, 1, 1], "emission": [0, 0, 0] },
      "lights": [ { "type": "directional", "space": "camera", "direction": [0, 0, -1], "diffuse": [0.8, 0.8, 0.8] } ] })");
    file.close();
    QString error;
    QVERIFY2(this->Window->openFile(this->path("one-light.json"), &error), qPrintable(error));
    LightPanel* panel = this->Window->lightPanel();
    const Rgb full = this->grab();
    std::vector<size_t> mesh; // pixels of the mesh lit well inside (0, 255)
    for (size_t i = 0; i < full.pixels.size(); i += 3)
    {
      if (full.pixels[i] >= 20 && full.pixels[i] <= 235)
      {
        mesh.push_back(i);
      }
    }
    QVERIFY(mesh.size() > 1000);

    // Intensity 0.5: every channel of every mesh pixel halves.
    panel->numberBox("intensity")->setValue(0.5);
    Rgb half = this->grab();
    for (size_t i : mesh)
    {
      for (int c = 0; c < 3; ++c)
      {
        QVERIFY(std::abs(2.0 * half.pixels[i + c] - full.pixels[i + c]) <= 2.0);
      }
    }
    // The diffuse colour at 0: the mesh goes black (it has no other light).
    panel->colourButton("diffuse")->slider()->setValue(0);
    Rgb dark = this->grab();
    for (size_t i : mesh)
    {
      QVERIFY(dark.pixels[i] == 0 && dark.pixels[i + 1] == 0 && dark.pixels[i + 2] == 0);
    }
    // An ambient light of colour 1 at intensity 0.5 lights k_a only: 255 * 0.5 * (0.2, 0.4, 0.6) everywhere.
    panel->typeBox()->setCurrentText("ambient");
    QCOMPARE(this->Window->document()->scene().lights[0].type, LightType::Ambient);
    QVERIFY(!panel->editor("diffuse")->isEnabled() && panel->editor("ambient")->isEnabled());
    panel->colourButton("ambient")->slider()->setValue(1000);
    Rgb ambient = this->grab();
    for (size_t i : mesh)
    {
      for (int c = 0; c < 3; ++c)
      {
        QVERIFY(std::abs(ambient.pixels[i + c] - 255.0 * 0.5 * (0.2 + 0.2 * c)) <= 1.0);
      }
    }
  }

  void lightSpaceSwitchKeepsTheLightInPlace()
  {
    // Camera-light space by hand, from the view's camera: the focal point at
    // the origin, the eye at (0, 0, 1), x to the right of the view, y up it,
    // lengths in units of the eye's distance to the focal point.
    vtkCamera* camera = this->Window->view()->camera();
    double eye[3], focal[3], viewUp[3], back[3], right[3], up[3];
    camera->GetPosition(eye);
    camera->GetFocalPoint(focal);
    camera->GetViewUp(viewUp);
    vtkMath::Subtract(eye, focal, back);
    const double distance = vtkMath::Normalize(back);
    vtkMath::Cross(viewUp, back, right);
    vtkMath::Normalize(right);
    vtkMath::Cross(back, right, up);
    const auto toCamera = [&](const glm::vec3& v, bool point) {
      double d[3] = { v.x - (point ? focal[0] : 0.0), v.y - (point ? focal[1] : 0.0), v.z - (point ? focal[2] : 0.0) };
      const double scale = point ? distance : 1.0;
      return glm::dvec3(vtkMath::Dot(d, right), vtkMath::Dot(d, up), vtkMath::Dot(d, back)) / scale;
    };
    const auto toWorld = [&](const glm::vec3& v, bool point) {
      const double scale = point ? distance : 1.0;
      glm::dvec3 w(0.0);
      for (int i = 0; i < 3; ++i)
      {
        w[i] = (point ? focal[i] : 0.0) + scale * (v.x * right[i] + v.y * up[i] + v.z * back[i]);
      }
      return w;
    };
    // The frame is VTK's view transform, the renderer's: it takes the
    // focal point to (0, 0, -distance).
    double f[4] = { focal[0], focal[1], focal[2], 1.0 };
    camera->GetViewTransformMatrix()->MultiplyPoint(f, f);
    QVERIFY(std::abs(f[0]) < 1e-9 && std::abs(f[1]) < 1e-9 && std::abs(f[2] + distance) < 1e-9 * distance);

    LightPanel* panel = this->Window->lightPanel();
    auto* space = qobject_cast<QComboBox*>(panel->editor("space"));
    QVERIFY(space != nullptr);
    const auto near = [](const glm::dvec3& expected, const glm::vec3& actual) {
      return glm::length(expected - glm::dvec3(actual)) < 1e-4 * std::max(1.0, glm::length(expected));
    };
    const auto shows = [panel](const char* key, const glm::vec3& value) {
      bool same = true;
      for (int i = 0; i < 3; ++i)
      {
        same = same && std::abs(panel->componentBox(key, i)->value() - value[i]) <= 1e-4;
      }
      return same;
    };

    // The point light "bulb" at world (1, 1, 1) becomes a camera light at
    // the same place: the camera-space numbers of that point, the same picture.
    const Rgb before = this->grab();
    panel->list()->setCurrentRow(2);
    const SceneLight bulb = this->Window->document()->scene().lights[2];
    QCOMPARE(bulb.space, LightSpace::World);
    space->setCurrentText("camera");
    const SceneLight bulbInCamera = this->Window->document()->scene().lights[2];
    QCOMPARE(bulbInCamera.space, LightSpace::Camera);
    QVERIFY(near(toCamera(bulb.position, true), bulbInCamera.position));
    QVERIFY(near(toCamera(bulb.direction, false), bulbInCamera.direction));
    QVERIFY(shows("position", bulbInCamera.position));
    double differing = fractionDiffering(before, this->grab(), 1);
    QVERIFY2(differing <= 0.0005, qPrintable(QString("%1 of pixels differ").arg(differing)));

    // The camera spot "rim" becomes a world light where the camera puts it.
    panel->list()->setCurrentRow(1);
    const SceneLight rim = this->Window->document()->scene().lights[1];
    QCOMPARE(rim.space, LightSpace::Camera);
    space->setCurrentText("world");
    const SceneLight rimInWorld = this->Window->document()->scene().lights[1];
    QCOMPARE(rimInWorld.space, LightSpace::World);
    QVERIFY(near(toWorld(rim.position, true), rimInWorld.position));
    QVERIFY(near(toWorld(rim.direction, false), rimInWorld.direction));
    QVERIFY(shows("direction", rimInWorld.direction));
    differing = fractionDiffering(before, this->grab(), 1);
    QVERIFY2(differing <= 0.0005, qPrintable(QString("%1 of pixels differ").arg(differing)));

    // And back: the numbers the file gave, to float precision.
    space->setCurrentText("camera");
    QVERIFY(near(glm::dvec3(rim.position), this->Window->document()->scene().lights[1].position));

    // Keeping the bulb's numbers instead would have moved it: the picture changes.
    Scene kept = this->Window->document()->scene();
    kept.lights[2] = bulb;
    kept.lights[2].space = LightSpace::Camera;
    this->Window->document()->setScene(kept, LightsChange);
    QVERIFY(fractionDiffering(before, this->grab(), 1) > 0.01);
  }

  void coloursAboveOneKeepTheirValue()
  {
    // Colours may exceed 1 (the scene keys' range, up to kMaxColourValue).
    QFile file(this->path("bright.json"));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({ "imageSize": [320, 240], "shading": { "model": "blinn-phong" },
      "material": { "diffuse": [1.5, 0.75, 0.3], "emission": [0, 0, 0] },
      "lights": [ { "name": "lamp", "type": "point", "position": [1, 1, 1],
        "diffuse": [2, 2, 2], "specular": [3, 1.5, 0] } ] })");
    file.close();
    QString error;
    QVERIFY2(this->Window->openFile(this->path("bright.json"), &error), qPrintable(error));
    LightPanel* lights = this->Window->lightPanel();
    MaterialPanel* material = this->Window->materialPanel();
    QCOMPARE(lights->list()->currentRow(), 0);

    // Each colour control takes its key's range and shows the brightness (the
    // largest component) as the file gives it; the slider stops at 1.
    for (const SceneKey<SceneLight>& key : lightKeys())
    {
      if (key.kind == SceneKeyKind::Colour)
      {
        QCOMPARE(lights->colourButton(key.name)->spinBox()->minimum(), key.lo);
        QCOMPARE(lights->colourButton(key.name)->spinBox()->maximum(), key.hi);
      }
    }
    for (const SceneKey<SceneMaterial>& key : materialKeys())
    {
      if (key.kind == SceneKeyKind::Colour)
      {
        QCOMPARE(material->colourControl(key.name)->spinBox()->maximum(), key.hi);
      }
    }
    QVERIFY(lights->colourButton("diffuse")->spinBox()->maximum() > 1.0);
    QCOMPARE(lights->colourButton("diffuse")->spinBox()->value(), 2.0);
    QCOMPARE(lights->colourButton("specular")->spinBox()->value(), 3.0);
    QCOMPARE(lights->colourButton("specular")->slider()->value(), lights->colourButton("specular")->slider()->maximum());
    QCOMPARE(material->colourControl("diffuse")->spinBox()->value(), 1.5);

    // Edit other values in both panels, then save: the colours are as the file gave them.
    lights->numberBox("intensity")->setValue(0.5);
    NumberControl* shininess = this->Window->materialPanel()->numberControl("shininess");
    shininess->slider()->setValue(shininess->positionOf(64.0));
    QVERIFY2(this->Window->saveScene(this->path("bright-saved.json"), &error), qPrintable(error));
    vtkNew<slScene> saved;
    const QByteArray savedPath = this->path("bright-saved.json").toLocal8Bit();
    QVERIFY(saved->ReadFile(savedPath.constData()));
    QCOMPARE(saved->GetScene().lights[0].intensity, 0.5f);
    QVERIFY(saved->GetScene().lights[0].diffuse == glm::vec3(2.0f));
    QVERIFY(saved->GetScene().lights[0].specular == glm::vec3(3.0f, 1.5f, 0.0f));
    QVERIFY(saved->GetScene().material.diffuse == glm::vec3(1.5f, 0.75f, 0.3f));

    // A brightness beyond the slider's end can be typed; the hue stays.
    lights->colourButton("specular")->spinBox()->setValue(6.0);
    QVERIFY(this->Window->document()->scene().lights[0].specular == glm::vec3(6.0f, 3.0f, 0.0f));
    material->colourControl("diffuse")->spinBox()->setValue(3.0);
    QVERIFY(this->Window->document()->scene().material.diffuse == glm::vec3(3.0f, 1.5f, 0.6f));
    // The slider still sets a brightness in [0, 1]: half of 1.
    lights->colourButton("diffuse")->slider()->setValue(500);
    QVERIFY(this->Window->document()->scene().lights[0].diffuse == glm::vec3(0.5f));
  }

  void lightDirectionIsNeverZero()
  {
    // Zeroing the direction one component at a time: no scene file may hold
    // a zero direction, so the panel keeps the last one and the scene saves
    // and loads back.
    LightPanel* panel = this->Window->lightPanel();
    panel->list()->setCurrentRow(0);
    for (int i = 0; i < 3; ++i)
    {
      panel->componentBox("direction", i)->setValue(0.0);
    }
    QVERIFY(glm::length(this->Window->document()->scene().lights[0].direction) > 0.0f);
    QString error;
    QVERIFY2(this->Window->saveScene(this->path("turned.json"), &error), qPrintable(error));
    const std::string text = this->Window->document()->vtkScene()->ToJSON();
    QVERIFY2(this->Window->openFile(this->path("turned.json"), &error), qPrintable(error));
    QCOMPARE(this->Window->document()->vtkScene()->ToJSON(), text);
  }

  void lightsStopAtWhatThePassDraws()
  {
    LightPanel* panel = this->Window->lightPanel();
    const int most = slLightingPass::GetMaximumNumberOfLights();
    while (panel->addButton()->isEnabled())
    {
      panel->addLight("point");
      QVERIFY(static_cast<int>(this->Window->document()->scene().lights.size()) <= most);
    }
    QCOMPARE(static_cast<int>(this->Window->document()->scene().lights.size()), most);
    panel->addLight("point");
    QCOMPARE(static_cast<int>(this->Window->document()->scene().lights.size()), most);

    // A scene with more is refused as `shadelab render` refuses it; the current one stays.
    const std::string shown = this->Window->document()->vtkScene()->ToJSON();
    QString text = R"({ "lights": [)";
    for (int i = 0; i <= most; ++i)
    {
      text += QString(i ? ", " : "") + R"({ "type": "point", "position": [1, 1, 1] })";
    }
    QFile file(this->path("crowd.json"));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write((text + "] }").toUtf8());
    file.close();
    QString error;
    QVERIFY(!this->Window->openFile(this->path("crowd.json"), &error));
    QCOMPARE(error, this->path("crowd.json") + ": " + QString::fromStdString(slLightingPass::GetLightCountProblem(most + 1)));
    QCOMPARE(this->Window->document()->vtkScene()->ToJSON(), shown);
  }

  void lightChoosersCoverTheScenesLights()
  {
    // The N.L field and the lobe are of the chosen light: choices are the scene's lights.
    const int last = static_cast<int>(this->Window->document()->scene().lights.size()) - 1;
    QCOMPARE(this->Window->fieldsPanel()->lightBox()->maximum(), last);
    QCOMPARE(this->Window->brdfPanel()->lightBox()->maximum(), last);
    this->Window->lightPanel()->addLight("point");
    QCOMPARE(this->Window->fieldsPanel()->lightBox()->maximum(), last + 1);
    QCOMPARE(this->Window->brdfPanel()->lightBox()->maximum(), last + 1);
    // Light 2 (the point light "bulb") is the one whose N.L is shown.
    this->Window->fieldsPanel()->fieldBox()->setCurrentIndex(1);
    this->Window->fieldsPanel()->lightBox()->setValue(2);
    vtkPolyData* field = this->Window->view()->fieldMesh();
    QVERIFY(field != nullptr);
    vtkDataArray* cosine = field->GetPointData()->GetArray("CosTheta");
    vtkDataArray* normals = field->GetPointData()->GetNormals();
    QVERIFY(cosine && normals);
    const glm::vec3 bulb = this->Window->document()->scene().lights[2].position; // world space
    for (vtkIdType i = 0; i < field->GetNumberOfPoints(); i += 97)
    {
      double p[3], n[3];
      field->GetPoint(i, p);
      normals->GetTuple(i, n);
      const double l[3] = { bulb.x - p[0], bulb.y - p[1], bulb.z - p[2] };
      const double expected = std::max(0.0, vtkMath::Dot(n, l) / (vtkMath::Norm(n) * vtkMath::Norm(l)));
      QVERIFY2(std::abs(cosine->GetTuple1(i) - expected) < 1e-4,
        qPrintable(QString("point %1: %2, expected %3").arg(i).arg(cosine->GetTuple1(i)).arg(expected)));
    }
  }

  void fieldFollowsTheNormalsPanel()
  {
    // A field is computed on the normals the normals panel asks for.
    this->Window->fieldsPanel()->fieldBox()->setCurrentIndex(1); // CosTheta
    SceneView* view = this->Window->view();
    this->Window->normalsPanel()->weightingBox()->setCurrentIndex(0); // uniform
    QCOMPARE(view->mode(), SceneView::FieldMode);
    vtkDataArray* shown = view->fieldMesh()->GetPointData()->GetNormals();
    // Uniform weighting, computed here by the renderers' own normals function.
    NormalsSettings uniform = this->Window->document()->normals();
    QCOMPARE(uniform.weighting, 0);
    vtkNew<slMeshReader> reader;
    reader->SetFileName(kSpot);
    reader->Update();
    uniform.replace = true;
    vtkSmartPointer<vtkPolyData> expected = slWithRenderNormals(reader->GetOutput(), uniform);
    QCOMPARE(shown->GetNumberOfTuples(), expected->GetPointData()->GetNormals()->GetNumberOfTuples());
    double worst = 0.0;
    for (vtkIdType i = 0; i < shown->GetNumberOfTuples(); ++i)
    {
      double a[3], b[3];
      shown->GetTuple(i, a);
      expected->GetPointData()->GetNormals()->GetTuple(i, b);
      worst = std::max(worst, std::sqrt(vtkMath::Distance2BetweenPoints(a, b)));
    }
    QVERIFY2(worst < 1e-5, qPrintable(QString("normals differ by up to %1").arg(worst)));
  }

  void referenceOfAnotherMeshIsDropped()
  {
    // A reference still being computed when another mesh opens is not shown on it.
    FieldsPanel* panel = this->Window->fieldsPanel();
    QSignalSpy finished(panel->job(), &ReferenceJob::finished);
    panel->samplesBox()->setValue(4);
    panel->computeButton()->click();
    QVERIFY(panel->job()->running());
    QFile file(this->path("tetra.off"));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
    file.close();
    QString error;
    QVERIFY2(this->Window->openFile(this->path("tetra.off"), &error), qPrintable(error)); // before the job can report
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 60000);
    QTest::qWait(50);
    QVERIFY(panel->reference() == nullptr);
    QCOMPARE(this->Window->view()->mode(), SceneView::LitMode);
    QVERIFY(panel->computeButton()->isEnabled());

    // One computed while the scene changes is stale when it arrives.
    panel->computeButton()->click();
    QVERIFY(panel->job()->running());
    Scene scene = this->Window->document()->scene();
    scene.lights[0].intensity = 0.5f;
    this->Window->document()->setScene(scene, LightsChange);
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 2, 60000);
    QVERIFY(panel->reference() != nullptr);
    QVERIFY2(panel->statusLabel()->text().contains("changed"), qPrintable(panel->statusLabel()->text()));
  }

  void windowScreenshotLikeTheView()
  {
    // --window-screenshot writes what --screenshot writes (PNG, EXR, ...)
    // and says why it cannot, naming the file.
    const QString mesh = QString(SHADELAB_DATA_DIR) + "/meshes/spot.obj";
    QTemporaryDir runtime;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert("XDG_RUNTIME_DIR", runtime.path());
    QProcess viewer;
    viewer.setProcessEnvironment(environment);
    viewer.start(QString(SHADELAB_VIEWER_PROGRAM), { mesh, "--window-screenshot", this->path("window.exr") });
    QVERIFY(viewer.waitForFinished(60000));
    QVERIFY2(viewer.exitCode() == 0, viewer.readAllStandardError().constData());
    vtkNew<slImageReader> reader;
    const QByteArray file = this->path("window.exr").toLocal8Bit();
    reader->SetFileName(file.constData());
    QCOMPARE(QString::fromStdString(updateError(reader)), QString());
    int dims[3];
    reader->GetOutput()->GetDimensions(dims);
    QVERIFY(dims[0] > this->Window->document()->scene().width); // the view and the panels beside it

    const QList<QPair<QString, QString>> cases = {
      { this->path("no-such-folder/w.png"), "No such file or directory" },
      { this->path("w.gif"), "unsupported image format" },
    };
    for (const auto& c : cases)
    {
      QProcess failing;
      failing.setProcessEnvironment(environment);
      failing.start(QString(SHADELAB_VIEWER_PROGRAM), { mesh, "--window-screenshot", c.first });
      QVERIFY(failing.waitForFinished(60000));
      const QString message = QString::fromUtf8(failing.readAllStandardError()).trimmed();
      QCOMPARE(failing.exitCode(), 1);
      QVERIFY2(message.startsWith("shadelab-viewer: " + c.first + ": ") && !message.contains('\n'), qPrintable(message));
      QVERIFY2(message.contains(c.second), qPrintable(message));
    }
  }

  void init()
  {
    if (!this->Folder)
    {
      this->Folder.reset(new QTemporaryDir);
    }
    QVERIFY(this->Folder->isValid());
    QFile file(this->path("scene.json"));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(kSceneText);
    file.close();
    this->Window.reset(new MainWindow);
    this->Window->setQuiet(true);
    QString error;
    QVERIFY2(this->Window->openFile(this->path("scene.json"), &error), qPrintable(error));
    QVERIFY2(this->Window->openFile(kSpot, &error), qPrintable(error));
    this->Window->show();
    QVERIFY(QTest::qWaitForWindowExposed(this->Window.get()));
    this->Window->setViewSize(320, 240);
    QTRY_COMPARE(this->Window->view()->size(), QSize(320, 240));
    QTest::qWait(50);
  }

  void cleanup() { this->Window.reset(); }

  void sameImageAsShadelabRender()
  {
    const Rgb view = this->grab();
    QCOMPARE(view.width, 320);
    QCOMPARE(view.height, 240);
    const Rgb offscreen = renderOffscreen(this->Window->document()->scene());
    QVERIFY2(fractionDiffering(view, offscreen) <= 0.002,
      qPrintable(QString("%1 of pixels differ").arg(fractionDiffering(view, offscreen))));
  }

  void shininessSliderChangesTheHighlight()
  {
    const Rgb before = this->grab();
    NumberControl* shininess = this->Window->materialPanel()->numberControl("shininess");
    QVERIFY(shininess->logarithmic());
    shininess->slider()->setValue(shininess->positionOf(256.0));
    const float n = this->Window->document()->scene().material.shininess;
    QVERIFY(std::abs(n - 256.0f) / 256.0f < 0.01f);
    const Rgb after = this->grab();
    // The highlights shrink: the image changes, and exactly as `shadelab render` shows n = 256.
    QVERIFY(fractionDiffering(before, after) > 0.005);
    QVERIFY(fractionDiffering(after, renderOffscreen(this->Window->document()->scene())) <= 0.002);
  }

  void frequencySwitchMatchesRender()
  {
    const Rgb phong = this->grab();
    this->Window->shadingPanel()->frequencyBox()->setCurrentText("flat");
    QCOMPARE(this->Window->document()->scene().frequency, ShadingFrequency::Flat);
    const Rgb flat = this->grab();
    QVERIFY(fractionDiffering(phong, flat) > 0.05);
    QVERIFY(fractionDiffering(flat, renderOffscreen(this->Window->document()->scene())) <= 0.002);
    this->Window->shadingPanel()->frequencyBox()->setCurrentText("gouraud");
    const Rgb gouraud = this->grab();
    QVERIFY(fractionDiffering(gouraud, flat) > 0.05);
    QVERIFY(fractionDiffering(gouraud, renderOffscreen(this->Window->document()->scene())) <= 0.002);
  }

  void savedSceneLoadsBackUnchanged()
  {
    // Move the camera and change the material first, so that the file has to carry them.
    this->Window->view()->camera()->Azimuth(35.0);
    this->Window->view()->camera()->Elevation(-10.0);
    NumberControl* shininess = this->Window->materialPanel()->numberControl("shininess");
    shininess->slider()->setValue(shininess->positionOf(90.0));
    const Rgb before = this->grab();
    QString error;
    QVERIFY2(this->Window->saveScene(this->path("saved.json"), &error), qPrintable(error));
    const std::string text = this->Window->document()->vtkScene()->ToJSON();

    QVERIFY(this->Window->openFile(this->path("scene.json"), &error)); // something else in between
    QVERIFY(fractionDiffering(before, this->grab()) > 0.01);
    QVERIFY2(this->Window->openFile(this->path("saved.json"), &error), qPrintable(error));
    QCOMPARE(this->Window->document()->vtkScene()->ToJSON(), text);
    const double differing = fractionDiffering(before, this->grab());
    QVERIFY2(differing <= 0.002, qPrintable(QString("%1 of pixels differ").arg(differing)));
  }

  void brdfFileShadesAndItsSlidersAreUniforms()
  {
    const Rgb model = this->grab();
    QString error;
    const QString file = QString(SHADELAB_DATA_DIR) + "/brdf/blinn-phong-normalized.brdf";
    QVERIFY2(this->Window->openFile(file, &error), qPrintable(error));
    QCOMPARE(QString::fromStdString(this->Window->document()->vtkScene()->GetBrdfFilePath()), file);
    const Rgb glossy = this->grab();
    QVERIFY(fractionDiffering(model, glossy) > 0.01);
    QVERIFY(fractionDiffering(glossy, renderOffscreen(this->Window->document()->scene())) <= 0.002);

    // Its parameters are sliders; moving one re-renders with a uniform.
    BrdfFilePanel* panel = this->Window->brdfFilePanel();
    QSlider* ks = panel->slider("ks");
    QVERIFY(ks != nullptr);
    QCOMPARE(ks->value(), BrdfFilePanel::kSteps / 2); // the default 0.5 in [0, 1]
    const int builds = this->Window->view()->lightingPass()->GetNumberOfShaderBuilds();
    ks->setValue(0);
    QCOMPARE(this->Window->document()->scene().brdf.parameters, std::vector<std::string>{ "ks=0" });
    const Rgb matte = this->grab();
    QCOMPARE(this->Window->view()->lightingPass()->GetNumberOfShaderBuilds(), builds);
    QVERIFY(fractionDiffering(glossy, matte) > 0.005);
    QVERIFY(fractionDiffering(matte, renderOffscreen(this->Window->document()->scene())) <= 0.002);

    // Saved with the scene; "Use the model" goes back.
    QVERIFY2(this->Window->saveScene(this->path("brdf.json"), &error), qPrintable(error));
    QVERIFY(this->Window->document()->vtkScene()->ToJSON().find("\"ks\": 0") != std::string::npos);
    panel->removeButton()->click();
    QVERIFY(this->Window->document()->scene().brdf.file.empty());
    QVERIFY(fractionDiffering(model, this->grab()) <= 0.002);
  }

  void brokenBrdfFileIsOneLine()
  {
    QString error;
    QVERIFY(!this->Window->openFile(this->path("missing.brdf"), &error));
    QCOMPARE(error, this->path("missing.brdf") + ": cannot open BRDF file: No such file or directory");
    QVERIFY(this->Window->document()->scene().brdf.file.empty());

    // GLSL that does not compile: the view says so in one line, with the file's line.
    const QString broken = QString(SHADELAB_DATA_DIR) + "/brdf/broken-glsl.brdf";
    QSignalSpy problems(this->Window->view(), &SceneView::problem);
    QVERIFY2(this->Window->openFile(broken, &error), qPrintable(error));
    this->grab();
    QCOMPARE(problems.count(), 1);
    const QString message = problems.first().first().toString();
    QVERIFY2(message.startsWith(broken + ":12: ") && !message.contains('\n'), qPrintable(message));
  }

  void droppedMeshOpens()
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetThetaResolution(24);
    sphere->SetPhiResolution(12);
    vtkNew<vtkPLYWriter> writer;
    writer->SetInputConnection(sphere->GetOutputPort());
    const QByteArray file = this->path("ball.ply").toLocal8Bit();
    writer->SetFileName(file.constData());
    QVERIFY(writer->Write());
    const Rgb before = this->grab();

    QMimeData data;
    data.setUrls({ QUrl::fromLocalFile(this->path("ball.ply")) });
    QDragEnterEvent enter(QPoint(10, 10), Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(this->Window.get(), &enter);
    QVERIFY(enter.isAccepted());
    QDropEvent drop(QPointF(10, 10), Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(this->Window.get(), &drop);
    QCOMPARE(this->Window->document()->meshPath(), this->path("ball.ply"));
    QCOMPARE(this->Window->document()->mesh()->GetNumberOfPolys(), sphere->GetOutput()->GetNumberOfPolys());
    QVERIFY(fractionDiffering(before, this->grab()) > 0.05);
  }

  void badMeshKeepsTheCurrentOne()
  {
    QFile file(this->path("broken.off"));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n");
    file.close();
    vtkPolyData* before = this->Window->document()->mesh();
    QString error;
    QVERIFY(!this->Window->openFile(this->path("broken.off"), &error));
    QCOMPARE(error, this->path("broken.off") + ": line 6: vertex index 9 is out of range [0, 3)");
    QCOMPARE(this->Window->document()->mesh(), before);
    QVERIFY(!this->Window->openFile(this->path("missing.json"), &error));
    QVERIFY2(error.startsWith(this->path("missing.json") + ": "), qPrintable(error));
  }

  void glTFOpens()
  {
    // A single triangle, positions and indices in a .bin beside the .gltf.
    const float positions[9] = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
    const unsigned short indices[4] = { 0, 1, 2, 0 };
    QFile bin(this->path("tri.bin"));
    QVERIFY(bin.open(QIODevice::WriteOnly));
    bin.write(reinterpret_cast<const char*>(positions), sizeof positions);
    bin.write(reinterpret_cast<const char*>(indices), sizeof indices);
    bin.close();
    QFile gltf(this->path("tri.gltf"));
    QVERIFY(gltf.open(QIODevice::WriteOnly));
    gltf.write(R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
      "buffers": [{"uri": "tri.bin", "byteLength": 44}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0,0,0], "max": [1,1,0]},
                    {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]})");
    gltf.close();
    QString error;
    QVERIFY2(this->Window->openFile(this->path("tri.gltf"), &error), qPrintable(error));
    QCOMPARE(this->Window->document()->mesh()->GetNumberOfPolys(), vtkIdType(1));
  }

  void fieldsPanelShowsCosTheta()
  {
    const Rgb lit = this->grab();
    this->Window->fieldsPanel()->fieldBox()->setCurrentIndex(1); // CosTheta
    SceneView* view = this->Window->view();
    QCOMPARE(view->mode(), SceneView::FieldMode);
    QCOMPARE(view->fieldName(), QString("CosTheta"));
    QVERIFY(findScalarBar(view->renderers().front()) != nullptr);
    const Rgb field = this->grab();
    QVERIFY(fractionDiffering(lit, field) > 0.05);
    // The field follows the lights: turning the key light changes it.
    Scene scene = this->Window->document()->scene();
    scene.lights[0].direction = glm::vec3(-0.5f, 0.5f, -1.0f);
    this->Window->document()->setScene(scene, LightsChange);
    QVERIFY(fractionDiffering(field, this->grab()) > 0.02);
    this->Window->fieldsPanel()->fieldBox()->setCurrentIndex(0);
    QCOMPARE(view->mode(), SceneView::LitMode);
  }

  void splitViewShowsThreeFrequencies()
  {
    this->Window->shadingPanel()->splitBox()->setChecked(true);
    SceneView* view = this->Window->view();
    QCOMPARE(view->mode(), SceneView::SplitMode);
    QCOMPARE(static_cast<int>(view->renderers().size()), 3);
    for (auto& renderer : view->renderers()) // linked cameras: one camera for all
    {
      QCOMPARE(renderer->GetActiveCamera(), view->camera());
    }
    const Rgb image = this->grab();
    // The flat third and the Phong third differ (same camera, other frequency).
    Rgb left, right;
    left.width = right.width = image.width / 3;
    left.height = right.height = image.height;
    for (int y = 0; y < image.height; ++y)
    {
      const auto row = image.pixels.begin() + 3 * static_cast<size_t>(y) * image.width;
      left.pixels.insert(left.pixels.end(), row, row + 3 * left.width);
      right.pixels.insert(right.pixels.end(), row + 3 * 2 * left.width, row + 3 * 3 * left.width);
    }
    QVERIFY(fractionDiffering(left, right) > 0.02);
    this->Window->shadingPanel()->splitBox()->setChecked(false);
    QCOMPARE(static_cast<int>(view->renderers().size()), 1);
  }

  void lightWidgetMovesCameraLight()
  {
    LightWidgets* widgets = this->Window->view()->lightWidgets();
    QCOMPARE(widgets->count(), 3); // ambient lights have none
    // Drag the spot (camera light 1) to a new world position by hand.
    vtkCamera* camera = this->Window->view()->camera();
    const glm::vec3 eye(camera->GetPosition()[0], camera->GetPosition()[1], camera->GetPosition()[2]);
    const glm::vec3 focal(camera->GetFocalPoint()[0], camera->GetFocalPoint()[1], camera->GetFocalPoint()[2]);
    const glm::vec3 up(camera->GetViewUp()[0], camera->GetViewUp()[1], camera->GetViewUp()[2]);
    double target[3] = { 0.3, 1.5, 0.2 };
    vtkLightWidget* widget = nullptr;
    for (int i = 0; i < widgets->count(); ++i)
    {
      widget = widgets->lightOf(i) == 1 ? widgets->widget(i) : widget;
    }
    QVERIFY(widget != nullptr);
    const Rgb before = this->grab();
    widget->GetLightRepresentation()->SetLightPosition(target);
    widget->InvokeEvent(vtkCommand::InteractionEvent, nullptr);
    const SceneLight moved = this->Window->document()->scene().lights[1];
    QCOMPARE(moved.space, LightSpace::Camera); // still follows the camera
    const SceneLight world = lightInWorldSpace(moved, eye, focal, up);
    for (int i = 0; i < 3; ++i)
    {
      QVERIFY(std::abs(world.position[i] - static_cast<float>(target[i])) < 1e-4f);
    }
    // The view shows the moved light exactly as `shadelab render` draws the
    // edited scene.
    const Rgb after = this->grab();
    QVERIFY(fractionDiffering(before, after) > 0.001);
    const Rgb offscreen = renderOffscreen(this->Window->document()->scene());
    QVERIFY2(fractionDiffering(after, offscreen) <= 0.002,
      qPrintable(QString("%1 of pixels differ from the offscreen render").arg(fractionDiffering(after, offscreen))));
  }

  void addAndRemoveLights()
  {
    LightPanel* panel = this->Window->lightPanel();
    const size_t before = this->Window->document()->scene().lights.size();
    const Rgb image = this->grab();
    panel->addLight("point");
    QCOMPARE(this->Window->document()->scene().lights.size(), before + 1);
    QCOMPARE(this->Window->view()->lightWidgets()->count(), 4);
    QVERIFY(fractionDiffering(image, this->grab()) > 0.01);
    QCOMPARE(panel->list()->currentRow(), static_cast<int>(before));
    panel->removeSelectedLight();
    QCOMPARE(this->Window->document()->scene().lights.size(), before);
    QVERIFY(fractionDiffering(image, this->grab()) <= 0.002);
  }

  void pickedPointShowsItsLobe()
  {
    BrdfPanel* panel = this->Window->brdfPanel();
    panel->pickButton()->setChecked(true);
    SceneView* view = this->Window->view();
    const int actorsBefore = view->renderers().front()->GetActors()->GetNumberOfItems();
    QVERIFY(view->pickAt(160, 120)); // the middle of the view is on the cow
    QVERIFY(panel->pickedPoint() >= 0);
    // The incidence angle of light 0 (the key light: directional, camera
    // space, direction (0.5, -0.5, -1)) at the picked point, computed here
    // from VTK's own camera: its view matrix maps world to camera space, so
    // its inverse takes the camera-space direction to the world.
    vtkPolyData* mesh = view->meshWithNormals();
    double normal[3];
    mesh->GetPointData()->GetNormals()->GetTuple(panel->pickedPoint(), normal);
    vtkNew<vtkMatrix4x4> cameraToWorld;
    vtkMatrix4x4::Invert(view->camera()->GetViewTransformMatrix(), cameraToWorld);
    const double inCamera[4] = { 0.5, -0.5, -1.0, 0.0 };
    double direction[4];
    cameraToWorld->MultiplyPoint(inCamera, direction);
    const double toLight[3] = { -direction[0], -direction[1], -direction[2] };
    const double cosTheta = vtkMath::Dot(normal, toLight) / (vtkMath::Norm(normal) * vtkMath::Norm(toLight));
    QVERIFY2(cosTheta > 0.0, "the middle of the view should face the key light");
    const double expected = vtkMath::DegreesFromRadians(std::acos(cosTheta));
    QVERIFY2(std::abs(panel->incidenceDegrees() - expected) < 1e-3,
      qPrintable(QString("incidence %1, expected %2").arg(panel->incidenceDegrees()).arg(expected)));
    QVERIFY(view->renderers().front()->GetActors()->GetNumberOfItems() > actorsBefore); // the lobe
    QVERIFY(!panel->pictureLabel()->pixmap(Qt::ReturnByValue).isNull());
    QVERIFY(!view->pickAt(2, 2)); // background: nothing picked
  }

  void referenceProgressAndCancel()
  {
    FieldsPanel* panel = this->Window->fieldsPanel();
    QSignalSpy finished(panel->job(), &ReferenceJob::finished);
    QSignalSpy progress(panel->job(), &ReferenceJob::progress);
    panel->samplesBox()->setValue(1 << 16); // minutes of work: it must be cancelled
    panel->computeButton()->click();
    QVERIFY(panel->job()->running());
    QVERIFY(panel->cancelButton()->isEnabled());
    QTRY_VERIFY_WITH_TIMEOUT(progress.count() > 0, 60000);
    panel->cancelButton()->click();
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 60000);
    QCOMPARE(finished.at(0).at(0).toString(), QString("cancelled"));
    QVERIFY(panel->reference() == nullptr);
    QVERIFY(panel->computeButton()->isEnabled());

    panel->samplesBox()->setValue(4);
    panel->computeButton()->click();
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 2, 60000);
    QCOMPARE(finished.at(1).at(0).toString(), QString());
    QVERIFY(panel->reference() != nullptr);
    QVERIFY(panel->reference()->GetPointData()->GetArray("RadianceError") != nullptr);
    QCOMPARE(panel->progressBar()->value(), 100);
    QCOMPARE(this->Window->view()->mode(), SceneView::FieldMode); // the reference is shown
  }

  void referenceJobAppliesTheSceneTexture()
  {
    // The scene's diffuse texture colours k_d in the job's reference, as the
    // view draws it: an all-red (0.8, 0.2, 0.2) texture on a plane facing a
    // small sun gives k_d * red * I / pi (normalised Lambert, N.L = 1).
    QFile texture(this->path("red.ppm"));
    QVERIFY(texture.open(QIODevice::WriteOnly));
    texture.write(QByteArray("P6\n2 2\n255\n") + QByteArray("\xcc\x33\x33", 3).repeated(4));
    texture.close();
    Scene scene;
    scene.model = ShadingModel::LambertNormalized;
    scene.material.ambient = scene.material.specular = scene.material.emission = glm::vec3(0.0f);
    scene.material.diffuse = glm::vec3(0.9f);
    scene.material.diffuseTexture = this->path("red.ppm").toStdString();
    SceneLight sun;
    sun.type = LightType::Directional;
    sun.direction = glm::vec3(0.0f, 0.0f, -1.0f);
    sun.intensity = 2.0f;
    scene.lights = { sun };
    vtkNew<vtkPlaneSource> plane; // in z = 0, normal +z, texture coordinates 0..1
    plane->SetResolution(2, 2);
    plane->Update();
    vtkNew<vtkCamera> camera;
    ReferenceJob job;
    QSignalSpy finished(&job, &ReferenceJob::finished);
    ReferenceSettings settings;
    settings.samplesPerPoint = 16;
    settings.strategy = 3; // light sampling
    QVERIFY(job.start(plane->GetOutput(), scene, camera, settings));
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 60000);
    QCOMPARE(finished.at(0).at(0).toString(), QString());
    vtkPolyData* out = job.result();
    QVERIFY(out != nullptr);
    const glm::vec3 red(0.8f, 0.2f, 0.2f);
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    {
      double radiance[3], sigma[3];
      out->GetPointData()->GetArray("Radiance")->GetTuple(i, radiance);
      out->GetPointData()->GetArray("RadianceStdError")->GetTuple(i, sigma);
      for (int c = 0; c < 3; ++c)
      {
        const double expected = 0.9 * red[c] * 2.0 / vtkMath::Pi();
        QVERIFY2(std::abs(radiance[c] - expected) <= 0.005 * expected + 5.0 * sigma[c],
          qPrintable(QString("point %1 channel %2: %3, expected %4").arg(i).arg(c).arg(radiance[c]).arg(expected)));
      }
    }
  }

  void fieldsFollowTheSceneTexture()
  {
    // The Diffuse field colours k_d with the scene's texture, as the view
    // draws it: a grey k_d under a (0.8, 0.2, 0.2) texture gives red four
    // times green at every lit point of the (textured) spot mesh.
    QFile texture(this->path("red.ppm"));
    QVERIFY(texture.open(QIODevice::WriteOnly));
    texture.write(QByteArray("P6\n2 2\n255\n") + QByteArray("\xcc\x33\x33", 3).repeated(4));
    texture.close();
    Scene scene = this->Window->document()->scene();
    scene.material.diffuse = glm::vec3(0.9f);
    scene.material.diffuseTexture = this->path("red.ppm").toStdString();
    this->Window->document()->setScene(scene, MaterialChange);
    this->Window->fieldsPanel()->fieldBox()->setCurrentIndex(3); // Diffuse
    SceneView* view = this->Window->view();
    QCOMPARE(view->fieldName(), QString("Diffuse"));
    vtkDataArray* diffuse = view->fieldMesh()->GetPointData()->GetArray("Diffuse");
    QVERIFY(diffuse != nullptr);
    vtkIdType lit = 0;
    for (vtkIdType i = 0; i < diffuse->GetNumberOfTuples(); ++i)
    {
      double d[3];
      diffuse->GetTuple(i, d);
      if (d[1] > 1e-6)
      {
        ++lit;
        QVERIFY2(std::abs(d[0] - 4.0 * d[1]) <= 1e-3 * d[0] && std::abs(d[2] - d[1]) <= 1e-3 * d[1],
          qPrintable(QString("point %1: %2 %3 %4").arg(i).arg(d[0]).arg(d[1]).arg(d[2])));
      }
    }
    QVERIFY(lit > diffuse->GetNumberOfTuples() / 4);
  }

  void screenshotsAsPNGAndEXR()
  {
    const Rgb view = this->grab();
    QString error;
    for (const QString& name : { QString("shot.png"), QString("shot.exr") })
    {
      QVERIFY2(this->Window->saveScreenshot(this->path(name), &error), qPrintable(error));
      vtkNew<slImageReader> reader;
      const QByteArray file = this->path(name).toLocal8Bit();
      reader->SetFileName(file.constData());
      QCOMPARE(QString::fromStdString(updateError(reader)), QString());
      int dims[3];
      reader->GetOutput()->GetDimensions(dims);
      QCOMPARE(dims[0], view.width);
      QCOMPARE(dims[1], view.height);
    }
    QVERIFY(!this->Window->saveScreenshot(this->path("no/such/folder/shot.png"), &error));
    QVERIFY2(error.contains("no/such/folder/shot.png"), qPrintable(error));
  }

  void matchesTheRegressionBaselines()
  {
    // The viewer's captures against the same baselines as `shadelab render`
    // (tests/regression): Spot under every light type, Blinn-Phong, at each
    // frequency chosen in the shading panel.
    QString error;
    QVERIFY2(this->Window->openFile(SHADELAB_DATA_DIR "/scenes/regression/all-lights.json", &error), qPrintable(error));
    const Scene& scene = this->Window->document()->scene();
    this->Window->setViewSize(scene.width, scene.height);
    QTRY_COMPARE(this->Window->view()->size(), QSize(scene.width, scene.height));
    this->Window->shadingPanel()->modelBox()->setCurrentText("blinn-phong");
    for (const char* frequency : { "flat", "gouraud", "phong" })
    {
      this->Window->shadingPanel()->frequencyBox()->setCurrentText(frequency);
      const std::string name = std::string("spot-blinn-phong-") + frequency;
      const regression::Verdict verdict = regression::compareWithBaseline(this->Window->view()->grabImage(),
        SHADELAB_DATA_DIR "/baselines/" + name + ".png", SHADELAB_TEST_OUTPUT_DIR, "viewer-" + name);
      QVERIFY2(verdict.passed, qPrintable(QString::fromStdString(name + ": " + verdict.message)));
    }
  }

  void noDisplayGivesOneLine()
  {
    // Without an X display the viewer says so in one line and exits with 1.
    QProcess viewer;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.remove("DISPLAY");
    environment.remove("QT_QPA_PLATFORM");
    environment.remove("WAYLAND_DISPLAY");
    viewer.setProcessEnvironment(environment);
    viewer.start(QString(SHADELAB_VIEWER_PROGRAM), QStringList());
    QVERIFY(viewer.waitForFinished(30000));
    QCOMPARE(viewer.exitCode(), 1);
    const QString message = QString::fromUtf8(viewer.readAllStandardError()).trimmed();
    QVERIFY2(message.startsWith("shadelab-viewer: ") && !message.contains('\n'), qPrintable(message));
    QVERIFY2(message.contains("DISPLAY"), qPrintable(message));
  }

  void helpAndVersionNeedNoDisplay()
  {
    // Asking how to run the viewer works where it cannot run: --help and
    // --version print and exit 0 without a display. The help names every
    // panel --panel can raise (the window's own docks, not a list).
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.remove("DISPLAY");
    environment.remove("QT_QPA_PLATFORM");
    environment.remove("WAYLAND_DISPLAY");
    for (const QString& option : { QString("--help"), QString("--version") })
    {
      QProcess viewer;
      viewer.setProcessEnvironment(environment);
      viewer.start(QString(SHADELAB_VIEWER_PROGRAM), { option });
      QVERIFY(viewer.waitForFinished(30000));
      const QString out = QString::fromUtf8(viewer.readAllStandardOutput());
      QVERIFY2(viewer.exitCode() == 0, qPrintable(option + ": " + viewer.readAllStandardError()));
      QVERIFY2(out.contains("shadelab-viewer"), qPrintable(out));
      if (option == "--help")
      {
        const QString panelHelp = out.simplified().mid(out.simplified().indexOf("--panel")); // lines wrap
        const QList<QDockWidget*> docks = this->Window->findChildren<QDockWidget*>();
        QVERIFY(docks.size() >= 7);
        for (const QDockWidget* dock : docks)
        {
          QVERIFY2(panelHelp.contains(dock->windowTitle()), qPrintable(dock->windowTitle() + " missing in: " + panelHelp));
          QVERIFY(this->Window->raisePanel(dock->windowTitle().toUpper()));
        }
      }
    }
  }

  void scriptedFailuresGiveOneLine()
  {
    // A mesh that cannot be read, a screenshot that cannot be written: one
    // line each, exit 1, and not VTK's multi-line report before it.
    const QString mesh = QString(SHADELAB_DATA_DIR) + "/meshes/spot.obj";
    const QString folder = QString(SHADELAB_TEST_OUTPUT_DIR);
    QDir().mkpath(folder);
    const QList<QPair<QStringList, QString>> cases = {
      { { folder + "/no-such-mesh.obj", "--screenshot", folder + "/x.png" }, "no-such-mesh.obj" },
      { { mesh, "--screenshot", folder + "/no-such-folder/x.png" }, "no-such-folder/x.png" },
      { { mesh, "--screenshot", folder + "/x.gif" }, "x.gif" },
    };
    // Qt's own note about a missing XDG_RUNTIME_DIR is not the viewer's.
    QTemporaryDir runtime;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert("XDG_RUNTIME_DIR", runtime.path());
    for (const auto& c : cases)
    {
      QProcess viewer;
      viewer.setProcessEnvironment(environment);
      viewer.start(QString(SHADELAB_VIEWER_PROGRAM), c.first);
      QVERIFY(viewer.waitForFinished(60000));
      const QString message = QString::fromUtf8(viewer.readAllStandardError()).trimmed();
      QCOMPARE(viewer.exitCode(), 1);
      QVERIFY2(message.startsWith("shadelab-viewer: ") && !message.contains('\n'), qPrintable(message));
      QVERIFY2(message.contains(c.second), qPrintable(message));
    }
  }

  void readsNumbersUnderADecimalCommaLocale()
  {
    // Under de_DE (LC_NUMERIC with a decimal comma) the viewer still reads
    // "0.5" in a mesh file: a legacy VTK file goes through ShadeLab's check
    // and VTK's reader, both of which read numbers with the C library.
    QTemporaryDir work;
    if (!QFile::exists("/usr/share/i18n/locales/de_DE") ||
      QProcess::execute("localedef", { "-i", "de_DE", "-f", "UTF-8", work.path() + "/de_DE.UTF-8" }) != 0)
    {
      QSKIP("cannot make a de_DE locale here (Debian package locales)");
    }
    const QString mesh = work.path() + "/half.vtk";
    QFile file(mesh);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("# vtk DataFile Version 3.0\nhalf\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n"
               "0 0 0 0.5 0 0 0 0.5 0\nPOLYGONS 1 4\n3 0 1 2\n");
    file.close();
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert("XDG_RUNTIME_DIR", work.path());
    environment.insert("LOCPATH", work.path());
    environment.insert("LC_ALL", "de_DE.UTF-8");
    QProcess viewer;
    viewer.setProcessEnvironment(environment);
    viewer.start(QString(SHADELAB_VIEWER_PROGRAM), { mesh, "--screenshot", work.path() + "/shot.png" });
    QVERIFY(viewer.waitForFinished(60000));
    QVERIFY2(viewer.exitCode() == 0, viewer.readAllStandardError().constData());
    QVERIFY(QFile::exists(work.path() + "/shot.png"));
  }

  void materialControlsFollowTheModel()
  {
    // For every model, a material parameter has a control shown exactly when
    // changing it changes the image: the image, not the table, decides here.
    QString error;
    QVERIFY2(this->Window->document()->computeTangents(error), qPrintable(error)); // the anisotropic models' frame
    MaterialPanel* panel = this->Window->materialPanel();
    for (const std::string& model : modelNames())
    {
      this->Window->shadingPanel()->modelBox()->setCurrentText(QString::fromStdString(model));
      QCOMPARE(modelName(this->Window->document()->scene().model), model);
      const Scene original = this->Window->document()->scene();
      const Rgb before = this->grab();
      QStringList changing;
      for (const SceneKey<SceneMaterial>& key : materialKeys())
      {
        Scene edited = original;
        if (key.vector)
        {
          edited.material.*(key.vector) = glm::vec3(0.9f, 0.5f, 0.2f) - 0.5f * (original.material.*(key.vector));
        }
        else if (key.number)
        {
          // Far across the range: a tenth from the end the value is away from.
          const double v = original.material.*(key.number);
          edited.material.*(key.number) =
            static_cast<float>(v - key.lo < 0.5 * (key.hi - key.lo) ? key.hi - 0.1 * (key.hi - key.lo)
                                                                   : key.lo + 0.1 * (key.hi - key.lo));
        }
        else
        {
          continue; // the texture has no control
        }
        this->Window->document()->setScene(edited, MaterialChange);
        if (fractionDiffering(before, this->grab(), 0) > 0.0)
        {
          changing << QString::fromUtf8(key.name);
        }
        this->Window->document()->setScene(original, MaterialChange);
      }
      QCOMPARE(panel->shownKeys(), changing);
      QVERIFY2(changing.size() >= 3, qPrintable(changing.join(", ")));
    }
  }

  void roughnessChangesMicrofacetsOnly()
  {
    // Through the roughness control: Blinn-Phong does not read it, GGX does.
    NumberControl* roughness = this->Window->materialPanel()->numberControl("roughness");
    QVERIFY(roughness != nullptr && !roughness->logarithmic());
    this->Window->shadingPanel()->modelBox()->setCurrentText("blinn-phong");
    QVERIFY(!this->Window->materialPanel()->shownKeys().contains("roughness"));
    const Rgb blinnPhong = this->grab();
    roughness->slider()->setValue(roughness->positionOf(0.8));
    QVERIFY(std::abs(this->Window->document()->scene().material.roughness - 0.8f) < 1e-3f);
    QCOMPARE(fractionDiffering(blinnPhong, this->grab(), 0), 0.0);

    this->Window->shadingPanel()->modelBox()->setCurrentText("cook-torrance-ggx");
    QVERIFY(this->Window->materialPanel()->shownKeys().contains("roughness"));
    QVERIFY(!this->Window->materialPanel()->shownKeys().contains("shininess"));
    const Rgb rough = this->grab();
    QVERIFY(fractionDiffering(rough, renderOffscreen(this->Window->document()->scene())) <= 0.002);
    roughness->spinBox()->setValue(0.1);
    QVERIFY(std::abs(this->Window->document()->scene().material.roughness - 0.1f) < 1e-6f);
    const Rgb smooth = this->grab();
    QVERIFY2(fractionDiffering(rough, smooth) > 0.005,
      qPrintable(QString("%1 of pixels differ").arg(fractionDiffering(rough, smooth))));
    QVERIFY(fractionDiffering(smooth, renderOffscreen(this->Window->document()->scene())) <= 0.002);
  }

  void anisotropicModelOffersTangents()
  {
    ShadingPanel* shading = this->Window->shadingPanel();
    QVERIFY(shading->tangentsLabel()->isHidden());
    const Rgb blinnPhong = this->grab();
    shading->modelBox()->setCurrentText("ward");
    // One line, in the panel and the status bar, and a button that can help.
    const QString line = shading->tangentsLabel()->text();
    QVERIFY(!shading->tangentsLabel()->isHidden());
    QVERIFY2(line.startsWith("ward is anisotropic and needs the mesh's tangents: spot.obj has none"), qPrintable(line));
    QVERIFY(!line.contains('\n'));
    QCOMPARE(this->Window->statusBar()->currentMessage(), line);
    QVERIFY(shading->tangentsButton()->isEnabled());
    const Rgb fixedFrame = this->grab();
    QVERIFY(fractionDiffering(blinnPhong, fixedFrame) > 0.01);

    shading->tangentsButton()->click();
    vtkPolyData* mesh = this->Window->document()->mesh();
    QVERIFY(slLitFilter::HasTangents(mesh));
    QVERIFY(mesh->GetPointData()->GetNormals() == nullptr); // the normals settings still decide them
    QVERIFY(shading->tangentsLabel()->isHidden());
    QVERIFY(shading->tangentsButton()->isHidden());
    // Lit in the tangents' frame now: not the fixed one, and as `shadelab render` draws the mesh with tangents.
    const Rgb tangentFrame = this->grab();
    QVERIFY(fractionDiffering(fixedFrame, tangentFrame) > 0.001);
    QVERIFY(fractionDiffering(tangentFrame, renderOffscreen(this->Window->document()->scene(), mesh)) <= 0.002);

    // A mesh without texture coordinates: the line says so, and the button cannot help.
    QFile file(this->path("tetra.off"));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
    file.close();
    QString error;
    QVERIFY2(this->Window->openFile(this->path("tetra.off"), &error), qPrintable(error));
    QVERIFY2(shading->tangentsLabel()->text().contains("tetra.off has none, and no texture coordinates"),
      qPrintable(shading->tangentsLabel()->text()));
    QVERIFY(!shading->tangentsButton()->isEnabled());
  }

  void pickedLobeFollowsTheMaterial()
  {
    // The BRDF panel draws the lobe of the current model and material.
    this->Window->shadingPanel()->modelBox()->setCurrentText("cook-torrance-ggx");
    BrdfPanel* panel = this->Window->brdfPanel();
    panel->pickButton()->setChecked(true);
    QVERIFY(this->Window->view()->pickAt(160, 120));
    const QImage rough = panel->pictureLabel()->pixmap(Qt::ReturnByValue).toImage();
    QVERIFY(!rough.isNull());
    this->Window->materialPanel()->numberControl("roughness")->spinBox()->setValue(0.1);
    QTRY_VERIFY(panel->pictureLabel()->pixmap(Qt::ReturnByValue).toImage() != rough);
    const QString info = panel->infoLabel()->text();
    QVERIFY2(info.endsWith("cook-torrance-ggx roughness = 0.1, ior = 1.5"), qPrintable(info));
  }

  void normalsPanelRecomputesNormals()
  {
    NormalsPanel* panel = this->Window->normalsPanel();
    const Rgb angle = this->grab();
    panel->weightingBox()->setCurrentIndex(0); // uniform
    QCOMPARE(this->Window->document()->normals().weighting, 0);
    const Rgb uniform = this->grab();
    QVERIFY(fractionDiffering(angle, uniform, 1) > 0.0005); // other weights, other normals, other shading
    const int actors = this->Window->view()->renderers().front()->GetActors()->GetNumberOfItems();
    panel->glyphsBox()->setChecked(true);
    QCOMPARE(this->Window->view()->renderers().front()->GetActors()->GetNumberOfItems(), actors + 1);
    QVERIFY(fractionDiffering(uniform, this->grab()) > 0.01);
  }
};

int main(int argc, char** argv)
{
  QSurfaceFormat format = QVTKOpenGLNativeWidget::defaultFormat();
  format.setSamples(0);
  QSurfaceFormat::setDefaultFormat(format);
  QApplication app(argc, argv);
  ViewerTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "ViewerTest.moc"
#include "VTKErrors.h"
