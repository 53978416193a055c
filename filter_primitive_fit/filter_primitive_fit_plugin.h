// filter_primitive_fit_plugin.h: PrimitiveFitFilters as a plugin of the MeshLab generation being built.
#ifndef PRIMITIVE_EDIT_FILTER_PRIMITIVE_FIT_PLUGIN_H
#define PRIMITIVE_EDIT_FILTER_PRIMITIVE_FIT_PLUGIN_H

#include "filter_primitive_fit.h"
#include "plugin_api/filter_plugin.h"

class FilterPrimitiveFitPlugin : public primitive_edit::meshlab::FilterPluginAdapter
{
  Q_OBJECT
  PRIMITIVE_EDIT_FILTER_PLUGIN

public:
  FilterPrimitiveFitPlugin() : FilterPluginAdapter(std::make_unique<PrimitiveFitFilters>()) {}
};

#endif
