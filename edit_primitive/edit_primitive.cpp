#include "edit_primitive.h"

#include "primitive_edit_panel.h"

#include "common/base/describe_primitive.h"
#include "common/geometry/primitive_wireframe.h"
#include "common/snap/describe_snap_report.h"

#include <common/GLExtensionsManager.h>
#include <meshlab/glarea.h>
#include <wrap/gl/pick.h>
#include <wrap/qt/device_to_logical.h>

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QKeyEvent>
#include <QMainWindow>
#include <QMessageBox>
#include <QMouseEvent>

#include <limits>

using namespace primitive_edit;

namespace {

// A press that moves less than this (in pixels) is a click.
constexpr int kClickSlack = 4;

Eigen::Vector2d to_gl(GLArea* gla, const QPoint& p)
{
  const vcg::Point2f q = QTLogicalToOpenGL(gla, p);
  return Eigen::Vector2d(q[0], q[1]);
}

} // namespace

EditPrimitivePlugin::EditPrimitivePlugin()
{
  // Polls while MeshLab is busy with the new layer: it tells no one when an import is done.
  restart_timer_.setSingleShot(true);
  restart_timer_.setInterval(50);
  connect(&restart_timer_, &QTimer::timeout, this, &EditPrimitivePlugin::restartOnCurrentLayer);
}

EditPrimitivePlugin::~EditPrimitivePlugin() { delete dock_; }

QString EditPrimitivePlugin::Info()
{
  return "Edit a scan by segments and primitives: pick segments, merge them, split them by a line, fit a plane, "
         "sphere, cylinder, cone or torus, edit its parameters and snap the segment onto it.";
}

void EditPrimitivePlugin::renderingData(MeshModel& m, MLRenderingData& dt)
{
  if (m.cm.fn == 0)
    return;
  // Segments are shown by face colour; the quality mirrors the ids so that PLY files keep them.
  had_face_quality_ = m.hasDataMask(MeshModel::MM_FACEQUALITY);
  m.updateDataMask(MeshModel::MM_FACECOLOR | MeshModel::MM_FACEQUALITY);
  // A quality the tool adds holds no ids yet: -1 (no segmentation), not MeshLab's 0, which would read as one
  // segment when the tool is started again or the saved file reopened.
  if (!had_face_quality_)
    for (CFaceO& f : m.cm.face)
      f.Q() = -1;
  MLRenderingData::RendAtts atts;
  dt.get(MLRenderingData::PR_SOLID, atts);
  atts[MLRenderingData::ATT_NAMES::ATT_VERTPOSITION] = true;
  atts[MLRenderingData::ATT_NAMES::ATT_VERTNORMAL] = true;
  atts[MLRenderingData::ATT_NAMES::ATT_FACECOLOR] = true;
  atts[MLRenderingData::ATT_NAMES::ATT_VERTCOLOR] = false;
  dt.set(MLRenderingData::PR_SOLID, atts);
}

bool EditPrimitivePlugin::start(MeshDocument& md, GLArea* gla, MLSceneGLSharedDataContext* context)
{
  attachLog(md);
  if (md.mm() == nullptr) {
    logWarning("Primitive Edit: there is no mesh to edit.");
    return false;
  }
  return startOn(*md.mm(), gla, context);
}

bool EditPrimitivePlugin::startOn(MeshModel& m, GLArea* gla, MLSceneGLSharedDataContext* context)
{
  if (gla == nullptr || context == nullptr)
    return false;
  const EditOutcome attached = session_.attach(m.cm, had_face_quality_);
  if (!attached.status.ok()) {
    logWarning(QString::asprintf("Primitive Edit: cannot edit %s: %s.", qUtf8Printable(m.label()),
                                 attached.status.error.c_str()));
    return false;
  }
  if (!GLExtensionsManager::initializeGLextensions_notThrowing()) {
    session_.detach();
    return false;
  }
  model_ = &m;
  gla_ = gla;
  context_ = context;
  have_camera_ = false;
  pressed_ = drawing_line_ = pick_pending_ = false;

  if (dock_ == nullptr) {
    dock_ = new QDockWidget("Primitive Edit", gla->window());
    dock_->setObjectName("PrimitiveEditDock");
    panel_ = new PrimitiveEditPanel(dock_);
    dock_->setWidget(panel_);
    connect(panel_, &PrimitiveEditPanel::segmentRequested, this, &EditPrimitivePlugin::segment);
    connect(panel_, &PrimitiveEditPanel::mergeRequested, this, &EditPrimitivePlugin::merge);
    connect(panel_, &PrimitiveEditPanel::fitRequested, this, &EditPrimitivePlugin::fit);
    connect(panel_, &PrimitiveEditPanel::parametersEdited, this, &EditPrimitivePlugin::parametersEdited);
    connect(panel_, &PrimitiveEditPanel::applyRequested, this, &EditPrimitivePlugin::apply);
    connect(panel_, &PrimitiveEditPanel::undoRequested, this, &EditPrimitivePlugin::undo);
    connect(panel_, &PrimitiveEditPanel::viewFocusRequested, this, [this] {
      if (gla_ != nullptr)
        gla_->setFocus();
    });
  }
  if (auto* window = qobject_cast<QMainWindow*>(gla->window()))
    window->addDockWidget(Qt::LeftDockWidgetArea, dock_);
  else
    dock_->setFloating(true);
  dock_->show();
  panel_->setStatus(QString());
  gla->setCursor(Qt::CrossCursor);
  // The keys of the tool (M, F, Enter, ...) go to the view.
  gla->setFocus();
  logLine(QString::asprintf("Primitive Edit: editing %s (%d faces): %s.", qUtf8Printable(m.label()), m.cm.fn,
                            attached.summary.c_str()));
  refresh(false);
  return true;
}

void EditPrimitivePlugin::end(MeshModel&, GLArea* gla, MLSceneGLSharedDataContext*)
{
  restart_timer_.stop();
  restart_document_ = nullptr;
  restart_view_ = nullptr;
  if (session_.attached() && session_.can_undo())
    logLine(QString("Primitive Edit: closed; its %1 undo step(s) are gone (the mesh keeps its segments and shape).")
                .arg(session_.undo_depth()));
  session_.detach();
  if (dock_ != nullptr)
    dock_->hide();
  if (gla != nullptr)
    gla->setCursor(Qt::ArrowCursor);
  highlight_.clear();
  wireframe_.resize(0, 3);
  model_ = nullptr;
  gla_ = nullptr;
  context_ = nullptr;
  have_camera_ = false;
}

void EditPrimitivePlugin::changeLayer(MeshDocument& md, MeshModel& old_model, GLArea* gla,
                                      MLSceneGLSharedDataContext* context)
{
  if (md.mm() == &old_model && model_ == &old_model && session_.attached())
    return;
  if (md.mm() != nullptr && session_.attached())
    logLine(QString("Primitive Edit: the current layer is now %1; the tool moves to it.").arg(md.mm()->label()));
  end(old_model, gla, context);
  restart_document_ = &md;
  restart_view_ = gla;
  restart_context_ = context;
  // Out of MeshLab's layer-change handler, which may still be loading the layer.
  restart_timer_.start();
}

void EditPrimitivePlugin::restartOnCurrentLayer()
{
  if (restart_document_ == nullptr || restart_view_ == nullptr)
    return;
  if (restart_document_->isBusy()) {
    restart_timer_.start();
    return;
  }
  MeshDocument& md = *restart_document_;
  GLArea* gla = restart_view_;
  restart_document_ = nullptr;
  restart_view_ = nullptr;
  // MeshLab asks for the tool's rendering (segment colours) only when the tool starts, for the layer current
  // then.
  if (MeshModel* m = md.mm(); m != nullptr && restart_context_ != nullptr) {
    MLRenderingData dt;
    restart_context_->getRenderInfoPerMeshView(m->id(), gla->context(), dt);
    renderingData(*m, dt);
    MLPoliciesStandAloneFunctions::disableRedundatRenderingDataAccordingToPriorities(dt);
    restart_context_->setRenderingDataPerMeshView(m->id(), gla->context(), dt);
    restart_context_->manageBuffers(m->id());
  }
  if (start(md, gla, restart_context_))
    return;
  // MeshLab still counts the tool as active: end it as its button does, so that the button goes off and the
  // next Ctrl+Shift+P starts the tool again.
  logWarning("Primitive Edit: closed, the current layer cannot be edited.");
  if (QAction* action = gla->getCurrentEditAction()) {
    if (gla->suspendedEditor)  // the button of a suspended tool (Esc) first resumes it
      action->trigger();
    action->trigger();
  }
}

void EditPrimitivePlugin::report(const QString& what, const EditOutcome& outcome)
{
  report(outcome.status.ok(), what, outcome.status.ok() ? outcome.summary : outcome.status.error);
}

void EditPrimitivePlugin::report(bool ok, const QString& what, const std::string& message)
{
  const QString text = QString("Primitive Edit: %1: %2.").arg(what, QString::fromStdString(message));
  if (ok)
    logLine(text);
  else
    logWarning(text);
  if (panel_ != nullptr)
    panel_->setStatus(text);
}

QString EditPrimitivePlugin::pickedText() const
{
  QStringList ids;
  for (int s : session_.picked())
    ids << QString::number(s);
  if (ids.isEmpty())
    return QString("no segment");
  return QString("segment%1 %2 (%3 faces)")
      .arg(ids.size() > 1 ? "s" : "", ids.join(", "))
      .arg(session_.picked_faces().size());
}

void EditPrimitivePlugin::refresh(bool geometry_moved)
{
  if (model_ == nullptr)
    return;
  const CMeshO& m = model_->cm;
  highlight_.clear();
  for (int f : session_.picked_faces())
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c)
        highlight_.push_back(float(m.face[size_t(f)].cP(k)[c]));
  wireframe_ = session_.edited() ? primitive_wireframe(*session_.edited(), session_.fit_points())
                                 : Eigen::MatrixX3d(0, 3);
  if (panel_ != nullptr) {
    panel_->setSegmentInfo(session_.segment_count(), pickedText());
    panel_->setCanUndo(session_.can_undo(), QString::fromStdString(session_.undo_label()));
    panel_->showPrimitive(session_.edited(), session_.edited_rms());
  }
  if (context_ != nullptr) {
    MLRenderingData::RendAtts atts;
    atts[MLRenderingData::ATT_NAMES::ATT_FACECOLOR] = true;
    if (geometry_moved) {
      atts[MLRenderingData::ATT_NAMES::ATT_VERTPOSITION] = true;
      atts[MLRenderingData::ATT_NAMES::ATT_VERTNORMAL] = true;
      atts[MLRenderingData::ATT_NAMES::ATT_FACENORMAL] = true;
    }
    context_->meshAttributesUpdated(model_->id(), false, atts);
    context_->manageBuffers(model_->id());
  }
  if (gla_ != nullptr)
    gla_->updateAllSiblingsGLAreas();
}

void EditPrimitivePlugin::segment()
{
  if (model_ == nullptr)
    return;
  QApplication::setOverrideCursor(Qt::WaitCursor);
  EditOutcome outcome;
  if (panel_->segmentByPrimitiveFit()) {
    SegmentByPrimitiveGrowingParams params;
    params.tolerance = panel_->segmentTolerance();
    outcome = session_.auto_segment(params);
  } else {
    SegmentByNormalAngleParams params;
    params.angle_deg = panel_->angle();
    outcome = session_.auto_segment(params);
  }
  QApplication::restoreOverrideCursor();
  report("automatic segmentation", outcome);
  refresh(false);
}

void EditPrimitivePlugin::merge()
{
  const EditOutcome outcome = session_.merge_picked();
  report("merge", outcome);
  refresh(false);
}

void EditPrimitivePlugin::split(const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
  if (!have_camera_) {
    report(false, "split", "the view is not ready yet; try again");
    return;
  }
  const EditOutcome outcome = session_.split_picked_by_screen_line(a, b, modelview_, projection_, viewport_);
  report("split", outcome);
  refresh(false);
}

void EditPrimitivePlugin::fit()
{
  const std::optional<PrimitiveType> type = panel_->type();
  const bool relations = panel_->relations();
  QApplication::setOverrideCursor(Qt::WaitCursor);  // with relations every segment is fitted: 0.4 s at 1M faces
  const FitResult result = session_.fit(type, panel_->method(), relations);
  QApplication::restoreOverrideCursor();
  const QString what = QString("fit %1 to %2 (%3%4)")
                           .arg(type ? primitive_type_name(*type) : "Auto", pickedText(),
                                fit_method_name(panel_->method()), relations ? ", with relations" : "");
  if (result.status.ok()) {
    std::string message = describe_primitive(result.primitive) + "; RMS " +
                          QString::number(result.rms, 'g', 4).toStdString() + ", max residual " +
                          QString::number(result.max_residual, 'g', 4).toStdString() + ", " +
                          std::to_string(result.point_count) + " points";
    for (std::size_t i = 0; i < session_.fit_relations().size(); ++i)
      message += (i == 0 ? "; relations held: " : "; ") + session_.fit_relations()[i];
    if (!session_.relations_refused().empty())
      message += "; relations not held: " + session_.relations_refused();
    report(true, what, message);
  } else {
    report(false, what, result.status.error);
  }
  if (const std::string warning = session_.fit_warning(); !warning.empty())
    report(false, what, warning);
  if (result.status.ok() && !type)
    panel_->setType(result.primitive.type);
  refresh(false);
}

void EditPrimitivePlugin::parametersEdited()
{
  if (!session_.edited())
    return;
  QString error;
  const std::optional<Primitive> typed = panel_->editedPrimitive(&error);
  const EditOutcome outcome =
      typed ? session_.set_edited(*typed) : EditOutcome::refused(error.toStdString());
  // A refused value is not kept: the fields show the primitive in use again.
  report("edited primitive", outcome.status.ok() ? outcome : EditOutcome::refused(outcome.status.error +
                                                                                    "; the previous value is kept"));
  refresh(false);
}

void EditPrimitivePlugin::apply()
{
  if (model_ == nullptr)
    return;
  // A value typed but not yet confirmed counts; one that is refused stops the apply.
  if (session_.edited()) {
    QString error;
    const std::optional<Primitive> typed = panel_->editedPrimitive(&error);
    const EditOutcome edited = typed ? session_.set_edited(*typed) : EditOutcome::refused(error.toStdString());
    if (!edited.status.ok()) {
      report("apply", EditOutcome::refused(edited.status.error + "; nothing applied"));
      refresh(false);
      return;
    }
  }
  const QString what = QString("apply to %1").arg(pickedText());
  ApplyOutcome outcome = session_.apply(true);
  if (outcome.needs_confirmation) {
    report(false, what, outcome.status.error);
    // The session says why (a far move, or a primitive far larger than the segment).
    const QMessageBox::StandardButton answer = QMessageBox::warning(
        gla_, "Primitive Edit",
        QString("Applying: %1.\nThe primitive may not be what the segment is (check its type and parameters). "
                "Apply anyway?")
            .arg(QString::fromStdString(outcome.status.error)),
        QMessageBox::Apply | QMessageBox::Cancel, QMessageBox::Cancel);
    if (answer != QMessageBox::Apply) {
      report(false, what, "cancelled; the mesh is unchanged");
      refresh(false);
      return;
    }
    outcome = session_.apply(true, true);
  }
  if (outcome.status.ok()) {
    report(true, what,
           "snapped onto " + outcome.summary + "; " + describe_snap_report(outcome.report));
    model_->setMeshModified();
  } else {
    report(false, what, outcome.status.error);
  }
  refresh(outcome.status.ok());
}

void EditPrimitivePlugin::undo()
{
  const std::string what = session_.undo_label();
  const bool moved = session_.undo_moves_vertices();
  const bool ok = session_.undo();
  report(ok, "undo", ok ? what : std::string("nothing to undo"));
  refresh(ok && moved);
}

void EditPrimitivePlugin::pickAt(const Eigen::Vector2d& at, bool additive)
{
  if (model_ == nullptr)
    return;
  // Candidates from vcg's picking under a small square; the nearest to the eye is the visible one.
  std::vector<CFaceO*> candidates;
  vcg::GLPickTri<CMeshO>::PickFace(int(at.x()), int(at.y()), model_->cm, candidates, 3, 3);
  const Eigen::Matrix4d clip_from_object = projection_ * modelview_;
  int face = -1;
  double nearest = std::numeric_limits<double>::infinity();
  for (CFaceO* f : candidates) {
    const Point3m b = vcg::Barycenter(*f);
    const Eigen::Vector4d c = clip_from_object * Eigen::Vector4d(b[0], b[1], b[2], 1.0);
    const double depth = c.z() / c.w();
    if (std::isfinite(depth) && depth < nearest) {
      nearest = depth;
      face = int(vcg::tri::Index(model_->cm, f));
    }
  }
  const bool hit = session_.pick(face, additive);
  if (hit)
    logLine(QString("Primitive Edit: picked %1.").arg(pickedText()));
  else if (!additive)
    logLine("Primitive Edit: no segment there; picks cleared.");
  refresh(false);
}

void EditPrimitivePlugin::mousePress(QMouseEvent* event, MeshModel&, GLArea* gla)
{
  if (event->button() != Qt::LeftButton || gla_ == nullptr)
    return;
  pressed_ = true;
  drawing_line_ = (event->modifiers() & Qt::ControlModifier) != 0;
  press_pos_ = event->pos();
  line_start_ = line_end_ = to_gl(gla, event->pos());
}

void EditPrimitivePlugin::mouseMove(QMouseEvent* event, MeshModel&, GLArea* gla)
{
  if (!pressed_ || !drawing_line_ || gla_ == nullptr)
    return;
  line_end_ = to_gl(gla, event->pos());
  gla->update();
}

void EditPrimitivePlugin::mouseRelease(QMouseEvent* event, MeshModel&, GLArea* gla)
{
  if (!pressed_ || event->button() != Qt::LeftButton || gla_ == nullptr)
    return;
  pressed_ = false;
  const bool click = (event->pos() - press_pos_).manhattanLength() <= kClickSlack;
  if (drawing_line_) {
    drawing_line_ = false;
    line_end_ = to_gl(gla, event->pos());
    if (click)
      report(false, "split", "drag across the segment with Ctrl held to draw the cutting line");
    else
      split(line_start_, line_end_);
    gla->update();
    return;
  }
  if (click) {
    pick_pending_ = true;
    pick_additive_ = (event->modifiers() & Qt::ShiftModifier) != 0;
    pick_at_ = to_gl(gla, event->pos());
    gla->update();
  }
}

void EditPrimitivePlugin::keyPress(QKeyEvent* event, MeshModel&, GLArea*)
{
  if (gla_ == nullptr)
    return;
  const bool ctrl = (event->modifiers() & Qt::ControlModifier) != 0;
  switch (event->key()) {
  case Qt::Key_M: merge(); break;
  case Qt::Key_F: fit(); break;
  case Qt::Key_S: segment(); break;
  case Qt::Key_R: panel_->focusSizeField(); break;
  case Qt::Key_U: undo(); break;
  case Qt::Key_Z:
    if (!ctrl)
      return;
    undo();
    break;
  case Qt::Key_Return:
  case Qt::Key_Enter: apply(); break;
  case Qt::Key_0: panel_->setType(std::nullopt); break;
  case Qt::Key_1:
  case Qt::Key_2:
  case Qt::Key_3:
  case Qt::Key_4:
  case Qt::Key_5: panel_->setType(PrimitiveType(event->key() - Qt::Key_1)); break;
  default: return;
  }
  event->accept();
}

void EditPrimitivePlugin::draw(MeshModel& m, GLArea* gla)
{
  if (model_ == nullptr || &m != model_)
    return;
  glPushMatrix();
  glMultMatrix(m.cm.Tr);
  GLdouble mv[16], pr[16];
  GLint vp[4];
  glGetDoublev(GL_MODELVIEW_MATRIX, mv);
  glGetDoublev(GL_PROJECTION_MATRIX, pr);
  glGetIntegerv(GL_VIEWPORT, vp);
  modelview_ = Eigen::Map<const Eigen::Matrix4d>(mv);
  projection_ = Eigen::Map<const Eigen::Matrix4d>(pr);
  viewport_ = Eigen::Vector4d(vp[0], vp[1], vp[2], vp[3]);
  have_camera_ = true;
  if (pick_pending_) {
    pick_pending_ = false;
    pickAt(pick_at_, pick_additive_);
  }
  drawOverlay();
  glPopMatrix();

  if (drawing_line_) {
    // The split line, in window coordinates over everything.
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadIdentity();
    glOrtho(0, QTDeviceWidth(gla), 0, QTDeviceHeight(gla), -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glLoadIdentity();
    glPushAttrib(GL_ENABLE_BIT | GL_LINE_BIT | GL_CURRENT_BIT);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_LIGHTING);
    glDisable(GL_TEXTURE_2D);
    glLineWidth(QTLogicalToDevice(gla, 2));
    glColor3f(1.f, 0.1f, 0.1f);
    glBegin(GL_LINES);
    glVertex2d(line_start_.x(), line_start_.y());
    glVertex2d(line_end_.x(), line_end_.y());
    glEnd();
    glPopAttrib();
    glPopMatrix();
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
  }
  logRealTime("Primitive Edit", m.shortName(),
              "Click: pick a segment, Shift+click: add/remove<br>Ctrl+drag: split by a line<br>"
              "M merge, 0-5 type (Auto, Plane, Sphere, Cylinder, Cone, Torus), F fit, R edit radius,<br>"
              "Enter apply, Ctrl+Z / U undo, S segment; Esc: rotate the view");
}

void EditPrimitivePlugin::drawOverlay()
{
  glPushAttrib(GL_ENABLE_BIT | GL_LINE_BIT | GL_CURRENT_BIT | GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT |
               GL_POLYGON_BIT);
  glDisable(GL_LIGHTING);
  glDisable(GL_TEXTURE_2D);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDepthFunc(GL_LEQUAL);
  if (!highlight_.empty()) {
    // Picked segments: black and white diagonal hatching just in front of the surface. A pattern, not a
    // colour, so it cannot be mistaken for a segment's own colour.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(-1.f, -1.f);
    glEnable(GL_POLYGON_STIPPLE);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, highlight_.data());
    for (int pass = 0; pass < 2; ++pass) {
      GLubyte pattern[128];  // 32 x 32 bits, stripes 4 pixels wide
      for (int y = 0; y < 32; ++y)
        for (int byte = 0; byte < 4; ++byte) {
          GLubyte bits = 0;
          for (int bit = 0; bit < 8; ++bit)
            if ((((byte * 8 + bit + y) / 4) % 2) == pass)
              bits = GLubyte(bits | (0x80 >> bit));
          pattern[y * 4 + byte] = bits;
        }
      glPolygonStipple(pattern);
      if (pass == 0)
        glColor4f(1.f, 1.f, 1.f, 0.75f);
      else
        glColor4f(0.f, 0.f, 0.f, 0.55f);
      glDrawArrays(GL_TRIANGLES, 0, GLsizei(highlight_.size() / 3));
    }
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisable(GL_POLYGON_STIPPLE);
  }
  if (wireframe_.rows() > 0) {
    // The edited primitive: bright where visible, faint where hidden behind the mesh.
    glLineWidth(2.f);
    for (int pass = 0; pass < 2; ++pass) {
      if (pass == 0) {
        glDisable(GL_DEPTH_TEST);
        glColor4f(0.1f, 0.9f, 1.f, 0.25f);
      } else {
        glEnable(GL_DEPTH_TEST);
        glColor4f(0.1f, 0.9f, 1.f, 1.f);
      }
      glBegin(GL_LINES);
      for (Eigen::Index i = 0; i < wireframe_.rows(); ++i)
        glVertex3d(wireframe_(i, 0), wireframe_(i, 1), wireframe_(i, 2));
      glEnd();
    }
  }
  glPopAttrib();
}
