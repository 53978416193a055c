// filter_segment_plugin.h: SegmentFilters as a plugin of the MeshLab generation being built.
#ifndef PRIMITIVE_EDIT_FILTER_SEGMENT_PLUGIN_H
#define PRIMITIVE_EDIT_FILTER_SEGMENT_PLUGIN_H

#include "filter_segment.h"
#include "plugin_api/filter_plugin.h"

class FilterSegmentPlugin : public primitive_edit::meshlab::FilterPluginAdapter
{
  Q_OBJECT
  PRIMITIVE_EDIT_FILTER_PLUGIN

public:
  FilterSegmentPlugin() : FilterPluginAdapter(std::make_unique<SegmentFilters>()) {}
};

#endif
