// smooth_face_normals.h: face normals from the geometry, denoised by area-weighted averaging over neighbours.
//
// Input:  a vcg triangle mesh, its FaceAdjacency, a number of smoothing passes, optionally a crease angle and
//         the threads (parallel_for.h; <= 0: all).
//         Stored normals are ignored: scans often carry stale or per-vertex-interpolated ones.
// Output: one unit normal per face (indexed by vcg::tri::Index), or the zero vector for deleted faces and
//         for faces whose normal is undefined (zero area, NaN/Inf coordinates) with no usable neighbour.
//         Each pass replaces a face's normal by the normalised area-weighted sum of its own normal and its
//         neighbours' normals. Zero normals (zero area, NaN) contribute nothing. A neighbour whose current
//         normal differs from the face's by crease_angle_deg or more is left out, so that averaging removes
//         noise without rounding sharp edges away (the default 180 averages every neighbour). A pass reads
//         only the previous pass's normals, so the result does not depend on the thread count.
// Complexity: O(iterations * (F + adjacency size)) time divided by the threads, O(F) memory.
#ifndef PRIMITIVE_EDIT_SMOOTH_FACE_NORMALS_H
#define PRIMITIVE_EDIT_SMOOTH_FACE_NORMALS_H

#include "common/base/constants.h"
#include "common/base/huge_page_vector.h"
#include "common/base/parallel_for.h"
#include "common/mesh/face_adjacency.h"

#include <Eigen/Core>
#include <vcg/complex/complex.h>

#include <cmath>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace primitive_edit {

template <class MeshType>
std::vector<Eigen::Vector3d> smooth_face_normals(const MeshType& m, const FaceAdjacency& adj, int iterations,
                                                 double crease_angle_deg = 180.0, int threads = 0)
{
  const std::size_t face_count = m.face.size();
  std::vector<Eigen::Vector3d> normal = huge_page_vector(face_count, Eigen::Vector3d(Eigen::Vector3d::Zero()));
  std::vector<double> area = huge_page_vector(face_count, 0.0);
  for (std::size_t f = 0; f < face_count; ++f) {
    const auto& face = m.face[f];
    if (face.IsD() || face.cV(0) == nullptr || face.cV(1) == nullptr || face.cV(2) == nullptr)
      continue;
    const Eigen::Vector3d p0(double(face.cP(0)[0]), double(face.cP(0)[1]), double(face.cP(0)[2]));
    const Eigen::Vector3d p1(double(face.cP(1)[0]), double(face.cP(1)[1]), double(face.cP(1)[2]));
    const Eigen::Vector3d p2(double(face.cP(2)[0]), double(face.cP(2)[1]), double(face.cP(2)[2]));
    const Eigen::Vector3d n = (p1 - p0).cross(p2 - p0);
    const double length = n.norm();
    if (!std::isfinite(length) || length <= 0.0)
      continue;
    normal[f] = n / length;
    area[f] = 0.5 * length;
  }
  if (iterations <= 0 || int(face_count) != adj.face_count())
    return normal;

  const bool gated = crease_angle_deg < 180.0;
  const double min_cos = std::cos(radians_from_degrees(crease_angle_deg));
  std::vector<Eigen::Vector3d> next = huge_page_vector<Eigen::Vector3d>(face_count);
  // Below this many faces a second thread costs more than it saves.
  constexpr std::size_t kFacesPerThread = 20000;
  // The crease test is a template argument, so that the ungated passes (the segmentation's) have no test at all.
  auto smooth = [&](auto gate) {
    constexpr bool kGated = decltype(gate)::value;
    parallel_for(face_count, threads, kFacesPerThread, [&](std::size_t begin, std::size_t end) {
      for (std::size_t f = begin; f < end; ++f) {
        const Eigen::Vector3d& own = normal[f];
        const bool has_own = kGated && !own.isZero(0.0);
        Eigen::Vector3d sum = area[f] * own;
        for (int i = adj.offset[f]; i < adj.offset[f + 1]; ++i) {
          const std::size_t g = std::size_t(adj.neighbour[std::size_t(i)]);
          if (kGated && has_own && own.dot(normal[g]) <= min_cos)
            continue;
          sum += area[g] * normal[g];
        }
        const double length = sum.norm();
        if (std::isfinite(length) && length > 0.0)
          next[f] = sum / length;
        else
          next[f] = own;
      }
    });
  };
  for (int pass = 0; pass < iterations; ++pass) {
    if (gated)
      smooth(std::true_type());
    else
      smooth(std::false_type());
    normal.swap(next);
  }
  return normal;
}

} // namespace primitive_edit

#endif
