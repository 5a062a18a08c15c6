// shadelab-viewer [MESH] [--scene S.json] [--screenshot OUT] [--window-screenshot OUT]
#include "MainWindow.h"
#include "SceneView.h"
#include "ShadingPanel.h"
#include "ViewerDocument.h"

#include "slFileExtension.h"
#include "slImageWriter.h"
#include "slOffscreen.h"
#include "slOutputWindow.h"
#include "slScene.h"

#include <QApplication>
#include <QCheckBox>
#include <QCommandLineParser>
#include <QSurfaceFormat>
#include <QTimer>
#include <QVTKOpenGLNativeWidget.h>

#include <clocale>
#include <cstdlib>
#include <iostream>

namespace
{
/// The folder of the bundled example (Spot and the default scene), opened
/// when no mesh is given: share/shadelab beside the program, installed or in
/// the build tree (which lays it out as installed). Never a path of the
/// machine that built it: an installed viewer must not reach into a source
/// tree.
QString bundledDataDir()
{
  return QCoreApplication::applicationDirPath() + "/" + SHADELAB_INSTALLED_DATA_FROM_BIN;
}

int fail(const QString& message)
{
  std::cerr << "shadelab-viewer: " << message.toStdString() << "\n";
  return 1;
}

/// The name and version --help and --version print.
void nameApplication()
{
  QCoreApplication::setApplicationName("shadelab-viewer");
  QCoreApplication::setApplicationVersion(SHADELAB_VERSION);
}

/// "A, B or C".
QString listWithOr(QStringList items)
{
  const QString last = items.isEmpty() ? QString() : items.takeLast();
  return items.isEmpty() ? last : items.join(", ") + " or " + last;
}
} // namespace

int main(int argc, char** argv)
{
  QCommandLineParser parser;
  parser.setApplicationDescription("ShadeLab's interactive viewer: the lighting equation term by term, live.");
  const QCommandLineOption helpOption = parser.addHelpOption();
  const QCommandLineOption versionOption = parser.addVersionOption();
  parser.addPositionalArgument("mesh", "mesh to open (OBJ, PLY, STL, VTP, VTK, OFF, glTF); default: the bundled Spot");
  const QCommandLineOption sceneOption(
    QStringList{ "s", "scene" }, "JSON scene to open (default: the bundled default scene)", "FILE");
  const QCommandLineOption shotOption(
    "screenshot", "render the view at the scene's image size, write it (PNG, EXR, ...) and quit", "FILE");
  const QCommandLineOption windowShotOption(
    "window-screenshot", "write a picture of the whole window, panels included (PNG, EXR, ...), and quit", "FILE");
  const QCommandLineOption panelOption(
    "panel", "raise a panel: " + listWithOr(shadelab::viewer::MainWindow::panelNames()) + " (any case)", "NAME");
  const QCommandLineOption splitOption("split", "start in the split view flat | Gouraud | Phong");
  const QCommandLineOption verboseOption("verbose", "also print VTK's own multi-line error reports");
  parser.addOptions({ sceneOption, shotOption, windowShotOption, panelOption, splitOption, verboseOption });

  // --help and --version need no display: answered before it is looked for,
  // by a core application. (Qt's own options, such as -platform, are only
  // known once QApplication has taken them, so a parse error here waits.)
  QStringList arguments;
  for (int i = 0; i < argc; ++i)
  {
    arguments << QString::fromLocal8Bit(argv[i]);
  }
  if (parser.parse(arguments) && (parser.isSet(helpOption) || parser.isSet(versionOption)))
  {
    QCoreApplication core(argc, argv);
    nameApplication();
    parser.process(core); // prints and exits with 0
  }

  const std::string display = slDisplayProblem();
  if (!display.empty() && !std::getenv("QT_QPA_PLATFORM") && !std::getenv("WAYLAND_DISPLAY"))
  {
    return fail(QString::fromStdString(display));
  }
  // Multisampling off, as in `shadelab render`: the same scene, the same pixels.
  QSurfaceFormat format = QVTKOpenGLNativeWidget::defaultFormat();
  format.setSamples(0);
  QSurfaceFormat::setDefaultFormat(format);
  QApplication app(argc, argv);
  // QApplication takes the locale from the environment; numbers in mesh and
  // scene files are read with the C library and VTK, which then expect a
  // decimal comma under de_DE and the like ("0.5" is not a number). The
  // interface's own texts keep the user's language.
  std::setlocale(LC_NUMERIC, "C");
  nameApplication();

  parser.process(app);
  // As in `shadelab`: the viewer reports each problem itself, in one line or
  // a dialog that gives VTK's reason (slErrorCapture); VTK's own reports
  // would only repeat it on the terminal.
  slOutputWindow::Install(parser.isSet(verboseOption));

  shadelab::viewer::MainWindow window;
  const bool scripted = parser.isSet(shotOption) || parser.isSet(windowShotOption);
  window.setQuiet(scripted);
  const QStringList positional = parser.positionalArguments();
  if (positional.size() > 1)
  {
    return fail("give at most one mesh (got " + QString::number(positional.size()) + ")");
  }
  for (const QCommandLineOption& option : { shotOption, windowShotOption })
  {
    if (parser.isSet(option))
    {
      // Before anything is loaded or rendered.
      const QByteArray shot = parser.value(option).toLocal8Bit();
      const std::string problem = slFormatProblem(shot.constData(), "image", slImageWriter::GetSupportedExtensions());
      if (!problem.empty())
      {
        return fail(parser.value(option) + ": " + QString::fromStdString(problem));
      }
    }
  }
  const bool defaults = positional.isEmpty() && !parser.isSet(sceneOption);
  const QString scene = parser.isSet(sceneOption) ? parser.value(sceneOption) : (defaults ? bundledDataDir() + "/scenes/default.json" : "");
  const QString mesh = positional.isEmpty() ? bundledDataDir() + "/meshes/spot.obj" : positional.first();
  QString error;
  if ((!scene.isEmpty() && !window.openFile(scene, &error)) || !window.openFile(mesh, &error))
  {
    if (scripted)
    {
      return fail(error);
    }
  }
  const shadelab::Scene& s = window.document()->scene();
  window.show();
  window.setViewSize(s.width, s.height);
  if (parser.isSet(panelOption) && !window.raisePanel(parser.value(panelOption)))
  {
    return fail("--panel: no panel named \"" + parser.value(panelOption) + "\"");
  }
  if (parser.isSet(splitOption))
  {
    window.shadingPanel()->splitBox()->setChecked(true);
  }
  if (!scripted)
  {
    return QApplication::exec();
  }
  // Scripted: let the window reach its size, then write and quit.
  int status = 0;
  QTimer::singleShot(0, [&] {
    window.view()->renderNow();
    if (parser.isSet(shotOption) && !window.saveScreenshot(parser.value(shotOption), &error))
    {
      status = fail(error);
    }
    window.view()->renderNow(); // with the light widgets, which the view screenshot leaves out
    if (parser.isSet(windowShotOption) && !window.saveWindowScreenshot(parser.value(windowShotOption), &error))
    {
      status = fail(error);
    }
    QApplication::quit();
  });
  QApplication::exec();
  return status;
}
