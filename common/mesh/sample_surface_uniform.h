// sample_surface_uniform.h: N random points spread uniformly by area over a triangle mesh (Monte Carlo).
//
// Input:  any vcg triangle mesh, the number of samples N >= 1 and a seed. Deleted faces, faces with a
//         NaN/infinite vertex coordinate and zero-area faces are skipped (they carry no area).
// Output: *samples, an N x 3 matrix of points (double). Each sample picks a face with probability proportional to
//         its area, then a uniform point inside it. The same mesh, N and seed give the same points on every
//         platform (std::mt19937_64 and our own bits-to-double mapping, no std:: distributions).
//         Optionally the face index (vcg::tri::Index) of each sample. On failure (N < 1, no face with
//         area) a failure saying why, and *samples empty.
// Cost:   O(F + N log F) time, O(F) memory besides the output.
#ifndef PRIMITIVE_EDIT_SAMPLE_SURFACE_UNIFORM_H
#define PRIMITIVE_EDIT_SAMPLE_SURFACE_UNIFORM_H

#include "common/base/status.h"

#include <vcg/complex/complex.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace primitive_edit {

namespace detail {

// A double uniform in [0, 1) from the top 53 bits: the same on every standard library.
inline double unit_uniform(std::mt19937_64& rng)
{
  return double(rng() >> 11) * (1.0 / 9007199254740992.0);
}

} // namespace detail

template <class MeshType>
Status sample_surface_uniform(const MeshType& mesh, Eigen::Index count, std::uint64_t seed,
                              Eigen::MatrixX3d* samples, Eigen::VectorXi* sample_faces = nullptr)
{
  auto fail = [&](std::string why) {
    samples->resize(0, 3);
    if (sample_faces != nullptr)
      sample_faces->resize(0);
    return Status::failure(std::move(why));
  };
  if (count < 1)
    return fail("the number of samples must be at least 1");

  // Cumulative areas of the usable faces, so that a uniform number in [0, total) picks a face by area.
  std::vector<double> cumulative;
  std::vector<int> face_index;
  std::vector<Eigen::Matrix3d> corners;  // columns are the three vertices
  double total = 0.0;
  for (const auto& f : mesh.face) {
    if (f.IsD())
      continue;
    Eigen::Matrix3d c;
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i)
        c(i, k) = double(f.cV(k)->cP()[i]);
    if (!c.allFinite())
      continue;
    const double area = 0.5 * (c.col(1) - c.col(0)).cross(c.col(2) - c.col(0)).norm();
    if (!(area > 0.0) || !std::isfinite(area))
      continue;
    total += area;
    cumulative.push_back(total);
    face_index.push_back(int(vcg::tri::Index(mesh, f)));
    corners.push_back(c);
  }
  if (cumulative.empty())
    return fail(mesh.fn == 0 ? "the mesh has no faces"
                              : "the mesh has no face with a positive, finite area to sample");
  if (!std::isfinite(total))
    return fail("the total surface area overflows");

  std::mt19937_64 rng(seed);
  samples->resize(count, 3);
  if (sample_faces != nullptr)
    sample_faces->resize(count);
  for (Eigen::Index s = 0; s < count; ++s) {
    const double pick = detail::unit_uniform(rng) * total;
    // upper_bound: the first face whose cumulative area exceeds `pick`; min() guards rounding at the end.
    const size_t j = std::min(size_t(std::upper_bound(cumulative.begin(), cumulative.end(), pick) -
                                     cumulative.begin()),
                              cumulative.size() - 1);
    double a = detail::unit_uniform(rng);
    double b = detail::unit_uniform(rng);
    if (a + b > 1.0) {  // fold the parallelogram's far half back onto the triangle
      a = 1.0 - a;
      b = 1.0 - b;
    }
    const Eigen::Matrix3d& c = corners[j];
    samples->row(s) = (c.col(0) + a * (c.col(1) - c.col(0)) + b * (c.col(2) - c.col(0))).transpose();
    if (sample_faces != nullptr)
      (*sample_faces)(s) = face_index[j];
  }
  return Status::success();
}

} // namespace primitive_edit

#endif
