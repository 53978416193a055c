// filter_measure_accuracy: the MeshLab filter "Measure: Accuracy Against Reference" (section 3 of Yang,
// Oh, Choi, "Mesh Editing with an Intuitive User Interface"): samples the measured mesh uniformly by area,
// measures each sample's shortest distance to the reference (CAD) mesh and logs the share within the
// tolerance, mean, RMS, max and a histogram; optionally paints a deviation map on the measured mesh.
// The geometry is in common/mesh/sample_surface_uniform.h and common/measure/measure_accuracy.h.
#ifndef PRIMITIVE_EDIT_FILTER_MEASURE_ACCURACY_H
#define PRIMITIVE_EDIT_FILTER_MEASURE_ACCURACY_H

#include <common/interfaces.h>

class FilterMeasureAccuracyPlugin : public QObject, public MeshFilterInterface
{
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
  Q_INTERFACES(MeshFilterInterface)

public:
  enum { MEASURE_ACCURACY };

  FilterMeasureAccuracyPlugin();

  QString pluginName() const override;
  using MeshFilterInterface::filterName;
  using MeshFilterInterface::filterInfo;
  QString filterName(FilterIDType filter) const override;
  QString filterInfo(FilterIDType filter) const override;
  FilterClass getClass(QAction*) override { return Measure; }
  FILTER_ARITY filterArity(QAction*) const override { return FIXED; }
  int postCondition(QAction*) const override;
  using MeshFilterInterface::initParameterSet;
  void initParameterSet(QAction* action, MeshDocument& md, RichParameterList& parlst) override;
  bool applyFilter(QAction* action, MeshDocument& md, const RichParameterList& parlst, vcg::CallBackPos* cb) override;

private:
  bool fail(const QString& message);
};

#endif
