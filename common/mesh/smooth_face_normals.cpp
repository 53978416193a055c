#include "common/mesh/smooth_face_normals.h"

#include "common/base/constants.h"
#include "common/base/huge_page_vector.h"
#include "common/base/parallel_for.h"

#include <cmath>
#include <cstddef>
#include <type_traits>

namespace primitive_edit {

std::vector<Eigen::Vector3d> smooth_face_normals(std::vector<Eigen::Vector3d> normal, const std::vector<double>& area,
                                                 const FaceAdjacency& adj, int iterations, double crease_angle_deg,
                                                 int threads)
{
  const std::size_t face_count = normal.size();
  if (iterations <= 0 || int(face_count) != adj.face_count() || area.size() != face_count)
    return normal;

  const bool gated = crease_angle_deg < 180.0;
  const double min_cos = std::cos(radians_from_degrees(crease_angle_deg));
  std::vector<Eigen::Vector3d> next = huge_page_vector<Eigen::Vector3d>(face_count);
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
