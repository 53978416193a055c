// test_fit_data.h: synthetic samples of primitives for the fit tests and benchmark: points with exact
// outward normals on a (partial) patch, Gaussian noise, perturbed normals and outliers, seeded. Also the
// primitive makers (make_plane ...) and distance_to_line, which the fit and snap tests share.
#ifndef PRIMITIVE_EDIT_TEST_FIT_DATA_H
#define PRIMITIVE_EDIT_TEST_FIT_DATA_H

#include "common/base/constants.h"
#include "common/geometry/closest_point_on_primitive.h"
#include "common/base/primitive.h"

#include <Eigen/Geometry>

#include <cmath>
#include <random>

namespace test_fit {

using primitive_edit::Primitive;
using primitive_edit::PrimitiveType;

struct Sample
{
  Eigen::MatrixX3d points, normals;
};

// Patch of a primitive: u in [0, 1) spans `sweep` radians around the axis (for planes: x in [-1, 1] * extent),
// v in [0, 1) spans the other direction: height for cylinders, [near, far] apex distance along the axis
// for cones, polar angle [0, cap] for spheres, the full tube for tori.
struct Patch
{
  double sweep = 2 * primitive_edit::kPi;
  double extent = 1.0;      // plane half size, cylinder height
  double cap = primitive_edit::kPi;  // sphere: polar angle of the cap
  double near = 1.0, far = 2.0;  // cone: axial distances of the frustum
};

inline Sample sample_primitive(const Primitive& p, const Patch& patch, int n, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const Eigen::Vector3d a = p.axis.normalized();
  const Eigen::Vector3d e1 = primitive_edit::any_orthogonal(a), e2 = a.cross(e1);
  Sample s;
  s.points.resize(n, 3);
  s.normals.resize(n, 3);
  for (int i = 0; i < n; ++i) {
    const double u = U(rng), v = U(rng);
    const double phi = u * patch.sweep;
    const Eigen::Vector3d radial = std::cos(phi) * e1 + std::sin(phi) * e2;
    Eigen::Vector3d x = Eigen::Vector3d::Zero(), nrm = a;
    switch (p.type) {
    case PrimitiveType::Plane:
      x = p.origin + (2 * u - 1) * patch.extent * e1 + (2 * v - 1) * patch.extent * e2;
      nrm = a;
      break;
    case PrimitiveType::Sphere: {
      // Uniform on the cap: cos(theta) uniform in [cos(cap), 1].
      const double ct = 1 - v * (1 - std::cos(patch.cap)), st = std::sqrt(std::max(0.0, 1 - ct * ct));
      nrm = ct * a + st * radial;
      x = p.origin + p.radius * nrm;
      break;
    }
    case PrimitiveType::Cylinder:
      nrm = radial;
      x = p.origin + (v - 0.5) * patch.extent * a + p.radius * radial;
      break;
    case PrimitiveType::Cone: {
      const double h = patch.near + v * (patch.far - patch.near);
      x = p.origin + h * a + h * std::tan(p.half_angle) * radial;
      nrm = -std::sin(p.half_angle) * a + std::cos(p.half_angle) * radial;
      break;
    }
    case PrimitiveType::Torus: {
      const double t = 2 * primitive_edit::kPi * v;
      nrm = std::cos(t) * radial + std::sin(t) * a;
      x = p.origin + p.radius * radial + p.minor_radius * nrm;
      break;
    }
    }
    s.points.row(i) = x.transpose();
    s.normals.row(i) = nrm.normalized().transpose();
  }
  return s;
}

// Gaussian noise of standard deviation sigma on every coordinate; normals tilted by about `degrees`.
inline void add_noise(Sample* s, double sigma, double degrees, unsigned seed)
{
  std::mt19937 rng(seed);
  std::normal_distribution<double> N(0.0, 1.0);
  const double tilt = primitive_edit::radians_from_degrees(degrees);
  for (Eigen::Index i = 0; i < s->points.rows(); ++i) {
    s->points.row(i) += sigma * Eigen::RowVector3d(N(rng), N(rng), N(rng));
    const Eigen::Vector3d n = s->normals.row(i).transpose();
    const Eigen::Vector3d t1 = primitive_edit::any_orthogonal(n), t2 = n.cross(t1);
    const Eigen::Vector3d tilted = n + tilt * (N(rng) * t1 + N(rng) * t2) / std::sqrt(2.0);
    s->normals.row(i) = tilted.normalized().transpose();
  }
}

// Moves a fraction of the points (every k-th) by a random offset of length in [lo, hi].
inline void add_outliers(Sample* s, double fraction, double lo, double hi, unsigned seed)
{
  std::mt19937 rng(seed);
  std::normal_distribution<double> N(0.0, 1.0);
  std::uniform_real_distribution<double> U(lo, hi);
  const int step = static_cast<int>(std::lround(1.0 / fraction));
  for (Eigen::Index i = 0; i < s->points.rows(); i += step) {
    const Eigen::Vector3d d = Eigen::Vector3d(N(rng), N(rng), N(rng)).normalized();
    s->points.row(i) += U(rng) * d.transpose();
  }
}

inline Primitive make_plane(Eigen::Vector3d origin, Eigen::Vector3d normal)
{
  Primitive p;
  p.type = PrimitiveType::Plane;
  p.origin = origin;
  p.axis = normal.normalized();
  return p;
}

inline Primitive make_sphere(Eigen::Vector3d centre, double r)
{
  Primitive p;
  p.type = PrimitiveType::Sphere;
  p.origin = centre;
  p.radius = r;
  return p;
}

inline Primitive make_cylinder(Eigen::Vector3d origin, Eigen::Vector3d axis, double r)
{
  Primitive p;
  p.type = PrimitiveType::Cylinder;
  p.origin = origin;
  p.axis = axis.normalized();
  p.radius = r;
  return p;
}

inline Primitive make_cone(Eigen::Vector3d apex, Eigen::Vector3d axis, double half_angle)
{
  Primitive p;
  p.type = PrimitiveType::Cone;
  p.origin = apex;
  p.axis = axis.normalized();
  p.half_angle = half_angle;
  return p;
}

inline Primitive make_torus(Eigen::Vector3d centre, Eigen::Vector3d axis, double major, double minor)
{
  Primitive p;
  p.type = PrimitiveType::Torus;
  p.origin = centre;
  p.axis = axis.normalized();
  p.radius = major;
  p.minor_radius = minor;
  return p;
}

inline double distance_to_line(const Eigen::Vector3d& p, const Eigen::Vector3d& origin, const Eigen::Vector3d& axis)
{
  const Eigen::Vector3d v = p - origin;
  return (v - v.dot(axis) * axis).norm();
}

} // namespace test_fit

#endif
