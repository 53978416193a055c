// locate_on_surface.h: the point of a triangle surface nearest to a query point, found by walking from a face
// near it, so that a point that moves a little at a time is followed at almost no cost.
//
// Input:  `position(v)` (a vertex's position, Eigen::Vector3d), face_vertex (3 vertex indices per face, -1 = a
//         dead face) and its VertexFaces, `enters(f)` (whether face f belongs to the surface), a start face of
//         the surface and the query point p.
// Output: SurfaceLocation: the face where the walk stopped and the point of that face nearest to p (p itself
//         when p lies on it). On a surface that is flat or gently curved around p, that point is the nearest
//         point of the whole surface; the walk does not search beyond its path.
// Method: a visibility walk (Devillers, Pion, Teillaud, "Walking in a triangulation", 2002) over the surface:
//         p is projected onto the current face's plane; while one of its barycentric coordinates is negative,
//         the walk crosses the edge opposite the most negative one into the surface's face beyond it. It
//         stops on a face that holds the projection (the answer), at a face of zero area (its nearest corner),
//         or at the surface's border or after max_steps faces (a walk that cycles on a folded surface); then a
//         descent moves to a face sharing a corner whose nearest point is nearer, while one is, at most
//         max_steps times (along a border the nearest point can be on faces the walk did not cross).
// Cost:   O(faces walked x faces around an edge's endpoint); at a border, O(descent steps x faces around a face).
#ifndef PRIMITIVE_EDIT_LOCATE_ON_SURFACE_H
#define PRIMITIVE_EDIT_LOCATE_ON_SURFACE_H

#include "common/geometry/closest_point_on_triangle.h"
#include "common/mesh/vertex_faces.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstddef>
#include <vector>

namespace primitive_edit {

struct SurfaceLocation
{
  int face = -1;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
};

template <class Position, class Enters>
SurfaceLocation locate_on_surface(Position&& position, const std::vector<int>& face_vertex,
                                  const VertexFaces& vertex_faces, Enters&& enters, int start_face,
                                  const Eigen::Vector3d& p, int max_steps = 64)
{
  auto corner = [&](int f, int k) { return face_vertex[3 * std::size_t(f) + std::size_t(k)]; };
  // The face of the surface other than f on the edge (a, b), or -1.
  auto across = [&](int f, int a, int b) {
    for (int i = vertex_faces.offset[std::size_t(a)]; i < vertex_faces.offset[std::size_t(a) + 1]; ++i) {
      const int g = vertex_faces.face[std::size_t(i)];
      if (g != f && (corner(g, 0) == b || corner(g, 1) == b || corner(g, 2) == b) && enters(g))
        return g;
    }
    return -1;
  };
  SurfaceLocation at;
  at.face = start_face;
  for (int step = 0;; ++step) {
    const int f = at.face;
    const Eigen::Vector3d a = position(corner(f, 0)), b = position(corner(f, 1)), c = position(corner(f, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a);
    const double area2 = n.squaredNorm();
    if (!(area2 > 0)) { // a degenerate face: its nearest corner
      at.point = a;
      for (const Eigen::Vector3d& q : {b, c})
        if ((q - p).squaredNorm() < (at.point - p).squaredNorm())
          at.point = q;
      return at;
    }
    // Barycentric coordinates of p's projection: the signed areas of the sub-triangles opposite each corner.
    const double w[3] = {(c - b).cross(p - b).dot(n) / area2, (a - c).cross(p - c).dot(n) / area2,
                         (b - a).cross(p - a).dot(n) / area2};
    int most_negative = -1;
    for (int k = 0; k < 3; ++k)
      if (w[k] < 0 && (most_negative < 0 || w[k] < w[most_negative]))
        most_negative = k;
    if (most_negative < 0) {
      at.point = closest_point_on_triangle(p, a, b, c);
      return at;
    }
    const int next = step < max_steps
                         ? across(f, corner(f, (most_negative + 1) % 3), corner(f, (most_negative + 2) % 3))
                         : -1;
    if (next < 0)
      break;
    at.face = next;
  }
  // Stopped outside the face: at the surface's border the nearest point may lie along it, on faces the walk
  // did not reach. Descend: move to a face sharing a corner whose nearest point is nearer, while there is one.
  auto nearest_on = [&](int f, Eigen::Vector3d& q) {
    const Eigen::Vector3d a = position(corner(f, 0)), b = position(corner(f, 1)), c = position(corner(f, 2));
    if (!((b - a).cross(c - a).squaredNorm() > 0))
      return false;
    q = closest_point_on_triangle(p, a, b, c);
    return true;
  };
  nearest_on(at.face, at.point);
  for (int step = 0; step < max_steps; ++step) {
    double best = (at.point - p).squaredNorm();
    int better = -1;
    Eigen::Vector3d q;
    for (int k = 0; k < 3; ++k) {
      const int v = corner(at.face, k);
      for (int i = vertex_faces.offset[std::size_t(v)]; i < vertex_faces.offset[std::size_t(v) + 1]; ++i) {
        const int g = vertex_faces.face[std::size_t(i)];
        if (g != at.face && enters(g) && nearest_on(g, q) && (q - p).squaredNorm() < best) {
          best = (q - p).squaredNorm();
          better = g;
          at.point = q;
        }
      }
    }
    if (better < 0)
      return at;
    at.face = better;
  }
  return at;
}

} // namespace primitive_edit

#endif
