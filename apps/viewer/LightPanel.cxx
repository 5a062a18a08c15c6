#include "LightPanel.h"

#include "ColorButton.h"
#include "LightWidgets.h"
#include "SceneView.h"
#include "ViewerDocument.h"

#include "slLightingPass.h"

#include "shadelab/SceneKeys.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadelab
{
namespace viewer
{

namespace
{
/// Decimals of every light spin box: what the panel shows and what can be
/// typed. A value read from a file keeps all its digits until it is edited.
constexpr int kDecimals = 4;

QString describe(const SceneLight& light, size_t index)
{
  const QString name = light.name.empty() ? QString("light %1").arg(index) : QString::fromStdString(light.name);
  return QString("%1 (%2%3)")
    .arg(name, lightTypeName(light.type), light.space == LightSpace::Camera ? ", camera" : "");
}

/// A spin box over a key's range. Its size hint ignores the range: an
/// unbounded key (a position) would otherwise ask for the width of
/// 3.4e38 written out.
class KeySpinBox : public QDoubleSpinBox
{
public:
  using QDoubleSpinBox::QDoubleSpinBox;
  QSize sizeHint() const override
  {
    const QSize hint = QDoubleSpinBox::sizeHint();
    return QSize(std::min(hint.width(), this->fontMetrics().horizontalAdvance("-000000.0000") + 24), hint.height());
  }
  QSize minimumSizeHint() const override { return this->sizeHint(); }
};

/// A range end as a spin box can hold it: scene values are floats.
double finiteEnd(double end)
{
  const double largest = std::numeric_limits<float>::max();
  return std::max(-largest, std::min(largest, end));
}
} // namespace

LightPanel::LightPanel(ViewerDocument* document, SceneView* view, QWidget* parent)
  : QWidget(parent)
  , Document(document)
  , View(view)
  , List(new QListWidget(this))
  , Add(new QPushButton(tr("Add"), this))
  , Remove(new QPushButton(tr("Remove"), this))
  , ShowWidgets(new QCheckBox(tr("Show and drag lights in the view"), this))
  , Editor(new QWidget(this))
  , Form(new QFormLayout(this->Editor))
  , Type(new QComboBox(this->Editor))
{
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(this->List, 1);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(this->Add);
  buttons->addWidget(this->Remove);
  layout->addLayout(buttons);
  layout->addWidget(this->ShowWidgets);
  layout->addWidget(this->Editor);

  auto* addMenu = new QMenu(this->Add);
  for (const std::string& type : lightTypeNames())
  {
    const QString name = QString::fromStdString(type);
    addMenu->addAction(name, this, [this, name] { this->addLight(name); });
    this->Type->addItem(name);
  }
  this->Add->setMenu(addMenu);

  this->Form->setContentsMargins(0, 0, 0, 0);
  this->Form->addRow(tr("type"), this->Type);
  for (size_t key = 0; key < lightKeys().size(); ++key)
  {
    this->addRow(key);
  }

  this->ShowWidgets->setChecked(view->lightWidgets()->enabled());
  connect(this->ShowWidgets, &QCheckBox::toggled, view, &SceneView::setLightWidgets);
  connect(this->Remove, &QPushButton::clicked, this, &LightPanel::removeSelectedLight);
  connect(this->List, &QListWidget::currentRowChanged, this, &LightPanel::showLight);
  connect(this->Type, QOverload<int>::of(&QComboBox::currentIndexChanged), this, &LightPanel::editType);
  connect(document, &ViewerDocument::sceneChanged, this, &LightPanel::showScene);
  this->showScene();
}

void LightPanel::addRow(size_t key)
{
  const SceneKey<SceneLight>& k = lightKeys()[key];
  Row row;
  row.key = key;
  const size_t index = this->Rows.size();
  const auto spinBox = [this, &k, index] {
    auto* box = new KeySpinBox(this->Editor);
    box->setDecimals(kDecimals);
    // An open end is the nearest value the box can hold inside it (a cutoff above 0).
    const double step = std::pow(10.0, -kDecimals);
    box->setRange(finiteEnd(k.lo + (k.openLo ? step : 0.0)), finiteEnd(k.hi - (k.openHi ? step : 0.0)));
    box->setSingleStep(k.hi - k.lo > 50.0 && k.hi - k.lo <= 1e4 ? 1.0 : 0.05); // degrees, exponents: whole steps
    box->setKeyboardTracking(false);
    connect(box, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this, index] { this->editKey(index); });
    return box;
  };
  switch (k.kind)
  {
    case SceneKeyKind::Text:
      row.text = new QLineEdit(this->Editor);
      row.editor = row.text;
      connect(row.text, &QLineEdit::editingFinished, this, [this, index] { this->editKey(index); });
      break;
    case SceneKeyKind::Space:
      row.space = new QComboBox(this->Editor);
      for (const std::string& space : lightSpaceNames())
      {
        row.space->addItem(QString::fromStdString(space));
      }
      row.editor = row.space;
      connect(row.space, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this, index] { this->editKey(index); });
      break;
    case SceneKeyKind::Number:
      row.number = spinBox();
      row.editor = row.number;
      break;
    case SceneKeyKind::Colour:
      row.colour = new ColorButton(k.lo, k.hi, this->Editor); // the key's range, above 1 too
      row.editor = row.colour;
      connect(row.colour, &ColorButton::valueChanged, this, [this, index] { this->editKey(index); });
      break;
    case SceneKeyKind::Point:
    case SceneKeyKind::Direction:
    case SceneKeyKind::Coefficients:
    {
      row.editor = new QWidget(this->Editor);
      auto* line = new QHBoxLayout(row.editor);
      line->setContentsMargins(0, 0, 0, 0);
      for (QDoubleSpinBox*& box : row.components)
      {
        box = spinBox();
        line->addWidget(box);
      }
      break;
    }
    case SceneKeyKind::Parameters:
      return; // not a light's
  }
  const QString what = k.what ? QString::fromUtf8(k.what) : QString();
  row.editor->setToolTip(what);
  this->Form->addRow(QString::fromUtf8(k.name), row.editor);
  this->Form->labelForField(row.editor)->setToolTip(what);
  this->Rows.push_back(row);
}

const LightPanel::Row* LightPanel::rowOf(const QString& key) const
{
  for (const Row& row : this->Rows)
  {
    if (key == QString::fromUtf8(lightKeys()[row.key].name))
    {
      return &row;
    }
  }
  return nullptr;
}

QWidget* LightPanel::editor(const QString& key) const
{
  const Row* row = this->rowOf(key);
  return row ? row->editor : nullptr;
}

QDoubleSpinBox* LightPanel::numberBox(const QString& key) const
{
  const Row* row = this->rowOf(key);
  return row ? row->number : nullptr;
}

QDoubleSpinBox* LightPanel::componentBox(const QString& key, int i) const
{
  const Row* row = this->rowOf(key);
  return row && i >= 0 && i < 3 ? row->components[i] : nullptr;
}

ColorButton* LightPanel::colourButton(const QString& key) const
{
  const Row* row = this->rowOf(key);
  return row ? row->colour : nullptr;
}

void LightPanel::addLight(const QString& typeName)
{
  Scene scene = this->Document->scene();
  LightType type = LightType::Directional;
  if (!parseLightTypeName(typeName.toStdString(), type) ||
    !slLightingPass::GetLightCountProblem(static_cast<int>(scene.lights.size()) + 1).empty())
  {
    return;
  }
  SceneLight light = defaultLight(type);
  light.name = typeName.toStdString() + " " + std::to_string(scene.lights.size());
  if (lightTakes(type, kLightSpace))
  {
    // A camera light from above the viewer's right shoulder: visible at once.
    light.space = LightSpace::Camera;
    light.position = glm::vec3(0.5f, 0.5f, 1.0f);
    light.direction = -light.position;
  }
  scene.lights.push_back(light);
  this->Document->setScene(scene, LightsChange);
  this->List->setCurrentRow(static_cast<int>(scene.lights.size()) - 1);
}

void LightPanel::removeSelectedLight()
{
  const int row = this->List->currentRow();
  Scene scene = this->Document->scene();
  if (row < 0 || row >= static_cast<int>(scene.lights.size()))
  {
    return;
  }
  scene.lights.erase(scene.lights.begin() + row);
  this->Document->setScene(scene, LightsChange);
}

void LightPanel::showScene()
{
  const Scene& scene = this->Document->scene();
  const int row = this->List->currentRow();
  this->Showing = true;
  this->List->clear();
  for (size_t i = 0; i < scene.lights.size(); ++i)
  {
    this->List->addItem(describe(scene.lights[i], i));
  }
  this->Showing = false;
  const int count = static_cast<int>(scene.lights.size());
  // The pass draws a limited number of lights: no more can be added.
  this->Add->setEnabled(slLightingPass::GetLightCountProblem(count + 1).empty());
  this->List->setCurrentRow(count == 0 ? -1 : std::min(std::max(row, 0), count - 1));
  this->showLight(this->List->currentRow());
}

void LightPanel::showLight(int index)
{
  const Scene& scene = this->Document->scene();
  const bool valid = index >= 0 && index < static_cast<int>(scene.lights.size());
  this->Editor->setEnabled(valid);
  this->Remove->setEnabled(valid);
  if (!valid || this->Showing)
  {
    return;
  }
  const SceneLight& l = scene.lights[static_cast<size_t>(index)];
  this->Showing = true;
  this->Type->setCurrentText(lightTypeName(l.type));
  for (const Row& row : this->Rows)
  {
    const SceneKey<SceneLight>& key = lightKeys()[row.key];
    if (row.text)
    {
      row.text->setText(QString::fromStdString(l.*(key.text)));
    }
    else if (row.space)
    {
      row.space->setCurrentText(lightSpaceName(l.*(key.space)));
    }
    else if (row.number)
    {
      row.number->setMaximum(finiteEnd(keyUpperLimit(key, l))); // the edge's is the cutoff
      row.number->setValue(l.*(key.number));
    }
    else if (row.colour)
    {
      row.colour->setValue(l.*(key.vector));
    }
    else
    {
      for (int i = 0; i < 3; ++i)
      {
        row.components[i]->setValue((l.*(key.vector))[i]);
      }
    }
    // Live for the light types that take the key (LightingTables.h).
    row.editor->setEnabled(lightTakesKey(l.type, key));
  }
  this->Showing = false;
}

void LightPanel::editType()
{
  const int index = this->List->currentRow();
  Scene scene = this->Document->scene();
  if (this->Showing || index < 0 || index >= static_cast<int>(scene.lights.size()))
  {
    return;
  }
  parseLightTypeName(this->Type->currentText().toStdString(), scene.lights[static_cast<size_t>(index)].type);
  this->Document->setScene(scene, LightsChange);
}

void LightPanel::editKey(size_t rowIndex)
{
  const int index = this->List->currentRow();
  Scene scene = this->Document->scene();
  if (this->Showing || index < 0 || index >= static_cast<int>(scene.lights.size()))
  {
    return;
  }
  const Row& row = this->Rows[rowIndex];
  const SceneKey<SceneLight>& key = lightKeys()[row.key];
  SceneLight& l = scene.lights[static_cast<size_t>(index)];
  if (row.text)
  {
    l.*(key.text) = row.text->text().toStdString();
  }
  else if (row.space)
  {
    // The light stays where the view shows it: its position and direction
    // are converted with the view's camera, not kept as numbers.
    LightSpace space = l.*(key.space);
    parseLightSpaceName(row.space->currentText().toStdString(), space);
    l = lightInSpace(l, space, this->View->camera());
  }
  else if (row.number)
  {
    l.*(key.number) = static_cast<float>(row.number->value());
  }
  else if (row.colour)
  {
    l.*(key.vector) = row.colour->value();
  }
  else
  {
    glm::vec3 value;
    for (int i = 0; i < 3; ++i)
    {
      value[i] = static_cast<float>(row.components[i]->value());
    }
    if (key.kind == SceneKeyKind::Direction && !directionProblem(value).empty())
    {
      // No direction to travel along, and no scene may hold it: keep the last one.
      this->showLight(index);
      return;
    }
    l.*(key.vector) = value;
  }
  // A value bounded by another (a spot's edge by its cutoff) stays within it.
  for (const SceneKey<SceneLight>& bounded : lightKeys())
  {
    if (bounded.upTo && bounded.number)
    {
      l.*(bounded.number) = std::min(l.*(bounded.number), l.*(bounded.upTo));
    }
  }
  this->Document->setScene(scene, LightsChange);
}

} // namespace viewer
} // namespace shadelab
