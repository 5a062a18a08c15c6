#include "BrdfFilePanel.h"

#include "ColorButton.h"
#include "ViewerDocument.h"

#include "slScene.h"

#include "shadelab/BrdfAssignment.h"
#include "shadelab/Error.h"
#include "shadelab/ValueLimits.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>

#include <cmath>

namespace shadelab
{
namespace viewer
{

namespace
{
int sliderAt(const BrdfParameter& p, float value)
{
  const float span = p.maximum - p.minimum;
  return span > 0.0f ? static_cast<int>(std::lround(BrdfFilePanel::kSteps * (value - p.minimum) / span)) : 0;
}

double valueAt(const BrdfParameter& p, int position)
{
  return p.minimum + (static_cast<double>(p.maximum) - p.minimum) * position / BrdfFilePanel::kSteps;
}
} // namespace

BrdfFilePanel::BrdfFilePanel(ViewerDocument* document, QWidget* parent)
  : QWidget(parent)
  , Document(document)
  , FileLabel(new QLabel(this))
  , Open(new QPushButton(tr("Open .brdf..."), this))
  , Remove(new QPushButton(tr("Use the model"), this))
  , Form(new QFormLayout)
{
  auto* layout = new QVBoxLayout(this);
  this->FileLabel->setWordWrap(true);
  layout->addWidget(this->FileLabel);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(this->Open);
  buttons->addWidget(this->Remove);
  layout->addLayout(buttons);
  layout->addLayout(this->Form);
  layout->addStretch(1);

  connect(this->Open, &QPushButton::clicked, this, [this] {
    const QString path =
      QFileDialog::getOpenFileName(this, tr("Open BRDF"), QString(), tr("BRDF Explorer BRDFs (*.brdf);;All files (*)"));
    QString error;
    if (!path.isEmpty() && !this->Document->openBrdf(path, error))
    {
      emit problem(error);
    }
  });
  connect(this->Remove, &QPushButton::clicked, this, [this] {
    Scene scene = this->Document->scene();
    scene.brdf = SceneBrdf();
    this->Document->setScene(scene, ShadingChange);
  });
  connect(document, &ViewerDocument::sceneChanged, this, &BrdfFilePanel::showScene);
  this->showScene();
}

QSlider* BrdfFilePanel::slider(const QString& name) const
{
  for (const Row& row : this->Rows)
  {
    if (row.parameter.name == name.toStdString())
    {
      return row.slider;
    }
  }
  return nullptr;
}

QCheckBox* BrdfFilePanel::checkBox(const QString& name) const
{
  for (const Row& row : this->Rows)
  {
    if (row.parameter.name == name.toStdString())
    {
      return row.check;
    }
  }
  return nullptr;
}

ColorButton* BrdfFilePanel::colorButton(const QString& name) const
{
  for (const Row& row : this->Rows)
  {
    if (row.parameter.name == name.toStdString())
    {
      return row.colour;
    }
  }
  return nullptr;
}

void BrdfFilePanel::rebuild(const std::string& path)
{
  while (this->Form->rowCount() > 0)
  {
    this->Form->removeRow(0);
  }
  this->Rows.clear();
  this->File = BrdfFile();
  this->ShownPath = path;
  if (path.empty())
  {
    return;
  }
  try
  {
    this->File = readBrdfFile(path);
  }
  catch (const Error& e)
  {
    emit problem(QString::fromStdString(e.what()));
    return;
  }
  for (const BrdfParameter& p : this->File.parameters)
  {
    Row row;
    row.parameter = p;
    const QString label = QString::fromStdString(p.name);
    switch (p.kind)
    {
      case BrdfParameter::Kind::Float:
      {
        row.slider = new QSlider(Qt::Horizontal, this);
        row.slider->setRange(0, kSteps);
        row.box = new QDoubleSpinBox(this);
        row.box->setRange(p.minimum, p.maximum);
        row.box->setDecimals(3);
        row.box->setSingleStep((static_cast<double>(p.maximum) - p.minimum) / 100.0);
        auto* line = new QHBoxLayout;
        line->addWidget(row.slider, 1);
        line->addWidget(row.box);
        this->Form->addRow(label, line);
        connect(row.slider, &QSlider::valueChanged, this,
          [this, p](int position) { this->setParameter(p, glm::vec3(static_cast<float>(valueAt(p, position)))); });
        connect(row.box, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
          [this, p](double value) { this->setParameter(p, glm::vec3(static_cast<float>(value))); });
        break;
      }
      case BrdfParameter::Kind::Bool:
        row.check = new QCheckBox(this);
        this->Form->addRow(label, row.check);
        connect(row.check, &QCheckBox::toggled, this, [this, p](bool on) { this->setParameter(p, glm::vec3(on ? 1.0f : 0.0f)); });
        break;
      case BrdfParameter::Kind::Color:
        // A .brdf colour has no range of its own: the scene's colours' range.
        row.colour = new ColorButton(0.0, shadelab::kMaxColourValue, this);
        this->Form->addRow(label, row.colour);
        connect(row.colour, &ColorButton::valueChanged, this, [this, p](const glm::vec3& c) { this->setParameter(p, c); });
        break;
    }
    this->Rows.push_back(row);
  }
}

void BrdfFilePanel::setParameter(const BrdfParameter& parameter, const glm::vec3& value)
{
  Scene scene = this->Document->scene();
  const std::string assignment = brdfAssignment(parameter, value);
  const std::string prefix = parameter.name + "=";
  bool replaced = false;
  for (std::string& a : scene.brdf.parameters)
  {
    if (a.compare(0, prefix.size(), prefix) == 0)
    {
      a = assignment;
      replaced = true;
    }
  }
  if (!replaced)
  {
    scene.brdf.parameters.push_back(assignment);
  }
  if (scene.brdf.parameters != this->Document->scene().brdf.parameters)
  {
    this->Document->setScene(scene, MaterialChange); // a uniform
  }
}

void BrdfFilePanel::showScene()
{
  const SceneBrdf& brdf = this->Document->scene().brdf;
  const std::string path = this->Document->vtkScene()->GetBrdfFilePath();
  this->FileLabel->setText(path.empty() ? tr("No .brdf file: the lighting model reflects.")
                                        : QFileInfo(QString::fromStdString(path)).fileName());
  this->FileLabel->setToolTip(QString::fromStdString(path));
  this->Remove->setEnabled(!path.empty());
  if (path != this->ShownPath)
  {
    this->rebuild(path);
  }
  if (this->Rows.empty())
  {
    return;
  }
  std::vector<glm::vec3> values;
  try
  {
    values = brdfParameterValues(this->File, brdf.parameters);
  }
  catch (const Error& e)
  {
    emit problem(QString::fromStdString(e.what()));
    return;
  }
  for (size_t i = 0; i < this->Rows.size(); ++i)
  {
    Row& row = this->Rows[i];
    const glm::vec3& v = values[i];
    if (row.slider)
    {
      const QSignalBlocker blockSlider(row.slider);
      const QSignalBlocker blockBox(row.box);
      row.slider->setValue(sliderAt(row.parameter, v.x));
      row.box->setValue(v.x);
    }
    if (row.check)
    {
      const QSignalBlocker block(row.check);
      row.check->setChecked(v.x != 0.0f);
    }
    if (row.colour)
    {
      row.colour->setValue(v);
    }
  }
}

} // namespace viewer
} // namespace shadelab
