// bench_snap: snap_segments on a ~1M-face labelled box (10 x 6 x 4, noisy, rounded edges) onto its six
// exact planes, with sharp edges and flip prevention; float and double meshes. Median of 5 runs. The box is the
// snap tests' (tests/unit/rounded_box.h), at 0.0222 steps.
#include "common/snap/snap_segments.h"
#include "../tests/unit/rounded_box.h"
#include "median.h"

#include <vcg/complex/complex.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
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

template <class Mesh>
void run(const char* name, const plate_fixture::RoundedBox& box)
{
  Mesh m;
  plate_fixture::build_mesh(m, box.soup);
  std::vector<typename Mesh::CoordType> original;
  for (const auto& v : m.vert)
    original.push_back(v.cP());

  std::vector<double> seconds;
  primitive_edit::SnapReport report;
  for (int run = 0; run < 5; ++run) {
    for (size_t i = 0; i < original.size(); ++i)
      m.vert[i].P() = original[i];
    const auto start = std::chrono::steady_clock::now();
    report = primitive_edit::snap_segments(m, box.soup.labels, box.planes);
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  const auto [fastest, slowest] = std::minmax_element(seconds.begin(), seconds.end());
  std::printf("%-7s faces %zu vertices %zu: median %.1f ms (min %.1f, max %.1f), %.1f ns/vertex; "
              "moved %d, edge %d, corner %d, reverted %d, mean displacement %.4f, max %.4f\n",
              name, m.face.size(), m.vert.size(), 1e3 * median(seconds), 1e3 * *fastest, 1e3 * *slowest,
              1e9 * median(seconds) / double(m.vert.size()), report.moved_vertices, report.edge_vertices,
              report.corner_vertices, report.reverted_vertices, report.mean_displacement, report.max_displacement);
}

} // namespace

int main()
{
  // Step 0.0222 on 10 x 6 x 4 gives 1,004,400 triangles.
  const plate_fixture::RoundedBox box = plate_fixture::make_rounded_box({10, 6, 4}, 0.0222, 0.1, 0.002, 1);
  run<FloatMesh>("float", box);
  run<DoubleMesh>("double", box);
  return 0;
}
