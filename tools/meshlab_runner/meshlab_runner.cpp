// meshlab_runner: batch MeshLab 2025.07 without its GUI, as meshlabserver did for 2020.09 (2025.07 has
// none; its users script it with PyMeshLab, which cannot be installed here). Loads the plugins beside the
// binary (plugins/), opens meshes, runs a .mlx filter script or one filter with parameters given on the
// command line, and saves the current mesh with the attributes asked for (face quality keeps segment ids).
//
//   meshlab_runner -i in.ply [-i more.ply] [-s script.mlx] [-f "Filter Name" [-a Name=Value]...]
//                  [-o out.ply [-m fq vc ...]] [-l log.txt] [-p plugin_dir]
//   meshlab_runner --list [-i in.ply]       every filter's name, PyMeshLab name (and, with a mesh, each
//                                           parameter's name, type and default as a script's <Param>)
//   meshlab_runner -d filters.txt           meshlabserver's filter dump ("\section fN NAME" lines)
//
// Scripts are meshlabserver's .mlx: each <Param name=... value=.../> sets the parameter of that name; the
// value is read by the parameter's own type, so scripts written for 2020.09 (RichPoint3f, RichSaveFile)
// run unchanged. Parameters a script leaves out keep their defaults, as in PyMeshLab. -f takes a filter's
// menu name or PyMeshLab name. The log goes to stdout (and to -l). Exit 0 on success, 255 when a filter
// fails (the reason, then "Problem with filter: NAME", as meshlabserver), 1 on bad usage or files.
#include <common/globals.h>
#include <common/mlexception.h>
#include <common/parameters/rich_parameter_list.h>
#include <common/plugins/plugin_manager.h>
#include <common/utilities/load_save.h>

#include <QApplication>
#include <QDir>
#include <QDomDocument>
#include <QFile>
#include <QFileInfo>
#include <QTextStream>

#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace {

struct Options
{
  std::vector<QString> inputs;
  QString script, output, log_file, plugin_dir, filter, dump;
  std::vector<std::pair<QString, QString>> arguments;  // -a Name=Value for -f
  QStringList mask;
  bool list = false;
};

struct FilterStep
{
  QString name;
  std::map<QString, QDomElement> params;   // from a script
  std::map<QString, QString> values;       // from the command line
};

class Log
{
public:
  Log(GLLogStream& stream, const QString& file) : stream_(stream), file_(file) {}

  // Prints the log lines written since the last call.
  void flush()
  {
    const auto& lines = stream_.logStringList();
    for (int i = printed_; i < lines.size(); ++i)
      line(lines[i].second);
    printed_ = lines.size();
  }

  void line(const QString& text)
  {
    std::printf("%s\n", qUtf8Printable(text));
    std::fflush(stdout);
    if (!file_.isEmpty()) {
      QFile f(file_);
      if (f.open(QIODevice::Append | QIODevice::Text))
        QTextStream(&f) << text << "\n";
    }
  }

private:
  GLLogStream& stream_;
  QString file_;
  int printed_ = 0;
};

bool parse_options(int argc, char** argv, Options& o)
{
  for (int i = 1; i < argc; ++i) {
    const QString a = argv[i];
    auto next = [&](QString& out) {
      if (i + 1 >= argc)
        return false;
      out = QString::fromLocal8Bit(argv[++i]);
      return true;
    };
    QString v;
    if (a == "-i" && next(v)) o.inputs.push_back(v);
    else if (a == "-s" && next(v)) o.script = v;
    else if (a == "-o" && next(v)) o.output = v;
    else if (a == "-l" && next(v)) o.log_file = v;
    else if (a == "-p" && next(v)) o.plugin_dir = v;
    else if (a == "-f" && next(v)) o.filter = v;
    else if (a == "-d" && next(v)) o.dump = v;
    else if (a == "-a" && next(v)) {
      const int eq = v.indexOf('=');
      if (eq <= 0)
        return false;
      o.arguments.emplace_back(v.left(eq), v.mid(eq + 1));
    } else if (a == "-m") {
      while (i + 1 < argc && argv[i + 1][0] != '-')
        o.mask << QString(argv[++i]);
    } else if (a == "--list") o.list = true;
    else return false;
  }
  return o.list || !o.dump.isEmpty() || (!o.inputs.empty() && (!o.script.isEmpty() || !o.filter.isEmpty() || !o.output.isEmpty()));
}

// The filter of that menu name or PyMeshLab name, and its plugin.
bool find_filter(PluginManager& pm, const QString& name, FilterPlugin*& plugin, QAction*& action)
{
  for (FilterPlugin* p : pm.filterPluginIterator())
    for (QAction* a : p->actions())
      if (p->filterName(a) == name || p->pythonFilterName(a) == name) {
        plugin = p;
        action = a;
        return true;
      }
  return false;
}

// Sets a parameter from a script's <Param> or a command line's text, by the parameter's own type.
bool set_parameter(RichParameter& p, const QDomElement* element, const QString& text, QString& error)
{
  const QString value = element ? element->attribute("value") : text;
  bool ok = true;
  if (p.isOfType<RichInt>() || p.isOfType<RichEnum>() || p.isOfType<RichMesh>())
    p.setValue(IntValue(value.toInt(&ok)));
  else if (p.isOfType<RichFloat>() || p.isOfType<RichPercentage>() || p.isOfType<RichDynamicFloat>())
    p.setValue(FloatValue(value.toFloat(&ok)));
  else if (p.isOfType<RichBool>()) {
    ok = value == "true" || value == "false" || value == "1" || value == "0";
    p.setValue(BoolValue(value == "true" || value == "1"));
  } else if (p.isOfType<RichString>() || p.isOfType<RichFileSave>() || p.isOfType<RichFileOpen>())
    p.setValue(StringValue(value));
  else if (p.isOfType<RichPosition>() || p.isOfType<RichDirection>()) {
    Scalarm c[3];
    const QStringList parts = value.split(QRegExp("[ ,]+"), Qt::SkipEmptyParts);
    for (int k = 0; k < 3 && ok; ++k)
      c[k] = element ? element->attribute(QString("xyz"[k])).toFloat(&ok)
                     : (parts.size() == 3 ? parts[k].toFloat(&ok) : (ok = false, 0));
    p.setValue(Point3Value(Point3m(c[0], c[1], c[2])));
  } else {
    error = QString("parameter %1 has a type (%2) the runner cannot set").arg(p.name(), p.stringType());
    return false;
  }
  if (!ok)
    error = QString("parameter %1: '%2' is not a valid value").arg(p.name(), value);
  return ok;
}

bool read_script(const QString& path, std::vector<FilterStep>& steps, QString& error)
{
  QFile file(path);
  QDomDocument doc;
  QString message;
  if (!file.open(QIODevice::ReadOnly) || !doc.setContent(&file, false, &message)) {
    error = "cannot read the script " + path + (message.isEmpty() ? "" : ": " + message);
    return false;
  }
  const QDomElement root = doc.documentElement();
  if (root.nodeName() != "FilterScript") {
    error = path + " is not a FilterScript";
    return false;
  }
  for (QDomElement f = root.firstChildElement("filter"); !f.isNull(); f = f.nextSiblingElement("filter")) {
    FilterStep step;
    step.name = f.attribute("name");
    for (QDomElement p = f.firstChildElement("Param"); !p.isNull(); p = p.nextSiblingElement("Param"))
      step.params[p.attribute("name")] = p;
    steps.push_back(step);
  }
  return true;
}

// Runs one step on the document; false when the filter is unknown, a parameter is bad or the filter fails.
bool run_step(PluginManager& pm, MeshDocument& md, const FilterStep& step, Log& log)
{
  FilterPlugin* plugin = nullptr;
  QAction* action = nullptr;
  log.line("filter: " + step.name);
  if (!find_filter(pm, step.name, plugin, action)) {
    log.line("no plugin has a filter named " + step.name);
    log.line("Problem with filter: " + step.name);
    return false;
  }
  plugin->setLog(&md.Log);
  RichParameterList parameters = plugin->initParameterList(action, md);
  QString error;
  auto set = [&](const QString& name, const QDomElement* element, const QString& text) {
    auto it = parameters.findParameter(name);
    if (it == parameters.end()) {
      error = "the filter has no parameter " + name;
      return false;
    }
    return set_parameter(*it, element, text, error);
  };
  bool ok = true;
  for (const auto& [name, element] : step.params)
    ok = ok && set(name, &element, QString());
  for (const auto& [name, text] : step.values)
    ok = ok && set(name, nullptr, text);
  if (!ok) {
    log.line(step.name + ": " + error);
    log.line("Problem with filter: " + step.name);
    return false;
  }
  try {
    unsigned int post = 0;
    plugin->applyFilter(action, parameters, md, post, nullptr);
    log.flush();
  } catch (const MLException& e) {
    log.flush();  // the adapter logged the reason
    log.line("Problem with filter: " + step.name);
    return false;
  }
  return true;
}

int save_mesh(PluginManager& pm, MeshDocument& md, const Options& o, Log& log)
{
  MeshModel& mesh = *md.mm();
  const QString ext = QFileInfo(o.output).suffix().toLower();
  IOPlugin* io = pm.outputMeshPlugin(ext);
  if (io == nullptr) {
    log.line("cannot save " + o.output + ": no plugin writes ." + ext);
    return 1;
  }
  static const std::map<QString, int> bits = {
      {"vc", vcg::tri::io::Mask::IOM_VERTCOLOR},   {"vq", vcg::tri::io::Mask::IOM_VERTQUALITY},
      {"vn", vcg::tri::io::Mask::IOM_VERTNORMAL},  {"vt", vcg::tri::io::Mask::IOM_VERTTEXCOORD},
      {"fc", vcg::tri::io::Mask::IOM_FACECOLOR},   {"fq", vcg::tri::io::Mask::IOM_FACEQUALITY},
      {"fn", vcg::tri::io::Mask::IOM_FACENORMAL},  {"wt", vcg::tri::io::Mask::IOM_WEDGTEXCOORD}};
  int mask = 0;
  for (const QString& m : o.mask) {
    auto it = bits.find(m);
    if (it == bits.end()) {
      log.line("unknown -m flag " + m + " (vc vq vn vt fc fq fn wt)");
      return 1;
    }
    mask |= it->second;
  }
  int capability = 0, default_bits = 0;
  io->setLog(&md.Log);
  io->exportMaskCapability(ext, capability, default_bits);
  try {
    io->save(ext, o.output, mesh, mask & capability, io->initSaveParameter(ext, mesh), nullptr);
  } catch (const MLException& e) {
    log.line("cannot save " + o.output + ": " + QString(e.what()));
    return 1;
  }
  log.line("saved " + o.output);
  return 0;
}

void list_filters(PluginManager& pm, MeshDocument& md)
{
  for (FilterPlugin* p : pm.filterPluginIterator())
    for (QAction* a : p->actions()) {
      std::printf("%s\t%s\n", qUtf8Printable(p->filterName(a)), qUtf8Printable(p->pythonFilterName(a)));
      if (md.mm() == nullptr)
        continue;
      try {
        for (const RichParameter& r : p->initParameterList(a, md)) {
          QDomDocument doc;
          QString xml;
          QTextStream text(&xml);
          r.fillToXMLDocument(doc, false).save(text, -1);
          std::printf("    %s (%s) %s\n", qUtf8Printable(r.name()), qUtf8Printable(r.stringType()),
                      qUtf8Printable(xml.trimmed()));
        }
      } catch (const std::exception&) {
        std::printf("    (its parameters need mesh components this mesh lacks)\n");
      }
    }
}

// meshlabserver -d's format, as far as scripts read it: one "\section fN NAME" line a filter.
bool dump_filters(PluginManager& pm, const QString& path)
{
  QFile file(path);
  if (!file.open(QIODevice::WriteOnly | QIODevice::Text))
    return false;
  QTextStream out(&file);
  int n = 0;
  for (FilterPlugin* p : pm.filterPluginIterator())
    for (QAction* a : p->actions())
      out << "\\section f" << n++ << " " << p->filterName(a) << "\n"
          << "PyMeshLab: " << p->pythonFilterName(a) << "\n\n";
  return true;
}

} // namespace

int main(int argc, char** argv)
{
  // Filters need no display; plugins that make actions need a QApplication.
  if (!qEnvironmentVariableIsSet("DISPLAY") && !qEnvironmentVariableIsSet("QT_QPA_PLATFORM"))
    qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  Options o;
  if (!parse_options(argc, argv, o)) {
    std::fprintf(stderr, "usage: meshlab_runner -i in.ply [-i ...] [-s script.mlx] [-f FILTER [-a Name=Value]...] "
                         "[-o out.ply [-m fq vc ...]] [-l log] [-p plugin_dir] | --list [-i in.ply] | -d dump.txt\n");
    return 1;
  }
  if (!o.log_file.isEmpty())
    QFile::remove(o.log_file);

  PluginManager& pm = meshlab::pluginManagerInstance();
  try {
    pm.loadPlugins(QDir(o.plugin_dir.isEmpty() ? meshlab::defaultPluginPath() : o.plugin_dir));
  } catch (const MLException& e) {
    std::fprintf(stderr, "meshlab_runner: %s\n", e.what());
    return 1;
  }
  if (!o.dump.isEmpty())
    return dump_filters(pm, o.dump) ? 0 : 1;
  MeshDocument md;
  Log log(md.Log, o.log_file);
  for (const QString& input : o.inputs) {
    try {
      meshlab::loadMeshWithStandardParameters(input, md);
    } catch (const MLException& e) {
      log.line("cannot open " + input + ": " + QString(e.what()));
      return 1;
    }
    log.line(QString("opened %1 (%2 vertices, %3 faces)").arg(input).arg(md.mm()->cm.vn).arg(md.mm()->cm.fn));
  }
  if (o.list) {
    list_filters(pm, md);
    return 0;
  }

  std::vector<FilterStep> steps;
  QString error;
  if (!o.script.isEmpty() && !read_script(o.script, steps, error)) {
    log.line(error);
    return 1;
  }
  if (!o.filter.isEmpty()) {
    FilterStep step;
    step.name = o.filter;
    for (const auto& [name, value] : o.arguments)
      step.values[name] = value;
    steps.push_back(step);
  }
  for (const FilterStep& step : steps)
    if (!run_step(pm, md, step, log))
      return 255;
  if (!o.output.isEmpty())
    return save_mesh(pm, md, o, log);
  return 0;
}
