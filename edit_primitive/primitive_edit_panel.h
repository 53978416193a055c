// primitive_edit_panel.h: the Primitive Edit tool's dock panel, plain Qt widgets: automatic segmentation
// (by primitive fit for scans, or by normal angle, with the filters' defaults), the picked segments with
// Merge, the primitive type with Fit (holding the relations with the other segments, or alone), the fitted
// parameters as editable fields with the RMS residual, Apply and Undo. Its width is fixed (long status lines
// wrap), so the view beside it never moves. Fields take what users type (scientific notation, signs) and hold
// the exact value until the user changes the text. It only shows values and emits requests; the edit plugin
// does the work.
#ifndef PRIMITIVE_EDIT_PRIMITIVE_EDIT_PANEL_H
#define PRIMITIVE_EDIT_PRIMITIVE_EDIT_PANEL_H

#include "common/base/primitive.h"
#include "common/fit/fit_result.h"

#include <QWidget>

#include <optional>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;

class PrimitiveEditPanel : public QWidget
{
  Q_OBJECT

public:
  explicit PrimitiveEditPanel(QWidget* parent = nullptr);

  // The segmentation the Segment button runs: by primitive fit (with its tolerance, 0 = automatic) or by
  // normal angle (with its angle).
  bool segmentByPrimitiveFit() const;
  double segmentTolerance() const;
  double angle() const;
  // The chosen type; std::nullopt for Auto.
  std::optional<primitive_edit::PrimitiveType> type() const;
  // How the fit starts (Refined starts, the paper's direct fit, or it refined).
  primitive_edit::FitMethod method() const;
  // Whether the fit holds the relations with the other segments (as Fit All) or fits the picked ones alone.
  bool relations() const;
  void setType(std::optional<primitive_edit::PrimitiveType> type);

  void setSegmentInfo(int segment_count, const QString& picked);
  // Shows a fitted (or edited) primitive in the fields, or clears them.
  void showPrimitive(const std::optional<primitive_edit::Primitive>& primitive, double rms);
  // The shown primitive with the values of the fields the user changed; std::nullopt when a changed field is
  // not a number (error says which).
  std::optional<primitive_edit::Primitive> editedPrimitive(QString* error) const;
  void setCanUndo(bool can_undo, const QString& what);
  void setStatus(const QString& text);
  // Puts the keyboard focus in the first size field of the shown type (radius, half-angle, ...).
  void focusSizeField();

signals:
  void segmentRequested();
  void mergeRequested();
  void fitRequested();
  void parametersEdited();
  void applyRequested();
  void undoRequested();
  // Return was pressed in a field: the keyboard goes back to the view.
  void viewFocusRequested();

private:
  class QGroupBox* buildSegmentsGroup();
  class QGroupBox* buildPrimitiveGroup();
  void buildFooter(class QVBoxLayout* layout);
  QLineEdit* addField(const QString& label);
  void fieldEdited(QLineEdit* field);
  void updateFieldVisibility();
  void updateSegmentationFields();

  QComboBox* method_ = nullptr;
  QDoubleSpinBox* tolerance_ = nullptr;
  QDoubleSpinBox* angle_ = nullptr;
  class QFormLayout* segmentation_fields_ = nullptr;
  QLabel* segments_ = nullptr;
  QLabel* picked_ = nullptr;
  QComboBox* type_ = nullptr;
  QComboBox* fit_method_ = nullptr;
  class QCheckBox* relations_ = nullptr;
  QLineEdit* radius_ = nullptr;
  QLineEdit* minor_ = nullptr;
  QLineEdit* half_angle_ = nullptr;
  QLineEdit* axis_[3] = {nullptr, nullptr, nullptr};
  QLineEdit* origin_[3] = {nullptr, nullptr, nullptr};
  QLabel* rms_ = nullptr;
  QPushButton* apply_ = nullptr;
  QPushButton* undo_ = nullptr;
  QLabel* status_ = nullptr;
  class QFormLayout* fields_ = nullptr;
  std::optional<primitive_edit::Primitive> shown_;
  bool filling_ = false;
};

#endif
