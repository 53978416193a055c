// filter_primitive_fit: MeshLab filters that give a segment a primitive (plane, sphere, cylinder, cone,
// torus), report its parameters, and move the segment onto the primitive with edited parameters
// (section 2.2 of Yang, Oh, Choi, "Mesh Editing with an Intuitive User Interface"). The geometry is in
// common/; this suite reads parameters, validates input, applies results and reports in the log. Written
// once for every MeshLab generation (meshlab_api/filter_suite.h); filter_primitive_fit_plugin.h makes it a
// plugin of the generation being built.
#ifndef PRIMITIVE_EDIT_FILTER_PRIMITIVE_FIT_H
#define PRIMITIVE_EDIT_FILTER_PRIMITIVE_FIT_H

#include "meshlab_api/filter_suite.h"
#include "plugin_api/mesh_document.h"

namespace primitive_edit {
struct FitAllSegmentsResult;
}

class PrimitiveFitFilters : public primitive_edit::meshlab::FilterSuite
{
public:
  enum { PRIMITIVE_FIT_SEGMENT, PRIMITIVE_SNAP_SEGMENT, PRIMITIVE_FIT_ALL_SEGMENTS };

  QString pluginName() const override;
  std::vector<primitive_edit::meshlab::FilterDefinition> filters() const override;
  void parameters(int id, MeshDocument& document, primitive_edit::meshlab::ParameterList& out) const override;
  primitive_edit::Status apply(int id, primitive_edit::meshlab::FilterRun& run) override;

private:
  using Arguments = primitive_edit::meshlab::FilterArguments;
  using Run = primitive_edit::meshlab::FilterRun;
  using Status = primitive_edit::Status;

  Status fitOrSnapSegment(MeshModel& mm, const Arguments& parlst, bool snap, Run& run);
  Status fitAllSegments(MeshModel& mm, const Arguments& parlst, Run& run);
  static void logRelations(const QString& name, const primitive_edit::FitAllSegmentsResult& r, Run& run);
};

#endif
