#include "NormalsPanel.h"

#include "SceneView.h"
#include "ViewerDocument.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>

namespace shadelab
{
namespace viewer
{

NormalsPanel::NormalsPanel(ViewerDocument* document, SceneView* view, QWidget* parent)
  : QWidget(parent)
  , Document(document)
  , Weighting(new QComboBox(this))
  , Splitting(new QCheckBox(tr("keep edges sharper than the feature angle sharp"), this))
  , FeatureAngle(new QDoubleSpinBox(this))
  , Replace(new QCheckBox(tr("recompute normals the file has"), this))
  , Glyphs(new QCheckBox(tr("show normals as glyphs"), this))
{
  // In slPolyDataNormals::WeightingType order.
  this->Weighting->addItems({ tr("uniform"), tr("area"), tr("angle (default)"), tr("Max (Nelson Max 1999)") });
  this->FeatureAngle->setRange(0.0, 180.0);
  this->FeatureAngle->setSuffix(QString::fromUtf8("\u00b0"));
  this->FeatureAngle->setKeyboardTracking(false);
  const NormalsSettings& settings = document->normals();
  this->Weighting->setCurrentIndex(settings.weighting);
  this->Splitting->setChecked(settings.splitting);
  this->FeatureAngle->setValue(settings.featureAngle);
  this->Replace->setChecked(settings.replace);

  auto* form = new QFormLayout(this);
  form->addRow(tr("Weighting"), this->Weighting);
  form->addRow(tr("Splitting"), this->Splitting);
  form->addRow(tr("Feature angle"), this->FeatureAngle);
  form->addRow(tr("Mesh normals"), this->Replace);
  form->addRow(tr("Glyphs"), this->Glyphs);

  connect(this->Weighting, QOverload<int>::of(&QComboBox::currentIndexChanged), this, &NormalsPanel::apply);
  connect(this->Splitting, &QCheckBox::toggled, this, &NormalsPanel::apply);
  connect(this->FeatureAngle, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, &NormalsPanel::apply);
  connect(this->Replace, &QCheckBox::toggled, this, &NormalsPanel::apply);
  connect(this->Glyphs, &QCheckBox::toggled, view, &SceneView::setNormalGlyphs);
}

void NormalsPanel::apply()
{
  NormalsSettings settings;
  settings.weighting = this->Weighting->currentIndex();
  settings.splitting = this->Splitting->isChecked();
  settings.featureAngle = this->FeatureAngle->value();
  settings.replace = this->Replace->isChecked();
  this->FeatureAngle->setEnabled(settings.splitting);
  this->Document->setNormals(settings);
}

} // namespace viewer
} // namespace shadelab
