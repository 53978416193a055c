// growing_faces.h: what segment_by_primitive_growing knows of each face, and whether a face agrees with a
// primitive.
//
// Input:  a vcg triangle mesh, its FaceAdjacency, the passes of normal smoothing and the threads for it.
// Output: GrowingFaces: per face the centroid, the area, the smoothed normal (smooth_face_normals.h) and
//         `valid` (a finite centroid, a defined normal and a positive area; other faces never seed, grow or
//         count in a share) and `deleted` (the mesh's deleted faces, which keep no label). Then the tests the
//         phases share:
//         face_near_primitive the centroid's distance to a primitive and the normals' |cosine| (planes directly);
//         FaceAgreement    whether a face agrees with a primitive: the centroid within tol of it and the
//                          normal within the angle of the primitive's normal there (either side), the angle
//                          widened linearly to twice its value as the distance goes to 0: on a rough scan the
//                          local slope of a face that lies on the surface is noise, while a face of another
//                          surface meeting it at an edge is near it only on a band narrower than tol;
//         sampled_share    the share (by area) of at most kShareSampleCount evenly strided faces that agree;
//                          agreeing_share_reaches, whether that share over all of them reaches a threshold;
//         sampled_rms      the RMS (by area) of those faces' centroid distances to a primitive;
//         face_samples     the centroids, normals and areas of at most max_count evenly strided faces, as
//                          fits take them (of one list, or of two as if joined);
//         face_cost        how badly a primitive explains a face: the centroid's distance plus up to one
//                          tolerance for a normal that disagrees (the order in which leftover faces are
//                          handed out, and the border relaxation's measure);
//         curvature_radius the smallest radius of curvature of a primitive (infinite for planes and cones).
// Cost:   O(F * smoothing passes) for the faces; O(1) per face test.
#ifndef PRIMITIVE_EDIT_GROWING_FACES_H
#define PRIMITIVE_EDIT_GROWING_FACES_H

#include "common/base/constants.h"
#include "common/base/huge_page_vector.h"
#include "common/base/prefetch.h"
#include "common/base/primitive.h"
#include "common/geometry/closest_point_on_primitive.h"
#include "common/mesh/face_adjacency.h"
#include "common/mesh/face_centroids_and_areas.h"
#include "common/mesh/smooth_face_normals.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace primitive_edit {

struct GrowingFaces
{
  std::vector<Eigen::Vector3d> centroid, normal;
  std::vector<double> area;
  std::vector<char> valid;
  std::vector<char> deleted;  // the mesh's deleted faces, which no phase labels
};

constexpr int kShareSampleCount = 2000; // faces sampled_share looks at, at most

template <class MeshType>
GrowingFaces growing_faces(const MeshType& m, const FaceAdjacency& adj, int smoothing_iterations, int threads = 0)
{
  GrowingFaces g;
  const std::size_t n = m.face.size();
  std::vector<Eigen::Vector3d> raw;
  FaceCentroidsAndAreas faces = face_centroids_and_areas(m, threads, &raw);
  g.normal = smooth_face_normals(std::move(raw), faces.area, adj, std::max(0, smoothing_iterations), 180.0, threads);
  g.centroid = std::move(faces.centroid);
  g.area = std::move(faces.area);
  g.deleted = std::move(faces.deleted);
  assign_on_huge_pages(g.valid, n, char(0));
  for (std::size_t f = 0; f < n; ++f) {
    if (g.normal[f].isZero(0.0)) {
      g.centroid[f].setZero();
      g.area[f] = 0.0;
    }
    g.valid[f] = g.area[f] > 0.0 ? 1 : 0;
  }
  return g;
}

// The samples of `first` followed by `second`, taken as from the two lists joined, without joining them: a
// merge test of two regions of a million faces each would otherwise copy both.
inline void face_samples(const GrowingFaces& g, const std::vector<int>& first, const std::vector<int>& second,
                         int max_count, Eigen::MatrixX3d& points, Eigen::MatrixX3d& normals, Eigen::VectorXd& weights)
{
  const std::size_t n = first.size() + second.size();
  const std::size_t count = std::min(n, std::size_t(std::max(1, max_count)));
  points.resize(Eigen::Index(count), 3);
  normals.resize(Eigen::Index(count), 3);
  weights.resize(Eigen::Index(count));
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t j = count == n ? i : (i * n) / count;
    const std::size_t f = std::size_t(j < first.size() ? first[j] : second[j - first.size()]);
    points.row(Eigen::Index(i)) = g.centroid[f].transpose();
    normals.row(Eigen::Index(i)) = g.normal[f].transpose();
    weights[Eigen::Index(i)] = g.area[f];
  }
}

inline void face_samples(const GrowingFaces& g, const std::vector<int>& faces, int max_count,
                         Eigen::MatrixX3d& points, Eigen::MatrixX3d& normals, Eigen::VectorXd& weights)
{
  face_samples(g, faces, {}, max_count, points, normals, weights);
}

// The distance of a face's centroid c to prim and the |cosine| between its normal n and prim's normal there. A
// plane, most regions' primitive, skips the projection's switch and closest point: the same two numbers.
struct FaceNearPrimitive
{
  double distance, cosine;
};

inline FaceNearPrimitive face_near_primitive(const Primitive& prim, const Eigen::Vector3d& c, const Eigen::Vector3d& n)
{
  if (prim.type == PrimitiveType::Plane)
    return {std::abs((c - prim.origin).dot(prim.axis)), std::abs(prim.axis.dot(n))};
  const PrimitiveProjection pr = project_onto_primitive(prim, c);
  return {std::abs(pr.signed_distance), std::abs(pr.normal.dot(n))};
}

// The cosines of the angle bounds are computed once per loop: a normal within the angle agrees
// at any distance within tol and one beyond twice the angle at none, so only the faces between need acos (it
// took 5% of the segmentation). The 1e-9 margins keep every decision the one acos alone gives.
class FaceAgreement
{
public:
  FaceAgreement(double tol, double angle)
      : tol_(tol), angle_(angle), always_(tol > 0 ? std::cos(angle) + 1e-9 : 2.0),
        never_(tol > 0 && 2 * angle < kPi / 2 ? std::cos(2 * angle) - 1e-9 : -1.0)
  {
  }
  bool operator()(const GrowingFaces& g, const Primitive& prim, int f) const
  {
    const FaceNearPrimitive near = face_near_primitive(prim, g.centroid[std::size_t(f)], g.normal[std::size_t(f)]);
    const double d = near.distance;
    if (!(d <= tol_))
      return false;
    const double c = std::min(1.0, near.cosine);
    if (c > always_)
      return true;
    if (c < never_)
      return false;
    return std::acos(c) <= angle_ * (2.0 - d / tol_);
  }

private:
  double tol_, angle_, always_, never_;
};

// The shares' loads are what they wait on: the faces this many places ahead in the list are asked for early
// (prefetch.h), all that a share reads of a face.
constexpr std::size_t kShareAhead = 8;

inline void prefetch_share_face(const GrowingFaces& g, std::size_t f)
{
  prefetch(g.centroid.data() + f);
  prefetch(g.normal.data() + f);
  prefetch(g.area.data() + f);
}

// body(f) for the faces[i * n / count], i = 0 .. count - 1, count = min(n, max_count): evenly strided faces, in
// list order, the faces a few places ahead asked for early.
template <class Body>
void for_each_strided_face(const GrowingFaces& g, const std::vector<int>& faces, std::size_t max_count, Body body)
{
  const std::size_t n = faces.size();
  const std::size_t count = std::min(n, max_count);
  auto at = [&](std::size_t i) { return std::size_t(faces[count == n ? i : (i * n) / count]); };
  for (std::size_t i = 0; i < count; ++i) {
    if (i + kShareAhead < count)
      prefetch_share_face(g, at(i + kShareAhead));
    body(at(i));
  }
}

// Share (by area) of the strided faces (for_each_strided_face) for which holds(f).
template <class Holds>
double strided_share_where(const GrowingFaces& g, const std::vector<int>& faces, std::size_t max_count, Holds holds)
{
  double in = 0, all = 0;
  for_each_strided_face(g, faces, max_count, [&](std::size_t f) {
    all += g.area[f];
    if (holds(int(f)))
      in += g.area[f];
  });
  return all > 0 ? in / all : 0.0;
}

// The same share of the faces that agree with prim.
inline double strided_share(const GrowingFaces& g, const Primitive& prim, const std::vector<int>& faces, double tol,
                            double angle, std::size_t max_count)
{
  const FaceAgreement agrees(tol, angle);
  return strided_share_where(g, faces, max_count, [&](int f) { return agrees(g, prim, f); });
}

// Whether the agreeing share of all `faces` is at least `share`, stopping as soon as that is sure: the area that
// agrees only grows, and once even the faces left cannot lift it to `share` of the total, it never will. The
// sums run in strided_share's order, so every verdict is the one its share gives (the 1e-6 slack covers the
// rounding of the area left). A region's refit and a type change are accepted this way (on the 1M-face peer part
// the shares over every face took 0.065 s of the 0.15 s that growth spent accepting fits). The faces a few places
// ahead in the list are asked for early (prefetch.h), as in strided_share_where.
inline bool agreeing_share_reaches(const GrowingFaces& g, const Primitive& prim, const std::vector<int>& faces,
                                   double tol, double angle, double share)
{
  const std::size_t n = faces.size();
  double all = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (i + 2 * kShareAhead < n)
      prefetch(g.area.data() + faces[i + 2 * kShareAhead]);
    all += g.area[std::size_t(faces[i])];
  }
  if (!(all > 0))
    return 0.0 >= share;
  const FaceAgreement agrees(tol, angle);
  double in = 0, left = all;
  for (std::size_t i = 0; i < n; ++i) {
    const int f = faces[i];
    if (i + kShareAhead < n)
      prefetch_share_face(g, std::size_t(faces[i + kShareAhead]));
    if (in / all >= share)
      return true;
    if (in + left + 1e-6 * all < share * all)
      return false;
    left -= g.area[std::size_t(f)];
    if (agrees(g, prim, f))
      in += g.area[std::size_t(f)];
  }
  return in / all >= share;
}

inline double sampled_share(const GrowingFaces& g, const Primitive& prim, const std::vector<int>& faces, double tol,
                            double angle)
{
  return strided_share(g, prim, faces, tol, angle, kShareSampleCount);
}

// The RMS (by area) of the centroid distances to prim of the strided faces sampled_share takes.
inline double sampled_rms(const GrowingFaces& g, const Primitive& prim, const std::vector<int>& faces)
{
  double squares = 0, all = 0;
  for_each_strided_face(g, faces, kShareSampleCount, [&](std::size_t f) {
    const double d = face_near_primitive(prim, g.centroid[f], g.normal[f]).distance;
    squares += g.area[f] * d * d;
    all += g.area[f];
  });
  return all > 0 ? std::sqrt(squares / all) : 0.0;
}

inline double face_cost(const GrowingFaces& g, const Primitive& prim, int f, double tol)
{
  if (!g.valid[std::size_t(f)])
    return std::numeric_limits<double>::max();
  const FaceNearPrimitive near = face_near_primitive(prim, g.centroid[std::size_t(f)], g.normal[std::size_t(f)]);
  return near.distance + tol * (1.0 - near.cosine);
}

inline double curvature_radius(const Primitive& p)
{
  switch (p.type) {
  case PrimitiveType::Sphere:
  case PrimitiveType::Cylinder: return p.radius;
  case PrimitiveType::Torus: return p.minor_radius;
  default: return std::numeric_limits<double>::infinity();
  }
}

} // namespace primitive_edit

#endif
