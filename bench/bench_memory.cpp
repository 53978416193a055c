// bench_memory: peak memory of segmentation and fit-all on a large mesh laid out like MeshLab's CMeshO, as a
// ratio to the mesh's own size (its vertex and face vectors), and the time of each phase.
//
// Benchmarks use common/ only, so the mesh type here mirrors CMeshO's always-present components (float
// coordinates, normals, quality, colour, flags per vertex; vertex refs, flags, normal per face) plus the face
// quality and colour MeshLab enables when the segment filters run (its optional components, stored in
// side vectors there, are inline here: the same bytes per face).
//
// The mesh is a closed box, every side an n x n grid (12 n^2 faces; default ~4M), with a little noise and a
// malformed fringe when asked (--malformed: zero-area faces and a NaN vertex, as scans have).
// Phases: "segmentation" = build_face_adjacency + segment_by_normal_angle; "fit-all" = gather_segment_samples
// + fit_primitive_auto per segment + snap_segments. Peak RSS per phase: /proc/self/clear_refs resets VmHWM
// before the phase, VmHWM - VmRSS(before) after it is what the phase added. Goal: <= 2x the mesh size.
// Usage: bench_memory [faces (default 4000000)] [--malformed] [--runs R (default 3; times are medians)]
//        e.g. bench_memory 10000000 --malformed   (the 10-million-face run; not for CI)
#include "common/mesh/face_adjacency.h"
#include "common/fit/fit_primitive_auto.h"
#include "common/mesh/gather_segment_samples.h"
#include "common/segment/segment_by_normal_angle.h"
#include "common/snap/snap_segments.h"
#include "median.h"
#include "read_number.h"

#include <vcg/complex/complex.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>
#include <random>
#include <string>
#include <vector>

using namespace primitive_edit;

namespace bench_mesh {

class BVertex;
class BFace;
struct BUsedTypes : public vcg::UsedTypes<vcg::Use<BVertex>::AsVertexType, vcg::Use<BFace>::AsFaceType> {};
class BVertex : public vcg::Vertex<BUsedTypes, vcg::vertex::Coord3f, vcg::vertex::BitFlags, vcg::vertex::Normal3f,
                                   vcg::vertex::Qualityf, vcg::vertex::Color4b> {};
class BFace : public vcg::Face<BUsedTypes, vcg::face::VertexRef, vcg::face::BitFlags, vcg::face::Normal3f,
                               vcg::face::Qualityf, vcg::face::Color4b> {};
class BMesh : public vcg::tri::TriMesh<std::vector<BVertex>, std::vector<BFace>> {};

} // namespace bench_mesh

using bench_mesh::BFace;
using bench_mesh::BMesh;
using bench_mesh::BVertex;

namespace {

// A /proc/self/status field in kB (VmRSS, VmHWM), 0 if unavailable.
long status_kb(const char* field)
{
  std::ifstream in("/proc/self/status");
  std::string line;
  const size_t n = std::strlen(field);
  while (std::getline(in, line))
    if (line.compare(0, n, field) == 0 && line.size() > n && line[n] == ':')
      return std::atol(line.c_str() + n + 1);
  return 0;
}

// Resets the peak RSS (VmHWM) to the current RSS; false when the kernel does not allow it.
bool reset_peak()
{
  std::ofstream out("/proc/self/clear_refs");
  out << "5";
  return bool(out);
}

void build_box(BMesh& m, int n, bool malformed)
{
  std::mt19937 rng(7);
  std::normal_distribution<float> noise(0.0f, 1e-4f);
  const float size[3] = {10, 6, 4};
  const int per_side = (n + 1) * (n + 1);
  vcg::tri::Allocator<BMesh>::AddVertices(m, size_t(6 * per_side));
  vcg::tri::Allocator<BMesh>::AddFaces(m, size_t(12) * size_t(n) * size_t(n));
  size_t v = 0, f = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, w = (axis + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      const size_t base = v;
      for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
          vcg::Point3f p;
          p[axis] = size[axis] * float(side) + noise(rng);
          p[u] = size[u] * float(i) / float(n);
          p[w] = size[w] * float(j) / float(n);
          m.vert[v++].P() = p;
        }
      // Sides are not welded: the seams are borders, which costs the segmentation nothing.
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          BVertex* a = &m.vert[base + size_t(i * (n + 1) + j)];
          BVertex* b = a + (n + 1);
          BVertex* c = b + 1;
          BVertex* d = a + 1;
          BFace& f1 = m.face[f++];
          BFace& f2 = m.face[f++];
          f1.V(0) = a; f1.V(1) = side ? b : c; f1.V(2) = side ? c : b;
          f2.V(0) = a; f2.V(1) = side ? c : d; f2.V(2) = side ? d : c;
        }
    }
  }
  if (malformed) {
    // Every 1000th face collapsed onto an edge, a NaN vertex: the defects a scan has.
    for (size_t k = 0; k < m.face.size(); k += 1000)
      m.face[k].V(2) = m.face[k].V(1);
    m.vert[m.vert.size() / 2].P()[0] = std::nanf("");
  }
}

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct Phase
{
  double seconds = 0;
  double peak_mb = 0;  // RSS added by the phase at its peak
};

} // namespace

int main(int argc, char** argv)
{
  long faces = 4000000;
  bool malformed = false;
  int runs = 3;
  bool ok = true;
  for (int i = 1; i < argc && ok; ++i) {
    if (std::strcmp(argv[i], "--malformed") == 0)
      malformed = true;
    else if (std::strcmp(argv[i], "--runs") == 0 && i + 1 < argc)
      ok = read_number("--runs", argv[++i], 1, kMaxRuns, runs);
    else
      ok = read_number("FACES", argv[i], 1L, 1000000000L, faces);
  }
  if (!ok)
    return 2;
  const int n = std::max(1, int(std::lround(std::sqrt(double(faces) / 12.0))));

  BMesh m;
  build_box(m, n, malformed);
  const double mesh_mb = (double(m.vert.capacity()) * sizeof(BVertex) + double(m.face.capacity()) * sizeof(BFace)) /
                         (1024.0 * 1024.0);
  std::printf("mesh: %zu vertices, %zu faces (n = %d%s); vertex+face vectors %.1f MB (BVertex %zu B, BFace %zu B)\n",
              m.vert.size(), m.face.size(), n, malformed ? ", malformed" : "", mesh_mb, sizeof(BVertex),
              sizeof(BFace));
  if (!reset_peak())
    std::printf("warning: cannot reset VmHWM; peaks include earlier phases\n");

  std::vector<double> seg_s, seg_mb, fit_s, fit_mb;
  int K = 0, fitted = 0;
  for (int r = 0; r < runs; ++r) {
    BMesh work;
    vcg::tri::Append<BMesh, BMesh>::MeshCopy(work, m);
    std::vector<int> seg;
    {
      const long before = status_kb("VmRSS");
      reset_peak();
      const auto t0 = std::chrono::steady_clock::now();
      {
        const FaceAdjacency adj = build_face_adjacency(work);
        SegmentByNormalAngleParams params;
        K = segment_by_normal_angle(work, adj, params, seg);
      }
      seg_s.push_back(seconds_since(t0));
      seg_mb.push_back(double(status_kb("VmHWM") - before) / 1024.0);
    }
    {
      const long before = status_kb("VmRSS");
      reset_peak();
      const auto t0 = std::chrono::steady_clock::now();
      {
        const std::vector<SegmentSamples> samples = gather_segment_samples(work, seg, K);
        std::vector<std::optional<Primitive>> prims(static_cast<size_t>(K));
        fitted = 0;
        for (int s = 0; s < K; ++s) {
          const SegmentSamples& ss = samples[size_t(s)];
          const AutoFitResult fit = fit_primitive_auto(ss.points, ss.normals, ss.weights);
          if (fit.status.ok()) {
            prims[size_t(s)] = fit.best.primitive;
            ++fitted;
          }
        }
        snap_segments(work, seg, prims);
      }
      fit_s.push_back(seconds_since(t0));
      fit_mb.push_back(double(status_kb("VmHWM") - before) / 1024.0);
    }
  }
  std::printf("segmentation: %d segments, %.2f s (median of %d), peak +%.1f MB = %.2fx the mesh\n", K, median(seg_s),
              runs, median(seg_mb), median(seg_mb) / mesh_mb);
  std::printf("fit-all:      %d of %d segments fitted, %.2f s (median of %d), peak +%.1f MB = %.2fx the mesh\n",
              fitted, K, median(fit_s), runs, median(fit_mb), median(fit_mb) / mesh_mb);
  return 0;
}
