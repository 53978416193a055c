#include "meshlab_api/filter_suite.h"

namespace primitive_edit::meshlab {

namespace {

ParameterDefinition definition(ParameterDefinition::Kind kind, const QString& name, const QVariant& value,
                               const QString& label, const QString& tooltip)
{
  ParameterDefinition d;
  d.kind = kind;
  d.name = name;
  d.value = value;
  d.label = label;
  d.tooltip = tooltip;
  return d;
}

} // namespace

void ParameterList::addInt(const QString& name, int value, const QString& label, const QString& tooltip)
{
  definitions_.push_back(definition(ParameterDefinition::Kind::Int, name, value, label, tooltip));
}

void ParameterList::addFloat(const QString& name, double value, const QString& label, const QString& tooltip)
{
  definitions_.push_back(definition(ParameterDefinition::Kind::Float, name, value, label, tooltip));
}

void ParameterList::addBool(const QString& name, bool value, const QString& label, const QString& tooltip)
{
  definitions_.push_back(definition(ParameterDefinition::Kind::Bool, name, value, label, tooltip));
}

void ParameterList::addEnum(const QString& name, int value, const QStringList& values, const QString& label,
                            const QString& tooltip)
{
  definitions_.push_back(definition(ParameterDefinition::Kind::Enum, name, value, label, tooltip));
  definitions_.back().enum_values = values;
}

void ParameterList::addString(const QString& name, const QString& value, const QString& label,
                              const QString& tooltip)
{
  definitions_.push_back(definition(ParameterDefinition::Kind::String, name, value, label, tooltip));
}

void ParameterList::addSaveFile(const QString& name, const QString& value, const QString& extension,
                                const QString& label, const QString& tooltip)
{
  definitions_.push_back(definition(ParameterDefinition::Kind::SaveFile, name, value, label, tooltip));
  definitions_.back().file_extension = extension;
}

void ParameterList::addPosition(const QString& name, const Eigen::Vector3d& value, const QString& label,
                                const QString& tooltip)
{
  definitions_.push_back(definition(ParameterDefinition::Kind::Position, name, QVariant(), label, tooltip));
  definitions_.back().vector = value;
}

void ParameterList::addDirection(const QString& name, const Eigen::Vector3d& value, const QString& label,
                                 const QString& tooltip)
{
  definitions_.push_back(definition(ParameterDefinition::Kind::Direction, name, QVariant(), label, tooltip));
  definitions_.back().vector = value;
}

void ParameterList::addMesh(const QString& name, int mesh_id, const QString& label, const QString& tooltip)
{
  definitions_.push_back(definition(ParameterDefinition::Kind::Mesh, name, mesh_id, label, tooltip));
}

} // namespace primitive_edit::meshlab
