// bench_measure_accuracy: the paper's accuracy measurement at its size, 1M samples against a 1M-face
// reference (a tessellated torus), timing sampling, index build and distance queries (median of 3 runs),
// for several grid densities and for a measured surface that is offset from the reference.
#include "common/base/constants.h"
#include "common/measure/measure_accuracy.h"
#include "common/mesh/sample_surface_uniform.h"
#include "median.h"

#include <vcg/complex/complex.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <vector>

namespace {

// Float coordinates, like MeshLab's CMeshO.
class BVertex;
class BFace;
struct BUsedTypes : public vcg::UsedTypes<vcg::Use<BVertex>::AsVertexType, vcg::Use<BFace>::AsFaceType> {};
class BVertex : public vcg::Vertex<BUsedTypes, vcg::vertex::Coord3f, vcg::vertex::BitFlags> {};
class BFace : public vcg::Face<BUsedTypes, vcg::face::VertexRef, vcg::face::BitFlags> {};
class BMesh : public vcg::tri::TriMesh<std::vector<BVertex>, std::vector<BFace>> {};


// Torus around z of major radius R and tube radius r: rings x sides quads, 2 triangles each.
void make_torus(BMesh& m, double R, double r, int rings, int sides)
{
  m.Clear();
  vcg::tri::Allocator<BMesh>::AddVertices(m, size_t(rings) * size_t(sides));
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sides; ++j) {
      const double u = 2.0 * primitive_edit::kPi * i / rings, v = 2.0 * primitive_edit::kPi * j / sides;
      m.vert[size_t(i) * sides + j].P() =
          vcg::Point3f(float((R + r * std::cos(v)) * std::cos(u)), float((R + r * std::cos(v)) * std::sin(u)),
                       float(r * std::sin(v)));
    }
  vcg::tri::Allocator<BMesh>::AddFaces(m, size_t(rings) * size_t(sides) * 2);
  size_t f = 0;
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sides; ++j) {
      BVertex* a = &m.vert[size_t(i) * sides + j];
      BVertex* b = &m.vert[size_t((i + 1) % rings) * sides + j];
      BVertex* c = &m.vert[size_t((i + 1) % rings) * sides + (j + 1) % sides];
      BVertex* d = &m.vert[size_t(i) * sides + (j + 1) % sides];
      m.face[f].V(0) = a; m.face[f].V(1) = b; m.face[f].V(2) = c; ++f;
      m.face[f].V(0) = a; m.face[f].V(1) = c; m.face[f].V(2) = d; ++f;
    }
}

// CPU time of this process: the machine is shared, so wall time says little.
double cpu_seconds()
{
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// One measurement: the measured torus has tube radius r_measured, the reference 10 (major 40), so the
// samples lie |r_measured - 10| from the reference.
void run(const BMesh& measured, const BMesh& reference, Eigen::Index samples_n, double cell_size_factor,
         const char* label)
{
  std::vector<double> t_sample, t_index, t_query;
  primitive_edit::AccuracyReport r;
  Eigen::Vector3i grid;
  for (int run = 0; run < 3; ++run) {
    double t0 = cpu_seconds();
    Eigen::MatrixX3d samples;
    if (const primitive_edit::Status s = primitive_edit::sample_surface_uniform(measured, samples_n, std::uint64_t(run), &samples); !s) {
      std::fprintf(stderr, "bench_measure_accuracy: %s\n", s.error.c_str());
      std::exit(1);
    }
    t_sample.push_back(cpu_seconds() - t0);
    t0 = cpu_seconds();
    primitive_edit::SurfaceDistanceIndex index(reference, Eigen::Affine3d::Identity(), cell_size_factor);
    t_index.push_back(cpu_seconds() - t0);
    grid = index.grid_size();
    t0 = cpu_seconds();
    r = primitive_edit::measure_accuracy(samples, index, 0.42);
    t_query.push_back(cpu_seconds() - t0);
  }
  std::printf("%-22s cell factor %3.1f grid %4dx%4dx%4d | sampling %6.3f s  index %6.3f s  queries %7.3f s | "
              "within %5.1f%%  mean %.4f  max %.4f\n",
              label, cell_size_factor, grid.x(), grid.y(), grid.z(), median(t_sample), median(t_index),
              median(t_query), 100.0 * r.within_tolerance_share, r.mean, r.max);
}

} // namespace

int main()
{
  BMesh reference, measured;
  make_torus(reference, 40.0, 10.0, 1000, 500);  // 1,000,000 faces
  std::printf("reference: %d faces; 1,000,000 samples per run; CPU seconds, median of 3 runs\n", reference.fn);
  const Eigen::Index n = 1000000;

  make_torus(measured, 40.0, 10.3, 700, 350);  // 0.3 outside the reference everywhere
  for (double factor : {1.0, 2.0, 4.0})
    run(measured, reference, n, factor, "offset 0.3 (aligned)");
  // Misaligned scans: a query d cells away from the reference surface visits O(d^3) cells (cells are
  // about 0.3 here).
  for (double offset : {1.0, 2.0}) {
    make_torus(measured, 40.0, 10.0 + offset, 700, 350);
    char label[32];
    std::snprintf(label, sizeof label, "offset %.1f", offset);
    run(measured, reference, n, primitive_edit::kDefaultCellSizeFactor, label);
  }
  return 0;
}
