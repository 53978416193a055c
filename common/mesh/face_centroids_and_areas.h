// face_centroids_and_areas.h: the centroid and area of every face of a mesh, in double precision, and on request
// its unit normal.
//
// Input:  a vcg triangle mesh, the threads (parallel_for.h; <= 0: all), optionally a vector for the normals.
// Output: centroid[f] and area[f] for f = vcg::tri::Index(m, face). A face that is deleted, lacks a vertex,
//         or whose centroid or area is not finite gets centroid (0, 0, 0) and area 0; a degenerate face gets
//         its centroid and area 0. So area[f] > 0 marks exactly the faces with a usable centroid and plane.
//         deleted[f] is 1 for a deleted face: read in the same pass, as a caller that must tell deleted faces
//         from unusable ones would otherwise read every face again (a 4M-face mesh's faces are 0.4 GB).
//         The normals, when asked for: the unit normal of each face with area > 0 (the same cross product as
//         the area), the zero vector for the others. A caller that needs both (the segmentations) reads the
//         vertices once.
// Cost:   O(F) divided by the threads; each face writes only its own entries, so every thread count gives the
//         same arrays.
#ifndef PRIMITIVE_EDIT_FACE_CENTROIDS_AND_AREAS_H
#define PRIMITIVE_EDIT_FACE_CENTROIDS_AND_AREAS_H

#include "common/base/huge_page_vector.h"
#include "common/base/parallel_for.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vcg/complex/complex.h>

#include <cmath>
#include <vector>

namespace primitive_edit {

struct FaceCentroidsAndAreas
{
  std::vector<Eigen::Vector3d> centroid;
  std::vector<double> area;
  std::vector<char> deleted;
};

// The centroid, area and (when asked for) unit normal of one face, as face_centroids_and_areas gives them; false
// (and nothing written) for a face that is deleted, lacks a vertex, or whose centroid or area is not finite.
template <class FaceType>
bool face_centroid_and_area(const FaceType& face, Eigen::Vector3d& centroid, double& area,
                            Eigen::Vector3d* unit_normal = nullptr)
{
  if (face.IsD() || face.cV(0) == nullptr || face.cV(1) == nullptr || face.cV(2) == nullptr)
    return false;
  Eigen::Vector3d p[3];
  for (int k = 0; k < 3; ++k)
    p[k] = Eigen::Vector3d(double(face.cP(k)[0]), double(face.cP(k)[1]), double(face.cP(k)[2]));
  const Eigen::Vector3d cross = (p[1] - p[0]).cross(p[2] - p[0]);
  const double length = cross.norm();
  const double a = 0.5 * length;
  const Eigen::Vector3d c = (p[0] + p[1] + p[2]) / 3.0;
  if (!std::isfinite(a) || !c.allFinite())
    return false;
  centroid = c;
  area = a;
  if (unit_normal && length > 0.0)
    *unit_normal = cross / length;
  return true;
}

template <class MeshType>
FaceCentroidsAndAreas face_centroids_and_areas(const MeshType& m, int threads = 0,
                                               std::vector<Eigen::Vector3d>* unit_normals = nullptr)
{
  const std::size_t n = m.face.size();
  FaceCentroidsAndAreas out;
  assign_on_huge_pages(out.centroid, n, Eigen::Vector3d(Eigen::Vector3d::Zero()));
  assign_on_huge_pages(out.area, n, 0.0);
  assign_on_huge_pages(out.deleted, n, char(0));
  if (unit_normals)
    assign_on_huge_pages(*unit_normals, n, Eigen::Vector3d(Eigen::Vector3d::Zero()));
  parallel_for(n, threads, kFacesPerThread, [&](std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f) {
      out.deleted[f] = m.face[f].IsD() ? 1 : 0;
      face_centroid_and_area(m.face[f], out.centroid[f], out.area[f], unit_normals ? &(*unit_normals)[f] : nullptr);
    }
  });
  return out;
}

} // namespace primitive_edit

#endif
