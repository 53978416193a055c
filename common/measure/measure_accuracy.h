// measure_accuracy.h: how close a measured surface is to a reference (CAD) surface, as in the paper's
// section 3: the share of samples whose shortest distance to the reference is within a tolerance.
//
// SurfaceDistanceIndex: the live, finite, non-degenerate triangles of a reference vcg mesh, copied in
//   double precision into a vcg::GridStaticPtr (uniform grid with cells about the triangles' size),
//   answering unsigned point-to-surface distances. Zero-area faces are left out: their points lie on
//   the edges of their neighbours. Build O(F log F). A query searches cells ring by ring around the
//   point, pruned by the previous query's closest triangle, until the rest of the grid is farther than
//   the best triangle: O(1) cells near the surface, O(d^3) cells d cells away from it. (vcg::GridClosest
//   re-scans its growing box at every ring, O(d^4): minutes for a scan offset by a few cells.)
// summarize_accuracy(distances, tolerance): share within tolerance (d <= tolerance), mean, RMS, max and
//   a histogram of kAccuracyHistogramBins bins over [0, 2 * tolerance) plus one overflow bin. O(N).
// measure_accuracy(samples, reference or index, tolerance): distances of N sample points, summarized.
//   O(N) queries.
// vertex_distances(mesh, index): the distance of every vertex of a mesh to the reference (for a
//   deviation map), indexed by vcg::tri::Index. O(V) queries.
// Failures (empty input, NaN/infinite coordinates, tolerance <= 0, reference without usable faces,
// cancelled by the progress callback) give a failed Status saying why; never NaN.
#ifndef PRIMITIVE_EDIT_MEASURE_ACCURACY_H
#define PRIMITIVE_EDIT_MEASURE_ACCURACY_H

#include "common/base/progress.h"
#include "common/base/status.h"
#include "common/geometry/closest_point_on_triangle.h"

#include <vcg/complex/complex.h>
#include <vcg/space/index/grid_static_ptr.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace primitive_edit {

constexpr int kAccuracyHistogramBins = 10;

// Grid cell edge, in units of the reference's RMS triangle size sqrt(area / triangles): cells about as
// large as a few triangles keep both the empty cells crossed and the triangles tested per query few
// (bench/bench_measure_accuracy.cpp measures the choice).
constexpr double kDefaultCellSizeFactor = 2.0;

// The grid never has more cells than this many per triangle (memory: 8 bytes per cell), so that a thin
// or sparse reference in a large bounding box gets coarser cells instead of gigabytes of empty ones.
constexpr double kMaxGridCellsPerTriangle = 8.0;

namespace detail {

// One reference triangle, as the grid stores it: GetBBox, IsD and ScalarType are what GridStaticPtr needs.
struct ReferenceTriangle
{
  typedef double ScalarType;
  Eigen::Vector3d a, b, c;

  void GetBBox(vcg::Box3d& box) const
  {
    box.SetNull();
    box.Add(vcg::Point3d(a.x(), a.y(), a.z()));
    box.Add(vcg::Point3d(b.x(), b.y(), b.z()));
    box.Add(vcg::Point3d(c.x(), c.y(), c.z()));
  }
  bool IsD() const { return false; }
};

// Marks the triangles tested by one query (a triangle spans several cells; test it once): a stamp per
// triangle, so that clearing all marks is O(1) and the mesh needs no per-face mark component.
class TriangleStampMarker
{
public:
  void reset(const ReferenceTriangle* first, size_t count)
  {
    first_ = first;
    stamps_.assign(count, 0u);
    stamp_ = 0u;
  }
  void UnMarkAll()
  {
    if (++stamp_ == 0u) {  // wrapped around: old stamps could collide
      std::fill(stamps_.begin(), stamps_.end(), 0u);
      stamp_ = 1u;
    }
  }
  bool IsMarked(const ReferenceTriangle* t) const { return stamps_[size_t(t - first_)] == stamp_; }
  void Mark(const ReferenceTriangle* t) { stamps_[size_t(t - first_)] = stamp_; }

private:
  const ReferenceTriangle* first_ = nullptr;
  std::vector<std::uint32_t> stamps_;
  std::uint32_t stamp_ = 0u;
};

// The low 21 bits of x spread to every third bit (bit k goes to bit 3k), for Morton codes.
inline std::uint64_t spread_bits_by_3(std::uint64_t x)
{
  x &= 0x1FFFFF;
  x = (x | x << 32) & 0x1F00000000FFFFull;
  x = (x | x << 16) & 0x1F0000FF0000FFull;
  x = (x | x << 8) & 0x100F00F00F00F00Full;
  x = (x | x << 4) & 0x10C30C30C30C30C3ull;
  x = (x | x << 2) & 0x1249249249249249ull;
  return x;
}

// Reports every 2^16 steps; false when the callback asks to stop.
inline bool report_every_65536(const Progress& progress, Eigen::Index done, Eigen::Index total, const char* what)
{
  if (!progress || (done & 0xFFFF) != 0 || total <= 0)
    return true;
  return progress(int(100.0 * double(done) / double(total)), what);
}

} // namespace detail

class SurfaceDistanceIndex
{
public:
  // Indexes the reference's live faces, mapped by `to_world` (MeshLab's per-layer transform).
  template <class MeshType>
  explicit SurfaceDistanceIndex(const MeshType& reference,
                                const Eigen::Affine3d& to_world = Eigen::Affine3d::Identity(),
                                double cell_size_factor = kDefaultCellSizeFactor)
  {
    if (!(cell_size_factor > 0.0) || !std::isfinite(cell_size_factor)) {
      status_ = Status::failure("the grid cell size factor must be positive");
      return;
    }
    triangles_.reserve(size_t(std::max(reference.fn, 0)));
    double area = 0.0;
    for (const auto& f : reference.face) {
      if (f.IsD())
        continue;
      Eigen::Vector3d v[3];
      for (int k = 0; k < 3; ++k)
        v[k] = to_world * Eigen::Vector3d(double(f.cV(k)->cP()[0]), double(f.cV(k)->cP()[1]),
                                          double(f.cV(k)->cP()[2]));
      const bool finite = v[0].allFinite() && v[1].allFinite() && v[2].allFinite();
      const double twice_area = finite ? (v[1] - v[0]).cross(v[2] - v[0]).norm() : 0.0;
      if (!(twice_area > 0.0) || !std::isfinite(twice_area)) {
        ++skipped_faces_;
        continue;
      }
      area += 0.5 * twice_area;
      triangles_.push_back(detail::ReferenceTriangle{v[0], v[1], v[2]});
      vcg::Box3d triangle_box;
      triangles_.back().GetBBox(triangle_box);
      box_.Add(triangle_box);
    }
    if (triangles_.empty()) {
      status_ = Status::failure(reference.fn == 0
                                ? "the reference mesh has no faces"
                                : "the reference mesh has no face with finite coordinates and a positive area");
      return;
    }
    if (!std::isfinite(area) || !std::isfinite(box_.Diag())) {
      status_ = Status::failure("the reference mesh is too large for double precision");
      return;
    }
    build_grid(area, cell_size_factor);
    marker_.reset(triangles_.data(), triangles_.size());
  }

  SurfaceDistanceIndex(const SurfaceDistanceIndex&) = delete;  // the grid points into triangles_
  SurfaceDistanceIndex& operator=(const SurfaceDistanceIndex&) = delete;

  // Failed when the reference has nothing to measure against; every query then fails too.
  const Status& status() const { return status_; }
  Eigen::Index triangle_count() const { return Eigen::Index(triangles_.size()); }
  Eigen::Index skipped_face_count() const { return skipped_faces_; }
  Eigen::Vector3i grid_size() const { return Eigen::Vector3i(grid_.siz[0], grid_.siz[1], grid_.siz[2]); }

  // Unsigned distance from a finite point p to the reference surface; infinity when the index failed.
  double distance(const Eigen::Vector3d& p)
  {
    if (!status_)
      return std::numeric_limits<double>::infinity();
    // Start from the previous query's closest triangle: queries come in spatial order, so it is
    // usually near, and its distance prunes most cells at once.
    double best = (closest_point_on_triangle(p, triangles_[last_].a, triangles_[last_].b,
                                                     triangles_[last_].c) - p).norm();
    size_t best_index = last_;
    marker_.UnMarkAll();
    marker_.Mark(&triangles_[last_]);
    // Visit the cells ring by ring (Chebyshev distance k from p's cell, clamped into the grid), until
    // everything outside the rings done is farther than the best triangle found.
    Eigen::Vector3i c;
    for (int a = 0; a < 3; ++a)
      c[a] = int(std::clamp(std::floor((p[a] - grid_.bbox.min[a]) / grid_.voxel[a]), 0.0, double(grid_.siz[a] - 1)));
    for (int k = 0;; ++k) {
      const Eigen::Vector3i lo = (c.array() - k).max(0);
      const Eigen::Vector3i hi = (c.array() + k).min(Eigen::Array3i(grid_.siz[0] - 1, grid_.siz[1] - 1, grid_.siz[2] - 1));
      auto visit = [&](int x, int y, int z) {
        const Eigen::Vector3i cell(x, y, z);
        if (cells_distance(p, cell, cell) >= best)
          return;
        typename Grid::Cell first, last;
        grid_.Grid(x, y, z, first, last);
        for (auto l = first; l != last; ++l) {
          detail::ReferenceTriangle& t = **l;
          if (marker_.IsMarked(&t))
            continue;
          marker_.Mark(&t);
          const double d = (closest_point_on_triangle(p, t.a, t.b, t.c) - p).norm();
          if (d < best) {
            best = d;
            best_index = size_t(&t - triangles_.data());
          }
        }
      };
      for (int z = lo[2]; z <= hi[2]; ++z)
        for (int y = lo[1]; y <= hi[1]; ++y) {
          if (std::abs(z - c[2]) == k || std::abs(y - c[1]) == k) {
            for (int x = lo[0]; x <= hi[0]; ++x)
              visit(x, y, z);
          } else {  // inside the ring's z and y range: only its two x ends are on the shell
            if (c[0] - k >= 0)
              visit(c[0] - k, y, z);
            if (c[0] + k < grid_.siz[0])
              visit(c[0] + k, y, z);
          }
        }
      // The cells not visited yet lie in the slabs of the grid beyond each face of the visited box.
      double beyond = std::numeric_limits<double>::infinity();
      const Eigen::Vector3i first_cell(0, 0, 0);
      const Eigen::Vector3i last_cell(grid_.siz[0] - 1, grid_.siz[1] - 1, grid_.siz[2] - 1);
      for (int a = 0; a < 3; ++a) {
        if (lo[a] > 0) {
          Eigen::Vector3i slab_hi = last_cell;
          slab_hi[a] = lo[a] - 1;
          beyond = std::min(beyond, cells_distance(p, first_cell, slab_hi));
        }
        if (hi[a] < last_cell[a]) {
          Eigen::Vector3i slab_lo = first_cell;
          slab_lo[a] = hi[a] + 1;
          beyond = std::min(beyond, cells_distance(p, slab_lo, last_cell));
        }
      }
      if (beyond >= best)
        break;
    }
    last_ = best_index;
    return best;
  }

  // Distances of many finite points, queried in Morton (Z-curve) order of their position: neighbouring
  // queries then touch the same cells and triangles, which stay in cache (random order is ~10x slower on
  // a 1M-face reference). Result in the points' order. Fails (out empty) when the index failed, a point
  // is not finite, or the callback cancels.
  Status distances(const Eigen::MatrixX3d& points, Eigen::VectorXd& out, const Progress& progress = {},
                 const char* what = "Measuring distances")
  {
    out.resize(0);
    if (!status_)
      return status_;
    if (!points.allFinite())
      return Status::failure("some points have NaN or infinite coordinates");
    const Eigen::Index n = points.rows();
    std::vector<std::pair<std::uint64_t, Eigen::Index>> order(static_cast<size_t>(n));
    const Eigen::Vector3d lo = n > 0 ? Eigen::Vector3d(points.colwise().minCoeff().transpose()) : Eigen::Vector3d::Zero();
    const double extent = n > 0 ? (points.colwise().maxCoeff().transpose() - lo).maxCoeff() : 0.0;
    const double scale = extent > 0.0 && std::isfinite(extent) ? double((1u << 21) - 1) / extent : 0.0;
    for (Eigen::Index i = 0; i < n; ++i) {
      std::uint64_t key = 0;
      for (int axis = 0; axis < 3; ++axis) {
        const double t = scale > 0.0 ? std::clamp((points(i, axis) - lo[axis]) * scale, 0.0, double((1u << 21) - 1)) : 0.0;
        key |= detail::spread_bits_by_3(std::uint64_t(t)) << axis;
      }
      order[size_t(i)] = {key, i};
    }
    std::sort(order.begin(), order.end());
    out.resize(n);
    for (Eigen::Index k = 0; k < n; ++k) {
      if (!detail::report_every_65536(progress, k, n, what)) {
        out.resize(0);
        return Status::failure("cancelled");
      }
      const Eigen::Index i = order[size_t(k)].second;
      out(i) = distance(points.row(i).transpose());
    }
    return Status::success();
  }

private:
  typedef vcg::GridStaticPtr<detail::ReferenceTriangle, double> Grid;

  // Distance from p to the box of grid cells [lo, hi] (inclusive cell indices).
  double cells_distance(const Eigen::Vector3d& p, const Eigen::Vector3i& lo, const Eigen::Vector3i& hi) const
  {
    double sq = 0.0;
    for (int a = 0; a < 3; ++a) {
      const double from = grid_.bbox.min[a] + lo[a] * grid_.voxel[a];
      const double to = grid_.bbox.min[a] + (hi[a] + 1) * grid_.voxel[a];
      const double gap = p[a] < from ? from - p[a] : (p[a] > to ? p[a] - to : 0.0);
      sq += gap * gap;
    }
    return std::sqrt(sq);
  }

  // Cubic cells of edge factor * sqrt(area / triangles), coarsened when that would exceed the cell cap (and
  // along an axis where the coordinates' precision demands it).
  void build_grid(double area, double cell_size_factor)
  {
    const double n = double(triangles_.size());
    const double max_cells = std::min(kMaxGridCellsPerTriangle * n, double(1 << 26));  // int cell indices
    double cell = cell_size_factor * std::sqrt(area / n);
    // Pad by half a cell so that no triangle touches the grid's outer faces.
    auto cells_along = [&](int axis, double c) { return std::ceil(box_.Dim()[axis] / c) + 1.0; };
    auto cell_count = [&](double c) { return cells_along(0, c) * cells_along(1, c) * cells_along(2, c); };
    while (cell_count(cell) > max_cells)
      cell *= 1.1;
    Eigen::Vector3i size;
    vcg::Box3d grid_box;
    for (int axis = 0; axis < 3; ++axis) {
      // Far from the origin a cell must stay wider than the coordinates' precision, or the grid's box
      // collapses to zero width along that axis (found by the fuzz target: a flat mesh at z = 1e32).
      const double far = std::max(std::abs(box_.min[axis]), std::abs(box_.max[axis]));
      const double c = std::max(cell, 64 * std::numeric_limits<double>::epsilon() * far);
      size[axis] = int(cells_along(axis, c));
      const double centre = 0.5 * (box_.min[axis] + box_.max[axis]);
      grid_box.min[axis] = centre - 0.5 * size[axis] * c;
      grid_box.max[axis] = centre + 0.5 * size[axis] * c;
    }
    grid_.Set(triangles_.begin(), triangles_.end(), grid_box, vcg::Point3i(size[0], size[1], size[2]));
  }

  std::vector<detail::ReferenceTriangle> triangles_;
  Grid grid_;
  detail::TriangleStampMarker marker_;
  size_t last_ = 0;  // the previous query's closest triangle
  vcg::Box3d box_;  // of the indexed triangles
  Eigen::Index skipped_faces_ = 0;
  Status status_;
};

struct AccuracyReport
{
  Status status;
  Eigen::Index sample_count = 0;
  double tolerance = 0.0;
  double within_tolerance_share = 0.0;  // 0..1: samples with distance <= tolerance
  double mean = 0.0;
  double rms = 0.0;
  double max = 0.0;
  // histogram[i], i < kAccuracyHistogramBins: distances in [i, i + 1) * histogram_bin_width;
  // histogram[kAccuracyHistogramBins]: distances >= 2 * tolerance.
  double histogram_bin_width = 0.0;
  std::vector<Eigen::Index> histogram;
  Eigen::VectorXd distances;  // per sample, only when asked for
};

inline AccuracyReport summarize_accuracy(const Eigen::VectorXd& distances, double tolerance)
{
  AccuracyReport r;
  r.tolerance = tolerance;
  if (!(tolerance > 0.0) || !std::isfinite(tolerance)) {
    r.status = Status::failure("the tolerance must be a positive finite number");
    return r;
  }
  if (distances.size() == 0) {
    r.status = Status::failure("there are no distances to summarize");
    return r;
  }
  if (!distances.allFinite() || (distances.array() < 0.0).any()) {
    r.status = Status::failure("the distances must be finite and non-negative");
    return r;
  }
  r.sample_count = distances.size();
  r.histogram_bin_width = 2.0 * tolerance / kAccuracyHistogramBins;
  r.histogram.assign(kAccuracyHistogramBins + 1, 0);
  Eigen::Index within = 0;
  double sum = 0.0, sum_sq = 0.0, max = 0.0;
  for (Eigen::Index i = 0; i < distances.size(); ++i) {
    const double d = distances(i);
    within += d <= tolerance ? 1 : 0;
    sum += d;
    sum_sq += d * d;
    max = std::max(max, d);
    const double bin = std::floor(d / r.histogram_bin_width);
    ++r.histogram[bin >= kAccuracyHistogramBins ? kAccuracyHistogramBins : size_t(bin)];
  }
  const double n = double(distances.size());
  r.within_tolerance_share = double(within) / n;
  r.mean = sum / n;
  r.rms = std::sqrt(sum_sq / n);
  r.max = max;
  return r;
}

// Distances of the sample points to the indexed reference, summarized.
inline AccuracyReport measure_accuracy(const Eigen::MatrixX3d& samples, SurfaceDistanceIndex& index,
                                       double tolerance, bool keep_distances = false,
                                       const Progress& progress = {})
{
  AccuracyReport failed;
  failed.tolerance = tolerance;
  if (!index.status()) {
    failed.status = index.status();
    return failed;
  }
  if (samples.rows() == 0) {
    failed.status = Status::failure("there are no sample points");
    return failed;
  }
  if (!samples.allFinite()) {
    failed.status = Status::failure("some sample points have NaN or infinite coordinates");
    return failed;
  }
  if (!(tolerance > 0.0) || !std::isfinite(tolerance)) {
    failed.status = Status::failure("the tolerance must be a positive finite number");
    return failed;
  }
  Eigen::VectorXd d;
  failed.status = index.distances(samples, d, progress, "Measuring distances to the reference");
  if (!failed.status)
    return failed;
  AccuracyReport r = summarize_accuracy(d, tolerance);
  if (keep_distances)
    r.distances = std::move(d);
  return r;
}

// Same, building the index of `reference` first.
template <class MeshType>
AccuracyReport measure_accuracy(const Eigen::MatrixX3d& samples, const MeshType& reference, double tolerance,
                                bool keep_distances = false)
{
  SurfaceDistanceIndex index(reference);
  return measure_accuracy(samples, index, tolerance, keep_distances);
}

// Distance of each vertex of `mesh` (mapped by `to_world`) to the indexed reference, indexed by
// vcg::tri::Index; deleted vertices get 0. Fails on a non-finite live vertex or when cancelled.
template <class MeshType>
Status vertex_distances(const MeshType& mesh, SurfaceDistanceIndex& index, Eigen::VectorXd& distances,
                        const Eigen::Affine3d& to_world = Eigen::Affine3d::Identity(),
                        const Progress& progress = {})
{
  if (!index.status())
    return index.status();
  if (mesh.vn == 0)
    return Status::failure("the mesh has no vertices");
  // Live vertices' positions, queried together (in spatial order); deleted ones keep 0.
  std::vector<Eigen::Index> live;
  live.reserve(mesh.vert.size());
  for (const auto& v : mesh.vert)
    if (!v.IsD())
      live.push_back(Eigen::Index(vcg::tri::Index(mesh, v)));
  Eigen::MatrixX3d points(Eigen::Index(live.size()), 3);
  for (size_t k = 0; k < live.size(); ++k) {
    const auto& p = mesh.vert[size_t(live[k])].cP();
    points.row(Eigen::Index(k)) = (to_world * Eigen::Vector3d(double(p[0]), double(p[1]), double(p[2]))).transpose();
    if (!points.row(Eigen::Index(k)).allFinite())
      return Status::failure("vertex " + std::to_string(live[k]) + " has NaN or infinite coordinates");
  }
  Eigen::VectorXd live_distances;
  if (Status measured = index.distances(points, live_distances, progress, "Deviation map"); !measured)
    return measured;
  distances = Eigen::VectorXd::Zero(Eigen::Index(mesh.vert.size()));
  for (size_t k = 0; k < live.size(); ++k)
    distances(live[k]) = live_distances(Eigen::Index(k));
  return Status::success();
}

} // namespace primitive_edit

#endif
