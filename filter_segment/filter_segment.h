// filter_segment: MeshLab filters that split a mesh into segments by shape and fix the segmentation
// (section 2.1 of Yang, Oh, Choi, "Mesh Editing with an Intuitive User Interface"). The geometry is in
// common/; this suite reads parameters, validates input, stores the result and reports in the log. It is
// written once for every MeshLab generation (meshlab_api/filter_suite.h); filter_segment_plugin.h makes it
// a plugin of the generation being built.
#ifndef PRIMITIVE_EDIT_FILTER_SEGMENT_H
#define PRIMITIVE_EDIT_FILTER_SEGMENT_H

#include "meshlab_api/filter_suite.h"
#include "plugin_api/mesh_document.h"

#include <vector>

namespace primitive_edit {
struct FaceAdjacency;
}

class SegmentFilters : public primitive_edit::meshlab::FilterSuite
{
public:
  enum { SEGMENT_AUTO, SEGMENT_AUTO_PRIMITIVE, SEGMENT_MERGE_SELECTED, SEGMENT_SPLIT_BY_PLANE, SEGMENT_SPLIT_BY_SELECTION, SEGMENT_SELECT };

  QString pluginName() const override;
  std::vector<primitive_edit::meshlab::FilterDefinition> filters() const override;
  void parameters(int id, MeshDocument& document, primitive_edit::meshlab::ParameterList& out) const override;
  primitive_edit::Status apply(int id, primitive_edit::meshlab::FilterRun& run) override;

private:
  using Arguments = primitive_edit::meshlab::FilterArguments;
  using Run = primitive_edit::meshlab::FilterRun;
  using Status = primitive_edit::Status;

  Status autoSegment(MeshModel& mm, const Arguments& args, Run& run);
  Status autoSegmentByPrimitives(MeshModel& mm, const Arguments& args, Run& run);
  Status mergeSelected(MeshModel& mm, Run& run);
  Status splitByPlane(MeshModel& mm, const Arguments& args, Run& run);
  Status splitBySelection(MeshModel& mm, Run& run);
  Status selectSegment(MeshModel& mm, const Arguments& args, Run& run);
  // adjacency: the mesh's, when the caller has built it (else the colouring builds it).
  void storeSegments(MeshModel& mm, const std::vector<int>& segment_of_face,
                     const primitive_edit::FaceAdjacency* adjacency = nullptr);
};

#endif
