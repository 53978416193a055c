// primitive_edit_session.h: the state of the interactive Primitive Edit tool, without any window or Qt.
//
// A session is attached to one mesh. It keeps the segmentation (mirrored on the mesh by write_segment_ids
// after every change), the picked segments, the last fit and the primitive the user edited from it, and an
// undo stack. Every step calls common/ as the filters do: segment_by_primitive_growing or
// segment_by_normal_angle, merge_segments, split_segments_by_plane (with plane_from_screen_line, cutting only
// within the stroke), fit_segment on gather_segment_samples (the automatic type within the scan's roughness)
// or, with relations, fit_all_segments (the picked segments as one among all others, without snapping), and
// snap_onto_primitive. Each undoable step (auto segmentation, merge, split, apply) stores a snapshot:
// the segment ids, the recorded primitives, the picked segments and the old positions of the vertices it
// moved; undo() restores the latest one, up to kMaxUndo steps back, and the state the session started on is
// always the last (a segmentation that changes nothing is not a step). An apply that would move vertices
// farther than the segment is large waits for a confirmation (apply's `confirmed`).
// Merge and split keep the recorded primitive of every segment they leave whole (under its new id).
// Cost: attach, merge, split and undo O(F + V); fit and apply those of the fit (with relations: of every
//       segment's fit and the relations', as Fit All without snapping) and of snap_segments.
#ifndef PRIMITIVE_EDIT_PRIMITIVE_EDIT_SESSION_H
#define PRIMITIVE_EDIT_PRIMITIVE_EDIT_SESSION_H

#include "common/base/describe_primitive.h"
#include "common/fit/fit_residuals.h"
#include "common/geometry/closest_point_on_primitive.h"
#include "common/geometry/plane_from_screen_line.h"
#include "common/geometry/project_to_window.h"
#include "common/mesh/check_mesh_input.h"
#include "common/mesh/count_segments.h"
#include "common/mesh/surface_roughness_attribute.h"
#include "common/mesh/face_adjacency.h"
#include "common/mesh/gather_segment_samples.h"
#include "common/mesh/segment_attribute.h"
#include "common/mesh/segment_primitive_attribute.h"
#include "common/mesh/update_normals_and_bounds.h"
#include "common/relate/describe_relation.h"
#include "common/pipeline/fit_all_segments.h"
#include "common/pipeline/fit_segment.h"
#include "common/pipeline/snap_onto_primitive.h"
#include "common/segment/describe_carved_blends.h"
#include "common/segment/merge_segments.h"
#include "common/segment/segment_by_normal_angle.h"
#include "common/segment/segment_by_primitive_growing.h"
#include "common/segment/split_segments_by_plane.h"

#include <vcg/complex/complex.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <deque>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace primitive_edit {

// What a step did, in words for the log: a summary when it succeeded, the status's error when not.
struct EditOutcome
{
  Status status;
  std::string summary;

  static EditOutcome done(std::string summary) { return {Status::success(), std::move(summary)}; }
  static EditOutcome refused(std::string why) { return {Status::failure(std::move(why)), {}}; }
};

struct ApplyOutcome
{
  Status status;
  std::string summary;
  SnapReport report;
  bool needs_confirmation = false;  // refused only because it moves vertices farther than the segment is large
  double max_move = 0;              // the farthest a vertex would move (or moved)
  double segment_size = 0;          // the picked segments' bounding box diagonal
};

template <class MeshType>
class PrimitiveEditSession
{
public:
  using CoordType = typename MeshType::CoordType;
  static constexpr std::size_t kMaxUndo = 32;
  static constexpr double kImplausibleFitScale = 100;  // see implausible_size

  // Starts editing m. Refuses (the status says why) when m cannot be edited: empty, a point cloud, or
  // NaN coordinates. The segments are read from the mesh (read_segment_ids); with use_quality false only
  // from the SegmentId attribute, not from a face quality that holds something else. The mesh must outlive
  // the session or be detached first.
  EditOutcome attach(MeshType& m, bool use_quality = true)
  {
    detach();
    if (Status usable = check_mesh_input(m); !usable)
      return {std::move(usable), {}};
    mesh_ = &m;
    adjacency_ = build_face_adjacency(m);
    bool renumbered = false;
    if (!read_segment_ids(m, labels_, &renumbered) ||
        (!use_quality && !detail::has_int_face_attribute(m, std::string(kSegmentAttributeName))))
      labels_.assign(m.face.size(), -1);
    else  // the ids the user reads in the face quality are the session's (renumbered as the filters do), and
          // the segments are drawn: a mesh opened with stored ids has no segment colours yet
      write_segment_ids(m, labels_, &adjacency_);
    return EditOutcome::done(has_segments() ? std::to_string(segment_count()) + " segments" +
                                                  (renumbered ? " (stored ids renumbered 0 to K-1, in their order)" : "")
                                            : "no segments yet");
  }

  void detach()
  {
    mesh_ = nullptr;
    labels_.clear();
    adjacency_ = FaceAdjacency();
    picked_.clear();
    undo_.clear();
    roughness_.reset();
    clear_fit();
  }

  bool attached() const { return mesh_ != nullptr; }
  bool has_segments() const { return segment_count() > 0; }
  int segment_count() const { return count_segments(labels_); }
  const std::vector<int>& segment_of_face() const { return labels_; }
  int segment_of(int face) const
  {
    return face >= 0 && std::size_t(face) < labels_.size() ? labels_[std::size_t(face)] : -1;
  }
  // Faces of the picked segments.
  std::vector<int> picked_faces() const
  {
    std::vector<int> faces;
    for (std::size_t f = 0; f < labels_.size(); ++f)
      if (labels_[f] >= 0 && is_picked(labels_[f]))
        faces.push_back(int(f));
    return faces;
  }

  // Replaces the segmentation by the normal-angle method (the paper's; "Segment: Auto by Normal Angle").
  EditOutcome auto_segment(const SegmentByNormalAngleParams& params)
  {
    if (const EditOutcome bad = check_mesh(); !bad.status)
      return bad;
    if (const Status bad = check_normal_angle_params(params); !bad)
      return EditOutcome::refused(bad.error);
    std::vector<int> labels;
    const int k = segment_by_normal_angle(*mesh_, adjacency_, params, labels);
    char angle[32];
    std::snprintf(angle, sizeof angle, "%.3g", params.angle_deg);
    return replace_segmentation(std::move(labels), std::to_string(k) + " segments at " + angle + " degrees");
  }

  // Replaces the segmentation by primitive growing, for scans ("Segment: Auto by Primitive Fit", the same call).
  EditOutcome auto_segment(const SegmentByPrimitiveGrowingParams& params, const Progress& progress = {})
  {
    if (const EditOutcome bad = check_mesh(); !bad.status)
      return bad;
    if (const Status bad = check_primitive_growing_params(params); !bad)
      return EditOutcome::refused(bad.error);
    std::vector<int> labels;
    SegmentByPrimitiveGrowingReport report;
    SegmentByPrimitiveGrowingParams with_roughness = params;
    with_roughness.roughness = roughness();
    const int k = segment_by_primitive_growing(*mesh_, adjacency_, with_roughness, labels, &report, progress);
    char tolerance[64];
    std::snprintf(tolerance, sizeof tolerance, "%.4g (roughness %.4g)", report.tolerance, report.roughness);
    const std::string carved = describe_carved_blends(report.blends);
    EditOutcome done = replace_segmentation(std::move(labels), std::to_string(k) + " segments by primitive fit, "
                                                                                   "tolerance " + tolerance +
                                                                   (carved.empty() ? "" : "; " + carved));
    write_segment_blends(*mesh_, labels_, report.blends);
    return done;
  }

  // Picks the segment of a face: alone, or (additive) added to / removed from the picked ones. A face with no
  // segment (or -1: a click in empty space) clears the picks unless additive. Returns whether a segment
  // was hit.
  bool pick(int face, bool additive)
  {
    const int s = attached() ? segment_of(face) : -1;
    const std::vector<int> before = picked_;
    if (s < 0) {
      if (!additive)
        picked_.clear();
    } else if (!additive) {
      picked_.assign(1, s);
    } else {
      const auto it = std::find(picked_.begin(), picked_.end(), s);
      if (it == picked_.end())
        picked_.push_back(s);
      else
        picked_.erase(it);
    }
    if (picked_ != before)
      clear_fit();
    return s >= 0;
  }
  const std::vector<int>& picked() const { return picked_; }
  bool is_picked(int segment) const { return std::find(picked_.begin(), picked_.end(), segment) != picked_.end(); }

  // Merges the picked segments into one, which stays picked.
  EditOutcome merge_picked()
  {
    if (const EditOutcome bad = check_mesh(); !bad.status)
      return bad;
    if (picked_.size() < 2)
      return EditOutcome::refused("pick at least two segments to merge (Shift+click adds a segment)");
    push_snapshot(take_snapshot("merge"));
    std::vector<int> labels = labels_;
    const int before = segment_count();
    const int face = first_face_of(picked_.front());
    const int after = merge_segments(labels, picked_);
    store(labels, carry_primitives(labels));
    picked_.assign(1, segment_of(face));
    clear_fit();
    return EditOutcome::done(std::to_string(before - after + 1) + " segments merged into segment " +
                             std::to_string(picked_.front()) + "; " + std::to_string(after) + " segments");
  }

  // Cuts the picked segments by a plane (where options.cuttable allows); every connected piece becomes a
  // segment, pieces under options.min_piece_faces join a neighbour (split_segments_by_plane.h).
  EditOutcome split_picked_by_plane(const Eigen::Vector3d& point, const Eigen::Vector3d& normal,
                                    const SplitOptions& options = {})
  {
    if (const EditOutcome bad = check_mesh(); !bad.status)
      return bad;
    if (picked_.empty())
      return EditOutcome::refused("pick the segment to split first");
    if (!point.allFinite() || !normal.allFinite() || !(normal.norm() > 0))
      return EditOutcome::refused("the cutting plane is not valid");
    std::vector<int> labels = labels_;
    const int before = segment_count();
    const int after = split_segments_by_plane(*mesh_, adjacency_, labels, picked_, point, normal, options);
    if (after == before)
      return EditOutcome::refused("the line does not cut the picked segment (draw it across the segment)");
    push_snapshot(take_snapshot("split"));
    store(labels, carry_primitives(labels));
    const std::size_t cut = picked_.size();
    picked_.clear();
    clear_fit();
    return EditOutcome::done(std::to_string(cut) + " segment(s) cut into " +
                             std::to_string(after - before + int(cut)) + " pieces; " + std::to_string(after) +
                             " segments");
  }

  // The same along a stroke drawn on screen: the plane through the stroke and the view direction (see
  // plane_from_screen_line), cutting only faces that appear within the stroke's extent (a stroke in empty
  // space or across half a segment cuts nothing off), leaving no piece under kMinSplitPieceFaces faces.
  EditOutcome split_picked_by_screen_line(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                          const Eigen::Matrix4d& modelview, const Eigen::Matrix4d& projection,
                                          const Eigen::Vector4d& viewport)
  {
    const ScreenLinePlane plane = plane_from_screen_line(a, b, modelview, projection, viewport);
    if (!plane.status)
      return EditOutcome::refused(plane.status.error);
    if (const EditOutcome bad = check_mesh(); !bad.status)
      return bad;
    SplitOptions options;
    options.min_piece_faces = kMinSplitPieceFaces;
    options.cuttable.assign(mesh_->face.size(), 0);
    const Eigen::Matrix4d clip_from_object = projection * modelview;
    const Eigen::Vector2d along = b - a;
    const double margin = 2.0 / along.norm();  // pixels of slack at the stroke's ends
    for (const int f : picked_faces()) {
      const auto& face = mesh_->face[std::size_t(f)];
      Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
      for (int k = 0; k < 3; ++k)
        centroid += Eigen::Vector3d(double(face.cP(k)[0]), double(face.cP(k)[1]), double(face.cP(k)[2])) / 3.0;
      const std::optional<Eigen::Vector2d> q = project_to_window(centroid, clip_from_object, viewport);
      const double t = q ? (*q - a).dot(along) / along.squaredNorm() : -1.0;
      options.cuttable[std::size_t(f)] = t >= -margin && t <= 1.0 + margin;
    }
    return split_picked_by_plane(plane.point, plane.normal, options);
  }

  // Fits a primitive of the given type (std::nullopt: the type that explains the points best) to the union
  // of the picked segments, starting as `method` says (fit_result.h). With `relations`, when other segments
  // exist, the picked segments are fitted as one segment among all of them, as Primitive: Fit All Segments
  // does without snapping (fit_all_segments.h): the primitive then keeps the directions, axes and radii it
  // shares with the rest of the part, and fit_relations() describes those relations in the session's ids (a
  // segment alone gets its own fit, one that shares nothing within tolerance Fit All's fit). The relations'
  // fit is taken while its RMS is within sqrt(checked_cost_factor) (1.73 at the default RelationCost) of the
  // picked segments' own fit plus round-off (round_off_cost), as Fit All's check allows any segment; beyond, or
  // when it fails, the own fit is kept and relations_refused() says why.
  // On success the fit also becomes the edited primitive.
  FitResult fit(std::optional<PrimitiveType> type, FitMethod method = FitMethod::Refined, bool relations = false)
  {
    clear_fit();
    FitResult out;
    if (const EditOutcome bad = check_mesh(); !bad.status) {
      out.status = bad.status;
      return out;
    }
    if (picked_.empty()) {
      out.status = Status::failure("pick a segment to fit first");
      return out;
    }
    const SegmentSamples samples = picked_samples();
    AutoFitOptions options;
    options.fit.method = method;
    if (!type)  // as the filters: a segment of a rough scan is a primitive within the scan's roughness
      options.roughness = roughness();
    out = fit_segment(samples, type, options);
    if (relations && segment_count() > int(picked_.size())) {
      // Fit All checks each relation against its own fit of a segment, on the segment's vertices; the fit the
      // user gets without relations is the one on the picked faces, which can differ where a type is forced on
      // data it does not suit. The relations may cost the picked segments what Fit All lets them cost any
      // segment, measured against that fit.
      // On exact data both fits are exact to round-off, which may come out either way (1.3e-24 against 4e-28):
      // Fit All's checks allow it too, at the part's size as they measure it.
      double part_size = 0;
      const FitResult held = fit_among_all(type, method, part_size);
      const double allowed = std::sqrt(checked_cost_factor(RelationOptions().max_cost_increase)) * out.rms +
                             std::sqrt(round_off_cost(part_size, 1.0));
      if (held.status && (!out.status || held.rms <= allowed)) {
        out = held;
      } else if (held.status) {
        char text[160];
        std::snprintf(text, sizeof text, "the fit among all segments would raise the RMS to %.4g from %.4g alone",
                      held.rms, out.rms);
        fit_relations_.clear();
        relations_refused_ = text;
      } else if (out.status) {
        relations_refused_ = "the fit among all segments failed: " + held.status.error;
      }
    }
    if (!out.status)
      out.status = Status::failure("the picked segments " +
                                   std::string(type ? "cannot be fitted: " : "fit no primitive: ") + out.status.error);
    if (out.status) {
      fit_ = out;
      edited_ = out.primitive;
      edited_rms_ = out.rms;
      fit_points_ = samples.points;
    }
    return out;
  }
  const std::optional<FitResult>& last_fit() const { return fit_; }
  // The relations the last fit holds with other segments, one line each (describe_relation.h); empty without.
  const std::vector<std::string>& fit_relations() const { return fit_relations_; }
  // Why the last fit holds no relations although they were asked for ("the fit among all segments would raise the
  // RMS to ... from ... alone"); empty otherwise.
  const std::string& relations_refused() const { return relations_refused_; }
  // A warning when the last fit is far larger than the picked segments (implausible_size), else empty.
  std::string fit_warning() const
  {
    if (!fit_ || fit_points_.rows() == 0)
      return {};
    const Eigen::Vector3d low = fit_points_.colwise().minCoeff().transpose();
    const Eigen::Vector3d high = fit_points_.colwise().maxCoeff().transpose();
    const std::string why = implausible_size(fit_->primitive, 0.5 * (low + high), (high - low).norm());
    return why.empty() ? why : why + ": they are nearly flat or straight, and a plane or another type fits them better";
  }
  const std::optional<Primitive>& edited() const { return edited_; }
  // The RMS distance of the fitted points from the edited primitive (the fit's RMS until an edit).
  double edited_rms() const { return edited_rms_; }
  // Points of the last fit (to draw the primitive where the segment is).
  const Eigen::MatrixX3d& fit_points() const { return fit_points_; }

  // Replaces the edited primitive (the axis is normalised). Needs a fit first; the type must stay.
  EditOutcome set_edited(Primitive p)
  {
    if (!edited_)
      return EditOutcome::refused("fit a primitive first");
    if (p.type != edited_->type)
      return EditOutcome::refused("the type differs from the fitted one; fit again with the new type");
    if (p.axis.allFinite() && p.axis.norm() > 0)
      p.axis.normalize();
    if (!primitive_is_valid(p))
      return EditOutcome::refused("not a valid " + std::string(primitive_type_name(p.type)) + ": " +
                                  describe_primitive(p));
    edited_ = p;
    edited_rms_ = fit_residuals(p, fit_points_, Eigen::VectorXd()).rms;
    return EditOutcome::done(describe_primitive(p));
  }

  // Moves the picked segments onto the edited primitive, with sharp edges against the segments snapped
  // before (recorded on the mesh), and records the primitive for them. Normals and bounding box are updated.
  // Unless confirmed, refuses (needs_confirmation, the mesh untouched) when a vertex would move farther than
  // the picked segments' bounding box diagonal: an edited value or a fit far off the segment's size.
  ApplyOutcome apply(bool sharp_edges = true, bool confirmed = false)
  {
    ApplyOutcome out;
    if (const EditOutcome bad = check_mesh(); !bad.status) {
      out.status = bad.status;
      return out;
    }
    if (!edited_ || picked_.empty()) {
      out.status = Status::failure("pick a segment and fit a primitive first");
      return out;
    }
    const Eigen::Vector3d centre = measure_move(out);
    // A primitive far larger than the segment may move nothing (a huge cylinder lying on a flat face) and
    // still replace the segment's shape: it asks too.
    const std::string implausible = implausible_size(*edited_, centre, out.segment_size);
    if (!confirmed && (out.max_move > out.segment_size || !implausible.empty())) {
      char text[200];
      std::snprintf(text, sizeof text, "this would move vertices by up to %.4g, more than the segment's size (%.4g)",
                    out.max_move, out.segment_size);
      out.status = Status::failure((implausible.empty() ? std::string(text) : implausible) + ": confirm to apply");
      out.needs_confirmation = true;
      return out;
    }
    Snapshot snapshot = take_snapshot("apply");
    std::vector<CoordType> before(mesh_->vert.size());
    for (std::size_t v = 0; v < before.size(); ++v)
      before[v] = mesh_->vert[v].cP();
    SnapOptions options;
    options.sharp_edges = sharp_edges;
    out.report = snap_onto_primitive(*mesh_, labels_, picked_, *edited_, options, segment_count());
    for (std::size_t v = 0; v < before.size(); ++v)
      if (mesh_->vert[v].cP() != before[v])
        snapshot.positions.emplace_back(int(v), before[v]);
    push_snapshot(std::move(snapshot));
    out.summary = describe_primitive(*edited_);
    return out;
  }

  bool can_undo() const { return !undo_.empty(); }
  // What undo() would undo ("segmentation", "merge", "split", "apply"), or "" when nothing.
  std::string undo_label() const { return undo_.empty() ? std::string() : undo_.back().what; }
  // Whether undo() would move vertices (so that normals and render buffers need an update).
  bool undo_moves_vertices() const { return !undo_.empty() && !undo_.back().positions.empty(); }
  std::size_t undo_depth() const { return undo_.size(); }

  // Undoes the latest step: segment ids, recorded primitives, picks and moved vertices come back.
  bool undo()
  {
    if (undo_.empty() || !check_mesh().status) {
      undo_.clear();
      return false;
    }
    Snapshot s = std::move(undo_.back());
    undo_.pop_back();
    for (const auto& moved : s.positions)
      if (std::size_t(moved.first) < mesh_->vert.size())
        mesh_->vert[std::size_t(moved.first)].P() = moved.second;
    // Undoing an apply keeps the fit and the edited parameters, so the user can change them and apply again.
    if (s.labels != labels_ || s.picked != picked_)
      clear_fit();
    store(s.labels, s.primitives);
    picked_ = s.picked;
    if (!s.positions.empty())
      update_normals_and_bounds(*mesh_);
    return true;
  }

private:
  struct Snapshot
  {
    std::string what;
    std::vector<int> labels;
    SegmentPrimitives primitives;
    std::vector<int> picked;
    std::vector<std::pair<int, CoordType>> positions;
  };

  // The mesh may be changed behind the session's back (another filter while the tool is on).
  // The farthest a picked vertex is from the edited primitive, and the picked segments' size; returns the
  // centre of their bounding box.
  Eigen::Vector3d measure_move(ApplyOutcome& out) const
  {
    Eigen::AlignedBox3d box;
    for (const int f : picked_faces())
      for (int k = 0; k < 3; ++k) {
        const auto& p = mesh_->face[std::size_t(f)].cP(k);
        const Eigen::Vector3d q(static_cast<double>(p[0]), static_cast<double>(p[1]), static_cast<double>(p[2]));
        box.extend(q);
        out.max_move = std::max(out.max_move, std::abs(signed_distance_to_primitive(*edited_, q)));
      }
    out.segment_size = box.isEmpty() ? 0.0 : box.diagonal().norm();
    return box.isEmpty() ? Eigen::Vector3d(Eigen::Vector3d::Zero()) : Eigen::Vector3d(box.center());
  }

  // Why p is implausibly large for segments of this size around this centre (a radius, or a cone's apex
  // distance, over kImplausibleFitScale times their size: a fit to a nearly flat or straight patch, or a
  // mistyped value), else empty.
  static std::string implausible_size(const Primitive& p, const Eigen::Vector3d& centre, double size)
  {
    const double scale = p.type == PrimitiveType::Cone    ? (p.origin - centre).norm()
                         : p.type == PrimitiveType::Plane ? 0.0
                                                          : p.radius;
    if (!(scale > kImplausibleFitScale * size))
      return {};
    char text[160];
    std::snprintf(text, sizeof text, "the %s %s %.3g away, while the picked segments are %.3g across",
                  primitive_type_name(p.type),
                  p.type == PrimitiveType::Cone     ? "apex lies"
                  : p.type == PrimitiveType::Sphere ? "centre lies"
                                                    : "axis lies",
                  scale, size);
    return text;
  }

  // A segmentation that gives the segments the mesh has already is not a step: the history keeps real ones.
  EditOutcome replace_segmentation(std::vector<int> labels, const std::string& summary)
  {
    if (labels == labels_)
      return EditOutcome::done(summary + "; the segments are unchanged, no undo step added");
    push_snapshot(take_snapshot("segmentation"));
    store(labels, SegmentPrimitives());
    picked_.clear();
    clear_fit();
    return EditOutcome::done(summary);
  }

  EditOutcome check_mesh() const
  {
    if (mesh_ == nullptr)
      return EditOutcome::refused("no mesh is being edited");
    if (labels_.size() != mesh_->face.size() || adjacency_.face_count() != int(mesh_->face.size()))
      return EditOutcome::refused("the mesh has changed since the tool started; restart the tool");
    return EditOutcome::done({});
  }

  void clear_fit()
  {
    fit_.reset();
    edited_.reset();
    edited_rms_ = 0;
    fit_points_.resize(0, 3);
    fit_relations_.clear();
    relations_refused_.clear();
  }

  int first_face_of(int segment) const
  {
    for (std::size_t f = 0; f < labels_.size(); ++f)
      if (labels_[f] == segment)
        return int(f);
    return -1;
  }

  // The picked segments fitted as one among all segments, with the relations Fit All finds (fit); their
  // relations, in the session's ids, go to fit_relations_, and the length that scales their round-off to
  // part_size (0 when Fit All related nothing).
  FitResult fit_among_all(std::optional<PrimitiveType> type, FitMethod method, double& part_size)
  {
    std::vector<int> labels = labels_;
    const int face = first_face_of(picked_.front());
    const int count = merge_segments(labels, picked_);
    const int joined = labels[std::size_t(face)];
    std::vector<int> session_id(std::size_t(count), -1);
    for (std::size_t f = 0; f < labels.size(); ++f)
      if (labels[f] >= 0)
        session_id[std::size_t(labels[f])] = labels_[f];
    session_id[std::size_t(joined)] = picked_.front();
    FitAllSegmentsOptions options;
    options.types.assign(std::size_t(count), std::nullopt);
    options.types[std::size_t(joined)] = type;
    options.fit.method = method;
    options.roughness = roughness();
    const FitAllSegmentsResult all = fit_all_segments(*mesh_, labels, options);
    if (!all.status) {
      FitResult failed;
      failed.status = all.status;
      return failed;
    }
    part_size = all.part_size;
    FitResult out = all.fits[std::size_t(joined)];
    if (!out.status)
      return out;
    out.primitive = *all.primitives[std::size_t(joined)];
    std::vector<std::optional<Primitive>> by_session(static_cast<std::size_t>(segment_count()));
    for (int s = 0; s < count; ++s)
      by_session[std::size_t(session_id[std::size_t(s)])] = all.primitives[std::size_t(s)];
    for (Relation r : all.relations)
      if (r.a == joined || r.b == joined) {
        r.a = session_id[std::size_t(r.a)];
        r.b = session_id[std::size_t(r.b)];
        fit_relations_.push_back(describe_relation(r, by_session));
      }
    return out;
  }

  SegmentSamples picked_samples() const
  {
    std::vector<int> faces;
    for (std::size_t f = 0; f < labels_.size(); ++f)
      if (labels_[f] >= 0 && is_picked(labels_[f]))
        faces.push_back(int(f));
    return gather_face_samples(*mesh_, faces);
  }

  // The state before a step: segment ids, recorded primitives and picks (the step adds moved vertices).
  Snapshot take_snapshot(const char* what) const
  {
    return {what, labels_, read_segment_primitives(*mesh_, segment_count()), picked_, {}};
  }

  void push_snapshot(Snapshot s)
  {
    undo_.push_back(std::move(s));
    // The oldest snapshot is the state the tool started on: always reachable, the second oldest goes.
    if (undo_.size() > kMaxUndo)
      undo_.erase(undo_.begin() + 1);
  }

  // The recorded primitives under the new ids: a segment keeps its primitive when it is unchanged, i.e. its
  // faces are exactly the faces of one old segment.
  SegmentPrimitives carry_primitives(const std::vector<int>& labels) const
  {
    const int old_count = segment_count();
    int new_count = 0;
    for (int s : labels)
      new_count = std::max(new_count, s + 1);
    const SegmentPrimitives old = read_segment_primitives(*mesh_, old_count);
    std::vector<int> image(std::size_t(old_count), -1), preimage(std::size_t(new_count), -1);
    std::vector<char> whole_old(std::size_t(old_count), 1), whole_new(std::size_t(new_count), 1);
    for (std::size_t f = 0; f < labels.size(); ++f) {
      const int o = labels_[f], n = labels[f];
      if (o < 0 || n < 0)
        continue;
      int& i = image[std::size_t(o)];
      int& p = preimage[std::size_t(n)];
      if (i >= 0 && i != n)
        whole_old[std::size_t(o)] = 0;
      if (p >= 0 && p != o)
        whole_new[std::size_t(n)] = 0;
      i = n;
      p = o;
    }
    SegmentPrimitives carried(static_cast<std::size_t>(new_count));
    for (int o = 0; o < old_count; ++o) {
      const int n = image[std::size_t(o)];
      if (n >= 0 && whole_old[std::size_t(o)] && whole_new[std::size_t(n)])
        carried[std::size_t(n)] = old[std::size_t(o)];
    }
    return carried;
  }

  void store(const std::vector<int>& labels, const SegmentPrimitives& primitives)
  {
    labels_ = labels;
    write_segment_ids(*mesh_, labels_, &adjacency_); // merges, splits and applies keep the topology
    if (std::any_of(primitives.begin(), primitives.end(), [](const auto& p) { return p.has_value(); }))
      write_segment_primitives(*mesh_, primitives);
    else
      clear_segment_primitives(*mesh_);
  }

  // The scan's roughness, as the filters kept it on the mesh or estimated, once per session (the vertices a
  // fit sees do not move before an apply, and an apply moves them onto primitives, which only lowers it).
  double roughness()
  {
    if (!roughness_)
      roughness_ = surface_roughness(*mesh_, adjacency_);
    return *roughness_;
  }

  MeshType* mesh_ = nullptr;
  std::vector<int> labels_;
  FaceAdjacency adjacency_;
  std::vector<int> picked_;
  std::optional<FitResult> fit_;
  std::optional<Primitive> edited_;
  Eigen::MatrixX3d fit_points_ = Eigen::MatrixX3d(0, 3);
  double edited_rms_ = 0;
  std::deque<Snapshot> undo_;
  std::optional<double> roughness_;
  std::vector<std::string> fit_relations_;
  std::string relations_refused_;
};

} // namespace primitive_edit

#endif
