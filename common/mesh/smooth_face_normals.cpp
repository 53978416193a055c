#include "common/mesh/smooth_face_normals.h"

#include "common/base/constants.h"
#include "common/base/huge_page_vector.h"
#include "common/base/parallel_for.h"

#include <cmath>
#include <cstddef>

namespace primitive_edit {

namespace {

// The ungated passes (the segmentation's) keep each face's normal multiplied by its area, as every sum takes
// it: a neighbour is then one load of 24 bytes rather than a normal and an area from two arrays (the passes
// are bound by those loads). Each product is the one the sum formed before, so the normals are the same bits.
void smooth_weighted(std::vector<Eigen::Vector3d>& normal, std::vector<Eigen::Vector3d>& next,
                     const std::vector<double>& area, const FaceAdjacency& adj, int iterations, int threads)
{
  const std::size_t face_count = normal.size();
  parallel_for(face_count, threads, kFacesPerThread, [&](std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f)
      normal[f] = area[f] * normal[f];
  });
  for (int pass = 0; pass < iterations; ++pass) {
    const bool last = pass + 1 == iterations;
    parallel_for(face_count, threads, kFacesPerThread, [&](std::size_t begin, std::size_t end) {
      for (std::size_t f = begin; f < end; ++f) {
        Eigen::Vector3d sum = normal[f];
        for (int i = adj.offset[f]; i < adj.offset[f + 1]; ++i)
          sum += normal[std::size_t(adj.neighbour[std::size_t(i)])];
        const double length = sum.norm();
        if (std::isfinite(length) && length > 0.0) {
          const Eigen::Vector3d unit = sum / length;
          next[f] = last ? unit : Eigen::Vector3d(area[f] * unit);
        } else {
          // The face keeps its normal: its weighted one, or on the last pass that over its area.
          next[f] = !last ? normal[f] : area[f] > 0.0 ? Eigen::Vector3d(normal[f] / area[f]) : Eigen::Vector3d::Zero();
        }
      }
    });
    normal.swap(next);
  }
}

// A neighbour whose normal differs from the face's by the crease angle or more is left out.
void smooth_gated(std::vector<Eigen::Vector3d>& normal, std::vector<Eigen::Vector3d>& next,
                  const std::vector<double>& area, const FaceAdjacency& adj, int iterations, double min_cos,
                  int threads)
{
  const std::size_t face_count = normal.size();
  for (int pass = 0; pass < iterations; ++pass) {
    parallel_for(face_count, threads, kFacesPerThread, [&](std::size_t begin, std::size_t end) {
      for (std::size_t f = begin; f < end; ++f) {
        const Eigen::Vector3d& own = normal[f];
        const bool has_own = !own.isZero(0.0);
        Eigen::Vector3d sum = area[f] * own;
        for (int i = adj.offset[f]; i < adj.offset[f + 1]; ++i) {
          const std::size_t g = std::size_t(adj.neighbour[std::size_t(i)]);
          if (has_own && own.dot(normal[g]) <= min_cos)
            continue;
          sum += area[g] * normal[g];
        }
        const double length = sum.norm();
        next[f] = std::isfinite(length) && length > 0.0 ? Eigen::Vector3d(sum / length) : own;
      }
    });
    normal.swap(next);
  }
}

} // namespace

std::vector<Eigen::Vector3d> smooth_face_normals(std::vector<Eigen::Vector3d> normal, const std::vector<double>& area,
                                                 const FaceAdjacency& adj, int iterations, double crease_angle_deg,
                                                 int threads)
{
  const std::size_t face_count = normal.size();
  if (iterations <= 0 || int(face_count) != adj.face_count() || area.size() != face_count)
    return normal;

  std::vector<Eigen::Vector3d> next = huge_page_vector<Eigen::Vector3d>(face_count);
  if (crease_angle_deg < 180.0)
    smooth_gated(normal, next, area, adj, iterations, std::cos(radians_from_degrees(crease_angle_deg)), threads);
  else
    smooth_weighted(normal, next, area, adj, iterations, threads);
  return normal;
}

} // namespace primitive_edit
