// bench_segment: time of the automatic segmentation (segment_by_normal_angle with default parameters,
// adjacency build included) and of build_face_adjacency alone, on noisy tori of about 100k, 1M and 4M
// triangles with float coordinates like MeshLab's CMeshO. Prints the median of 5 runs and ns per face, in
// thread CPU time (what one core spends, robust when the machine is shared) and in wall-clock time.
#include "common/mesh/face_adjacency.h"
#include "common/segment/segment_by_normal_angle.h"
#include "median.h"

#include <vcg/complex/complex.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <random>
#include <vector>

namespace {

class BVertex;
class BFace;
struct BUsedTypes : public vcg::UsedTypes<vcg::Use<BVertex>::AsVertexType, vcg::Use<BFace>::AsFaceType> {};
class BVertex : public vcg::Vertex<BUsedTypes, vcg::vertex::Coord3f, vcg::vertex::Normal3f, vcg::vertex::BitFlags> {};
class BFace : public vcg::Face<BUsedTypes, vcg::face::VertexRef, vcg::face::Normal3f, vcg::face::BitFlags> {};
class BMesh : public vcg::tri::TriMesh<std::vector<BVertex>, std::vector<BFace>> {};

// Torus (radii 3 and 1) as a nu x nv grid, 2 nu nv triangles, vertices jittered by `noise` (Gaussian sigma).
void make_noisy_torus(BMesh& m, int nu, int nv, float noise_sigma)
{
  m.Clear();
  vcg::tri::Allocator<BMesh>::AddVertices(m, size_t(nu) * size_t(nv));
  std::mt19937 rng(1);
  std::normal_distribution<float> noise(0.0f, noise_sigma);
  const double two_pi = 6.283185307179586;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = two_pi * i / nu, v = two_pi * j / nv;
      const double r = 3.0 + std::cos(v);
      m.vert[size_t(i) * size_t(nv) + size_t(j)].P() =
          vcg::Point3f(float(r * std::cos(u)) + noise(rng), float(r * std::sin(u)) + noise(rng),
                       float(std::sin(v)) + noise(rng));
    }
  auto fi = vcg::tri::Allocator<BMesh>::AddFaces(m, 2 * size_t(nu) * size_t(nv));
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      auto at = [&](int a, int b) { return &m.vert[size_t(a % nu) * size_t(nv) + size_t(b % nv)]; };
      fi->V(0) = at(i, j);
      fi->V(1) = at(i + 1, j);
      fi->V(2) = at(i + 1, j + 1);
      ++fi;
      fi->V(0) = at(i, j);
      fi->V(1) = at(i + 1, j + 1);
      fi->V(2) = at(i, j + 1);
      ++fi;
    }
}

double thread_cpu_seconds()
{
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

struct Timing
{
  double cpu = 0.0;  // median thread CPU time, seconds
  double wall = 0.0; // median wall-clock time, seconds
};

template <class F>
Timing median_time(int runs, F&& run)
{
  std::vector<double> cpu, wall;
  for (int r = 0; r < runs; ++r) {
    const double cpu_start = thread_cpu_seconds();
    const auto wall_start = std::chrono::steady_clock::now();
    run();
    wall.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count());
    cpu.push_back(thread_cpu_seconds() - cpu_start);
  }
  return {median(cpu), median(wall)};
}

} // namespace

int main()
{
  using namespace primitive_edit;
  const int runs = 5;
  std::printf("median of %d runs; segment = segment_by_normal_angle with default parameters, adjacency included\n", runs);
  std::printf("%6s %9s %8s | %11s %8s %11s | %11s %8s %11s\n", "noise", "faces", "segments", "segment cpu", "ns/face",
              "segment wall", "adj cpu", "ns/face", "adj wall");
  // Light noise leaves one segment; heavy noise (about half an edge length at 1M faces) breaks the surface
  // into many small segments and so also times their absorption.
  const int sizes[][2] = {{500, 100}, {1000, 500}, {2000, 1000}};
  for (const float noise : {0.001f, 0.003f})
  for (const auto& size : sizes) {
    BMesh m;
    make_noisy_torus(m, size[0], size[1], noise);
    const double faces = double(m.fn);
    std::vector<int> seg;
    int K = 0;
    const Timing segment = median_time(runs, [&] { K = segment_by_normal_angle(m, SegmentByNormalAngleParams{}, seg); });
    std::size_t neighbours = 0;
    const Timing adjacency = median_time(runs, [&] { neighbours = build_face_adjacency(m).neighbour.size(); });
    std::printf("%6.3f %9d %8d | %10.3fs %8.1f %10.3fs | %10.3fs %8.1f %10.3fs\n", double(noise), m.fn, K, segment.cpu,
                1e9 * segment.cpu / faces, segment.wall, adjacency.cpu, 1e9 * adjacency.cpu / faces, adjacency.wall);
    if (neighbours != 3 * std::size_t(m.fn))
      std::printf("  unexpected adjacency size %zu\n", neighbours);
  }
  return 0;
}
