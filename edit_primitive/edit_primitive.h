// edit_primitive.h: the Primitive Edit tool (a MeshLab edit plugin): pick segments in the view, merge them,
// split them by a line drawn on screen, fit a primitive, edit its parameters and snap the segments onto it,
// with undo. The state logic is PrimitiveEditSession (primitive_edit_session.h); this class holds the GUI:
// mouse and keys, drawing over the mesh, the dock panel, the log and MeshLab's render buffers.
#ifndef PRIMITIVE_EDIT_EDIT_PRIMITIVE_H
#define PRIMITIVE_EDIT_EDIT_PRIMITIVE_H

#include "common/pipeline/primitive_edit_session.h"

#include "plugin_api/edit_plugin.h"
#include "plugin_api/mesh_document.h"

#include <QPoint>
#include <QPointer>
#include <QTimer>

#include <vector>

class PrimitiveEditPanel;
class QDockWidget;

class EditPrimitivePlugin : public primitive_edit::meshlab::EditToolAdapter
{
  Q_OBJECT

public:
  EditPrimitivePlugin();
  ~EditPrimitivePlugin() override;

  static QString Info();
  void renderingData(MeshModel& m, MLRenderingData& dt) override;
  // Sets the log before anything happens (MeshLab sets it only when drawing), then starts on the current mesh.
  bool start(MeshDocument& md, GLArea* gla, MLSceneGLSharedDataContext* context) override;
  void end(MeshModel& m, GLArea* gla, MLSceneGLSharedDataContext* context) override;
  // MeshLab also reports a layer change when the current layer stays the same (e.g. after a save): the
  // session, with its undo steps, is kept then; a real change restarts the tool on the new layer once
  // MeshLab has filled it, or closes the tool (its button too) when that layer cannot be edited.
  void changeLayer(MeshDocument& md, MeshModel& old_model, GLArea* gla, MLSceneGLSharedDataContext* context) override;
  void draw(MeshModel& m, GLArea* gla) override;
  void mousePress(QMouseEvent* event, MeshModel& m, GLArea* gla) override;
  void mouseMove(QMouseEvent* event, MeshModel& m, GLArea* gla) override;
  void mouseRelease(QMouseEvent* event, MeshModel& m, GLArea* gla) override;
  void keyPress(QKeyEvent* event, MeshModel& m, GLArea* gla) override;

private:
  bool startOn(MeshModel& m, GLArea* gla, MLSceneGLSharedDataContext* context);
  void restartOnCurrentLayer();
  void segment();
  void merge();
  void fit();
  void parametersEdited();
  void apply();
  void undo();
  void split(const Eigen::Vector2d& a, const Eigen::Vector2d& b);
  void pickAt(const Eigen::Vector2d& at, bool additive);
  // After a change: panel, cached drawings, MeshLab's buffers (colours, and positions and normals when
  // the geometry moved) and a redraw.
  void refresh(bool geometry_moved);
  void report(bool ok, const QString& what, const std::string& message);
  void report(const QString& what, const primitive_edit::EditOutcome& outcome);
  QString pickedText() const;
  void drawOverlay();

  primitive_edit::PrimitiveEditSession<CMeshO> session_;
  // Whether the mesh had face quality before the tool enabled it: a quality the tool just switched on is
  // all zero and no segmentation.
  bool had_face_quality_ = false;
  MeshModel* model_ = nullptr;
  GLArea* gla_ = nullptr;
  MLSceneGLSharedDataContext* context_ = nullptr;
  QDockWidget* dock_ = nullptr;
  PrimitiveEditPanel* panel_ = nullptr;

  // A restart after a layer change, waiting for MeshLab to finish the layer (an import reports the new
  // layer while it is still empty and loading).
  QTimer restart_timer_;
  QPointer<MeshDocument> restart_document_;
  QPointer<GLArea> restart_view_;
  MLSceneGLSharedDataContext* restart_context_ = nullptr;

  // Mouse: a press starts a pick (released without moving) or, with Ctrl, a split line.
  bool pressed_ = false;
  bool drawing_line_ = false;
  QPoint press_pos_;
  Eigen::Vector2d line_start_ = Eigen::Vector2d::Zero(), line_end_ = Eigen::Vector2d::Zero();
  // A click waiting for the next frame, where the GL matrices needed to pick are set.
  bool pick_pending_ = false;
  bool pick_additive_ = false;
  Eigen::Vector2d pick_at_ = Eigen::Vector2d::Zero();

  // The camera of the last frame, in the mesh's own coordinates (the layer transform included).
  bool have_camera_ = false;
  Eigen::Matrix4d modelview_ = Eigen::Matrix4d::Identity(), projection_ = Eigen::Matrix4d::Identity();
  Eigen::Vector4d viewport_ = Eigen::Vector4d::Zero();

  std::vector<float> highlight_;  // triangles of the picked segments, 9 floats each
  Eigen::MatrixX3d wireframe_;    // line ends of the edited primitive
};

#endif
