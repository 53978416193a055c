// edit_plugin.h (MeshLab 2020.09): an edit tool and its plugin, written once, as a MeshEditInterface
// and a MeshEditInterfaceFactory.
//
// A tool derives from EditToolAdapter and implements its hooks (start, end, changeLayer, draw, the mouse
// and the keys); MeshLab 2020.09's StartEdit/EndEdit/LayerChanged/Decorate forward to them, and logLine,
// logWarning and logRealTime write to MeshLab's log. The plugin derives from EditPluginAdapter (one
// action: icon, name, tooltip, shortcut) with PRIMITIVE_EDIT_EDIT_PLUGIN after Q_OBJECT, and makes its
// tool in createTool().
#ifndef PRIMITIVE_EDIT_PLUGIN_API_EDIT_PLUGIN_H
#define PRIMITIVE_EDIT_PLUGIN_API_EDIT_PLUGIN_H

#include <common/interfaces.h>

#include <QAction>
#include <QKeySequence>

#define PRIMITIVE_EDIT_EDIT_PLUGIN                                \
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_EDIT_INTERFACE_FACTORY_IID) \
  Q_INTERFACES(MeshEditInterfaceFactory)

namespace primitive_edit::meshlab {

class EditToolAdapter : public QObject, public MeshEditInterface
{
public:
  // The hooks a tool implements.
  virtual void renderingData(MeshModel&, MLRenderingData&) {}
  virtual bool start(MeshDocument& md, GLArea* gla, MLSceneGLSharedDataContext* context) = 0;
  virtual void end(MeshModel& m, GLArea* gla, MLSceneGLSharedDataContext* context) = 0;
  virtual void changeLayer(MeshDocument& md, MeshModel& old_model, GLArea* gla, MLSceneGLSharedDataContext* context) = 0;
  virtual void draw(MeshModel& m, GLArea* gla) = 0;
  virtual void mousePress(QMouseEvent* event, MeshModel& m, GLArea* gla) = 0;
  virtual void mouseMove(QMouseEvent* event, MeshModel& m, GLArea* gla) = 0;
  virtual void mouseRelease(QMouseEvent* event, MeshModel& m, GLArea* gla) = 0;
  virtual void keyPress(QKeyEvent* event, MeshModel& m, GLArea* gla) = 0;

protected:
  void attachLog(MeshDocument& md) { setLog(&md.Log); }
  void logLine(const QString& text) { Log("%s", qUtf8Printable(text)); }
  void logWarning(const QString& text) { Log(GLLogStream::WARNING, "%s", qUtf8Printable(text)); }
  void logRealTime(const QString& id, const QString& mesh, const QString& text)
  {
    RealTimeLog(id, mesh, "%s", qUtf8Printable(text));
  }

private:
  using MeshEditInterface::EndEdit;
  using MeshEditInterface::StartEdit;
  void suggestedRenderingData(MeshModel& m, MLRenderingData& dt) override { renderingData(m, dt); }
  bool StartEdit(MeshDocument& md, GLArea* gla, MLSceneGLSharedDataContext* c) override { return start(md, gla, c); }
  void EndEdit(MeshModel& m, GLArea* gla, MLSceneGLSharedDataContext* c) override { end(m, gla, c); }
  void LayerChanged(MeshDocument& md, MeshModel& old, GLArea* gla, MLSceneGLSharedDataContext* c) override
  {
    changeLayer(md, old, gla, c);
  }
  void Decorate(MeshModel& m, GLArea* gla) override { draw(m, gla); }
  void mousePressEvent(QMouseEvent* e, MeshModel& m, GLArea* gla) override { mousePress(e, m, gla); }
  void mouseMoveEvent(QMouseEvent* e, MeshModel& m, GLArea* gla) override { mouseMove(e, m, gla); }
  void mouseReleaseEvent(QMouseEvent* e, MeshModel& m, GLArea* gla) override { mouseRelease(e, m, gla); }
  void keyPressEvent(QKeyEvent* e, MeshModel& m, GLArea* gla) override { keyPress(e, m, gla); }
};

class EditPluginAdapter : public QObject, public MeshEditInterfaceFactory
{
public:
  // MeshLab 2020.09 does not name edit plugins; 2025.07 does, hence the unused first argument.
  EditPluginAdapter(const QString& /*plugin_name*/, const QIcon& icon, const QString& text, const QString& tooltip,
                    const QKeySequence& shortcut)
      : action_(new QAction(icon, text, this))
  {
    action_->setToolTip(tooltip);
    action_->setShortcut(shortcut);
    action_->setCheckable(true);
  }

  virtual EditToolAdapter* createTool() = 0;
  virtual QString description() const = 0;

  QList<QAction*> actions() const override { return {action_}; }
  MeshEditInterface* getMeshEditInterface(QAction* action) override { return action == action_ ? createTool() : nullptr; }
  QString getEditToolDescription(QAction*) override { return description(); }

private:
  QAction* action_;
};

} // namespace primitive_edit::meshlab

#endif
