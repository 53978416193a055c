// snap_segments.h: move the vertices of segments onto their primitives, with sharp edges and corners
// where snapped segments meet ("Primitive: Snap Segment").
//
// Input:  a vcg triangle mesh, segment_of_face (indexed by vcg::tri::Index(m, face); -1 or missing =
//         no segment), primitive_of_segment (the primitive of segment k, or std::nullopt to leave
//         segment k alone; an invalid primitive, e.g. with NaN parameters, counts as std::nullopt), and
//         SnapOptions.
// Output: vertex positions changed in place, and a SnapReport. The segments of a vertex are those of
//         its incident live faces; segments with equal primitives count once. A vertex on one snapped
//         primitive goes to its closest point there; on two, to the nearest point of their
//         intersection (sharp_edges, within max_edge_distance) or else to the nearer of its two
//         projections; on three or more, to their common point, else to the intersection of the two
//         nearest surfaces, else to the nearest projection. Vertices of unsnapped segments only are
//         untouched, except near a fold (below). Triangles do not flip (prevent_flips): a live face whose
//         normal turns by more than 90 degrees or whose area collapses (below 1e-3 of its original) is
//         first repaired (repair_folds, with repair_folds on): vertices near it slide along their
//         primitive or edge, and vertices of unsnapped faces along the scan's surface as it was (followed
//         face to face by locate_on_surface, on their side of a crease), until it unfolds
//         (repaired_vertices counts them). Where a fold remains, one of its moved vertices falls back one
//         step (edge/corner -> single projection -> the mean of its neighbours projected onto its surface ->
//         that mean itself -> original position), repeated until no face flips (reverted_vertices counts
//         them): of the three, the one whose step unfolds the face with the shortest move, else the most
//         snapped, then the most displaced. The steps along the surface come first, and the vertex that can
//         take one, because a vertex sent back to a rough scan stands off its snapped neighbours and folds
//         their faces in turn (the 1M-face bracket scan snapped onto its true primitives: 22,374 vertices held
//         back, 95.8% within 0.42 mm, against 12,396 and 97.2%). A vertex sent back to the scan or to the mean
//         of its neighbours then goes as far towards its projection as its faces allow without folding (in
//         sixteenths of the way, up to 8 sweeps; partway_vertices counts those that moved): on a rough scan it
//         stood 0.3-0.6 mm off. Corners,
//         vertices on the mesh's border, on a crease of unsnapped faces or on the border of a segment
//         (but along the edge of two primitives) never slide. folded_faces and
//         folded_area give what is left folded (zero with prevent_flips). A non-finite target leaves the
//         vertex where it is; non-finite vertices are never moved.
//         Face and vertex normals are NOT updated: that is the caller's job
//         (vcg::tri::UpdateNormal<MeshType>::PerFaceNormalized / PerVertexNormalizedPerFace).
// Needs:  only the face-vertex lists (no VF/FF topology): a vertex -> face table is built by counting
//         sort (vertex_faces.h).
// Cost:   O(V + F) plus O(1) math per vertex (placed on options.threads threads); the repair visits only the
//         faces around the folds (see repair_folds.h); each fall-back round only revisits the faces around the
//         vertices that moved back, and the way back towards the projection tries at most 16 positions a vertex
//         per sweep, 8 sweeps.
#ifndef PRIMITIVE_EDIT_SNAP_SEGMENTS_H
#define PRIMITIVE_EDIT_SNAP_SEGMENTS_H

#include "common/geometry/closest_point_on_intersection.h"
#include "common/geometry/closest_point_on_primitive.h"
#include "common/geometry/common_point_of_primitives.h"
#include "common/base/constants.h"
#include "common/base/huge_page_vector.h"
#include "common/base/lazy_lists.h"
#include "common/base/parallel_for.h"
#include "common/base/primitive.h"
#include "common/mesh/face_adjacency.h"
#include "common/mesh/locate_on_surface.h"
#include "common/mesh/vertex_faces.h"
#include "common/snap/repair_folds.h"

#include <vcg/complex/complex.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <tuple>
#include <vector>

namespace primitive_edit {

struct SnapOptions
{
  bool sharp_edges = true;
  // How far a shared vertex may travel to reach an edge/corner; <= 0: 5x the mean edge length of the mesh.
  double max_edge_distance = 0;
  bool prevent_flips = true;
  // With prevent_flips: slide vertices along their surfaces to unfold faces before holding any back.
  bool repair_folds = true;
  // With repair_folds: after the repair around each fold, a wide one (grown around the whole region) for the
  // folds left, which a primitive moved far from the scan needs (the edit tool's widened hole pushes the plane
  // around it outwards). Off, the first repair keeps what it undid of a fold it could not undo whole. Off for
  // primitives fitted to the scan (Fit All): on the bracket scans the wide repair undid almost none of the
  // folds left, and keeping the partial repairs gains more (bench/README.md, Snapping).
  bool wide_repair = true;
  // The repair's sweeps on this many threads (<= 0: every hardware thread); the result is the same on any count.
  int threads = 0;
};

// The options for snapping onto primitives fitted to the scan (Fit All; see wide_repair).
SnapOptions fitted_snap_options();

struct SnapReport
{
  int moved_vertices = 0, edge_vertices = 0, corner_vertices = 0, reverted_vertices = 0;
  // Vertices on faces of two or more snapped primitives, where edges and corners go: edge_vertices +
  // corner_vertices of them made it, the rest stand off their edge (out of reach, held back, sharp_edges off).
  int border_vertices = 0;
  int repaired_vertices = 0; // slid along their surface to unfold faces
  int partway_vertices = 0;  // of the reverted ones that went back to the scan or between their neighbours, moved
                             // part of the way to their surface
  int folded_faces = 0;      // left folded (normal turned over or area collapsed); 0 with prevent_flips
  double folded_area = 0;    // their area before snapping
  double mean_displacement = 0, max_displacement = 0;
};

namespace snap_detail {

// The phases of snap_segments over one mesh; the public function below runs them in order.
template <class MeshType>
class Snapper
{
  using CoordType = typename MeshType::CoordType;
  using ScalarType = typename MeshType::ScalarType;
  // kSlid: a vertex of unsnapped faces only, moved by the repair.
  enum Kind : std::uint8_t { kUntouched, kSingle, kEdge, kCorner, kSlid };
  // How far a vertex has fallen back from where its kind puts it (hold_back): kOnTarget, then kOnNearest (for
  // edges and corners the single projection, for a single projection the mean of its neighbours projected onto
  // its surface), then kBetween (the mean of its neighbours), then kAtRest
  // (where it was; also every untouched vertex); kPartway: from kAtRest or kBetween towards its projection
  // (go_partway).
  enum Stage : std::uint8_t { kOnTarget, kOnNearest, kBetween, kPartway, kAtRest };

public:
  Snapper(MeshType& m, const std::vector<int>& segment_of_face,
          const std::vector<std::optional<Primitive>>& primitive_of_segment, const SnapOptions& options)
      : m_(m), segment_of_face_(segment_of_face), primitive_of_segment_(primitive_of_segment), options_(options)
  {
  }

  SnapReport run()
  {
    if (m_.vert.empty() || m_.face.empty())
      return report_;
    group_equal_primitives();
    build_tables();
    place_on_targets();
    if (options_.prevent_flips && options_.repair_folds)
      repair();
    if (options_.prevent_flips) {
      hold_back();
      go_partway();
    }
    summarize();
    return report_;
  }

private:
  static Eigen::Vector3d to_eigen(const CoordType& c) { return {double(c[0]), double(c[1]), double(c[2])}; }
  static CoordType to_coord(const Eigen::Vector3d& e)
  {
    return CoordType(ScalarType(e.x()), ScalarType(e.y()), ScalarType(e.z()));
  }
  // A finite double can still overflow a float coordinate.
  static bool representable(const Eigen::Vector3d& e)
  {
    return e.allFinite() && e.cwiseAbs().maxCoeff() < double(std::numeric_limits<ScalarType>::max());
  }

  // Segments with identical primitives are one surface for the vertices they share: map every snapped
  // segment to a group of equal primitives (sorting keeps this O(S log S)).
  void group_equal_primitives()
  {
    auto key = [](const Primitive& q) {
      return std::make_tuple(int(q.type), q.origin.x(), q.origin.y(), q.origin.z(), q.axis.x(), q.axis.y(),
                             q.axis.z(), q.radius, q.minor_radius, q.half_angle);
    };
    const int ns = static_cast<int>(primitive_of_segment_.size());
    group_of_segment_.assign(std::size_t(ns), -1);
    std::vector<int> order;
    for (int s = 0; s < ns; ++s)
      if (primitive_of_segment_[std::size_t(s)] && primitive_is_valid(*primitive_of_segment_[std::size_t(s)]))
        order.push_back(s);
    auto prim = [&](int s) -> const Primitive& { return *primitive_of_segment_[std::size_t(s)]; };
    std::sort(order.begin(), order.end(),
              [&](int x, int y) { return std::make_pair(key(prim(x)), x) < std::make_pair(key(prim(y)), y); });
    for (std::size_t i = 0; i < order.size(); ++i) {
      if (i == 0 || key(prim(order[i])) != key(prim(order[i - 1])))
        group_primitive_.push_back(&prim(order[i]));
      group_of_segment_[std::size_t(order[i])] = static_cast<int>(group_primitive_.size()) - 1;
    }
  }

  int group_of_face(std::size_t fi) const
  {
    if (fi >= segment_of_face_.size())
      return -1;
    const int s = segment_of_face_[fi];
    return (s >= 0 && s < int(group_of_segment_.size())) ? group_of_segment_[std::size_t(s)] : -1;
  }

  // Vertex -> live faces, each face's edge cross product before snapping, the original positions and the
  // mean edge length for the automatic edge distance.
  void build_tables()
  {
    const std::size_t nv = m_.vert.size(), nf = m_.face.size();
    face_vertex_ = detail::face_vertex_indices(m_);
    vertex_faces_ = build_vertex_faces(face_vertex_, nv);
    original_ = huge_page_vector<CoordType>(nv);
    for (std::size_t v = 0; v < nv; ++v)
      original_[v] = m_.vert[v].cP();
    assign_on_huge_pages(reference_, nf, Eigen::Vector3d(Eigen::Vector3d::Zero()));
    double edge_sum = 0;
    std::size_t edge_count = 0;
    for (std::size_t f = 0; f < nf; ++f) {
      const int* c = &face_vertex_[3 * f];
      if (c[0] < 0)
        continue;
      const Eigen::Vector3d p0 = rest(c[0]), p1 = rest(c[1]), p2 = rest(c[2]);
      reference_[f] = (p1 - p0).cross(p2 - p0);
      for (const double len : {(p1 - p0).norm(), (p2 - p1).norm(), (p0 - p2).norm()})
        if (std::isfinite(len)) {
          edge_sum += len;
          ++edge_count;
        }
    }
    max_edge_distance_ = options_.max_edge_distance > 0
                             ? options_.max_edge_distance
                             : (edge_count > 0 ? 5.0 * edge_sum / double(edge_count) : 0.0);
  }

  Eigen::Vector3d rest(int v) const { return to_eigen(original_[std::size_t(v)]); }
  Eigen::Vector3d now(int v) const { return to_eigen(m_.vert[std::size_t(v)].cP()); }

  // The distinct primitive groups of vertex v, sorted.
  void gather(std::size_t v, std::vector<int>& groups) const
  {
    groups.clear();
    for (int i = vertex_faces_.offset[v]; i < vertex_faces_.offset[v + 1]; ++i) {
      const int g = group_of_face(std::size_t(vertex_faces_.face[std::size_t(i)]));
      if (g >= 0)
        groups.push_back(g);
    }
    std::sort(groups.begin(), groups.end());
    groups.erase(std::unique(groups.begin(), groups.end()), groups.end());
  }

  // Projection onto the nearest of the given primitives (used alone and as the fall-back of edges/corners).
  Eigen::Vector3d nearest_projection(const int* begin, const int* end, const Eigen::Vector3d& p) const
  {
    PrimitiveProjection best = project_onto_primitive(*group_primitive_[std::size_t(*begin)], p);
    for (const int* g = begin + 1; g < end; ++g) {
      const PrimitiveProjection pr = project_onto_primitive(*group_primitive_[std::size_t(*g)], p);
      if (std::abs(pr.signed_distance) < std::abs(best.signed_distance))
        best = pr;
    }
    return best.point;
  }
  Eigen::Vector3d nearest_projection(const std::vector<int>& groups, const Eigen::Vector3d& p) const
  {
    return nearest_projection(groups.data(), groups.data() + groups.size(), p);
  }

  // The edge or corner of three or more primitives nearest to p, if one is within reach.
  bool corner_or_edge(const std::vector<int>& groups, const Eigen::Vector3d& p, Eigen::Vector3d& target,
                      Kind& kind) const
  {
    std::vector<const Primitive*> prims;
    for (int g : groups)
      prims.push_back(group_primitive_[std::size_t(g)]);
    if (common_point_of_primitives(prims, p, max_edge_distance_, target)) {
      kind = kCorner;
      return true;
    }
    std::vector<std::pair<double, int>> by_distance;
    for (int g : groups)
      by_distance.emplace_back(std::abs(signed_distance_to_primitive(*group_primitive_[std::size_t(g)], p)), g);
    std::partial_sort(by_distance.begin(), by_distance.begin() + 2, by_distance.end());
    kind = kEdge;
    return closest_point_on_intersection(*group_primitive_[std::size_t(by_distance[0].second)],
                                         *group_primitive_[std::size_t(by_distance[1].second)], p,
                                         max_edge_distance_, target);
  }

  // Each vertex onto its target, on options_.threads threads: a vertex reads its rest position and the
  // tables, and writes only its own entries, so the result is the same on any count.
  void place_on_targets()
  {
    const std::size_t nv = m_.vert.size();
    kind_.assign(nv, kUntouched);
    stage_.assign(nv, kAtRest);
    std::atomic<int> border_vertices{0};
    parallel_for(nv, options_.threads, kFacesPerThread, [&](std::size_t begin, std::size_t end) {
      std::vector<int> groups;
      int border = 0;
      for (std::size_t v = begin; v < end; ++v)
        border += place_on_target(v, groups) ? 1 : 0;
      border_vertices += border;
    });
    report_.border_vertices += border_vertices;
  }

  // Places vertex v (groups: scratch); returns whether it is on the faces of two or more primitives.
  bool place_on_target(std::size_t v, std::vector<int>& groups)
  {
    if (m_.vert[v].IsD())
      return false;
    gather(v, groups);
    const Eigen::Vector3d p = rest(int(v));
    if (groups.empty() || !p.allFinite())
      return false;
    Eigen::Vector3d target;
    Kind k = kSingle;
    if (options_.sharp_edges && groups.size() == 2 &&
        closest_point_on_intersection(*group_primitive_[std::size_t(groups[0])],
                                      *group_primitive_[std::size_t(groups[1])], p, max_edge_distance_, target))
      k = kEdge;
    else if (!(options_.sharp_edges && groups.size() >= 3 && corner_or_edge(groups, p, target, k)))
      k = kSingle;
    if (k == kSingle)
      target = nearest_projection(groups, p);
    if (representable(target)) {
      kind_[v] = k;
      stage_[v] = kOnTarget;
      m_.vert[v].P() = to_coord(target);
    }
    return groups.size() >= 2;
  }

  // Whether the repair may slide vertex v: not a corner, not on the mesh's border nor a non-manifold edge
  // (a neighbour met once or more than twice around it), not on a segment's border unless on the edge of two
  // primitives, and for a vertex of unsnapped faces, not on a crease. Leaves v's groups in `groups` (none for
  // a vertex of unsnapped faces): what constrain(v) projects onto.
  bool slidable(std::size_t v, std::vector<int>& groups) const
  {
    groups.clear();
    if (m_.vert[v].IsD() || stage_[v] != (kind_[v] == kUntouched ? kAtRest : kOnTarget) || kind_[v] == kCorner ||
        !rest(int(v)).allFinite())
      return false;
    std::vector<int> around;
    for (int i = vertex_faces_.offset[v]; i < vertex_faces_.offset[v + 1]; ++i)
      for (int j = 0; j < 3; ++j) {
        const int u = face_vertex_[3 * std::size_t(vertex_faces_.face[std::size_t(i)]) + std::size_t(j)];
        if (std::size_t(u) != v)
          around.push_back(u);
      }
    std::sort(around.begin(), around.end());
    for (std::size_t i = 0; i < around.size();) {
      std::size_t j = i;
      while (j < around.size() && around[j] == around[i])
        ++j;
      if (j - i != 2)
        return false;
      i = j;
    }
    if (around.empty())
      return false;
    if (kind_[v] == kUntouched)
      return tangent_of_unsnapped(v).has_value();
    gather(v, groups);
    if (kind_[v] == kEdge)
      return groups.size() == 2;
    // A vertex on one primitive slides only inside its segment: on the border with unsnapped faces it
    // would carry the border along the primitive.
    for (int i = vertex_faces_.offset[v]; i < vertex_faces_.offset[v + 1]; ++i)
      if (group_of_face(std::size_t(vertex_faces_.face[std::size_t(i)])) != groups[0])
        return false;
    return true;
  }

  // Unsnapped faces more than 30 degrees apart meet at a crease: a vertex there does not slide, and a
  // sliding vertex does not cross one.
  static double cos_crease()
  {
    static const double cosine = std::cos(radians_from_degrees(30.0));
    return cosine;
  }

  // The unit normal at a vertex of unsnapped faces, or nothing on a crease (faces more than 30 degrees
  // from it), where sliding in a plane would cut the corner. Faces touching a snapped vertex are left out
  // when others remain: they are the blurred band the snap reshapes, not the surface the vertex lies on.
  std::optional<Eigen::Vector3d> tangent_of_unsnapped(std::size_t v) const
  {
    auto untouched = [&](int f) {
      const int* c = &face_vertex_[3 * std::size_t(f)];
      return kind_[std::size_t(c[0])] == kUntouched && kind_[std::size_t(c[1])] == kUntouched &&
             kind_[std::size_t(c[2])] == kUntouched;
    };
    bool any_untouched = false;
    for (int i = vertex_faces_.offset[v]; i < vertex_faces_.offset[v + 1]; ++i)
      any_untouched = any_untouched || untouched(vertex_faces_.face[std::size_t(i)]);
    auto counts = [&](int f) { return !any_untouched || untouched(f); };
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    for (int i = vertex_faces_.offset[v]; i < vertex_faces_.offset[v + 1]; ++i)
      if (counts(vertex_faces_.face[std::size_t(i)]))
        n += reference_[std::size_t(vertex_faces_.face[std::size_t(i)])];
    if (!(n.norm() > 0) || !n.allFinite())
      return std::nullopt;
    n.normalize();
    for (int i = vertex_faces_.offset[v]; i < vertex_faces_.offset[v + 1]; ++i) {
      const int f = vertex_faces_.face[std::size_t(i)];
      const Eigen::Vector3d& r = reference_[std::size_t(f)];
      if (counts(f) && (!(r.norm() > 0) || r.dot(n) < cos_crease() * r.norm()))
        return std::nullopt;
    }
    return n;
  }

  // The repair's `movable`: slidable(v), whose groups are listed for constrain(v) to read (here, as the repair
  // asks this on its calling thread, while constrain may run on several).
  bool movable_for_repair(std::size_t v) const
  {
    if (!slidable(v, scratch_groups_))
      return false;
    repair_groups_.get(v, [&](std::vector<int>& pool) {
      pool.insert(pool.end(), scratch_groups_.begin(), scratch_groups_.end());
    });
    return true;
  }

  // Puts p onto the surface vertex v was snapped to (its tangent plane for unsnapped faces). Writes only
  // host_face_[v]: the repair runs it on several threads, for different vertices.
  bool constrain(std::size_t v, const Eigen::Vector3d& p, Eigen::Vector3d& out) const
  {
    const auto [begin, end] = repair_groups_.built(v); // listed by movable_for_repair
    if (kind_[v] == kEdge)
      return end - begin >= 2 && closest_point_on_intersection(*group_primitive_[std::size_t(begin[0])],
                                                               *group_primitive_[std::size_t(begin[1])], p,
                                                               max_edge_distance_, out);
    if (kind_[v] == kSingle) {
      if (begin == end)
        return false;
      out = nearest_projection(begin, end, p);
      return true;
    }
    const std::optional<Eigen::Vector3d> n = tangent_of_unsnapped(v);
    if (!n)
      return false;
    // Onto the scan as it was (its unsnapped faces on this side of a crease), followed face to face: a
    // tangent plane of its own, which the noise tilts, would lift a vertex that slides far above its
    // neighbours.
    auto enters = [&](int f) {
      const Eigen::Vector3d& r = reference_[std::size_t(f)];
      return face_vertex_[3 * std::size_t(f)] >= 0 && group_of_face(std::size_t(f)) < 0 &&
             r.dot(*n) > cos_crease() * r.norm();
    };
    int& host = host_face_[v];
    for (int i = vertex_faces_.offset[v]; host < 0 && i < vertex_faces_.offset[v + 1]; ++i)
      if (enters(vertex_faces_.face[std::size_t(i)]))
        host = vertex_faces_.face[std::size_t(i)];
    if (host < 0)
      return false;
    const SurfaceLocation at =
        locate_on_surface([&](int u) { return rest(u); }, face_vertex_, vertex_faces_, enters, host, p);
    host = at.face;
    out = at.point;
    return true;
  }

  void repair()
  {
    const std::size_t nv = m_.vert.size();
    std::vector<Eigen::Vector3d> position = huge_page_vector<Eigen::Vector3d>(nv);
    for (std::size_t v = 0; v < nv; ++v)
      position[v] = now(int(v));
    // Narrow regions first (each fold's own neighbourhood), then wide ones for the folds left (RepairFoldsOptions::widen).
    assign_on_huge_pages(host_face_, nv, -1);
    repair_groups_ = LazyLists(nv);
    int rounds = 0;
    for (const bool widen : {false, true}) {
      if (widen && !options_.wide_repair)
        break;
      RepairFoldsOptions options;
      options.widen = widen;
      options.threads = options_.threads;
      // Partial repairs only when no wide repair follows: started from them instead of the snapped positions,
      // the wide repair of a widened hole failed (bench/README.md, Snapping).
      options.keep_partial = !widen && !options_.wide_repair;
      if (!widen)
        options.settle_sweeps = 0; // a narrow region is a few rings deep: its rounds have converged
      const RepairFoldsReport pass = repair_folds(
          position, face_vertex_, vertex_faces_, reference_, [&](std::size_t v) { return movable_for_repair(v); },
          [&](std::size_t v, const Eigen::Vector3d& p, Eigen::Vector3d& out) { return constrain(v, p, out); }, options);
      rounds += pass.rounds;
      if (pass.folded_faces == 0) // nothing left for the wide pass: spare its O(F) search for folds
        break;
    }
    if (rounds == 0)
      return;
    for (std::size_t v = 0; v < nv; ++v) {
      if (position[v] == now(int(v)) || !representable(position[v]))  // the mesh still holds the snapped positions
        continue;
      m_.vert[v].P() = to_coord(position[v]);
      if (kind_[v] == kUntouched) {
        kind_[v] = kSlid;
        stage_[v] = kOnTarget;
      }
      ++report_.repaired_vertices;
    }
  }

  bool face_is_bad(std::size_t f) const
  {
    const int* c = &face_vertex_[3 * f];
    if (c[0] < 0 || (stage_[std::size_t(c[0])] == kAtRest && stage_[std::size_t(c[1])] == kAtRest &&
                     stage_[std::size_t(c[2])] == kAtRest))
      return false;
    return face_is_folded(reference_[f], now(c[0]), now(c[1]), now(c[2]));
  }

  // The vertex of face f to fall back: of those whose next step back unfolds f, the one that moves least;
  // when none does, the most snapped (edge/corner before single), then the most displaced.
  int vertex_to_fall_back(std::size_t f, std::vector<int>& groups) const
  {
    int chosen = -1, unfolding = -1;
    std::pair<int, double> chosen_key(-1, 0.0);
    double unfolding_move = std::numeric_limits<double>::infinity();
    const int* c = &face_vertex_[3 * f];
    for (int j = 0; j < 3; ++j) {
      const std::size_t v = std::size_t(c[j]);
      if (stage_[v] == kAtRest)
        continue;
      const FallBack step = next_fall_back(v, groups);
      Eigen::Vector3d p[3] = {now(c[0]), now(c[1]), now(c[2])};
      p[j] = step.position;
      const double move = (step.position - now(int(v))).norm();
      if (!face_is_folded(reference_[f], p[0], p[1], p[2]) && move < unfolding_move) {
        unfolding = static_cast<int>(v);
        unfolding_move = move;
      }
      const int level = (stage_[v] == kOnTarget && (kind_[v] == kEdge || kind_[v] == kCorner)) ? 1 : 0;
      const std::pair<int, double> key(level, (now(int(v)) - rest(int(v))).norm());
      if (chosen < 0 || key > chosen_key) {
        chosen = static_cast<int>(v);
        chosen_key = key;
      }
    }
    return unfolding >= 0 ? unfolding : chosen;
  }

  struct FallBack
  {
    Stage stage;
    Eigen::Vector3d position;
  };

  // One step back: edge/corner -> single projection of the original position; a single projection -> the mean
  // of the vertex's neighbours as they are now, projected onto its surface; then that mean itself -> original
  // position. A vertex the repair slid goes straight back: it belongs to no snapped segment. `groups` is scratch,
  // the caller's, so that the walk over every folded face allocates nothing.
  FallBack next_fall_back(std::size_t v, std::vector<int>& groups) const
  {
    if (stage_[v] == kOnTarget && (kind_[v] == kEdge || kind_[v] == kCorner)) {
      gather(v, groups);
      const Eigen::Vector3d target = nearest_projection(groups, rest(int(v)));
      if (representable(target))
        return {kOnNearest, target};
    }
    if (stage_[v] < kBetween && kind_[v] != kSlid) {
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      int count = 0;
      for (int i = vertex_faces_.offset[v]; i < vertex_faces_.offset[v + 1]; ++i)
        for (int j = 0; j < 3; ++j) {
          const int u = face_vertex_[3 * std::size_t(vertex_faces_.face[std::size_t(i)]) + std::size_t(j)];
          if (std::size_t(u) != v) {
            sum += now(u);
            ++count;
          }
        }
      if (count > 0 && stage_[v] == kOnTarget && kind_[v] == kSingle) {
        gather(v, groups);
        if (!groups.empty())
          if (const Eigen::Vector3d target = nearest_projection(groups, sum / count); representable(target))
            return {kOnNearest, target};
      }
      if (count > 0 && representable(sum / count))
        return {kBetween, sum / count};
    }
    return {kAtRest, to_eigen(original_[v])};
  }

  void fall_back(std::size_t v, std::vector<int>& groups)
  {
    const FallBack step = next_fall_back(v, groups);
    stage_[v] = step.stage;
    m_.vert[v].P() = step.stage == kAtRest ? original_[v] : to_coord(step.position);
  }

  void hold_back()
  {
    const std::size_t nv = m_.vert.size(), nf = m_.face.size();
    std::vector<int> candidates;
    for (std::size_t f = 0; f < nf; ++f)
      if (face_vertex_[3 * f] >= 0)
        candidates.push_back(static_cast<int>(f));
    std::vector<std::uint8_t> reverted(nv, 0), drop(nv, 0);
    std::vector<int> dropped, groups;
    std::vector<int> face_mark = huge_page_vector(nf, -1);
    for (int round = 0; !candidates.empty(); ++round) {
      dropped.clear();
      for (int f : candidates) {
        if (!face_is_bad(std::size_t(f)))
          continue;
        const int chosen = vertex_to_fall_back(std::size_t(f), groups);
        if (chosen >= 0 && !drop[std::size_t(chosen)]) {
          drop[std::size_t(chosen)] = 1;
          dropped.push_back(chosen);
        }
      }
      for (int vi : dropped) {
        drop[std::size_t(vi)] = 0;
        reverted[std::size_t(vi)] = 1;
        fall_back(std::size_t(vi), groups);
      }
      candidates.clear();
      for (int vi : dropped)
        for (int i = vertex_faces_.offset[std::size_t(vi)]; i < vertex_faces_.offset[std::size_t(vi) + 1]; ++i) {
          const int f = vertex_faces_.face[std::size_t(i)];
          if (face_mark[std::size_t(f)] != round) {
            face_mark[std::size_t(f)] = round;
            candidates.push_back(f);
          }
        }
    }
    report_.reverted_vertices = static_cast<int>(std::count(reverted.begin(), reverted.end(), std::uint8_t(1)));
  }

  // Whether every live face around vertex v is unfolded, with the positions as they are now. Not face_is_bad:
  // it passes a face whose three vertices are kAtRest, as the vertex under test still is while it is tried.
  bool faces_unfolded_around(std::size_t v) const
  {
    for (int i = vertex_faces_.offset[v]; i < vertex_faces_.offset[v + 1]; ++i) {
      const std::size_t f = std::size_t(vertex_faces_.face[std::size_t(i)]);
      const int* c = &face_vertex_[3 * f];
      if (face_is_folded(reference_[f], now(c[0]), now(c[1]), now(c[2])))
        return false;
    }
    return true;
  }

  // The vertices held back to the scan or to the mean of their neighbours, each moved as far along the line from
  // where it is to its projection as its faces allow without folding: 1, 15/16, ... 1/16 of the way, the first
  // that folds no face. Sweeps again while one moved, as a neighbour's move can free another. Only a vertex's own
  // faces can fold when it moves, so the mesh stays without folds.
  void go_partway()
  {
    // Finer steps and more sweeps than 8 and 4 took the 1M bracket scan on its true primitives from 97.2% to 97.6%
    // within 0.42 mm, at 4M faces 0.3 s of the snap's 1.7 s (bench/README.md, Snapping).
    constexpr int kSteps = 16, kSweeps = 8;
    std::vector<int> held;
    for (std::size_t v = 0; v < m_.vert.size(); ++v)
      if (!m_.vert[v].IsD() && (stage_[v] == kAtRest || stage_[v] == kBetween) &&
          (kind_[v] == kSingle || kind_[v] == kEdge || kind_[v] == kCorner))
        held.push_back(int(v));
    std::vector<int> reached(held.size(), 0);  // sixteenths of the way taken
    std::vector<Eigen::Vector3d> start(held.size()), way(held.size());  // from where it is to its projection
    std::vector<int> groups;
    for (std::size_t i = 0; i < held.size(); ++i) {
      gather(std::size_t(held[i]), groups);
      start[i] = now(held[i]);
      way[i] = nearest_projection(groups, start[i]) - start[i];
    }
    for (int sweep = 0; sweep < kSweeps; ++sweep) {
      bool moved = false;
      for (std::size_t i = 0; i < held.size(); ++i) {
        const std::size_t v = std::size_t(held[i]);
        const CoordType before = m_.vert[v].cP();
        for (int k = kSteps; k > reached[i]; --k) {
          const Eigen::Vector3d candidate = start[i] + (double(k) / kSteps) * way[i];
          if (!representable(candidate))
            break;
          m_.vert[v].P() = to_coord(candidate);
          if (faces_unfolded_around(v)) {
            reached[i] = k;
            stage_[v] = kPartway;
            moved = true;
            break;
          }
          m_.vert[v].P() = before;
        }
      }
      if (!moved)
        break;
    }
    report_.partway_vertices = int(std::count_if(reached.begin(), reached.end(), [](int k) { return k > 0; }));
  }

  void summarize()
  {
    double displacement_sum = 0;
    for (std::size_t v = 0; v < m_.vert.size(); ++v) {
      if (kind_[v] == kUntouched || stage_[v] == kAtRest)
        continue;
      ++report_.moved_vertices;
      if (stage_[v] == kOnTarget && kind_[v] == kEdge)
        ++report_.edge_vertices;
      if (stage_[v] == kOnTarget && kind_[v] == kCorner)
        ++report_.corner_vertices;
      const double d = (now(int(v)) - rest(int(v))).norm();
      displacement_sum += d;
      report_.max_displacement = std::max(report_.max_displacement, d);
    }
    if (report_.moved_vertices > 0)
      report_.mean_displacement = displacement_sum / report_.moved_vertices;
    for (std::size_t f = 0; f < m_.face.size(); ++f)
      if (face_is_bad(f)) {
        ++report_.folded_faces;
        report_.folded_area += 0.5 * reference_[f].norm();
      }
  }

  MeshType& m_;
  const std::vector<int>& segment_of_face_;
  const std::vector<std::optional<Primitive>>& primitive_of_segment_;
  const SnapOptions& options_;
  SnapReport report_;
  std::vector<int> group_of_segment_;
  std::vector<const Primitive*> group_primitive_;
  std::vector<int> face_vertex_;
  VertexFaces vertex_faces_;
  std::vector<CoordType> original_;
  std::vector<Eigen::Vector3d> reference_;
  double max_edge_distance_ = 0;
  std::vector<std::uint8_t> kind_, stage_;
  mutable std::vector<int> scratch_groups_;
  mutable LazyLists repair_groups_{0}; // gather()'s groups of the vertices the repair's sweeps revisit
  mutable std::vector<int> host_face_; // per vertex of unsnapped faces: the scan's face it slides on, or -1
};

} // namespace snap_detail

template <class MeshType>
SnapReport snap_segments(MeshType& m, const std::vector<int>& segment_of_face,
                         const std::vector<std::optional<Primitive>>& primitive_of_segment,
                         const SnapOptions& options = {})
{
  return snap_detail::Snapper<MeshType>(m, segment_of_face, primitive_of_segment, options).run();
}

} // namespace primitive_edit

#endif
