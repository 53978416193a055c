// test_segment_samples.h: segments' samples the relation and blend tests share: a surface of revolution swept from
// its meridian profile, with noise, and a segment's own automatic fit.
#ifndef PRIMITIVE_EDIT_TEST_SEGMENT_SAMPLES_H
#define PRIMITIVE_EDIT_TEST_SEGMENT_SAMPLES_H

#include "common/base/constants.h"
#include "common/fit/fit_primitive_auto.h"
#include "common/geometry/closest_point_on_primitive.h"
#include "common/mesh/gather_segment_samples.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <random>

namespace test_segments {

using primitive_edit::SegmentSamples;

// n points of the surface swept about (point, axis) by profile(u) = (r, h), u in [0, 1), through `turn` of a full
// turn, with Gaussian noise of sigma along the profile's unit normal (r, h) -> normal(u); the weights share `area`.
inline SegmentSamples revolved(const Eigen::Vector3d& point, const Eigen::Vector3d& axis,
                               const std::function<Eigen::Vector2d(double)>& profile,
                               const std::function<Eigen::Vector2d(double)>& normal, int n, double sigma,
                               unsigned seed, double area = 1, double turn = 1)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::normal_distribution<double> N(0.0, 1.0);
  const Eigen::Vector3d e1 = axis.unitOrthogonal(), e2 = axis.cross(e1);
  SegmentSamples s;
  s.points.resize(n, 3);
  s.normals.resize(n, 3);
  for (int i = 0; i < n; ++i) {
    const double u = U(rng), phi = 2 * primitive_edit::kPi * turn * U(rng), e = sigma * N(rng);
    const Eigen::Vector2d rh = profile(u) + e * normal(u);
    const Eigen::Vector3d radial = std::cos(phi) * e1 + std::sin(phi) * e2;
    s.points.row(i) = (point + rh.y() * axis + rh.x() * radial).transpose();
    s.normals.row(i) = (normal(u).x() * radial + normal(u).y() * axis).transpose();
  }
  s.area = area;
  s.weights = Eigen::VectorXd::Constant(n, area / n);
  return s;
}

// The largest distance of the samples from p.
inline double max_distance(const primitive_edit::Primitive& p, const SegmentSamples& s)
{
  double worst = 0;
  for (Eigen::Index i = 0; i < s.points.rows(); ++i)
    worst = std::max(worst,
                     std::abs(primitive_edit::project_onto_primitive(p, s.points.row(i).transpose()).signed_distance));
  return worst;
}

// The distance of x from the line through point along the unit axis.
inline double distance_from_axis(const Eigen::Vector3d& x, const Eigen::Vector3d& point, const Eigen::Vector3d& axis)
{
  const Eigen::Vector3d d = x - point;
  return (d - d.dot(axis) * axis).norm();
}

// The segment's own automatic fit, as Fit All gives it with the scan's roughness; std::nullopt when free-form.
inline std::optional<primitive_edit::Primitive> auto_fit_or_none(const SegmentSamples& s, double roughness)
{
  primitive_edit::AutoFitOptions options;
  options.roughness = roughness;
  const primitive_edit::AutoFitResult r = primitive_edit::fit_primitive_auto(s.points, s.normals, s.weights, options);
  return r.status.ok() ? std::optional<primitive_edit::Primitive>(r.best.primitive) : std::nullopt;
}

} // namespace test_segments

#endif
