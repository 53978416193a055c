#include "primitive_edit_panel.h"

#include "common/base/constants.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include <cmath>
#include <limits>

using primitive_edit::Primitive;
using primitive_edit::PrimitiveType;

namespace {

constexpr double kDegrees = primitive_edit::degrees_from_radians(1.0);  // degrees per radian
constexpr double kBig = 1e9;

} // namespace

PrimitiveEditPanel::PrimitiveEditPanel(QWidget* parent) : QWidget(parent)
{
  auto* layout = new QVBoxLayout(this);

  auto* segmentation = new QGroupBox("Segments", this);
  auto* seg_layout = new QFormLayout(segmentation);
  angle_ = new QDoubleSpinBox(segmentation);
  angle_->setRange(1, 89);
  angle_->setDecimals(1);
  angle_->setValue(30);
  angle_->setSuffix(QString::fromUtf8(" °"));
  angle_->setToolTip("Adjacent faces whose normals differ by less than this angle join one segment.");
  auto* segment = new QPushButton("&Segment", segmentation);
  segment->setToolTip("Automatic segmentation by normal angle (key S in the view); replaces the segments.");
  auto* angle_row = new QHBoxLayout;
  angle_row->addWidget(angle_);
  angle_row->addWidget(segment);
  seg_layout->addRow("Angle", angle_row);
  segments_ = new QLabel(segmentation);
  seg_layout->addRow("Count", segments_);
  picked_ = new QLabel(segmentation);
  picked_->setWordWrap(true);
  seg_layout->addRow("Picked", picked_);
  auto* merge = new QPushButton("&Merge picked", segmentation);
  merge->setToolTip("Merge the picked segments into one (key M).");
  seg_layout->addRow(merge);
  layout->addWidget(segmentation);

  auto* primitive = new QGroupBox("Primitive", this);
  fields_ = new QFormLayout(primitive);
  type_ = new QComboBox(primitive);
  type_->addItems({"Auto", "Plane", "Sphere", "Cylinder", "Cone", "Torus"});
  auto* fit = new QPushButton("&Fit", primitive);
  fit->setToolTip("Fit the chosen type to the picked segments (key F).");
  auto* type_row = new QHBoxLayout;
  type_row->addWidget(type_);
  type_row->addWidget(fit);
  fields_->addRow("Type", type_row);
  radius_ = addField("Radius", 0, kBig, 5);
  minor_ = addField("Minor radius", 0, kBig, 5);
  half_angle_ = addField("Half-angle (°)", 0, 90, 4);
  for (int i = 0; i < 3; ++i)
    axis_[i] = addField(QString("Axis ") + QChar('x' + i), -1, 1, 6);
  for (int i = 0; i < 3; ++i)
    origin_[i] = addField(QString("Centre ") + QChar('x' + i), -kBig, kBig, 5);
  rms_ = new QLabel(primitive);
  fields_->addRow("RMS", rms_);
  apply_ = new QPushButton("&Apply", primitive);
  apply_->setToolTip("Move the picked segments onto the primitive with these parameters (key Enter).");
  fields_->addRow(apply_);
  layout->addWidget(primitive);

  undo_ = new QPushButton("&Undo", this);
  undo_->setToolTip("Undo the last segmentation, merge, split or apply (Ctrl+Z or U).");
  layout->addWidget(undo_);
  status_ = new QLabel(this);
  status_->setWordWrap(true);
  layout->addWidget(status_);
  auto* help = new QLabel("Click: pick a segment. Shift+click: add/remove. Ctrl+drag: split along the line. "
                          "Keys: M merge, 0-5 type, F fit, R edit radius, Enter apply, Ctrl+Z or U undo, "
                          "Esc to rotate the view.",
                          this);
  help->setWordWrap(true);
  layout->addWidget(help);
  layout->addStretch(1);

  connect(segment, &QPushButton::clicked, this, &PrimitiveEditPanel::segmentRequested);
  connect(merge, &QPushButton::clicked, this, &PrimitiveEditPanel::mergeRequested);
  connect(fit, &QPushButton::clicked, this, &PrimitiveEditPanel::fitRequested);
  connect(apply_, &QPushButton::clicked, this, &PrimitiveEditPanel::applyRequested);
  connect(undo_, &QPushButton::clicked, this, &PrimitiveEditPanel::undoRequested);
  showPrimitive(std::nullopt, 0);
  setCanUndo(false, QString());
}

QDoubleSpinBox* PrimitiveEditPanel::addField(const QString& label, double min, double max, int decimals)
{
  auto* field = new QDoubleSpinBox(this);
  field->setRange(min, max);
  field->setDecimals(decimals);
  field->setKeyboardTracking(false);
  field->setObjectName(label);
  fields_->addRow(label, field);
  connect(field, &QDoubleSpinBox::editingFinished, this, [this, field] { fieldEdited(field); });
  return field;
}

void PrimitiveEditPanel::fieldEdited(QDoubleSpinBox* field)
{
  if (filling_ || !shown_)
    return;
  emit parametersEdited();
  // editingFinished while the field keeps the focus means Return was pressed.
  if (field->hasFocus())
    emit viewFocusRequested();
}

double PrimitiveEditPanel::angle() const { return angle_->value(); }

std::optional<PrimitiveType> PrimitiveEditPanel::type() const
{
  const int i = type_->currentIndex();
  if (i <= 0)
    return std::nullopt;
  return PrimitiveType(i - 1);
}

void PrimitiveEditPanel::setType(std::optional<PrimitiveType> type)
{
  type_->setCurrentIndex(type ? int(*type) + 1 : 0);
}

void PrimitiveEditPanel::setSegmentInfo(int segment_count, const QString& picked)
{
  segments_->setText(segment_count > 0 ? QString::number(segment_count)
                                       : QString("none yet: choose an angle and press Segment"));
  picked_->setText(picked.isEmpty() ? QString("none (click a face)") : picked);
}

void PrimitiveEditPanel::showPrimitive(const std::optional<Primitive>& primitive, double rms)
{
  shown_ = primitive;
  filling_ = true;
  if (primitive) {
    radius_->setValue(primitive->radius);
    minor_->setValue(primitive->minor_radius);
    half_angle_->setValue(primitive->half_angle * kDegrees);
    for (int i = 0; i < 3; ++i) {
      axis_[i]->setValue(primitive->axis[i]);
      origin_[i]->setValue(primitive->origin[i]);
    }
    rms_->setText(QString::number(rms, 'g', 4));
  } else {
    rms_->setText("-");
  }
  filling_ = false;
  updateFieldVisibility();
}

void PrimitiveEditPanel::updateFieldVisibility()
{
  const bool shown = shown_.has_value();
  const PrimitiveType t = shown ? shown_->type : PrimitiveType::Plane;
  auto show = [this](QDoubleSpinBox* field, bool visible) {
    field->setVisible(visible);
    if (QWidget* label = fields_->labelForField(field))
      label->setVisible(visible);
  };
  show(radius_, shown && (t == PrimitiveType::Sphere || t == PrimitiveType::Cylinder || t == PrimitiveType::Torus));
  show(minor_, shown && t == PrimitiveType::Torus);
  show(half_angle_, shown && t == PrimitiveType::Cone);
  for (int i = 0; i < 3; ++i) {
    show(axis_[i], shown && t != PrimitiveType::Sphere);
    show(origin_[i], shown);
  }
  const char* names[] = {"Point", "Centre", "Axis point", "Apex", "Centre"};
  for (int i = 0; i < 3; ++i)
    if (auto* label = qobject_cast<QLabel*>(fields_->labelForField(origin_[i])))
      label->setText(QString("%1 %2").arg(names[int(t)]).arg(QChar('x' + i)));
  radius_->setToolTip(t == PrimitiveType::Torus ? "Major radius: axis to tube centre" : "Radius");
  apply_->setEnabled(shown);
}

Primitive PrimitiveEditPanel::editedPrimitive() const
{
  Primitive p = shown_.value_or(Primitive());
  // A field shows its value rounded to its decimals; only a field the user changed replaces the exact value.
  auto take = [](const QDoubleSpinBox* field, double& value, double scale) {
    if (field->value() != field->valueFromText(field->textFromValue(value * scale)))
      value = field->value() / scale;
  };
  take(radius_, p.radius, 1.0);
  take(minor_, p.minor_radius, 1.0);
  take(half_angle_, p.half_angle, kDegrees);
  for (int i = 0; i < 3; ++i) {
    take(axis_[i], p.axis[i], 1.0);
    take(origin_[i], p.origin[i], 1.0);
  }
  return p;
}

void PrimitiveEditPanel::setCanUndo(bool can_undo, const QString& what)
{
  undo_->setEnabled(can_undo);
  undo_->setText(can_undo ? QString("&Undo %1").arg(what) : QString("&Undo"));
}

void PrimitiveEditPanel::setStatus(const QString& text) { status_->setText(text); }

void PrimitiveEditPanel::focusSizeField()
{
  if (!shown_)
    return;
  QDoubleSpinBox* field = origin_[2];
  switch (shown_->type) {
  case PrimitiveType::Sphere:
  case PrimitiveType::Cylinder:
  case PrimitiveType::Torus: field = radius_; break;
  case PrimitiveType::Cone: field = half_angle_; break;
  case PrimitiveType::Plane: break;
  }
  field->setFocus(Qt::ShortcutFocusReason);
  field->selectAll();
}
