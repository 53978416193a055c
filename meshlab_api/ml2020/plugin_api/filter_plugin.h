// filter_plugin.h (MeshLab 2020.09): a FilterSuite as a MeshFilterInterface plugin.
//
// A plugin is `class X : public FilterPluginAdapter { Q_OBJECT PRIMITIVE_EDIT_FILTER_PLUGIN public:
// X() : FilterPluginAdapter(std::make_unique<Suite>()) {} };`. The adapter maps the suite's filters to
// actions, its parameter definitions to Rich* parameters and back, MeshLab's callback to Progress, the log
// to Log(), and a failed Status to errorMessage + false, logging the reason as a warning first.
#ifndef PRIMITIVE_EDIT_PLUGIN_API_FILTER_PLUGIN_H
#define PRIMITIVE_EDIT_PLUGIN_API_FILTER_PLUGIN_H

#include "meshlab_api/filter_suite.h"
#include "plugin_api/mesh_document.h"

#include <common/interfaces.h>

#include <memory>

#define PRIMITIVE_EDIT_FILTER_PLUGIN                   \
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID) \
  Q_INTERFACES(MeshFilterInterface)

namespace primitive_edit::meshlab {

class FilterPluginAdapter : public QObject, public MeshFilterInterface
{
public:
  explicit FilterPluginAdapter(std::unique_ptr<FilterSuite> suite);

  using MeshFilterInterface::filterInfo;
  using MeshFilterInterface::filterName;
  using MeshFilterInterface::initParameterSet;

  QString pluginName() const override;
  QString filterName(FilterIDType filter) const override;
  QString filterInfo(FilterIDType filter) const override;
  FilterClass getClass(QAction* action) override;
  FILTER_ARITY filterArity(QAction* action) const override;
  int getPreConditions(QAction* action) const override;
  int postCondition(QAction* action) const override;
  void initParameterSet(QAction* action, MeshDocument& md, RichParameterList& parlst) override;
  bool applyFilter(QAction* action, MeshDocument& md, const RichParameterList& parlst, vcg::CallBackPos* cb) override;

private:
  const FilterDefinition* definition(int id) const;

  std::unique_ptr<FilterSuite> suite_;
  std::vector<FilterDefinition> definitions_;
};

} // namespace primitive_edit::meshlab

#endif
