// filter_measure_accuracy_plugin.h: MeasureAccuracyFilters as a plugin of the MeshLab generation being built.
#ifndef PRIMITIVE_EDIT_FILTER_MEASURE_ACCURACY_PLUGIN_H
#define PRIMITIVE_EDIT_FILTER_MEASURE_ACCURACY_PLUGIN_H

#include "filter_measure_accuracy.h"
#include "plugin_api/filter_plugin.h"

class FilterMeasureAccuracyPlugin : public primitive_edit::meshlab::FilterPluginAdapter
{
  Q_OBJECT
  PRIMITIVE_EDIT_FILTER_PLUGIN

public:
  FilterMeasureAccuracyPlugin() : FilterPluginAdapter(std::make_unique<MeasureAccuracyFilters>()) {}
};

#endif
