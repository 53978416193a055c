// segment_by_normal_angle.h: the paper's automatic segmentation (Yang, Oh, Choi, section 2.1), with defaults that
// adapt it to noisy meshes.
//
// Input:  a vcg triangle mesh, optionally its FaceAdjacency (built here otherwise), and parameters:
//         angle_deg            two adjacent faces join when the angle between their smoothed normals is below it;
//         smoothing_iterations passes of normal averaging against scan noise:
//                              >= 0: the paper's method with that many passes of smooth_face_normals. Averaging
//                              skips neighbours beyond a crease angle of min(2 * angle_deg, 80) degrees, so that
//                              smoothing never blurs a sharp edge into a ramp of small steps the flood fill
//                              would walk across;
//                              < 0 (default): automatic. Without measurable noise, the paper's method with
//                              kPaperSmoothingPasses passes. On a noisy mesh (noise_scaled_normals.h) the passes
//                              grow with (noise / triangle size)^2, average over all neighbours (each face's own
//                              normal is off by more than any crease), and the fill does not enter the edge
//                              faces, where the normal turns as across a smoothed edge of angle_deg; after the
//                              fill they go to the neighbouring segment with the closest normal
//                              (assign_edge_faces.h);
//         min_segment_faces    segments with fewer faces are absorbed by the neighbouring segment with which
//                              they share the longest border (repeatedly, smallest first, until none is left
//                              or a small segment has no neighbour at all); < 0 (default): kMinSegmentShare of
//                              the faces, at least kMinSegmentFacesFloor, and with noise-scaled smoothing at
//                              least kMinSegmentFacesPerPass per pass.
//         check_normal_angle_params refuses values out of the filter's ranges, for adapters to call first.
// Output: segment_of_face (indexed by vcg::tri::Index): dense ids 0..K-1, -1 for deleted faces. Returns K.
//         The optional report holds the passes, the noise and the smallest segment size an automatic run chose.
//         Faces without a defined normal (zero area, NaN coordinates) join no neighbour in the flood fill; they
//         start as single-face segments and are absorbed like any small segment (with noise-scaled smoothing
//         they are edge faces, handed to a neighbouring segment). An adjacency whose size does
//         not match the mesh gives 0 and every face -1.
//         Measured at the defaults (bench/README.md): the peer part, 1M faces with noise 0.05 mm, gives its 12
//         surfaces (before: 7230 segments, none of them a surface); without noise, the same 12 as before.
// Complexity: O(F) for adjacency, smoothing and the iterative (explicit stack) flood fill; the absorption runs
//         in rounds, each linear in the faces of the still-small segments, with at least half of them merged
//         per round. Automatic smoothing adds the noise estimate (O(F)), its passes (O(passes * F), on every
//         core; the result does not depend on the thread count) and the edge faces' rounds. No maps.
#ifndef PRIMITIVE_EDIT_SEGMENT_BY_NORMAL_ANGLE_H
#define PRIMITIVE_EDIT_SEGMENT_BY_NORMAL_ANGLE_H

#include "common/base/constants.h"
#include "common/base/find_root.h"
#include "common/base/progress.h"
#include "common/base/status.h"
#include "common/mesh/compact_segment_ids.h"
#include "common/mesh/face_adjacency.h"
#include "common/mesh/smooth_face_normals.h"
#include "common/segment/assign_edge_faces.h"
#include "common/segment/noise_scaled_normals.h"

#include <Eigen/Core>
#include <vcg/complex/complex.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

namespace primitive_edit {

struct SegmentByNormalAngleParams
{
  double angle_deg = 20.0;
  int smoothing_iterations = -1;  // < 0: automatic, from the noise (noise_scaled_normals.h)
  int min_segment_faces = -1;     // < 0: automatic, kMinSegmentShare of the faces, at least kMinSegmentFacesFloor
};

// What an automatic run chose, for the caller's log.
struct SegmentByNormalAngleReport
{
  int smoothing_passes = 0;   // passes of normal averaging used
  bool edge_faces = false;    // true: noise-scaled averaging, edge faces handed out after the fill
  double noise = 0;           // the noise measured (automatic smoothing only)
  int min_segment_faces = 0;  // the smallest segment kept
};

// The automatic smallest segment: a share of the faces, so that a finer mesh of the same part loses the same
// specks; the floor keeps small meshes' behaviour (the paper's fixed size). After noise-scaled smoothing, a
// corner where three edges' ramps meet leaves a patch of edge-like normals about as large as the averaging's
// reach, whose area in faces grows with the passes (noisy cube, 14 passes: patches of 33 to 105 faces).
constexpr double kMinSegmentShare = 1.0 / 2000.0;
constexpr int kMinSegmentFacesFloor = 30;
constexpr int kMinSegmentFacesPerPass = 10;

// The ranges a user's parameters must lie in; the segmentation itself keeps within them whatever it is given
// (for the fuzz target), so adapters check first and refuse, rather than have a number silently changed.
constexpr double kMinNormalAngleDeg = 0.0, kMaxNormalAngleDeg = 180.0;  // both excluded
constexpr int kMaxNormalSmoothingSteps = 1000;

// Refuses parameters out of range, naming them as the filter's dialog does.
Status check_normal_angle_params(const SegmentByNormalAngleParams& params);

namespace detail {

// Length of the edge faces f and g share (0 when it is not finite); fv holds 3 vertex indices per face.
template <class MeshType>
double shared_edge_length(const MeshType& m, const std::vector<int>& fv, int f, int g)
{
  const int* a = &fv[3 * std::size_t(f)];
  const int* b = &fv[3 * std::size_t(g)];
  for (int k = 0; k < 3; ++k) {
    const int u = a[k];
    const int v = a[(k + 1) % 3];
    if (u == v || (b[0] != u && b[1] != u && b[2] != u) || (b[0] != v && b[1] != v && b[2] != v))
      continue;
    const auto d = m.vert[std::size_t(u)].cP() - m.vert[std::size_t(v)].cP();
    const double length = std::sqrt(double(d[0]) * double(d[0]) + double(d[1]) * double(d[1]) +
                                     double(d[2]) * double(d[2]));
    return std::isfinite(length) ? length : 0.0;
  }
  return 0.0;
}

// Per segment, the border length and edge count shared with the segment being absorbed; zero between calls.
struct BorderScratch
{
  explicit BorderScratch(std::size_t segments) : length(segments, 0.0), edges(segments, 0) {}
  std::vector<double> length;
  std::vector<int> edges;
  std::vector<int> touched;
};

// The segment (a root of parent) other than r that shares the longest border with the faces [first, last) of
// r, ties to the most edges; -1 when none borders them.
template <class MeshType>
int neighbour_with_longest_border(const MeshType& m, const FaceAdjacency& adj, const std::vector<int>& fv,
                                  const int* first, const int* last, const std::vector<int>& segment_of_face,
                                  std::vector<int>& parent, int r, BorderScratch& scratch)
{
  for (const int* face = first; face != last; ++face) {
    const int f = *face;
    for (int k = adj.offset[std::size_t(f)]; k < adj.offset[std::size_t(f) + 1]; ++k) {
      const int g = adj.neighbour[std::size_t(k)];
      const int sg = segment_of_face[std::size_t(g)];
      if (sg < 0)
        continue;
      const int s = find_root(parent, sg);
      if (s == r)
        continue;
      if (scratch.edges[std::size_t(s)] == 0)
        scratch.touched.push_back(s);
      scratch.length[std::size_t(s)] += shared_edge_length(m, fv, f, g);
      ++scratch.edges[std::size_t(s)];
    }
  }
  int best = -1;
  for (int s : scratch.touched)
    if (best < 0 || scratch.length[std::size_t(s)] > scratch.length[std::size_t(best)] ||
        (scratch.length[std::size_t(s)] == scratch.length[std::size_t(best)] &&
         scratch.edges[std::size_t(s)] > scratch.edges[std::size_t(best)]))
      best = s;
  for (int s : scratch.touched) {
    scratch.length[std::size_t(s)] = 0.0;
    scratch.edges[std::size_t(s)] = 0;
  }
  scratch.touched.clear();
  return best;
}

// Absorbs segments smaller than min_faces into the neighbour segment with the longest shared border.
// segment_of_face holds ids 0..K-1 (or -1); ids are left uncompacted.
template <class MeshType>
void absorb_small_segments(const MeshType& m, const FaceAdjacency& adj, int min_faces,
                           std::vector<int>& segment_of_face, int segment_count)
{
  const std::size_t K = std::size_t(segment_count);
  std::vector<int> size(K, 0);
  for (int s : segment_of_face)
    if (s >= 0)
      ++size[std::size_t(s)];
  std::vector<int> parent(K);
  for (std::size_t s = 0; s < K; ++s)
    parent[s] = int(s);
  std::vector<char> isolated(K, 0);

  const std::vector<int> fv = face_vertex_indices(m);
  // Faces that may still belong to a small segment; segments only grow, so the list only shrinks.
  std::vector<int> candidates;
  for (std::size_t f = 0; f < segment_of_face.size(); ++f) {
    const int s = segment_of_face[f];
    if (s >= 0 && size[std::size_t(s)] < min_faces)
      candidates.push_back(int(f));
  }

  std::vector<int> small_roots, slot(K, -1), face_offset, faces;
  BorderScratch scratch(K);
  for (;;) {
    // Group the candidate faces by their current (small, not isolated) root.
    small_roots.clear();
    std::size_t kept = 0;
    for (int f : candidates) {
      const int r = find_root(parent, segment_of_face[std::size_t(f)]);
      if (size[std::size_t(r)] >= min_faces || isolated[std::size_t(r)])
        continue;
      candidates[kept++] = f;
      if (slot[std::size_t(r)] < 0) {
        slot[std::size_t(r)] = int(small_roots.size());
        small_roots.push_back(r);
      }
    }
    candidates.resize(kept);
    if (small_roots.empty())
      break;
    face_offset.assign(small_roots.size() + 1, 0);
    for (int f : candidates)
      ++face_offset[std::size_t(slot[std::size_t(find_root(parent, segment_of_face[std::size_t(f)]))]) + 1];
    for (std::size_t i = 0; i < small_roots.size(); ++i)
      face_offset[i + 1] += face_offset[i];
    faces.resize(candidates.size());
    {
      std::vector<int> cursor(face_offset.begin(), face_offset.end() - 1);
      for (int f : candidates)
        faces[std::size_t(cursor[std::size_t(slot[std::size_t(find_root(parent, segment_of_face[std::size_t(f)]))])]++)] = f;
    }
    std::vector<int> order(small_roots.size());
    for (std::size_t i = 0; i < order.size(); ++i)
      order[i] = int(i);
    std::sort(order.begin(), order.end(), [&](int a, int b) {
      const int ra = small_roots[std::size_t(a)], rb = small_roots[std::size_t(b)];
      return size[std::size_t(ra)] != size[std::size_t(rb)] ? size[std::size_t(ra)] < size[std::size_t(rb)] : ra < rb;
    });

    bool merged = false;
    for (int i : order) {
      const int r = small_roots[std::size_t(i)];
      if (parent[std::size_t(r)] != r || size[std::size_t(r)] >= min_faces)
        continue; // absorbed by, or grown through, an earlier merge of this round
      const int best = neighbour_with_longest_border(m, adj, fv, faces.data() + face_offset[std::size_t(i)],
                                                     faces.data() + face_offset[std::size_t(i) + 1],
                                                     segment_of_face, parent, r, scratch);
      if (best < 0) {
        // Adjacency is symmetric, so a segment nobody borders now is a whole component: it stays.
        isolated[std::size_t(r)] = 1;
        continue;
      }
      parent[std::size_t(r)] = best;
      size[std::size_t(best)] += size[std::size_t(r)];
      merged = true;
    }
    for (int r : small_roots)
      slot[std::size_t(r)] = -1;
    if (!merged)
      break;
  }
  for (int& s : segment_of_face)
    if (s >= 0)
      s = find_root(parent, s);
}

// The flood fill: from each face not yet in a segment (and not blocked), in index order, a segment takes every
// neighbour that is not blocked and whose normal is within the angle (min_cos: its cosine). Returns the
// segments' count; faces left out keep -1.
template <class MeshType>
int flood_segments(const MeshType& m, const FaceAdjacency& adj, const std::vector<Eigen::Vector3d>& normal,
                   double min_cos, const std::vector<char>& blocked, std::vector<int>& segment_of_face,
                   int segment_count, const Progress& progress)
{
  const int face_count = int(m.face.size());
  std::vector<int> stack;
  int visited = 0;
  for (int seed = 0; seed < face_count; ++seed) {
    if (m.face[std::size_t(seed)].IsD() || segment_of_face[std::size_t(seed)] >= 0 || blocked[std::size_t(seed)])
      continue;
    const int id = segment_count++;
    segment_of_face[std::size_t(seed)] = id;
    stack.push_back(seed);
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      if ((++visited & 0xFFFF) == 0)
        report_progress(progress, 30 + int(40.0 * visited / face_count), "Growing segments");
      const Eigen::Vector3d& nf = normal[std::size_t(f)];
      if (nf.isZero(0.0))
        continue;
      for (int k = adj.offset[std::size_t(f)]; k < adj.offset[std::size_t(f) + 1]; ++k) {
        const int g = adj.neighbour[std::size_t(k)];
        if (segment_of_face[std::size_t(g)] >= 0 || blocked[std::size_t(g)])
          continue;
        const Eigen::Vector3d& ng = normal[std::size_t(g)];
        // Comparing the dot product with cos(angle) needs no acos; zero normals give 0 and never pass
        // for angles below 90 degrees, and are excluded explicitly above that.
        if (nf.dot(ng) > min_cos && !ng.isZero(0.0)) {
          segment_of_face[std::size_t(g)] = id;
          stack.push_back(g);
        }
      }
    }
  }
  return segment_count;
}

// The smallest segment kept: the parameter, or when automatic a share of the faces (at least
// kMinSegmentFacesFloor), and after noise-scaled smoothing at least kMinSegmentFacesPerPass per pass.
int min_segment_size(int min_segment_faces, int face_count, int noise_passes);

} // namespace detail

template <class MeshType>
int segment_by_normal_angle(const MeshType& m, const FaceAdjacency& adj, const SegmentByNormalAngleParams& params,
                            std::vector<int>& segment_of_face, const Progress& progress = {},
                            SegmentByNormalAngleReport* report = nullptr)
{
  const int face_count = int(m.face.size());
  segment_of_face.assign(std::size_t(face_count), -1);
  if (adj.face_count() != face_count)
    return 0; // adjacency of another mesh: nothing sensible to do

  report_progress(progress, 0, "Smoothing face normals");
  NoiseScaledNormals smoothed;
  if (params.smoothing_iterations < 0)
    smoothed = noise_scaled_normals(m, adj, params.angle_deg);
  const int passes = params.smoothing_iterations >= 0 ? params.smoothing_iterations : kPaperSmoothingPasses;
  if (smoothed.passes == 0) {
    // The paper's method: averaging skips neighbours beyond the crease, so that it never blurs a sharp edge
    // into a ramp of small steps the flood fill would walk across.
    const double crease = std::min(2.0 * params.angle_deg, 80.0);
    smoothed.normal = smooth_face_normals(m, adj, passes, crease);
    smoothed.edge_face.assign(std::size_t(face_count), 0);
  }

  report_progress(progress, 30, "Growing segments");
  const double min_cos = std::cos(radians_from_degrees(params.angle_deg));
  int segment_count =
      detail::flood_segments(m, adj, smoothed.normal, min_cos, smoothed.edge_face, segment_of_face, 0, progress);
  if (smoothed.passes > 0) {
    assign_edge_faces(adj, smoothed.normal, segment_of_face);
    // Edge faces with no segment around them (a component that is all edge) are filled the paper's way; few
    // faces, so no progress reports (they would restart below the fill's).
    const std::vector<char> none(std::size_t(face_count), 0);
    segment_count = detail::flood_segments(m, adj, smoothed.normal, min_cos, none, segment_of_face, segment_count, {});
  }

  const int min_faces = detail::min_segment_size(params.min_segment_faces, face_count, smoothed.passes);
  if (min_faces > 1 && segment_count > 1) {
    report_progress(progress, 70, "Absorbing small segments");
    detail::absorb_small_segments(m, adj, min_faces, segment_of_face, segment_count);
  }
  const int K = compact_segment_ids(segment_of_face);
  if (report != nullptr)
    *report = {smoothed.passes > 0 ? smoothed.passes : passes, smoothed.passes > 0, smoothed.noise, min_faces};
  report_progress(progress, 100, "Segmentation done");
  return K;
}

template <class MeshType>
int segment_by_normal_angle(const MeshType& m, const SegmentByNormalAngleParams& params,
                            std::vector<int>& segment_of_face, const Progress& progress = {},
                            SegmentByNormalAngleReport* report = nullptr)
{
  report_progress(progress, 0, "Building face adjacency");
  const FaceAdjacency adj = build_face_adjacency(m);
  return segment_by_normal_angle(m, adj, params, segment_of_face, progress, report);
}

} // namespace primitive_edit

#endif
