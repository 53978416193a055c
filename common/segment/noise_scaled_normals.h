// noise_scaled_normals.h: face normals averaged as much as a scan's noise needs, and the faces where they turn
// as across an edge, for the normal-angle segmentation (segment_by_normal_angle.h) of noisy meshes.
//
// Input:  a vcg triangle mesh, its FaceAdjacency, the segmentation angle in degrees, and the threads
//         (parallel_for.h; <= 0: all).
// Output: the passes used, the smoothed unit normal of every face (smooth_face_normals.h, zero where undefined),
//         the noise measured, and a flag per face: 1 on an edge face. passes is 0, and no face an edge face,
//         when the noise does not call for more than kPaperSmoothingPasses passes: the caller then keeps the
//         paper's method.
// Method: 1. the noise: measure_surface_roughness's noise about local quadrics on patches of kNoisePatchFaces
//            faces (a scan's smooth waves, which tilt the faces little, do not count), or the median distance
//            of a face's neighbours from its plane when that is less (a CAD mesh of planes between sharp edges:
//            0, even when it is too small for a patch to fit in one side), against the mean triangle size
//            h = sqrt(mean face area); a face normal scatters by about noise / h radians, and passes =
//            kNoisePassesPerSquaredRatio * (noise / h)^2, at most kMaxNoisePasses.
//         2. passes of area-weighted averaging over all neighbours: the noise averages away, and every edge
//            becomes a ramp a few rings wide across which the normal turns gradually, so that the fill's
//            neighbour test alone would walk across it (crease-gated averaging cannot help: each face's own
//            normal is off by tens of degrees, more than the crease).
//         3. after n passes the averaging is about a Gaussian of standard deviation sqrt(3 n / 8) face steps
//            (each pass takes a face and its 3 neighbours), so across the ramp of an edge of the segmentation
//            angle A the normal turns by at most A / sqrt(3 pi n / 4) per face step. A face that turns by more
//            than that against one of its neighbours is an edge face: the fill does not enter it, so that it
//            cannot creep along a ramp either, and such faces are handed to the segments later
//            (assign_edge_faces.h). A surface curved so tightly that it turns that fast between faces (radius
//            below about 4 * sqrt(passes) * h at 20 degrees) is taken for an edge too: on the peer part with
//            noise 0.1 mm (73 passes) its holes of radius 3.5 mm.
// Cost:   O(F + adjacency size) for the noise (400 patches and the neighbours' distances), O(passes * (F +
//         adjacency size)) divided by the threads for the averaging, O(F + adjacency size) for the edge faces;
//         O(F) memory.
#ifndef PRIMITIVE_EDIT_NOISE_SCALED_NORMALS_H
#define PRIMITIVE_EDIT_NOISE_SCALED_NORMALS_H

#include "common/base/constants.h"
#include "common/mesh/estimate_surface_roughness.h"
#include "common/mesh/face_adjacency.h"
#include "common/mesh/face_centroids_and_areas.h"
#include "common/mesh/smooth_face_normals.h"

#include <Eigen/Core>
#include <vcg/complex/complex.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace primitive_edit {

// The paper's few passes of crease-gated averaging, for meshes without measurable noise.
constexpr int kPaperSmoothingPasses = 2;
// The noise that tilts face normals is measured on patches of a few rings: a quadric there follows a CT scan's
// smooth waves (bracket scan: 0.013 mm against 0.131 on the default patches of F / 200 faces), not the white
// noise of a vertex (peer part: 0.020 against 0.029).
constexpr int kNoisePatchFaces = 60;
// Passes per (noise / h)^2: the peer part (1M faces, noise / h = 0.23 on such patches) gives 12 of 12 surfaces
// from 14 to 60 passes, and this takes about twice the fewest (26).
constexpr double kNoisePassesPerSquaredRatio = 500.0;
// Beyond this the averaging would cost more than the rest of the segmentation many times over.
constexpr int kMaxNoisePasses = 400;

struct NoiseScaledNormals
{
  int passes = 0;
  double noise = 0;
  std::vector<Eigen::Vector3d> normal;
  std::vector<char> edge_face;
};

// The passes the noise calls for (0: no more than the paper's).
int noise_smoothing_passes(double noise, double mean_face_area);

// The turn between neighbouring faces, in degrees, beyond which a face lies on an edge after `passes` passes.
double edge_turn_deg(double angle_deg, int passes);

// The median, over faces, of the RMS distance of a face's neighbours' centroids from its plane: 0 on a mesh
// whose surfaces are planes between sharp edges (most faces lie flat among their neighbours), however small;
// there a quadric patch of kNoisePatchFaces faces may find no side large enough and read the edges as noise.
double median_ring_plane_residual(const FaceCentroidsAndAreas& faces, const std::vector<Eigen::Vector3d>& raw,
                                  const FaceAdjacency& adj);

template <class MeshType>
NoiseScaledNormals noise_scaled_normals(const MeshType& m, const FaceAdjacency& adj, double angle_deg, int threads = 0)
{
  NoiseScaledNormals out;
  std::vector<Eigen::Vector3d> raw;
  const FaceCentroidsAndAreas faces = face_centroids_and_areas(m, threads, &raw);
  double area_sum = 0;
  int usable = 0;
  for (double a : faces.area)
    if (a > 0) {
      area_sum += a;
      ++usable;
    }
  const double quadric = measure_surface_roughness(faces.centroid, faces.area, adj, kNoisePatchFaces, threads).noise;
  out.noise = std::min(quadric, median_ring_plane_residual(faces, raw, adj));
  out.passes = usable > 0 ? noise_smoothing_passes(out.noise, area_sum / usable) : 0;
  out.edge_face.assign(m.face.size(), 0);
  if (out.passes == 0)
    return out;
  out.normal = smooth_face_normals(std::move(raw), faces.area, adj, out.passes, 180.0, threads);
  const double min_cos = std::cos(radians_from_degrees(edge_turn_deg(angle_deg, out.passes)));
  for (std::size_t f = 0; f < m.face.size(); ++f)
    for (int k = adj.offset[f]; k < adj.offset[f + 1]; ++k)
      if (out.normal[f].dot(out.normal[std::size_t(adj.neighbour[std::size_t(k)])]) < min_cos) {
        out.edge_face[f] = 1;
        break;
      }
  return out;
}

} // namespace primitive_edit

#endif
