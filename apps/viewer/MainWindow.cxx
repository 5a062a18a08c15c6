#include "MainWindow.h"

#include "BrdfFilePanel.h"
#include "BrdfPanel.h"
#include "FieldsPanel.h"
#include "LightPanel.h"
#include "MaterialPanel.h"
#include "NormalsPanel.h"
#include "SceneView.h"
#include "ShadingPanel.h"
#include "ViewerDocument.h"

#include "slImageWriter.h"
#include "slMeshReader.h"
#include "slUpdateOrThrow.h"

#include <vtkImageData.h>
#include <vtkSmartPointer.h>
#include <vtkNew.h>

#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QImage>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QScrollArea>
#include <QStatusBar>
#include <QUrl>

#include <algorithm>
#include <iterator>

namespace shadelab
{
namespace viewer
{

namespace
{
bool isScene(const QString& path)
{
  return QFileInfo(path).suffix().compare("json", Qt::CaseInsensitive) == 0;
}

bool isBrdf(const QString& path)
{
  return QFileInfo(path).suffix().compare("brdf", Qt::CaseInsensitive) == 0;
}

QString meshFilter()
{
  QStringList patterns;
  for (const QString& ext : QString(slMeshReader::GetSupportedExtensions()).split(' ', Qt::SkipEmptyParts))
  {
    patterns << "*" + ext;
  }
  return QObject::tr("Meshes (%1);;Scenes (*.json);;BRDF Explorer BRDFs (*.brdf);;All files (*)").arg(patterns.join(' '));
}

/// @p image as RGB unsigned char image data, row 0 at the bottom (as VTK's captures).
vtkSmartPointer<vtkImageData> toImageData(const QImage& image)
{
  const QImage rgb = image.convertToFormat(QImage::Format_RGB888);
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->SetDimensions(rgb.width(), rgb.height(), 1);
  out->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* pixels = static_cast<unsigned char*>(out->GetScalarPointer());
  const size_t row = 3 * static_cast<size_t>(rgb.width());
  for (int y = 0; y < rgb.height(); ++y)
  {
    std::copy(rgb.constScanLine(rgb.height() - 1 - y), rgb.constScanLine(rgb.height() - 1 - y) + row,
      pixels + row * static_cast<size_t>(y));
  }
  return out;
}

bool fail(const QString& message, QString* error)
{
  if (error)
  {
    *error = message;
  }
  return false;
}
} // namespace

MainWindow::MainWindow(QWidget* parent)
  : QMainWindow(parent)
  , Document(new ViewerDocument(this))
  , View(new SceneView(this->Document, this))
{
  this->setCentralWidget(this->View);
  this->Shading = new ShadingPanel(this->Document, this->View);
  this->Material = new MaterialPanel(this->Document);
  this->Lights = new LightPanel(this->Document, this->View);
  this->Normals = new NormalsPanel(this->Document, this->View);
  this->Fields = new FieldsPanel(this->Document, this->View);
  this->Brdf = new BrdfPanel(this->Document, this->View);
  this->BrdfFileEditor = new BrdfFilePanel(this->Document);

  QWidget* const panels[] = { this->Shading, this->Material, this->Lights, this->Normals, this->Fields, this->Brdf,
    this->BrdfFileEditor };
  const QStringList titles = panelNames();
  Q_ASSERT(titles.size() == static_cast<int>(std::size(panels)));
  QDockWidget* previous = nullptr;
  for (int i = 0; i < titles.size(); ++i)
  {
    auto* scroll = new QScrollArea;
    scroll->setWidget(panels[i]);
    scroll->setWidgetResizable(true);
    scroll->setMinimumWidth(panels[i]->sizeHint().width() + 24); // no horizontal scrolling
    auto* dock = new QDockWidget(titles[i], this);
    dock->setObjectName(titles[i]);
    dock->setWidget(scroll);
    this->addDockWidget(Qt::RightDockWidgetArea, dock);
    if (previous)
    {
      this->tabifyDockWidget(previous, dock);
    }
    previous = dock;
  }
  this->findChildren<QDockWidget*>().first()->raise();

  connect(this->View, &SceneView::problem, this, &MainWindow::showProblem);
  connect(this->Fields, &FieldsPanel::problem, this, &MainWindow::showProblem);
  connect(this->Brdf, &BrdfPanel::problem, this, &MainWindow::showProblem);
  connect(this->BrdfFileEditor, &BrdfFilePanel::problem, this, &MainWindow::showProblem);
  connect(this->Shading, &ShadingPanel::problem, this, &MainWindow::showProblem);
  connect(this->Shading, &ShadingPanel::notice, this, [this](const QString& line) {
    this->statusBar()->showMessage(line);
  });
  connect(this->Document, &ViewerDocument::meshChanged, this, &MainWindow::updateTitle);
  connect(this->Document, &ViewerDocument::sceneChanged, this, &MainWindow::updateTitle);
  this->setAcceptDrops(true);
  this->buildMenus();
  this->updateTitle();
}

MainWindow::~MainWindow() = default;

void MainWindow::buildMenus()
{
  QMenu* file = this->menuBar()->addMenu(tr("&File"));
  file->addAction(tr("&Open mesh or scene..."), this, [this] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Open"), QString(), meshFilter());
    if (!path.isEmpty())
    {
      this->openFile(path);
    }
  }, QKeySequence::Open);
  file->addAction(tr("&Save scene as..."), this, [this] {
    const QString path =
      QFileDialog::getSaveFileName(this, tr("Save scene"), this->Document->scenePath(), tr("Scenes (*.json)"));
    if (!path.isEmpty())
    {
      this->saveScene(path);
    }
  }, QKeySequence::SaveAs);
  file->addAction(tr("Save s&creenshot..."), this, [this] {
    const QString path = QFileDialog::getSaveFileName(
      this, tr("Save screenshot"), QString(), tr("PNG (*.png);;OpenEXR (*.exr);;Other formats (*)"));
    if (!path.isEmpty())
    {
      this->saveScreenshot(path);
    }
  }, QKeySequence(tr("Ctrl+P")));
  file->addSeparator();
  file->addAction(tr("&Quit"), this, &QWidget::close, QKeySequence::Quit);
}

bool MainWindow::openFile(const QString& path, QString* error)
{
  QString problem;
  const bool ok = isScene(path) ? this->Document->openScene(path, problem)
    : isBrdf(path)              ? this->Document->openBrdf(path, problem)
                                : this->Document->openMesh(path, problem);
  if (!ok)
  {
    this->showProblem(problem);
    return fail(problem, error);
  }
  this->statusBar()->showMessage(tr("Opened %1").arg(path), 5000);
  return true;
}

bool MainWindow::saveScene(const QString& path, QString* error)
{
  this->Document->recordCamera(this->View->camera());
  QString problem;
  if (!this->Document->saveScene(path, problem))
  {
    this->showProblem(problem);
    return fail(problem, error);
  }
  this->statusBar()->showMessage(tr("Saved %1").arg(path), 5000);
  return true;
}

bool MainWindow::saveScreenshot(const QString& path, QString* error)
{
  // The capture throws rather than hand over a picture it could not draw.
  return this->writeImage([this] { return this->View->grabImage(); }, path, error);
}

bool MainWindow::saveWindowScreenshot(const QString& path, QString* error)
{
  return this->writeImage([this] { return toImageData(this->grab().toImage()); }, path, error);
}

bool MainWindow::writeImage(const std::function<vtkSmartPointer<vtkImageData>()>& capture, const QString& path,
  QString* error)
{
  vtkNew<slImageWriter> writer;
  const QByteArray file = path.toLocal8Bit();
  writer->SetFileName(file.constData());
  try
  {
    writer->SetInputData(capture());
    slCallOrThrow(writer, [&] { return writer->Write(); });
  }
  catch (const shadelab::Error& e)
  {
    const QString problem = QString::fromUtf8(e.what());
    this->showProblem(problem);
    return fail(problem, error);
  }
  this->statusBar()->showMessage(tr("Saved %1").arg(path), 5000);
  return true;
}

void MainWindow::setViewSize(int width, int height)
{
  // The central widget gets exactly this size: the window grows around it.
  const QSize extra = this->size() - this->View->size();
  this->View->setMinimumSize(width, height);
  this->View->setMaximumSize(width, height);
  this->resize(extra + QSize(width, height));
}

QStringList MainWindow::panelNames()
{
  return { "Shading", "Material", "Lights", "Normals", "Fields", "BRDF", "BRDF file" };
}

bool MainWindow::raisePanel(const QString& name)
{
  for (QDockWidget* dock : this->findChildren<QDockWidget*>())
  {
    if (dock->windowTitle().compare(name, Qt::CaseInsensitive) == 0)
    {
      dock->raise();
      return true;
    }
  }
  return false;
}

void MainWindow::showProblem(const QString& message)
{
  this->statusBar()->showMessage(message);
  if (!this->Quiet)
  {
    QMessageBox::warning(this, tr("ShadeLab"), message);
  }
}

void MainWindow::updateTitle()
{
  const QString mesh = this->Document->meshPath().isEmpty() ? tr("no mesh") : QFileInfo(this->Document->meshPath()).fileName();
  const QString scene =
    this->Document->scenePath().isEmpty() ? tr("default scene") : QFileInfo(this->Document->scenePath()).fileName();
  this->setWindowTitle(tr("ShadeLab viewer - %1 - %2").arg(mesh, scene));
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event)
{
  if (event->mimeData()->hasUrls())
  {
    event->acceptProposedAction();
  }
}

void MainWindow::dropEvent(QDropEvent* event)
{
  // Scenes first, so a dropped mesh and scene show together whatever the order.
  QStringList scenes, meshes;
  for (const QUrl& url : event->mimeData()->urls())
  {
    if (url.isLocalFile())
    {
      (isScene(url.toLocalFile()) ? scenes : meshes) << url.toLocalFile();
    }
  }
  for (const QString& path : scenes + meshes)
  {
    this->openFile(path);
  }
  event->acceptProposedAction();
}

} // namespace viewer
} // namespace shadelab
