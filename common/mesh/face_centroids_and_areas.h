// face_centroids_and_areas.h: the centroid and area of every face of a mesh, in double precision.
//
// Input:  a vcg triangle mesh.
// Output: centroid[f] and area[f] for f = vcg::tri::Index(m, face). A face that is deleted, lacks a vertex,
//         or whose centroid or area is not finite gets centroid (0, 0, 0) and area 0; a degenerate face gets
//         its centroid and area 0. So area[f] > 0 marks exactly the faces with a usable centroid and plane.
// Cost:   O(F).
#ifndef PRIMITIVE_EDIT_FACE_CENTROIDS_AND_AREAS_H
#define PRIMITIVE_EDIT_FACE_CENTROIDS_AND_AREAS_H

#include "common/base/huge_page_vector.h"

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
};

// The centroid and area of one face, as face_centroids_and_areas gives them; false (and nothing written) for a
// face that is deleted, lacks a vertex, or whose centroid or area is not finite.
template <class FaceType>
bool face_centroid_and_area(const FaceType& face, Eigen::Vector3d& centroid, double& area)
{
  if (face.IsD() || face.cV(0) == nullptr || face.cV(1) == nullptr || face.cV(2) == nullptr)
    return false;
  Eigen::Vector3d p[3];
  for (int k = 0; k < 3; ++k)
    p[k] = Eigen::Vector3d(double(face.cP(k)[0]), double(face.cP(k)[1]), double(face.cP(k)[2]));
  const double a = 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).norm();
  const Eigen::Vector3d c = (p[0] + p[1] + p[2]) / 3.0;
  if (!std::isfinite(a) || !c.allFinite())
    return false;
  centroid = c;
  area = a;
  return true;
}

template <class MeshType>
FaceCentroidsAndAreas face_centroids_and_areas(const MeshType& m)
{
  const std::size_t n = m.face.size();
  FaceCentroidsAndAreas out;
  assign_on_huge_pages(out.centroid, n, Eigen::Vector3d(Eigen::Vector3d::Zero()));
  assign_on_huge_pages(out.area, n, 0.0);
  for (std::size_t f = 0; f < n; ++f)
    face_centroid_and_area(m.face[f], out.centroid[f], out.area[f]);
  return out;
}

} // namespace primitive_edit

#endif
