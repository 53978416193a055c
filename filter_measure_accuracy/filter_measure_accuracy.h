// filter_measure_accuracy: the MeshLab filter "Measure: Accuracy Against Reference" (section 3 of Yang,
// Oh, Choi, "Mesh Editing with an Intuitive User Interface"): samples the measured mesh uniformly by area,
// measures each sample's shortest distance to the reference (CAD) mesh and logs the share within the
// tolerance, mean, RMS, max and a histogram; optionally paints a deviation map on the measured mesh.
// The geometry is in common/mesh/sample_surface_uniform.h and common/measure/measure_accuracy.h. Written
// once for every MeshLab generation (meshlab_api/filter_suite.h); filter_measure_accuracy_plugin.h makes it
// a plugin of the generation being built.
#ifndef PRIMITIVE_EDIT_FILTER_MEASURE_ACCURACY_H
#define PRIMITIVE_EDIT_FILTER_MEASURE_ACCURACY_H

#include "meshlab_api/filter_suite.h"
#include "plugin_api/mesh_document.h"

class MeasureAccuracyFilters : public primitive_edit::meshlab::FilterSuite
{
public:
  enum { MEASURE_ACCURACY };

  QString pluginName() const override;
  std::vector<primitive_edit::meshlab::FilterDefinition> filters() const override;
  void parameters(int id, MeshDocument& document, primitive_edit::meshlab::ParameterList& out) const override;
  primitive_edit::Status apply(int id, primitive_edit::meshlab::FilterRun& run) override;
};

#endif
