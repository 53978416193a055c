#include "primitive_edit_panel.h"

#include "common/base/constants.h"
#include "common/base/describe_primitive.h"
#include "common/segment/segment_by_normal_angle.h"
#include "common/segment/segment_by_primitive_growing.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QVBoxLayout>

#include <cmath>
#include <limits>

using primitive_edit::Primitive;
using primitive_edit::PrimitiveType;

namespace {

constexpr double kDegrees = primitive_edit::degrees_from_radians(1.0);  // degrees per radian
constexpr int kPanelWidth = 280;  // pixels: fixed, so that the view beside the panel never moves

// Full precision, shortest form: what the user reads is the value in use (a fit's round-off shows as 0, and an
// untouched field keeps the exact value: editedPrimitive skips fields whose text is the one shown).
QString show_number(double x) { return QString::number(x, 'g', 10); }

} // namespace

PrimitiveEditPanel::PrimitiveEditPanel(QWidget* parent) : QWidget(parent)
{
  auto* layout = new QVBoxLayout(this);
  setFixedWidth(kPanelWidth);
  layout->addWidget(buildSegmentsGroup());
  layout->addWidget(buildPrimitiveGroup());
  buildFooter(layout);
  showPrimitive(std::nullopt, 0);
  setCanUndo(false, QString());
}

// Segments: the method and its parameters, Segment, the counts and Merge.
QGroupBox* PrimitiveEditPanel::buildSegmentsGroup()
{
  auto* segmentation = new QGroupBox("Segments", this);
  auto* seg_layout = new QFormLayout(segmentation);
  segmentation_fields_ = seg_layout;
  method_ = new QComboBox(segmentation);
  method_->addItems({"Primitive fit (scans)", "Normal angle"});
  method_->setToolTip("Primitive fit grows segments over faces within tolerance of a fitted primitive: for scans "
                      "with rough surfaces and blurred edges (as Segment: Auto by Primitive Fit). Normal angle "
                      "joins faces whose normals differ little: for clean meshes (as Segment: Auto by Normal "
                      "Angle).");
  seg_layout->addRow("&Method", method_);
  const primitive_edit::SegmentByPrimitiveGrowingParams growing;
  tolerance_ = new QDoubleSpinBox(segmentation);
  tolerance_->setRange(0, 1e6);
  tolerance_->setDecimals(4);
  tolerance_->setValue(growing.tolerance);
  tolerance_->setSpecialValueText("automatic");
  tolerance_->setToolTip("A face joins a primitive within this distance (mesh units); automatic: 3 times the "
                         "scan's roughness, which is estimated.");
  seg_layout->addRow("Tolerance", tolerance_);
  const primitive_edit::SegmentByNormalAngleParams normal_angle;
  angle_ = new QDoubleSpinBox(segmentation);
  angle_->setRange(1, 89);
  angle_->setDecimals(1);
  angle_->setValue(normal_angle.angle_deg);
  angle_->setSuffix(QString::fromUtf8(" °"));
  angle_->setToolTip("Adjacent faces whose normals differ by less than this angle join one segment.");
  seg_layout->addRow("Angle", angle_);
  auto* segment = new QPushButton("&Segment", segmentation);
  segment->setToolTip("Automatic segmentation by the chosen method (key S in the view); replaces the segments "
                      "(Undo restores them).");
  seg_layout->addRow(segment);
  segments_ = new QLabel(segmentation);
  segments_->setWordWrap(true);
  seg_layout->addRow("Count", segments_);
  picked_ = new QLabel(segmentation);
  picked_->setWordWrap(true);
  seg_layout->addRow("Picked", picked_);
  auto* merge = new QPushButton("&Merge picked", segmentation);
  merge->setToolTip("Merge the picked segments into one (key M).");
  seg_layout->addRow(merge);

  connect(segment, &QPushButton::clicked, this, &PrimitiveEditPanel::segmentRequested);
  connect(method_, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
          &PrimitiveEditPanel::updateSegmentationFields);
  // A method chosen (Alt+M and the arrow keys, or the mouse): the keys go back to the view, S segments.
  connect(method_, QOverload<int>::of(&QComboBox::activated), this, &PrimitiveEditPanel::viewFocusRequested);
  updateSegmentationFields();
  connect(merge, &QPushButton::clicked, this, &PrimitiveEditPanel::mergeRequested);
  return segmentation;
}

// Primitive: the type and Fit, the fit method, the parameters, the RMS and Apply.
QGroupBox* PrimitiveEditPanel::buildPrimitiveGroup()
{
  auto* primitive = new QGroupBox("Primitive", this);
  fields_ = new QFormLayout(primitive);
  type_ = new QComboBox(primitive);
  type_->addItems({"Auto", "Plane", "Sphere", "Cylinder", "Cone", "Torus"});
  auto* fit = new QPushButton("&Fit", primitive);
  fit->setToolTip("Fit the chosen type to the picked segments (key F).");
  // As narrow as its word, so that the type beside it reads whole ("Cylinder" was cut at the panel's width).
  fit->setFixedWidth(fit->fontMetrics().horizontalAdvance("Fit") + 32);
  auto* type_row = new QHBoxLayout;
  type_row->addWidget(type_, 1);
  type_row->addWidget(fit);
  fields_->addRow("Type", type_row);
  fit_method_ = new QComboBox(primitive);
  for (int i = 0; i < primitive_edit::kFitMethodCount; ++i)
    fit_method_->addItem(primitive_edit::fit_method_name(primitive_edit::FitMethod(i)));
  fit_method_->setToolTip("Refined starts: several starts refined on orthogonal distances (most accurate on "
                          "scans). Direct (paper): Andrews and Sequin's type-constrained direct quadric fit, "
                          "as the paper does; exact on exact data, biased by noise. Direct, refined: that fit "
                          "refined. A torus always takes the refined starts.");
  fields_->addRow("Method", fit_method_);
  relations_ = new QCheckBox("Relations", primitive);
  relations_->setChecked(true);
  relations_->setToolTip("Fit the picked segments together with all the others, as Primitive: Fit All Segments "
                         "does: directions parallel, perpendicular or at 45 degrees, coaxial and concentric "
                         "features, equal radii and fillets tangent to their faces hold where the scan allows, "
                         "so a face comes out square to the part instead of tilted by the roughness. The log "
                         "lists the relations. Off: the picked segments are fitted alone.");
  fields_->addRow(relations_);
  radius_ = addField("Radius");
  minor_ = addField("Minor radius");
  half_angle_ = addField("Half-angle (°)");
  for (int i = 0; i < 3; ++i)
    axis_[i] = addField(QString("Axis ") + QChar('x' + i));
  for (int i = 0; i < 3; ++i)
    origin_[i] = addField(QString("Centre ") + QChar('x' + i));
  rms_ = new QLabel(primitive);
  fields_->addRow("RMS", rms_);
  apply_ = new QPushButton("&Apply", primitive);
  apply_->setToolTip("Move the picked segments onto the primitive with these parameters (key Enter).");
  fields_->addRow(apply_);

  connect(fit, &QPushButton::clicked, this, &PrimitiveEditPanel::fitRequested);
  connect(apply_, &QPushButton::clicked, this, &PrimitiveEditPanel::applyRequested);
  return primitive;
}

// Below the groups: Undo, the status line and the help.
void PrimitiveEditPanel::buildFooter(QVBoxLayout* layout)
{
  undo_ = new QPushButton("&Undo", this);
  undo_->setToolTip("Undo the last segmentation, merge, split or apply (Ctrl+Z or U).");
  layout->addWidget(undo_);
  status_ = new QLabel(this);
  status_->setWordWrap(true);
  status_->hide();
  layout->addWidget(status_);
  auto* help = new QLabel("Click: pick a segment. Shift+click: add/remove. Ctrl+drag: split along the line. "
                          "Keys: M merge, 0-5 type, F fit, R edit radius, Enter apply, Ctrl+Z or U undo, "
                          "Esc to rotate the view.",
                          this);
  help->setWordWrap(true);
  layout->addWidget(help);
  layout->addStretch(1);
  connect(undo_, &QPushButton::clicked, this, &PrimitiveEditPanel::undoRequested);
}

QLineEdit* PrimitiveEditPanel::addField(const QString& label)
{
  auto* field = new QLineEdit(this);
  field->setObjectName(label);
  fields_->addRow(label, field);
  connect(field, &QLineEdit::editingFinished, this, [this, field] { fieldEdited(field); });
  return field;
}

void PrimitiveEditPanel::fieldEdited(QLineEdit* field)
{
  // editingFinished comes on Return and again when the focus leaves: only a changed text is an edit.
  if (filling_ || !shown_ || field->text() == field->property("shown").toString())
    return;
  emit parametersEdited();
  if (field->hasFocus())
    emit viewFocusRequested();
}

void PrimitiveEditPanel::updateSegmentationFields()
{
  const bool growing = segmentByPrimitiveFit();
  for (QWidget* field : {static_cast<QWidget*>(tolerance_), static_cast<QWidget*>(angle_)}) {
    const bool visible = (field == tolerance_) == growing;
    field->setVisible(visible);
    if (QWidget* label = segmentation_fields_->labelForField(field))
      label->setVisible(visible);
  }
}

bool PrimitiveEditPanel::segmentByPrimitiveFit() const { return method_->currentIndex() == 0; }

double PrimitiveEditPanel::segmentTolerance() const { return tolerance_->value(); }

double PrimitiveEditPanel::angle() const { return angle_->value(); }

std::optional<PrimitiveType> PrimitiveEditPanel::type() const
{
  const int i = type_->currentIndex();
  if (i <= 0)
    return std::nullopt;
  return PrimitiveType(i - 1);
}

primitive_edit::FitMethod PrimitiveEditPanel::method() const
{
  return primitive_edit::FitMethod(fit_method_->currentIndex());
}

bool PrimitiveEditPanel::relations() const
{
  return relations_->isChecked();
}

void PrimitiveEditPanel::setType(std::optional<PrimitiveType> type)
{
  type_->setCurrentIndex(type ? int(*type) + 1 : 0);
}

void PrimitiveEditPanel::setSegmentInfo(int segment_count, const QString& picked)
{
  segments_->setText(segment_count > 0 ? QString::number(segment_count)
                                       : QString("none yet: choose a method and press Segment"));
  picked_->setText(picked.isEmpty() ? QString("none (click a face)") : picked);
}

void PrimitiveEditPanel::showPrimitive(const std::optional<Primitive>& primitive, double rms)
{
  shown_ = primitive;
  filling_ = true;
  auto fill = [](QLineEdit* field, double value) {
    field->setText(show_number(value));
    field->setProperty("shown", field->text());
    field->setCursorPosition(0);
  };
  if (primitive) {
    fill(radius_, primitive->radius);
    fill(minor_, primitive->minor_radius);
    fill(half_angle_, primitive->half_angle * kDegrees);
    const double size = primitive_edit::primitive_size(*primitive);
    for (int i = 0; i < 3; ++i) {
      fill(axis_[i], primitive_edit::shown_value(primitive->axis[i], 1.0));
      fill(origin_[i], primitive_edit::shown_value(primitive->origin[i], size));
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
  auto show = [this](QLineEdit* field, bool visible) {
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

std::optional<Primitive> PrimitiveEditPanel::editedPrimitive(QString* error) const
{
  Primitive p = shown_.value_or(Primitive());
  bool ok = true;
  // A field shows its value to 10 digits; only a field whose text the user changed replaces the exact value.
  auto take = [&](const QLineEdit* field, double& value, double scale) {
    const QString text = field->text().trimmed();
    if (!ok || field->text() == field->property("shown").toString())
      return;
    bool number = false;
    const double typed = QLocale::c().toDouble(text, &number);
    if (!number || !std::isfinite(typed)) {
      ok = false;
      const auto* label = qobject_cast<const QLabel*>(fields_->labelForField(const_cast<QLineEdit*>(field)));
      if (error != nullptr)
        *error = QString("%1: \"%2\" is not a number").arg(label ? label->text() : field->objectName(), text);
      return;
    }
    value = typed / scale;
  };
  take(radius_, p.radius, 1.0);
  take(minor_, p.minor_radius, 1.0);
  take(half_angle_, p.half_angle, kDegrees);
  for (int i = 0; i < 3; ++i) {
    take(axis_[i], p.axis[i], 1.0);
    take(origin_[i], p.origin[i], 1.0);
  }
  if (!ok)
    return std::nullopt;
  return p;
}

void PrimitiveEditPanel::setCanUndo(bool can_undo, const QString& what)
{
  undo_->setEnabled(can_undo);
  undo_->setText(can_undo ? QString("&Undo %1").arg(what) : QString("&Undo"));
}

void PrimitiveEditPanel::setStatus(const QString& text)
{
  status_->setText(text);
  // An empty status takes no room: the panel looks the same each time the tool opens, whatever it said before.
  status_->setVisible(!text.isEmpty());
}

void PrimitiveEditPanel::focusSizeField()
{
  if (!shown_)
    return;
  QLineEdit* field = origin_[2];
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
