#include "plugin_api/filter_plugin.h"

namespace primitive_edit::meshlab {

FilterPluginAdapter::FilterPluginAdapter(std::unique_ptr<FilterSuite> suite)
    : suite_(std::move(suite)), definitions_(suite_->filters())
{
  for (const FilterDefinition& d : definitions_) {
    typeList << d.id;
    actionList << new QAction(d.name, this);
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

QString FilterPluginAdapter::filterName(FilterIDType filter) const
{
  const FilterDefinition* d = definition(filter);
  return d ? d->name : QString();
}

QString FilterPluginAdapter::filterInfo(FilterIDType filter) const
{
  const FilterDefinition* d = definition(filter);
  return d ? d->info : QString();
}

MeshFilterInterface::FilterClass FilterPluginAdapter::getClass(QAction* action)
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

MeshFilterInterface::FILTER_ARITY FilterPluginAdapter::filterArity(QAction* action) const
{
  const FilterDefinition* d = definition(ID(action));
  return d != nullptr && d->two_meshes ? FIXED : SINGLE_MESH;
}

int FilterPluginAdapter::getPreConditions(QAction* action) const
{
  const FilterDefinition* d = definition(ID(action));
  return d ? d->preconditions : int(MeshModel::MM_NONE);
}

int FilterPluginAdapter::postCondition(QAction* action) const
{
  const FilterDefinition* d = definition(ID(action));
  return d ? d->postconditions : int(MeshModel::MM_NONE);
}

void FilterPluginAdapter::initParameterSet(QAction* action, MeshDocument& md, RichParameterList& parlst)
{
  ParameterList list;
  suite_->parameters(ID(action), md, list);
  using Kind = ParameterDefinition::Kind;
  for (const ParameterDefinition& p : list.definitions()) {
    switch (p.kind) {
    case Kind::Int: parlst.addParam(RichInt(p.name, p.value.toInt(), p.label, p.tooltip)); break;
    case Kind::Float: parlst.addParam(RichFloat(p.name, float(p.value.toDouble()), p.label, p.tooltip)); break;
    case Kind::Bool: parlst.addParam(RichBool(p.name, p.value.toBool(), p.label, p.tooltip)); break;
    case Kind::Enum:
      parlst.addParam(RichEnum(p.name, p.value.toInt(), p.enum_values, p.label, p.tooltip));
      break;
    case Kind::String: parlst.addParam(RichString(p.name, p.value.toString(), p.label, p.tooltip)); break;
    case Kind::SaveFile:
      parlst.addParam(RichSaveFile(p.name, p.value.toString(), p.file_extension, p.label, p.tooltip));
      break;
    case Kind::Position:
    case Kind::Direction:
      parlst.addParam(RichPoint3f(p.name, vcg::Point3d(p.vector.x(), p.vector.y(), p.vector.z()), p.label, p.tooltip));
      break;
    case Kind::Mesh: parlst.addParam(RichMesh(p.name, md.getMesh(p.value.toInt()), &md, p.label, p.tooltip)); break;
    }
  }
}

bool FilterPluginAdapter::applyFilter(QAction* action, MeshDocument& md, const RichParameterList& parlst,
                                      vcg::CallBackPos* cb)
{
  const int id = ID(action);
  // The definitions again, for the kinds: a script lists every parameter, the values come from it.
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
      const vcg::Point3f v = parlst.getPoint3f(p.name);
      arguments.setVector(p.name, Eigen::Vector3d(v[0], v[1], v[2]));
      break;
    }
    case Kind::Mesh: arguments.setMesh(p.name, parlst.getMesh(p.name)); break;
    }
  }
  if (md.mm() == nullptr) {
    errorMessage = filterName(id) + ": there is no mesh.";
    Log(GLLogStream::WARNING, qUtf8Printable(errorMessage));
    return false;
  }
  FilterRun run{md, *md.mm(), arguments, [this](const QString& line) { Log("%s", qUtf8Printable(line)); },
                cb != nullptr ? Progress(cb) : Progress()};
  const Status status = suite_->apply(id, run);
  if (status.ok())
    return true;
  // meshlabserver prints only the log of a failed filter, the GUI shows errorMessage: say it in both.
  errorMessage = QString::fromStdString(status.error);
  Log(GLLogStream::WARNING, qUtf8Printable(errorMessage));
  return false;
}

} // namespace primitive_edit::meshlab
