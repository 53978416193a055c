// plate_with_hole.h: a test part for snapping: a 10 x 10 x 4 plate with a through hole of radius 2, its
// rims chamfered by 0.15 (the blurred edges of a scan), optionally noisy. Seven CAD faces: top (label 0),
// bottom (1), hole (2), sides +x, +y, -x, -y (3-6), with their exact primitives.
#ifndef PRIMITIVE_EDIT_TEST_PLATE_WITH_HOLE_H
#define PRIMITIVE_EDIT_TEST_PLATE_WITH_HOLE_H

#include "common/base/constants.h"
#include "common/base/primitive.h"

#include <vcg/complex/complex.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <random>
#include <vector>

namespace plate_fixture {

struct Soup
{
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> labels;
};

template <class M>
void build_mesh(M& m, const Soup& soup)
{
  using CoordType = typename M::CoordType;
  using ScalarType = typename M::ScalarType;
  m.Clear();
  vcg::tri::Allocator<M>::AddVertices(m, soup.points.size());
  for (size_t i = 0; i < soup.points.size(); ++i)
    m.vert[i].P() = CoordType(ScalarType(soup.points[i].x()), ScalarType(soup.points[i].y()),
                              ScalarType(soup.points[i].z()));
  vcg::tri::Allocator<M>::AddFaces(m, soup.triangles.size());
  for (size_t f = 0; f < soup.triangles.size(); ++f)
    for (int j = 0; j < 3; ++j)
      m.face[f].V(j) = &m.vert[static_cast<size_t>(soup.triangles[f][static_cast<size_t>(j)])];
}

struct PlateWithHole
{
  Soup soup;
  std::vector<int> kind;  // per vertex: 0 face, 1 hole rim, 2 outer rim, 3 vertical edge, 4 corner
  std::vector<std::optional<primitive_edit::Primitive>> primitives;  // by label
  double half = 5, thick = 4, hole = 2;
};

// Vertices get uniform noise in [-noise_amplitude, noise_amplitude] per coordinate.
inline PlateWithHole make_plate_with_hole(double noise_amplitude, unsigned seed = 11)
{
  using primitive_edit::Primitive;
  using primitive_edit::PrimitiveType;
  auto make_plane = [](const Eigen::Vector3d& origin, const Eigen::Vector3d& normal) {
    Primitive p;
    p.type = PrimitiveType::Plane;
    p.origin = origin;
    p.axis = normal.normalized();
    return p;
  };
  auto make_cylinder = [](const Eigen::Vector3d& origin, const Eigen::Vector3d& axis, double radius) {
    Primitive p;
    p.type = PrimitiveType::Cylinder;
    p.origin = origin;
    p.axis = axis.normalized();
    p.radius = radius;
    return p;
  };
  const double half = 5, thick = 4, hole = 2, chamfer = 0.15;
  const int around = 64, rings = 8, levels = 8;  // around divisible by 8 puts vertices on the square's corners
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> noise(-noise_amplitude, noise_amplitude);
  auto jitter = [&]() { return Eigen::Vector3d(noise(rng), noise(rng), noise(rng)); };
  auto angle = [&](double j) { return 2 * primitive_edit::kPi * j / around; };
  // Distance from the axis to the square's boundary along angle t.
  auto square = [&](double t) { return half / std::max(std::abs(std::cos(t)), std::abs(std::sin(t))); };
  auto ray = [&](int j) { return Eigen::Vector3d(std::cos(angle(j)), std::sin(angle(j)), 0); };

  PlateWithHole out;
  Soup& s = out.soup;
  std::vector<int>& kind = out.kind;
  auto add = [&](const Eigen::Vector3d& x, int k) {
    s.points.push_back(x + jitter());
    kind.push_back(k);
    return static_cast<int>(s.points.size()) - 1;
  };
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  std::vector<std::vector<int>> top(rings + 1), bottom(rings + 1), inner(levels + 1), outer(levels + 1);
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j < around; ++j) {
      const bool corner = j % (around / 4) == around / 8;
      const double r = hole + (square(angle(j)) - hole) * i / rings;
      // Chamfer the rims: towards the plate's inside, in from the outer wall or out from the hole.
      const double slide = i == 0 ? chamfer : (i == rings ? -chamfer : 0);
      const double drop = (i == 0 || i == rings) ? chamfer : 0;
      const int k = i == 0 ? 1 : (i == rings ? (corner ? 4 : 2) : 0);
      top[static_cast<size_t>(i)].push_back(add((r + slide) * ray(j) + (thick - drop) * up, k));
      bottom[static_cast<size_t>(i)].push_back(add((r + slide) * ray(j) + drop * up, k));
    }
  inner[0] = bottom[0];
  inner[levels] = top[0];
  outer[0] = bottom[rings];
  outer[levels] = top[rings];
  for (int l = 1; l < levels; ++l)
    for (int j = 0; j < around; ++j) {
      const bool corner = j % (around / 4) == around / 8;
      const double z = thick * l / levels;
      inner[static_cast<size_t>(l)].push_back(add(hole * ray(j) + z * up, 0));
      outer[static_cast<size_t>(l)].push_back(
          add((square(angle(j)) - (corner ? chamfer : 0)) * ray(j) + z * up, corner ? 3 : 0));
    }
  // Quads between two rows of vertices; `flip` reverses the orientation.
  auto strip = [&](const std::vector<int>& a, const std::vector<int>& b, bool flip, auto label_of) {
    for (int j = 0; j < around; ++j) {
      const size_t j0 = static_cast<size_t>(j), j1 = static_cast<size_t>((j + 1) % around);
      const std::array<int, 3> t1{a[j0], b[j0], b[j1]}, t2{a[j0], b[j1], a[j1]};
      s.triangles.push_back(flip ? std::array<int, 3>{t1[0], t1[2], t1[1]} : t1);
      s.triangles.push_back(flip ? std::array<int, 3>{t2[0], t2[2], t2[1]} : t2);
      s.labels.push_back(label_of(j));
      s.labels.push_back(label_of(j));
    }
  };
  // Sides of the square by the angle of a wall quad's middle: 3 (+x), 4 (+y), 5 (-x), 6 (-y).
  auto side_of = [&](int j) { return 3 + static_cast<int>(std::floor((angle(j + 0.5) + primitive_edit::kPi / 4) / (primitive_edit::kPi / 2))) % 4; };
  for (int i = 0; i < rings; ++i) {
    strip(top[static_cast<size_t>(i)], top[static_cast<size_t>(i + 1)], false, [](int) { return 0; });
    strip(bottom[static_cast<size_t>(i)], bottom[static_cast<size_t>(i + 1)], true, [](int) { return 1; });
  }
  for (int l = 0; l < levels; ++l) {
    strip(inner[static_cast<size_t>(l)], inner[static_cast<size_t>(l + 1)], false, [](int) { return 2; });
    strip(outer[static_cast<size_t>(l)], outer[static_cast<size_t>(l + 1)], true, side_of);
  }
  out.primitives = {
      make_plane(thick * up, up), make_plane({0, 0, 0}, -up), make_cylinder({0, 0, 0}, up, hole),
      make_plane({half, 0, 0}, {1, 0, 0}), make_plane({0, half, 0}, {0, 1, 0}), make_plane({-half, 0, 0}, {-1, 0, 0}),
      make_plane({0, -half, 0}, {0, -1, 0})};

  return out;
}

} // namespace plate_fixture

#endif
