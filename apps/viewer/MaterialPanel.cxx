#include "MaterialPanel.h"

#include "ColorButton.h"
#include "NumberControl.h"
#include "ViewerDocument.h"

#include "shadelab/SceneKeys.h"

#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QVBoxLayout>

namespace shadelab
{
namespace viewer
{

MaterialPanel::MaterialPanel(ViewerDocument* document, QWidget* parent)
  : QWidget(parent)
  , Document(document)
{
  auto* layout = new QVBoxLayout(this);
  auto* builtIn = new QGroupBox(tr("Parameters of the model"), this);
  this->Form = new QFormLayout(builtIn);
  layout->addWidget(builtIn);
  layout->addStretch(1);

  const auto& keys = materialKeys();
  for (int index = 0; index < static_cast<int>(keys.size()); ++index)
  {
    const SceneKey<SceneMaterial>& key = keys[static_cast<size_t>(index)];
    Row row;
    row.key = QString::fromUtf8(key.name);
    row.bit = key.materialParameter;
    row.index = index;
    if (key.vector)
    {
      row.colour = new ColorButton(key.lo, key.hi, builtIn); // the key's range, above 1 too
      row.editor = row.colour;
      connect(row.colour, &ColorButton::valueChanged, this, [this, index](const glm::vec3& value) {
        Scene scene = this->Document->scene();
        scene.material.*(materialKeys()[static_cast<size_t>(index)].vector) = value;
        this->Document->setScene(scene, MaterialChange);
      });
    }
    else if (key.number)
    {
      row.number = new NumberControl(key.lo, key.hi, builtIn);
      row.editor = row.number;
      connect(row.number, &NumberControl::valueChanged, this, [this, index](double value) {
        Scene scene = this->Document->scene();
        scene.material.*(materialKeys()[static_cast<size_t>(index)].number) = static_cast<float>(value);
        this->Document->setScene(scene, MaterialChange);
      });
    }
    else
    {
      continue; // the diffuse texture is the scene file's
    }
    row.editor->setToolTip(QString::fromUtf8(key.what));
    this->Form->addRow(row.key, row.editor);
    this->Form->labelForField(row.editor)->setToolTip(QString::fromUtf8(key.what));
    this->Rows.push_back(row);
  }
  connect(document, &ViewerDocument::sceneChanged, this, &MaterialPanel::showScene);
  this->showScene();
}

NumberControl* MaterialPanel::numberControl(const QString& key) const
{
  for (const Row& row : this->Rows)
  {
    if (row.key == key)
    {
      return row.number;
    }
  }
  return nullptr;
}

ColorButton* MaterialPanel::colourControl(const QString& key) const
{
  for (const Row& row : this->Rows)
  {
    if (row.key == key)
    {
      return row.colour;
    }
  }
  return nullptr;
}

QStringList MaterialPanel::shownKeys() const
{
  QStringList keys;
  for (const Row& row : this->Rows)
  {
    if (!row.editor->isHidden())
    {
      keys << row.key;
    }
  }
  return keys;
}

void MaterialPanel::showScene()
{
  const Scene& scene = this->Document->scene();
  const unsigned reads = modelInfo(scene.model).reads;
  for (const Row& row : this->Rows)
  {
    const SceneKey<SceneMaterial>& key = materialKeys()[static_cast<size_t>(row.index)];
    if (row.colour)
    {
      row.colour->setValue(scene.material.*(key.vector));
    }
    else
    {
      row.number->setValue(scene.material.*(key.number));
    }
    const bool shown = (reads & row.bit) != 0;
    row.editor->setVisible(shown);
    this->Form->labelForField(row.editor)->setVisible(shown);
  }
}

} // namespace viewer
} // namespace shadelab
