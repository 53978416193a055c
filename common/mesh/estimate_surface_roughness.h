// estimate_surface_roughness.h: a scan's roughness: its noise about local quadrics, or its waviness about local
// planes where that is smooth at the patch's scale.
//
// Input:  a vcg triangle mesh, or its face centroids and areas (face_centroids_and_areas.h; area <= 0: the
//         face takes no part) for a caller that has them already; its FaceAdjacency (face_adjacency.h); and
//         the patch size in faces (<= 0: automatic, max(60, F / 200): a fixed share of the surface, so that
//         the estimate does not depend on the resolution and sees noise correlated over more than a few
//         triangles, as a CT scan's is).
// Output: the surface's roughness at the scale of a patch, from patches grown breadth-first around up to 400
//         evenly spread faces, with the face centroids weighted by area:
//         noise    the lower quartile, over patches, of the RMS about the patch's least-squares quadric
//                  height field h = a u^2 + b uv + c v^2 + d u + e v + f over its PCA plane (u, v). A quadric
//                  follows a smooth surface's curvature at the patch's scale, so this is the noise on
//                  cylinders, spheres and cones as on planes (a plane's RMS grows with curvature: a patch of
//                  radius rho on a cylinder of radius R leaves about rho^2 / (6.7 R)); the lower quartile
//                  ignores patches that straddle an edge even where most do (a small part);
//         waviness the median, over the same patches, of the RMS about the patch's plane: it also holds noise
//                  correlated over more than the patch's curvature can follow, a CT scan's smooth waves,
//                  which a quadric absorbs but which a region's primitive will not.
//         roughness the waviness when it is within kMedianPatchSmoothRatio times the noise (the median patch
//                  is smooth: waves or gentle curvature), else the noise (the median patch straddles an edge).
//                  So curvature can raise it to at most 3 times the noise (before: without bound).
//         measure_surface_roughness returns all three, estimate_surface_roughness the roughness.
//         Faces that are deleted, degenerate or have non-finite coordinates take no part; 0 when no patch
//         of at least half the size (and 3 faces) exists.
//         Measured (bench/README.md, 400 patches of F / 200 faces): peer part 1M, vertex noise 0.05 along the
//         normal (centroid noise 0.029): noise 0.0292, waviness 0.177 (edges), returned 0.0292; the same part
//         without noise: 0; bracket CT scan 148k: noise 0.131, waviness 0.322, returned 0.322.
// Cost:   O(F) for the face centroids plus O(400 * patch size) divided by the threads.
#ifndef PRIMITIVE_EDIT_ESTIMATE_SURFACE_ROUGHNESS_H
#define PRIMITIVE_EDIT_ESTIMATE_SURFACE_ROUGHNESS_H

#include "common/base/huge_page_vector.h"
#include "common/base/parallel_for.h"
#include "common/mesh/face_adjacency.h"
#include "common/mesh/face_centroids_and_areas.h"
#include "common/geometry/weighted_pca.h"

#include <Eigen/Core>
#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace primitive_edit {

// A median plane RMS beyond this multiple of the quadric noise means the median patch straddles an edge.
constexpr double kMedianPatchSmoothRatio = 3.0;

// Weighted RMS of the points about their least-squares quadric height field over their PCA plane (pca: their
// weighted_pca); -1 when the patch has no plane (zero weight) or the normal equations are singular.
double quadric_patch_rms(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights, const WeightedPca& pca);

struct SurfaceRoughness
{
  double noise = 0, waviness = 0, roughness = 0;
};

namespace roughness_detail {

// A face that takes no part (area <= 0) holds this stamp.
constexpr int kUnusableFace = std::numeric_limits<int>::max();

// The patch of up to patch_faces faces grown breadth-first from a seed over faces whose stamp is below `mark`,
// stamping them `mark`. Stamps are the marks of earlier patches (a thread's marks increase) or kUnusableFace,
// so that one load tells both whether a face is usable and whether the patch has it.
void grow_patch(const FaceAdjacency& adj, int seed, int mark, int patch_faces, std::vector<int>& stamp,
                std::vector<int>& patch);

// The RMS about the patch's plane and about its quadric (NaN where there is none).
std::pair<double, double> patch_rms(const std::vector<Eigen::Vector3d>& centroid,
                                    const std::vector<double>& area, const std::vector<int>& patch);

// The usable faces (area > 0) of ranks (i * usable) / count, i = 0 .. count - 1, among the `usable` ones in
// index order: count faces spread evenly over the index range, found without listing every usable face.
std::vector<int> evenly_spread_faces(const std::vector<double>& area, std::size_t usable, std::size_t count);

} // namespace roughness_detail

SurfaceRoughness measure_surface_roughness(const std::vector<Eigen::Vector3d>& centroid,
                                           const std::vector<double>& area, const FaceAdjacency& adj,
                                           int patch_faces = 0, int threads = 0);

double estimate_surface_roughness(const std::vector<Eigen::Vector3d>& centroid, const std::vector<double>& area,
                                  const FaceAdjacency& adj, int patch_faces = 0, int threads = 0);

template <class MeshType>
double estimate_surface_roughness(const MeshType& m, const FaceAdjacency& adj, int patch_faces = 0)
{
  const FaceCentroidsAndAreas faces = face_centroids_and_areas(m);
  return estimate_surface_roughness(faces.centroid, faces.area, adj, patch_faces);
}

} // namespace primitive_edit

#endif
