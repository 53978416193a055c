#include "plugin_api/filter_plugin.h"

#include <common/mlexception.h>

namespace primitive_edit::meshlab {

FilterPluginAdapter::FilterPluginAdapter(std::unique_ptr<FilterSuite> suite)
    : suite_(std::move(suite)), definitions_(suite_->filters())
{
  for (const FilterDefinition& d : definitions_) {
    typeList.push_back(d.id);
    actionList.push_back(new QAction(d.name, this));
  }
}

const FilterDefinition* FilterPluginAdapter::definition(int id) const
{
  for (const FilterDefinition& d : definitions_)
    if (d.id == id)
      return &d;
  return nullptr;
}

QString FilterPluginAdapter::pluginName() const { return suite_->pluginName(); }

QString FilterPluginAdapter::filterName(ActionIDType filter) const
{
  const FilterDefinition* d = definition(filter);
  return d ? d->name : QString();
}

QString FilterPluginAdapter::pythonFilterName(ActionIDType filter) const
{
  const FilterDefinition* d = definition(filter);
  return d ? d->python_name : QString();
}

QString FilterPluginAdapter::filterInfo(ActionIDType filter) const
{
  const FilterDefinition* d = definition(filter);
  return d ? d->info : QString();
}

FilterPlugin::FilterClass FilterPluginAdapter::getClass(const QAction* action) const
{
  const FilterDefinition* d = definition(ID(action));
  int c = Generic;
  if (d != nullptr) {
    if (d->menus & MenuFaceColoring) c |= FaceColoring;
    if (d->menus & MenuSelection) c |= Selection;
    if (d->menus & MenuQuality) c |= Quality;
    if (d->menus & MenuSmoothing) c |= Smoothing;
    if (d->menus & MenuMeasure) c |= Measure;
  }
  return FilterClass(c);
}

FilterPlugin::FilterArity FilterPluginAdapter::filterArity(const QAction* action) const
{
  const FilterDefinition* d = definition(ID(action));
  return d != nullptr && d->two_meshes ? FIXED : SINGLE_MESH;
}

int FilterPluginAdapter::getPreConditions(const QAction* action) const
{
  const FilterDefinition* d = definition(ID(action));
  return d ? d->preconditions : int(MeshModel::MM_NONE);
}

int FilterPluginAdapter::postCondition(const QAction* action) const
{
  const FilterDefinition* d = definition(ID(action));
  return d ? d->postconditions : int(MeshModel::MM_NONE);
}

RichParameterList FilterPluginAdapter::initParameterList(const QAction* action, const MeshDocument& md)
{
  ParameterList list;
  // The suite reads the document's meshes (for defaults) but does not change them.
  suite_->parameters(ID(action), const_cast<MeshDocument&>(md), list);
  RichParameterList parlst;
  using Kind = ParameterDefinition::Kind;
  for (const ParameterDefinition& p : list.definitions()) {
    const Point3m v(Scalarm(p.vector.x()), Scalarm(p.vector.y()), Scalarm(p.vector.z()));
    switch (p.kind) {
    case Kind::Int: parlst.addParam(RichInt(p.name, p.value.toInt(), p.label, p.tooltip)); break;
    case Kind::Float: parlst.addParam(RichFloat(p.name, Scalarm(p.value.toDouble()), p.label, p.tooltip)); break;
    case Kind::Bool: parlst.addParam(RichBool(p.name, p.value.toBool(), p.label, p.tooltip)); break;
    case Kind::Enum:
      parlst.addParam(RichEnum(p.name, p.value.toInt(), p.enum_values, p.label, p.tooltip));
      break;
    case Kind::String: parlst.addParam(RichString(p.name, p.value.toString(), p.label, p.tooltip)); break;
    case Kind::SaveFile:
      parlst.addParam(RichFileSave(p.name, p.value.toString(), p.file_extension, p.label, p.tooltip));
      break;
    case Kind::Position: parlst.addParam(RichPosition(p.name, v, p.label, p.tooltip)); break;
    case Kind::Direction: parlst.addParam(RichDirection(p.name, v, p.label, p.tooltip)); break;
    case Kind::Mesh: parlst.addParam(RichMesh(p.name, unsigned(p.value.toInt()), &md, p.label, p.tooltip)); break;
    }
  }
  return parlst;
}

std::map<std::string, QVariant> FilterPluginAdapter::applyFilter(const QAction* action, const RichParameterList& parlst,
                                                                 MeshDocument& md, unsigned int& postConditionMask,
                                                                 vcg::CallBackPos* cb)
{
  const int id = ID(action);
  ParameterList list;
  suite_->parameters(id, md, list);
  FilterArguments arguments;
  using Kind = ParameterDefinition::Kind;
  for (const ParameterDefinition& p : list.definitions()) {
    switch (p.kind) {
    case Kind::Int: arguments.set(p.name, parlst.getInt(p.name)); break;
    case Kind::Float: arguments.set(p.name, double(parlst.getFloat(p.name))); break;
    case Kind::Bool: arguments.set(p.name, parlst.getBool(p.name)); break;
    case Kind::Enum: arguments.set(p.name, parlst.getEnum(p.name)); break;
    case Kind::String: arguments.set(p.name, parlst.getString(p.name)); break;
    case Kind::SaveFile: arguments.set(p.name, parlst.getSaveFileName(p.name)); break;
    case Kind::Position:
    case Kind::Direction: {
      const Point3m v = parlst.getPoint3m(p.name);
      arguments.setVector(p.name, Eigen::Vector3d(v[0], v[1], v[2]));
      break;
    }
    case Kind::Mesh: arguments.setMesh(p.name, md.getMesh(parlst.getMeshId(p.name))); break;
    }
  }
  if (md.mm() == nullptr) {
    const QString message = filterName(id) + ": there is no mesh.";
    log(GLLogStream::WARNING, message.toStdString());
    throw MLException(message);
  }
  FilterRun run{md, *md.mm(), arguments, [this](const QString& line) { log(line.toStdString()); },
                cb != nullptr ? Progress(cb) : Progress()};
  const Status status = suite_->apply(id, run);
  if (!status.ok()) {
    // Batch runners print the log; the GUI shows the exception's text: say it in both.
    log(GLLogStream::WARNING, status.error);
    throw MLException(QString::fromStdString(status.error));
  }
  const FilterDefinition* d = definition(id);
  postConditionMask = d ? unsigned(d->postconditions) : unsigned(MeshModel::MM_NONE);
  return {};
}

} // namespace primitive_edit::meshlab
