// filter_primitive_fit: MeshLab filters that give a segment a primitive (plane, sphere, cylinder, cone,
// torus), report its parameters, and move the segment onto the primitive with edited parameters
// (section 2.2 of Yang, Oh, Choi, "Mesh Editing with an Intuitive User Interface"). The geometry is in
// common/; this plugin reads parameters, validates input, applies results and reports in the log.
#ifndef PRIMITIVE_EDIT_FILTER_PRIMITIVE_FIT_H
#define PRIMITIVE_EDIT_FILTER_PRIMITIVE_FIT_H

#include <common/interfaces.h>

class FilterPrimitiveFitPlugin : public QObject, public MeshFilterInterface
{
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
  Q_INTERFACES(MeshFilterInterface)

public:
  enum { PRIMITIVE_FIT_SEGMENT, PRIMITIVE_SNAP_SEGMENT, PRIMITIVE_FIT_ALL_SEGMENTS };

  FilterPrimitiveFitPlugin();

  using MeshFilterInterface::filterInfo;
  using MeshFilterInterface::filterName;

  QString pluginName() const override;
  QString filterName(FilterIDType filter) const override;
  QString filterInfo(FilterIDType filter) const override;
  FilterClass getClass(QAction* action) override;
  FILTER_ARITY filterArity(QAction*) const override { return SINGLE_MESH; }
  int getPreConditions(QAction*) const override;
  int postCondition(QAction* action) const override;
  void initParameterSet(QAction* action, MeshModel& m, RichParameterList& parlst) override;
  bool applyFilter(QAction* action, MeshDocument& md, const RichParameterList& parlst, vcg::CallBackPos* cb) override;

private:
  bool fail(const QString& message);
  bool fitOrSnapSegment(MeshModel& mm, const RichParameterList& parlst, bool snap);
  bool fitAllSegments(MeshModel& mm, const RichParameterList& parlst, vcg::CallBackPos* cb);
};

#endif
