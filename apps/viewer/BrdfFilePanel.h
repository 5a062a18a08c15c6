#ifndef shadelab_viewer_BrdfFilePanel_h
#define shadelab_viewer_BrdfFilePanel_h
/**
 * @class   BrdfFilePanel
 * @brief   The scene's BRDF Explorer .brdf file: open one, go back to the
 *          model, and edit its parameters live.
 *
 * Each parameter of the file gets its widget: a float a slider over its
 * [min, max] with a spin box, a bool a check box, a colour a ColorButton.
 * A change goes to the document as the scene's brdf.parameters (the
 * "name=value" texts of `shadelab render --param`) in a MaterialChange: the
 * pass sets a uniform and rebuilds no shader. Opening a file is a
 * ShadingChange (its GLSL goes into the shaders). Problems (a file that no
 * longer reads, a value out of range) go out through problem().
 *
 * @sa ViewerDocument slLightingPass
 */

#include "shadelab/BrdfFile.h"

#include <QWidget>

#include <string>
#include <vector>

class QCheckBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QPushButton;
class QSlider;

namespace shadelab
{
namespace viewer
{
class ColorButton;
class ViewerDocument;

class BrdfFilePanel : public QWidget
{
  Q_OBJECT
public:
  explicit BrdfFilePanel(ViewerDocument* document, QWidget* parent = nullptr);

  /// Slider positions 0..kSteps over a float parameter's [min, max].
  static constexpr int kSteps = 1000;

  /// The widgets of parameter @p name, or null (for tests and shortcuts).
  QSlider* slider(const QString& name) const;
  QCheckBox* checkBox(const QString& name) const;
  ColorButton* colorButton(const QString& name) const;
  /// "Use the model": removes the scene's .brdf file.
  QPushButton* removeButton() const { return this->Remove; }

signals:
  void problem(const QString& message);

private:
  /// One row of the form: the parameter and whichever widget its kind has.
  struct Row
  {
    BrdfParameter parameter;
    QSlider* slider = nullptr;
    QDoubleSpinBox* box = nullptr;
    QCheckBox* check = nullptr;
    ColorButton* colour = nullptr;
  };

  void showScene();
  void rebuild(const std::string& path);
  void setParameter(const BrdfParameter& parameter, const glm::vec3& value);

  ViewerDocument* Document;
  QLabel* FileLabel;
  QPushButton* Open;
  QPushButton* Remove;
  QFormLayout* Form;
  std::string ShownPath; ///< the resolved path of the file whose rows are shown
  BrdfFile File;
  std::vector<Row> Rows;
};

} // namespace viewer
} // namespace shadelab

#endif
