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
//         untouched. Triangles do not flip: a live face whose normal turns by more than 90 degrees or
//         whose area collapses (below 1e-3 of its original) makes one of its moved vertices (the most
//         snapped, then the most displaced) fall back one step (edge/corner -> single projection ->
//         original position), repeated until no face flips (reverted_vertices counts them). A
//         non-finite target leaves the vertex where it is; non-finite vertices are never moved.
//         Face and vertex normals are NOT updated: that is the caller's job
//         (vcg::tri::UpdateNormal<MeshType>::PerFaceNormalized / PerVertexNormalizedPerFace).
// Needs:  only the face-vertex lists (no VF/FF topology): a vertex -> face table is built by counting
//         sort.
// Cost:   O(V + F) plus O(1) math per vertex; each fall-back round only revisits the faces around the
//         vertices that moved back.
#ifndef PRIMITIVE_EDIT_SNAP_SEGMENTS_H
#define PRIMITIVE_EDIT_SNAP_SEGMENTS_H

#include "common/geometry/closest_point_on_intersection.h"
#include "common/geometry/closest_point_on_primitive.h"
#include "common/geometry/common_point_of_primitives.h"
#include "common/base/primitive.h"

#include <vcg/complex/complex.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
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
};

struct SnapReport
{
  int moved_vertices = 0, edge_vertices = 0, corner_vertices = 0, reverted_vertices = 0;
  double mean_displacement = 0, max_displacement = 0;
};

template <class MeshType>
SnapReport snap_segments(MeshType& m, const std::vector<int>& segment_of_face,
                         const std::vector<std::optional<Primitive>>& primitive_of_segment,
                         const SnapOptions& options = {})
{
  using CoordType = typename MeshType::CoordType;
  using ScalarType = typename MeshType::ScalarType;
  SnapReport report;
  const size_t nv = m.vert.size();
  const size_t nf = m.face.size();
  if (nv == 0 || nf == 0)
    return report;

  auto to_eigen = [](const CoordType& c) { return Eigen::Vector3d(double(c[0]), double(c[1]), double(c[2])); };
  auto to_coord = [](const Eigen::Vector3d& e) {
    return CoordType(ScalarType(e.x()), ScalarType(e.y()), ScalarType(e.z()));
  };
  // A finite double can still overflow a float coordinate.
  auto representable = [](const Eigen::Vector3d& e) {
    return e.allFinite() && e.cwiseAbs().maxCoeff() < double(std::numeric_limits<ScalarType>::max());
  };

  // Segments with identical primitives are one surface for the vertices they share: map every snapped
  // segment to a group of equal primitives (sorting keeps this O(S log S)).
  const int ns = static_cast<int>(primitive_of_segment.size());
  std::vector<int> group_of_segment(ns, -1);
  std::vector<const Primitive*> group_primitive;
  {
    auto key = [](const Primitive& q) {
      return std::make_tuple(int(q.type), q.origin.x(), q.origin.y(), q.origin.z(), q.axis.x(), q.axis.y(),
                             q.axis.z(), q.radius, q.minor_radius, q.half_angle);
    };
    std::vector<int> order;
    for (int s = 0; s < ns; ++s)
      if (primitive_of_segment[s] && primitive_is_valid(*primitive_of_segment[s]))
        order.push_back(s);
    std::sort(order.begin(), order.end(), [&](int x, int y) {
      return std::make_pair(key(*primitive_of_segment[x]), x) < std::make_pair(key(*primitive_of_segment[y]), y);
    });
    for (size_t i = 0; i < order.size(); ++i) {
      const Primitive& q = *primitive_of_segment[order[i]];
      if (i == 0 || key(q) != key(*primitive_of_segment[order[i - 1]]))
        group_primitive.push_back(&q);
      group_of_segment[order[i]] = static_cast<int>(group_primitive.size()) - 1;
    }
  }
  auto group_of_face = [&](size_t fi) {
    if (fi >= segment_of_face.size())
      return -1;
    const int s = segment_of_face[fi];
    return (s >= 0 && s < ns) ? group_of_segment[s] : -1;
  };

  // Vertex -> live faces, by counting sort (CSR); also the mean edge length for the automatic distance.
  std::vector<int> offset(nv + 1, 0);
  double edge_sum = 0;
  size_t edge_count = 0;
  for (size_t fi = 0; fi < nf; ++fi) {
    const auto& f = m.face[fi];
    if (f.IsD())
      continue;
    for (int j = 0; j < 3; ++j) {
      ++offset[vcg::tri::Index(m, f.cV(j)) + 1];
      const double len = double(vcg::Distance(f.cP(j), f.cP((j + 1) % 3)));
      if (std::isfinite(len)) {
        edge_sum += len;
        ++edge_count;
      }
    }
  }
  for (size_t v = 0; v < nv; ++v)
    offset[v + 1] += offset[v];
  std::vector<int> incident(static_cast<size_t>(offset[nv]));
  {
    std::vector<int> fill(offset.begin(), offset.end() - 1);
    for (size_t fi = 0; fi < nf; ++fi) {
      const auto& f = m.face[fi];
      if (f.IsD())
        continue;
      for (int j = 0; j < 3; ++j)
        incident[static_cast<size_t>(fill[vcg::tri::Index(m, f.cV(j))]++)] = static_cast<int>(fi);
    }
  }
  const double max_edge_distance =
      options.max_edge_distance > 0 ? options.max_edge_distance
                                    : (edge_count > 0 ? 5.0 * edge_sum / double(edge_count) : 0.0);

  // The distinct primitive groups of vertex v, sorted.
  auto gather = [&](size_t v, std::vector<int>& groups) {
    groups.clear();
    for (int i = offset[v]; i < offset[v + 1]; ++i) {
      const int g = group_of_face(static_cast<size_t>(incident[i]));
      if (g >= 0)
        groups.push_back(g);
    }
    std::sort(groups.begin(), groups.end());
    groups.erase(std::unique(groups.begin(), groups.end()), groups.end());
  };
  // Projection onto the nearest of the given primitives (used alone and as the fall-back of edges/corners).
  auto nearest_projection = [&](const std::vector<int>& groups, const Eigen::Vector3d& p) {
    PrimitiveProjection best = project_onto_primitive(*group_primitive[groups[0]], p);
    for (size_t i = 1; i < groups.size(); ++i) {
      const PrimitiveProjection pr = project_onto_primitive(*group_primitive[groups[i]], p);
      if (std::abs(pr.signed_distance) < std::abs(best.signed_distance))
        best = pr;
    }
    return best.point;
  };

  enum Kind : std::uint8_t { kUntouched, kSingle, kEdge, kCorner };
  // stage 0: at the target of its kind, 1: single projection (edges/corners only), 2: original position.
  std::vector<std::uint8_t> kind(nv, kUntouched), stage(nv, 2);
  std::vector<CoordType> original(nv);
  std::vector<int> groups;
  std::vector<const Primitive*> prims;
  std::vector<std::pair<double, int>> by_distance;
  for (size_t v = 0; v < nv; ++v) {
    original[v] = m.vert[v].cP();
    if (m.vert[v].IsD())
      continue;
    gather(v, groups);
    if (groups.empty())
      continue;
    const Eigen::Vector3d p = to_eigen(original[v]);
    if (!p.allFinite())
      continue;
    Eigen::Vector3d target;
    Kind k = kSingle;
    if (options.sharp_edges && groups.size() == 2 &&
        closest_point_on_intersection(*group_primitive[groups[0]], *group_primitive[groups[1]], p,
                                      max_edge_distance, target)) {
      k = kEdge;
    } else if (options.sharp_edges && groups.size() >= 3) {
      prims.clear();
      for (int g : groups)
        prims.push_back(group_primitive[g]);
      if (common_point_of_primitives(prims, p, max_edge_distance, target)) {
        k = kCorner;
      } else {
        by_distance.clear();
        for (int g : groups)
          by_distance.emplace_back(std::abs(signed_distance_to_primitive(*group_primitive[g], p)), g);
        std::partial_sort(by_distance.begin(), by_distance.begin() + 2, by_distance.end());
        if (closest_point_on_intersection(*group_primitive[by_distance[0].second],
                                          *group_primitive[by_distance[1].second], p, max_edge_distance, target))
          k = kEdge;
      }
    }
    if (k == kSingle)
      target = nearest_projection(groups, p);
    if (!representable(target))
      continue;
    kind[v] = k;
    stage[v] = 0;
    m.vert[v].P() = to_coord(target);
  }

  if (options.prevent_flips) {
    // A face is bad when its normal turned by more than 90 degrees or its area (nearly) vanished; faces
    // that had no normal to begin with (degenerate or non-finite) cannot flip.
    auto face_is_bad = [&](size_t fi) {
      const auto& f = m.face[fi];
      const size_t i0 = vcg::tri::Index(m, f.cV(0)), i1 = vcg::tri::Index(m, f.cV(1)),
                   i2 = vcg::tri::Index(m, f.cV(2));
      if (stage[i0] == 2 && stage[i1] == 2 && stage[i2] == 2)
        return false;
      const Eigen::Vector3d o0 = to_eigen(original[i0]);
      const Eigen::Vector3d before = (to_eigen(original[i1]) - o0).cross(to_eigen(original[i2]) - o0);
      const double before_norm = before.norm();
      if (!std::isfinite(before_norm) || before_norm <= 0)
        return false;
      const Eigen::Vector3d n0 = to_eigen(f.cP(0));
      const Eigen::Vector3d after = (to_eigen(f.cP(1)) - n0).cross(to_eigen(f.cP(2)) - n0);
      return !(before.dot(after) > 0) || !(after.norm() > 1e-3 * before_norm);
    };
    std::vector<int> candidates;
    for (size_t fi = 0; fi < nf; ++fi)
      if (!m.face[fi].IsD())
        candidates.push_back(static_cast<int>(fi));
    std::vector<std::uint8_t> reverted(nv, 0);
    std::vector<std::uint8_t> drop(nv, 0);
    std::vector<int> dropped;
    std::vector<int> face_mark(nf, -1);
    for (int round = 0; !candidates.empty(); ++round) {
      dropped.clear();
      for (int fi : candidates) {
        if (!face_is_bad(static_cast<size_t>(fi)))
          continue;
        // Fall back the most snapped vertex first (edge/corner before single), then the most displaced.
        const auto& f = m.face[static_cast<size_t>(fi)];
        int chosen = -1;
        std::pair<int, double> chosen_key(-1, 0.0);
        for (int j = 0; j < 3; ++j) {
          const size_t v = vcg::tri::Index(m, f.cV(j));
          if (stage[v] == 2)
            continue;
          const int level = (stage[v] == 0 && (kind[v] == kEdge || kind[v] == kCorner)) ? 1 : 0;
          const std::pair<int, double> key(level, double(vcg::Distance(f.cP(j), original[v])));
          if (chosen < 0 || key > chosen_key) {
            chosen = static_cast<int>(v);
            chosen_key = key;
          }
        }
        if (chosen >= 0 && !drop[static_cast<size_t>(chosen)]) {
          drop[static_cast<size_t>(chosen)] = 1;
          dropped.push_back(chosen);
        }
      }
      for (int vi : dropped) {
        const size_t v = static_cast<size_t>(vi);
        drop[v] = 0;
        reverted[v] = 1;
        if (stage[v] == 0 && (kind[v] == kEdge || kind[v] == kCorner)) {
          gather(v, groups);
          const Eigen::Vector3d target = nearest_projection(groups, to_eigen(original[v]));
          if (representable(target)) {
            stage[v] = 1;
            m.vert[v].P() = to_coord(target);
            continue;
          }
        }
        stage[v] = 2;
        m.vert[v].P() = original[v];
      }
      candidates.clear();
      for (int vi : dropped)
        for (int i = offset[static_cast<size_t>(vi)]; i < offset[static_cast<size_t>(vi) + 1]; ++i)
          if (face_mark[static_cast<size_t>(incident[i])] != round) {
            face_mark[static_cast<size_t>(incident[i])] = round;
            candidates.push_back(incident[i]);
          }
    }
    report.reverted_vertices = static_cast<int>(std::count(reverted.begin(), reverted.end(), std::uint8_t(1)));
  }

  double displacement_sum = 0;
  for (size_t v = 0; v < nv; ++v) {
    if (kind[v] == kUntouched || stage[v] == 2)
      continue;
    ++report.moved_vertices;
    if (stage[v] == 0 && kind[v] == kEdge)
      ++report.edge_vertices;
    if (stage[v] == 0 && kind[v] == kCorner)
      ++report.corner_vertices;
    const double d = (to_eigen(m.vert[v].cP()) - to_eigen(original[v])).norm();
    displacement_sum += d;
    report.max_displacement = std::max(report.max_displacement, d);
  }
  if (report.moved_vertices > 0)
    report.mean_displacement = displacement_sum / report.moved_vertices;
  return report;
}

} // namespace primitive_edit

#endif
