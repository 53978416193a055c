// gather_segment_samples.h: the points a primitive is fitted to, per segment.
//
// Input:  a vcg triangle mesh, `segment_of_face` (index = vcg::tri::Index(m, face), -1 = none), the
//         segment count K and the threads to use (<= 0: every hardware thread).
// Output: for each segment k, the vertices of its faces, each once, with
//         - normals: the area-weighted mean of the normals of the segment's own faces around the vertex
//           (faces of other segments are left out, so a vertex on an edge gets the normal of this side),
//         - weights: a third of the area of those faces (the vertex's share of the segment's surface),
//         - vertex:  the mesh index of each vertex, and `area`, the segment's area.
//         Degenerate faces add nothing to normals and weights; vertices with non-finite coordinates are
//         skipped. The same on any thread count.
// Method: the live faces grouped by segment (a counting sort), then each segment's faces walked on their
//         own. The walk waits on memory (a vcg face is about 100 bytes, read out of order; at 1M faces it
//         was half of Fit All's fitting phase), so the segments are shared out among at most
//         kMostGatherThreads threads, largest first (for_each_largest_first, parallel_for.h), each thread with
//         its own vertex -> row table.
//         gather_face_samples gives the same samples for one list of faces (a segment, or faces a user picked),
//         without walking the other segments.
// Cost:   O(F + V + K) time, the walks divided among the threads; O(F + V x threads) extra memory.
//         gather_face_samples: O(V + the faces') time, O(V) extra memory.
#ifndef PRIMITIVE_EDIT_GATHER_SEGMENT_SAMPLES_H
#define PRIMITIVE_EDIT_GATHER_SEGMENT_SAMPLES_H

#include "common/base/huge_page_vector.h"
#include "common/base/parallel_for.h"

#include <vcg/complex/complex.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <numeric>
#include <vector>

namespace primitive_edit {

struct SegmentSamples
{
  Eigen::MatrixX3d points;
  Eigen::MatrixX3d normals;
  Eigen::VectorXd weights;
  std::vector<int> vertex;
  double area = 0.0;
};

namespace gather_detail {

// The live faces of each segment: segment s has faces[start[s] .. start[s + 1]), in mesh order.
struct FacesBySegment
{
  std::vector<int> start, faces;
};

template <class MeshType>
FacesBySegment group_faces_by_segment(const MeshType& m, const std::vector<int>& segment_of_face, int segment_count)
{
  const std::size_t face_count = m.face.size();
  FacesBySegment out;
  out.start.assign(std::size_t(segment_count) + 1, 0);
  // The segment of each live face, -1 for the rest: the faces themselves are read once.
  std::vector<int> segment = huge_page_vector<int>(face_count);
  for (std::size_t f = 0; f < face_count; ++f) {
    const int s = segment_of_face[f];
    segment[f] = (s >= 0 && s < segment_count && !m.face[f].IsD()) ? s : -1;
    if (segment[f] >= 0)
      ++out.start[std::size_t(s) + 1];
  }
  std::partial_sum(out.start.begin(), out.start.end(), out.start.begin());
  out.faces.resize(std::size_t(out.start.back()));
  std::vector<int> next(out.start.begin(), out.start.end() - 1);
  for (std::size_t f = 0; f < face_count; ++f)
    if (segment[f] >= 0)
      out.faces[std::size_t(next[std::size_t(segment[f])]++)] = int(f);
  return out;
}

// A thread's table costs 4 bytes a vertex, and the largest segment bounds the time whatever the threads (on
// the 1M bracket scan it holds a third of the samples): more threads than this would cost memory for nothing.
constexpr int kMostGatherThreads = 4;

// One thread's tables: local[v] is the row of vertex v in the segment being gathered (-1 between segments).
struct GatherScratch
{
  std::vector<int> local;
  std::vector<Eigen::Vector3d> normal_sum = {};
  std::vector<double> weight_sum = {};
  std::vector<int> rows = {};
};

// The samples of the segment whose faces are [first, last); t.local is all -1 again afterwards.
template <class MeshType>
SegmentSamples gather_one_segment(const MeshType& m, const int* first, const int* last, GatherScratch& t)
{
  auto position = [](const typename MeshType::VertexType* v) {
    return Eigen::Vector3d(double(v->cP()[0]), double(v->cP()[1]), double(v->cP()[2]));
  };
  t.normal_sum.clear();
  t.weight_sum.clear();
  t.rows.clear();
  double area = 0.0;
  for (const int* fi = first; fi != last; ++fi) {
    const auto& f = m.face[std::size_t(*fi)];
    Eigen::Vector3d p[3];
    int vi[3];
    bool ok = true;
    for (int k = 0; k < 3; ++k) {
      vi[k] = int(vcg::tri::Index(m, f.cV(k)));
      p[k] = position(f.cV(k));
      ok = ok && p[k].allFinite();
    }
    const Eigen::Vector3d cross = ok ? Eigen::Vector3d((p[1] - p[0]).cross(p[2] - p[0])) : Eigen::Vector3d::Zero();
    const double face_area = 0.5 * cross.norm();
    area += face_area;
    for (int k = 0; k < 3; ++k) {
      if (!p[k].allFinite())
        continue;
      const std::size_t v = std::size_t(vi[k]);
      if (t.local[v] < 0) {
        t.local[v] = int(t.rows.size());
        t.rows.push_back(vi[k]);
        t.normal_sum.push_back(Eigen::Vector3d::Zero());
        t.weight_sum.push_back(0.0);
      }
      t.normal_sum[std::size_t(t.local[v])] += cross; // |cross| = 2 * area: area-weighted
      t.weight_sum[std::size_t(t.local[v])] += face_area / 3.0;
    }
  }
  SegmentSamples samples;
  const Eigen::Index n = Eigen::Index(t.rows.size());
  samples.points.resize(n, 3);
  samples.normals.resize(n, 3);
  samples.weights.resize(n);
  advise_huge_pages(samples.points.data(), std::size_t(n) * 3 * sizeof(double));
  advise_huge_pages(samples.normals.data(), std::size_t(n) * 3 * sizeof(double));
  samples.vertex = t.rows;
  samples.area = area;
  for (int v : t.rows)
    t.local[std::size_t(v)] = -1;
  for (Eigen::Index r = 0; r < n; ++r) {
    samples.points.row(r) = position(&m.vert[std::size_t(t.rows[std::size_t(r)])]).transpose();
    const double len = t.normal_sum[std::size_t(r)].norm();
    samples.normals.row(r) = len > 0 ? Eigen::RowVector3d(t.normal_sum[std::size_t(r)].transpose() / len)
                                     : Eigen::RowVector3d::Zero();
    samples.weights[r] = t.weight_sum[std::size_t(r)];
  }
  return samples;
}

} // namespace gather_detail

template <class MeshType>
std::vector<SegmentSamples> gather_segment_samples(const MeshType& m, const std::vector<int>& segment_of_face,
                                                   int segment_count, int threads = 1)
{
  std::vector<SegmentSamples> out(size_t(std::max(segment_count, 0)));
  if (segment_count <= 0 || segment_of_face.size() != m.face.size())
    return out;
  const gather_detail::FacesBySegment grouped =
      gather_detail::group_faces_by_segment(m, segment_of_face, segment_count);
  std::vector<std::size_t> face_count(out.size());
  for (std::size_t s = 0; s < out.size(); ++s)
    face_count[s] = std::size_t(grouped.start[s + 1] - grouped.start[s]);
  const int workers = std::min(resolve_thread_count(threads), gather_detail::kMostGatherThreads);
  std::vector<gather_detail::GatherScratch> scratch(std::size_t(std::max(workers, 1)));
  for_each_largest_first(face_count, workers, [&](int worker, std::size_t s) {
    gather_detail::GatherScratch& t = scratch[std::size_t(worker)];
    if (t.local.size() != m.vert.size()) // allocated by its own thread, on its first segment
      t.local = huge_page_vector(m.vert.size(), -1);
    const int* faces = grouped.faces.data();
    out[s] = gather_detail::gather_one_segment(m, faces + grouped.start[s], faces + grouped.start[s + 1], t);
  });
  return out;
}

template <class MeshType>
SegmentSamples gather_face_samples(const MeshType& m, const std::vector<int>& faces)
{
  std::vector<int> live;
  live.reserve(faces.size());
  for (int f : faces)
    if (f >= 0 && std::size_t(f) < m.face.size() && !m.face[std::size_t(f)].IsD())
      live.push_back(f);
  gather_detail::GatherScratch scratch{huge_page_vector(m.vert.size(), -1)};
  return gather_detail::gather_one_segment(m, live.data(), live.data() + live.size(), scratch);
}

} // namespace primitive_edit

#endif
