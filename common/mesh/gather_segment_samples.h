// gather_segment_samples.h: the points a primitive is fitted to, per segment.
//
// Input:  a vcg triangle mesh, `segment_of_face` (index = vcg::tri::Index(m, face), -1 = none) and the
//         segment count K.
// Output: for each segment k, the vertices of its faces, each once, with
//         - normals: the area-weighted mean of the normals of the segment's own faces around the vertex
//           (faces of other segments are left out, so a vertex on an edge gets the normal of this side),
//         - weights: a third of the area of those faces (the vertex's share of the segment's surface),
//         - vertex:  the mesh index of each vertex, and `area`, the segment's area.
//         Degenerate faces add nothing to normals and weights; vertices with non-finite coordinates are
//         skipped.
// Cost:   O(F + V + K) time, O(F + V) extra memory.
#ifndef PRIMITIVE_EDIT_GATHER_SEGMENT_SAMPLES_H
#define PRIMITIVE_EDIT_GATHER_SEGMENT_SAMPLES_H

#include "common/base/huge_page_vector.h"

#include <vcg/complex/complex.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

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

template <class MeshType>
std::vector<SegmentSamples> gather_segment_samples(const MeshType& m, const std::vector<int>& segment_of_face,
                                                   int segment_count)
{
  std::vector<SegmentSamples> out(size_t(std::max(segment_count, 0)));
  const size_t face_count = m.face.size();
  if (segment_count <= 0 || segment_of_face.size() != face_count)
    return out;

  // Faces grouped by segment by a counting sort, so each segment is one contiguous run.
  std::vector<int> start(size_t(segment_count) + 1, 0);
  for (size_t f = 0; f < face_count; ++f) {
    const int s = segment_of_face[f];
    if (s >= 0 && s < segment_count && !m.face[f].IsD())
      ++start[size_t(s) + 1];
  }
  for (int s = 0; s < segment_count; ++s)
    start[size_t(s) + 1] += start[size_t(s)];
  std::vector<int> faces(size_t(start.back()));
  {
    std::vector<int> next(start.begin(), start.end() - 1);
    for (size_t f = 0; f < face_count; ++f) {
      const int s = segment_of_face[f];
      if (s >= 0 && s < segment_count && !m.face[f].IsD())
        faces[size_t(next[size_t(s)]++)] = int(f);
    }
  }

  auto finite = [](const Eigen::Vector3d& p) { return p.allFinite(); };
  auto position = [&](const typename MeshType::VertexType* v) {
    return Eigen::Vector3d(double(v->cP()[0]), double(v->cP()[1]), double(v->cP()[2]));
  };

  // local[v] is the row of vertex v in the current segment; stamp[v] says which segment set it.
  std::vector<int> local = huge_page_vector(m.vert.size(), -1), stamp = huge_page_vector(m.vert.size(), -1);
  std::vector<Eigen::Vector3d> normal_sum;
  std::vector<double> weight_sum;
  std::vector<int> rows;
  for (int s = 0; s < segment_count; ++s) {
    normal_sum.clear();
    weight_sum.clear();
    rows.clear();
    double area = 0.0;
    for (int i = start[size_t(s)]; i < start[size_t(s) + 1]; ++i) {
      const auto& f = m.face[size_t(faces[size_t(i)])];
      Eigen::Vector3d p[3];
      int vi[3];
      bool ok = true;
      for (int k = 0; k < 3; ++k) {
        vi[k] = int(vcg::tri::Index(m, f.cV(k)));
        p[k] = position(f.cV(k));
        ok = ok && finite(p[k]);
      }
      const Eigen::Vector3d cross = ok ? Eigen::Vector3d((p[1] - p[0]).cross(p[2] - p[0])) : Eigen::Vector3d::Zero();
      const double face_area = 0.5 * cross.norm();
      area += face_area;
      for (int k = 0; k < 3; ++k) {
        if (!finite(p[k]))
          continue;
        if (stamp[size_t(vi[k])] != s) {
          stamp[size_t(vi[k])] = s;
          local[size_t(vi[k])] = int(rows.size());
          rows.push_back(vi[k]);
          normal_sum.push_back(Eigen::Vector3d::Zero());
          weight_sum.push_back(0.0);
        }
        const int r = local[size_t(vi[k])];
        normal_sum[size_t(r)] += cross; // |cross| = 2 * area: area-weighted
        weight_sum[size_t(r)] += face_area / 3.0;
      }
    }
    SegmentSamples& samples = out[size_t(s)];
    const Eigen::Index n = Eigen::Index(rows.size());
    samples.points.resize(n, 3);
    samples.normals.resize(n, 3);
    samples.weights.resize(n);
    advise_huge_pages(samples.points.data(), std::size_t(n) * 3 * sizeof(double));
    advise_huge_pages(samples.normals.data(), std::size_t(n) * 3 * sizeof(double));
    samples.vertex = rows;
    samples.area = area;
    for (Eigen::Index r = 0; r < n; ++r) {
      samples.points.row(r) = position(&m.vert[size_t(rows[size_t(r)])]).transpose();
      const double len = normal_sum[size_t(r)].norm();
      samples.normals.row(r) = len > 0 ? Eigen::RowVector3d(normal_sum[size_t(r)].transpose() / len)
                                       : Eigen::RowVector3d::Zero();
      samples.weights[r] = weight_sum[size_t(r)];
    }
  }
  return out;
}

} // namespace primitive_edit

#endif
