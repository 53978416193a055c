// bench_snap: snap_segments on a ~1M-face labelled box (10 x 6 x 4, noisy, rounded edges) onto its six
// exact planes, with sharp edges and flip prevention; float and double meshes. Median of 5 runs.
#include "common/snap/snap_segments.h"

#include <vcg/complex/complex.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <optional>
#include <random>
#include <vector>

namespace {

class FV;
class FF;
struct FTypes : public vcg::UsedTypes<vcg::Use<FV>::AsVertexType, vcg::Use<FF>::AsFaceType> {};
class FV : public vcg::Vertex<FTypes, vcg::vertex::Coord3f, vcg::vertex::BitFlags> {};
class FF : public vcg::Face<FTypes, vcg::face::VertexRef, vcg::face::BitFlags> {};
class FloatMesh : public vcg::tri::TriMesh<std::vector<FV>, std::vector<FF>> {};

class DV;
class DF;
struct DTypes : public vcg::UsedTypes<vcg::Use<DV>::AsVertexType, vcg::Use<DF>::AsFaceType> {};
class DV : public vcg::Vertex<DTypes, vcg::vertex::Coord3d, vcg::vertex::BitFlags> {};
class DF : public vcg::Face<DTypes, vcg::face::VertexRef, vcg::face::BitFlags> {};
class DoubleMesh : public vcg::tri::TriMesh<std::vector<DV>, std::vector<DF>> {};

struct BoxSoup
{
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> labels;
  std::vector<std::optional<primitive_edit::Primitive>> planes;
};

// Box [0, size] on a lattice of step h, edges rounded by `round`, uniform noise; labels = side.
BoxSoup make_box(const Eigen::Vector3d& size, double h, double round, double noise)
{
  BoxSoup box;
  const Eigen::Vector3i n = (size / h).array().round().cast<int>();
  std::vector<int> index(static_cast<size_t>(n.x() + 1) * static_cast<size_t>(n.y() + 1) * static_cast<size_t>(n.z() + 1), -1);
  auto at = [&](const Eigen::Vector3i& c) -> int& {
    return index[(static_cast<size_t>(c.x()) * static_cast<size_t>(n.y() + 1) + static_cast<size_t>(c.y())) *
                     static_cast<size_t>(n.z() + 1) + static_cast<size_t>(c.z())];
  };
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-noise, noise);
  for (int i = 0; i <= n.x(); ++i)
    for (int j = 0; j <= n.y(); ++j)
      for (int k = 0; k <= n.z(); ++k) {
        const Eigen::Vector3i c(i, j, k);
        if (i != 0 && i != n.x() && j != 0 && j != n.y() && k != 0 && k != n.z())
          continue;
        const Eigen::Vector3d x = c.cast<double>().cwiseProduct(size).cwiseQuotient(n.cast<double>());
        const Eigen::Vector3d inner =
            x.cwiseMax(Eigen::Vector3d::Constant(round)).cwiseMin((size.array() - round).matrix());
        at(c) = static_cast<int>(box.points.size());
        box.points.push_back(inner + round * (x - inner).normalized() + Eigen::Vector3d(u(rng), u(rng), u(rng)));
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
          box.triangles.push_back({q00, q10, q11});
          box.triangles.push_back({q00, q11, q01});
        } else {
          box.triangles.push_back({q00, q11, q10});
          box.triangles.push_back({q00, q01, q11});
        }
        box.labels.push_back(side);
        box.labels.push_back(side);
      }
    primitive_edit::Primitive plane;
    plane.type = primitive_edit::PrimitiveType::Plane;
    plane.axis = Eigen::Vector3d::Zero();
    plane.axis[a] = positive ? 1 : -1;
    plane.origin[a] = positive ? size[a] : 0;
    box.planes.push_back(plane);
  }
  return box;
}

template <class Mesh>
void run(const char* name, const BoxSoup& box)
{
  using Coord = typename Mesh::CoordType;
  using Scalar = typename Mesh::ScalarType;
  Mesh m;
  vcg::tri::Allocator<Mesh>::AddVertices(m, box.points.size());
  std::vector<Coord> original;
  for (size_t i = 0; i < box.points.size(); ++i) {
    m.vert[i].P() = Coord(Scalar(box.points[i].x()), Scalar(box.points[i].y()), Scalar(box.points[i].z()));
    original.push_back(m.vert[i].P());
  }
  vcg::tri::Allocator<Mesh>::AddFaces(m, box.triangles.size());
  for (size_t f = 0; f < box.triangles.size(); ++f)
    for (int j = 0; j < 3; ++j)
      m.face[f].V(j) = &m.vert[static_cast<size_t>(box.triangles[f][static_cast<size_t>(j)])];

  std::vector<double> seconds;
  primitive_edit::SnapReport report;
  for (int run = 0; run < 5; ++run) {
    for (size_t i = 0; i < original.size(); ++i)
      m.vert[i].P() = original[i];
    const auto start = std::chrono::steady_clock::now();
    report = primitive_edit::snap_segments(m, box.labels, box.planes);
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(seconds.begin(), seconds.end());
  const double median = seconds[seconds.size() / 2];
  std::printf("%-7s faces %zu vertices %zu: median %.1f ms (min %.1f, max %.1f), %.1f ns/vertex; "
              "moved %d, edge %d, corner %d, reverted %d, mean displacement %.4f, max %.4f\n",
              name, m.face.size(), m.vert.size(), 1e3 * median, 1e3 * seconds.front(), 1e3 * seconds.back(),
              1e9 * median / double(m.vert.size()), report.moved_vertices, report.edge_vertices,
              report.corner_vertices, report.reverted_vertices, report.mean_displacement, report.max_displacement);
}

} // namespace

int main()
{
  // Step 0.0222 on 10 x 6 x 4 gives 1,004,400 triangles.
  const BoxSoup box = make_box({10, 6, 4}, 0.0222, 0.1, 0.002);
  run<FloatMesh>("float", box);
  run<DoubleMesh>("double", box);
  return 0;
}
