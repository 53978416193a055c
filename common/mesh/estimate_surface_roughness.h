// estimate_surface_roughness.h: a scan's noise level, the RMS of its surface about local planes.
//
// Input:  a vcg triangle mesh, or its face centroids and areas (face_centroids_and_areas.h; area <= 0: the
//         face takes no part) for a caller that has them already; its FaceAdjacency (face_adjacency.h); and
//         the patch size in faces (<= 0: automatic, max(60, F / 200): a fixed share of the surface, so that
//         the estimate does not depend on the resolution and sees noise correlated over more than a few
//         triangles, as a CT scan's is).
// Output: the median, over patches grown breadth-first around up to 400 evenly spread faces, of the RMS
//         distance of the patch's face centroids (weighted by area) from their least-squares plane. Most of
//         a scan is smooth at the scale of a patch, so the median is the noise rather than the curvature.
//         Faces that are deleted, degenerate or have non-finite coordinates take no part; 0 when no patch
//         of at least half the size (and 3 faces) exists.
// Cost:   O(F) for the face centroids plus O(400 * patch size).
#ifndef PRIMITIVE_EDIT_ESTIMATE_SURFACE_ROUGHNESS_H
#define PRIMITIVE_EDIT_ESTIMATE_SURFACE_ROUGHNESS_H

#include "common/mesh/face_adjacency.h"
#include "common/mesh/face_centroids_and_areas.h"
#include "common/geometry/weighted_pca.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <vector>

namespace primitive_edit {

inline double estimate_surface_roughness(const std::vector<Eigen::Vector3d>& centroid, const std::vector<double>& area,
                                         const FaceAdjacency& adj, int patch_faces = 0)
{
  const std::size_t n = centroid.size();
  if (area.size() != n || adj.face_count() != int(n) || n == 0)
    return 0.0;
  std::vector<int> usable_faces;
  for (std::size_t f = 0; f < n; ++f)
    if (area[f] > 0)
      usable_faces.push_back(int(f));
  if (patch_faces <= 0)
    patch_faces = std::max(60, int(usable_faces.size() / 200));

  const std::size_t seeds = std::min<std::size_t>(400, usable_faces.size());
  std::vector<int> stamp(n, -1), patch;
  std::vector<double> rms;
  for (std::size_t i = 0; i < seeds; ++i) {
    const int seed = usable_faces[(i * usable_faces.size()) / seeds];
    patch.assign(1, seed);
    stamp[std::size_t(seed)] = int(i);
    for (std::size_t head = 0; head < patch.size() && int(patch.size()) < patch_faces; ++head) {
      const int f = patch[head];
      for (int k = adj.offset[std::size_t(f)]; k < adj.offset[std::size_t(f) + 1] && int(patch.size()) < patch_faces;
           ++k) {
        const int h = adj.neighbour[std::size_t(k)];
        if (stamp[std::size_t(h)] != int(i) && area[std::size_t(h)] > 0) {
          stamp[std::size_t(h)] = int(i);
          patch.push_back(h);
        }
      }
    }
    if (int(patch.size()) < std::max(3, patch_faces / 2))
      continue;
    Eigen::MatrixX3d points(Eigen::Index(patch.size()), 3);
    Eigen::VectorXd weights(Eigen::Index(patch.size()));
    for (std::size_t j = 0; j < patch.size(); ++j) {
      points.row(Eigen::Index(j)) = centroid[std::size_t(patch[j])].transpose();
      weights[Eigen::Index(j)] = area[std::size_t(patch[j])];
    }
    const WeightedPca pca = weighted_pca(points, weights);
    if (pca.ok && std::isfinite(pca.eigenvalues[0]))
      rms.push_back(std::sqrt(std::max(0.0, pca.eigenvalues[0])));
  }
  if (rms.empty())
    return 0.0;
  std::nth_element(rms.begin(), rms.begin() + std::ptrdiff_t(rms.size() / 2), rms.end());
  return rms[rms.size() / 2];
}

template <class MeshType>
double estimate_surface_roughness(const MeshType& m, const FaceAdjacency& adj, int patch_faces = 0)
{
  const FaceCentroidsAndAreas faces = face_centroids_and_areas(m);
  return estimate_surface_roughness(faces.centroid, faces.area, adj, patch_faces);
}

} // namespace primitive_edit

#endif
