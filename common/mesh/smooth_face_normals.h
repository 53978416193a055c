// smooth_face_normals.h: face normals from the geometry, denoised by area-weighted averaging over neighbours.
//
// Input:  a vcg triangle mesh, or its faces' unit normals and areas (face_centroids_and_areas.h) for a caller that
//         has them already; its FaceAdjacency, a number of smoothing passes, optionally a crease angle and the
//         threads (parallel_for.h; <= 0: all).
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

#include "common/mesh/face_adjacency.h"
#include "common/mesh/face_centroids_and_areas.h"

#include <Eigen/Core>

#include <utility>
#include <vector>

namespace primitive_edit {

// The passes over unit normals (zero: undefined) weighted by the faces' areas; `normal` is taken by value so that
// a caller done with it gives it up.
std::vector<Eigen::Vector3d> smooth_face_normals(std::vector<Eigen::Vector3d> normal, const std::vector<double>& area,
                                                 const FaceAdjacency& adj, int iterations,
                                                 double crease_angle_deg = 180.0, int threads = 0);

template <class MeshType>
std::vector<Eigen::Vector3d> smooth_face_normals(const MeshType& m, const FaceAdjacency& adj, int iterations,
                                                 double crease_angle_deg = 180.0, int threads = 0)
{
  std::vector<Eigen::Vector3d> normal;
  const std::vector<double> area = face_centroids_and_areas(m, threads, &normal).area;
  return smooth_face_normals(std::move(normal), area, adj, iterations, crease_angle_deg, threads);
}

} // namespace primitive_edit

#endif
