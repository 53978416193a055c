// rounded_box.h: a test part for snapping, shared by the snap tests and bench_snap: a box [0, size] tessellated
// on a lattice of step h, its edges rounded with radius `round` (the blurred edges of a scan), every vertex
// shifted by uniform noise in [-noise, noise] per coordinate (seeded), then rotated by `rot` and moved by
// `shift`. Six CAD faces: label 2a where axis a is 0, 2a + 1 where it is size[a], with their exact planes. Per
// vertex: its lattice position on the box before rounding and noise (and rotation), and how many of its
// coordinates lie at a bound (1 side, 2 edge, 3 corner).
// Cost: O((size / h)^3) for the lattice index, O(surface vertices) for the rest.
#ifndef PRIMITIVE_EDIT_TEST_ROUNDED_BOX_H
#define PRIMITIVE_EDIT_TEST_ROUNDED_BOX_H

#include "plate_with_hole.h"
#include "test_fit_data.h"

#include <Eigen/Core>

#include <cstddef>
#include <optional>
#include <random>
#include <vector>

namespace plate_fixture {

struct RoundedBox
{
  Soup soup;
  std::vector<Eigen::Vector3d> lattice;
  std::vector<int> bound;
  std::vector<std::optional<primitive_edit::Primitive>> planes;
};

inline RoundedBox make_rounded_box(const Eigen::Vector3d& size, double h, double round, double noise, unsigned seed,
                                   const Eigen::Matrix3d& rot = Eigen::Matrix3d::Identity(),
                                   const Eigen::Vector3d& shift = Eigen::Vector3d::Zero())
{
  RoundedBox box;
  const Eigen::Vector3i n = (size / h).array().round().cast<int>();
  const std::size_t ny = std::size_t(n.y() + 1), nz = std::size_t(n.z() + 1);
  std::vector<int> index(std::size_t(n.x() + 1) * ny * nz, -1);
  auto at = [&](const Eigen::Vector3i& c) -> int& {
    return index[(std::size_t(c.x()) * ny + std::size_t(c.y())) * nz + std::size_t(c.z())];
  };
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-noise, noise);
  for (int i = 0; i <= n.x(); ++i)
    for (int j = 0; j <= n.y(); ++j)
      for (int k = 0; k <= n.z(); ++k) {
        const Eigen::Vector3i c(i, j, k);
        int bound = 0;
        for (int a = 0; a < 3; ++a)
          bound += (c[a] == 0 || c[a] == n[a]) ? 1 : 0;
        if (bound == 0)
          continue;
        const Eigen::Vector3d x = c.cast<double>().cwiseProduct(size).cwiseQuotient(n.cast<double>());
        // Rounded box: the point at distance `round` from the box shrunk by `round`.
        const Eigen::Vector3d inner = x.cwiseMax(Eigen::Vector3d::Constant(round)).cwiseMin((size.array() - round).matrix());
        const Eigen::Vector3d rounded = inner + round * (x - inner).normalized();
        at(c) = static_cast<int>(box.soup.points.size());
        box.soup.points.push_back(rot * (rounded + Eigen::Vector3d(u(rng), u(rng), u(rng))) + shift);
        box.lattice.push_back(x);
        box.bound.push_back(bound);
      }
  for (int side = 0; side < 6; ++side) {
    const int a = side / 2, ua = (a + 1) % 3, va = (a + 2) % 3;
    const bool positive = side % 2 == 1;
    for (int iu = 0; iu < n[ua]; ++iu)
      for (int iv = 0; iv < n[va]; ++iv) {
        auto corner = [&](int du, int dv) {
          Eigen::Vector3i c;
          c[a] = positive ? n[a] : 0;
          c[ua] = iu + du;
          c[va] = iv + dv;
          return at(c);
        };
        const int q00 = corner(0, 0), q10 = corner(1, 0), q11 = corner(1, 1), q01 = corner(0, 1);
        if (positive) {
          box.soup.triangles.push_back({q00, q10, q11});
          box.soup.triangles.push_back({q00, q11, q01});
        } else {
          box.soup.triangles.push_back({q00, q11, q10});
          box.soup.triangles.push_back({q00, q01, q11});
        }
        box.soup.labels.push_back(side);
        box.soup.labels.push_back(side);
      }
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    normal[a] = positive ? 1 : -1;
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();
    origin[a] = positive ? size[a] : 0;
    box.planes.push_back(test_fit::make_plane(rot * origin + shift, rot * normal));
  }
  return box;
}

} // namespace plate_fixture

#endif
