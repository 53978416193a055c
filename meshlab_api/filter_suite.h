// filter_suite.h: a plugin's filters, written once for every MeshLab generation.
//
// A FilterSuite says which filters a plugin has (name, PyMeshLab name, help, menu, mesh requirements),
// which parameters each takes, and runs one. It knows nothing of MeshLab's plugin classes: the adapter
// of the generation being built (plugin_api/filter_plugin.h, from meshlab_api/ml2020 or ml2025) turns it
// into a MeshLab 2020.09 MeshFilterInterface or a MeshLab 2025.07 FilterPlugin, builds that
// generation's parameter objects, reads the values back, reports progress and logs, and turns a failed
// Status into that generation's failure (errorMessage and false, or an MLException), always logging the
// reason first (meshlabserver prints the log, not the error message).
#ifndef PRIMITIVE_EDIT_MESHLAB_API_FILTER_SUITE_H
#define PRIMITIVE_EDIT_MESHLAB_API_FILTER_SUITE_H

#include "common/base/progress.h"
#include "common/base/status.h"

#include <QString>
#include <QStringList>
#include <QVariant>

#include <Eigen/Core>

#include <functional>
#include <map>
#include <vector>

class MeshModel;
class MeshDocument;

namespace primitive_edit::meshlab {

// Where a filter appears in MeshLab's Filters menu (flags: a filter may appear in two).
enum FilterMenu : int {
  MenuFaceColoring = 1 << 0,
  MenuSelection = 1 << 1,
  MenuQuality = 1 << 2,
  MenuSmoothing = 1 << 3,
  MenuMeasure = 1 << 4,
};

struct FilterDefinition
{
  int id = 0;
  QString name;         // the menu entry and the .mlx name, e.g. "Segment: Auto by Primitive Fit"
  QString python_name;  // PyMeshLab's name, e.g. "segment_auto_by_primitive_fit"
  QString info;         // help text (HTML)
  int menus = 0;        // FilterMenu flags
  int preconditions = 0;   // MeshModel::MM_* the mesh must have (e.g. MM_FACENUMBER)
  int postconditions = 0;  // MeshModel::MM_* the filter changes
  bool two_meshes = false; // takes a second mesh by parameter (arity FIXED)
};

struct ParameterDefinition
{
  enum class Kind { Int, Float, Bool, Enum, String, SaveFile, Position, Direction, Mesh };
  Kind kind = Kind::Int;
  QString name;        // the key in scripts and PyMeshLab (e.g. "Tolerance")
  QVariant value;      // default: int, double, bool, enum index, QString, or MeshModel::id()
  Eigen::Vector3d vector = Eigen::Vector3d::Zero();  // default of Position and Direction
  QString label;       // shown in the dialog
  QString tooltip;
  QStringList enum_values;
  QString file_extension;  // SaveFile, e.g. ".json"
};

// The parameters of one filter, in dialog order.
class ParameterList
{
public:
  void addInt(const QString& name, int value, const QString& label, const QString& tooltip);
  void addFloat(const QString& name, double value, const QString& label, const QString& tooltip);
  void addBool(const QString& name, bool value, const QString& label, const QString& tooltip);
  void addEnum(const QString& name, int value, const QStringList& values, const QString& label,
               const QString& tooltip);
  void addString(const QString& name, const QString& value, const QString& label, const QString& tooltip);
  void addSaveFile(const QString& name, const QString& value, const QString& extension, const QString& label,
                   const QString& tooltip);
  void addPosition(const QString& name, const Eigen::Vector3d& value, const QString& label, const QString& tooltip);
  void addDirection(const QString& name, const Eigen::Vector3d& value, const QString& label,
                    const QString& tooltip);
  // A layer of the document; `mesh_id` is MeshModel::id() of the default choice.
  void addMesh(const QString& name, int mesh_id, const QString& label, const QString& tooltip);

  const std::vector<ParameterDefinition>& definitions() const { return definitions_; }

private:
  std::vector<ParameterDefinition> definitions_;
};

// The values a filter runs with, read by parameter name as MeshLab's RichParameterList is.
class FilterArguments
{
public:
  void set(const QString& name, const QVariant& value) { values_[name] = value; }
  void setVector(const QString& name, const Eigen::Vector3d& value) { vectors_[name] = value; }
  void setMesh(const QString& name, MeshModel* mesh) { meshes_[name] = mesh; }

  int getInt(const QString& name) const { return values_.at(name).toInt(); }
  double getFloat(const QString& name) const { return values_.at(name).toDouble(); }
  bool getBool(const QString& name) const { return values_.at(name).toBool(); }
  int getEnum(const QString& name) const { return values_.at(name).toInt(); }
  QString getString(const QString& name) const { return values_.at(name).toString(); }
  Eigen::Vector3d getVector(const QString& name) const { return vectors_.at(name); }
  MeshModel* getMesh(const QString& name) const { return meshes_.at(name); }

private:
  std::map<QString, QVariant> values_;
  std::map<QString, Eigen::Vector3d> vectors_;
  std::map<QString, MeshModel*> meshes_;
};

// What a running filter gets: the document, its current mesh, the arguments, the log and progress.
struct FilterRun
{
  MeshDocument& document;
  MeshModel& mesh;
  const FilterArguments& arguments;
  std::function<void(const QString&)> log;
  Progress progress;

  // A printf-style line in MeshLab's log.
  template <class... Args>
  void logf(const char* format, Args... args) const
  {
    log(QString::asprintf(format, args...));
  }
};

// The failure of a filter, with the sentence for the log.
inline Status fail(const QString& why) { return Status::failure(why.toStdString()); }
// The failure of a filter because a core step failed: "context: the core's reason."
inline Status fail(const QString& context, const Status& why)
{
  return Status::failure(context.toStdString() + ": " + why.error + ".");
}

class FilterSuite
{
public:
  virtual ~FilterSuite() = default;
  virtual QString pluginName() const = 0;
  virtual std::vector<FilterDefinition> filters() const = 0;
  // The parameters of filter `id` and their defaults, which may depend on the document's meshes.
  virtual void parameters(int id, MeshDocument& document, ParameterList& out) const = 0;
  // Runs filter `id`. On failure the mesh must be untouched and the Status says why, in one sentence.
  virtual Status apply(int id, FilterRun& run) = 0;
};

} // namespace primitive_edit::meshlab

#endif
