// filter_plugin.h (MeshLab 2025.07): a FilterSuite as a FilterPlugin.
//
// A plugin is `class X : public FilterPluginAdapter { Q_OBJECT PRIMITIVE_EDIT_FILTER_PLUGIN public:
// X() : FilterPluginAdapter(std::make_unique<Suite>()) {} };`. The adapter maps the suite's filters to
// actions with their PyMeshLab names, its parameter definitions to Rich* parameters and back, MeshLab's
// callback to Progress, the log to log(), and a failed Status to an MLException, logging the reason as a
// warning first (batch runners print the log).
#ifndef PRIMITIVE_EDIT_PLUGIN_API_FILTER_PLUGIN_H
#define PRIMITIVE_EDIT_PLUGIN_API_FILTER_PLUGIN_H

#include "meshlab_api/filter_suite.h"
#include "plugin_api/mesh_document.h"

#include <common/plugins/interfaces/filter_plugin.h>

#include <memory>

#define PRIMITIVE_EDIT_FILTER_PLUGIN            \
  MESHLAB_PLUGIN_IID_EXPORTER(FILTER_PLUGIN_IID) \
  Q_INTERFACES(FilterPlugin)

namespace primitive_edit::meshlab {

class FilterPluginAdapter : public QObject, public FilterPlugin
{
public:
  explicit FilterPluginAdapter(std::unique_ptr<FilterSuite> suite);

  using FilterPlugin::filterInfo;
  using FilterPlugin::filterName;
  using FilterPlugin::initParameterList;
  using FilterPlugin::pythonFilterName;

  QString pluginName() const override;
  QString filterName(ActionIDType filter) const override;
  QString pythonFilterName(ActionIDType filter) const override;
  QString filterInfo(ActionIDType filter) const override;
  FilterClass getClass(const QAction* action) const override;
  FilterArity filterArity(const QAction* action) const override;
  int getPreConditions(const QAction* action) const override;
  int postCondition(const QAction* action) const override;
  RichParameterList initParameterList(const QAction* action, const MeshDocument& md) override;
  std::map<std::string, QVariant> applyFilter(const QAction* action, const RichParameterList& parlst,
                                              MeshDocument& md, unsigned int& postConditionMask,
                                              vcg::CallBackPos* cb) override;

private:
  const FilterDefinition* definition(int id) const;

  std::unique_ptr<FilterSuite> suite_;
  std::vector<FilterDefinition> definitions_;
};

} // namespace primitive_edit::meshlab

#endif
