// filter_segment: MeshLab filters that split a mesh into segments by shape and fix the segmentation
// (section 2.1 of Yang, Oh, Choi, "Mesh Editing with an Intuitive User Interface"). The geometry is in
// common/; this plugin reads parameters, validates input, stores the result and reports in the log.
#ifndef PRIMITIVE_EDIT_FILTER_SEGMENT_H
#define PRIMITIVE_EDIT_FILTER_SEGMENT_H

#include <common/interfaces.h>

class FilterSegmentPlugin : public QObject, public MeshFilterInterface
{
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
  Q_INTERFACES(MeshFilterInterface)

public:
  enum { SEGMENT_AUTO, SEGMENT_AUTO_PRIMITIVE, SEGMENT_MERGE_SELECTED, SEGMENT_SPLIT_BY_PLANE, SEGMENT_SPLIT_BY_SELECTION, SEGMENT_SELECT };

  FilterSegmentPlugin();

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
  bool autoSegment(MeshModel& mm, const RichParameterList& parlst, vcg::CallBackPos* cb);
  bool autoSegmentByPrimitives(MeshModel& mm, const RichParameterList& parlst, vcg::CallBackPos* cb);
  bool mergeSelected(MeshModel& mm);
  bool splitByPlane(MeshModel& mm, const RichParameterList& parlst);
  bool splitBySelection(MeshModel& mm);
  bool selectSegment(MeshModel& mm, const RichParameterList& parlst);
  void storeSegments(MeshModel& mm, const std::vector<int>& segment_of_face);
};

#endif
