// mesh_input_problem.h: why a mesh cannot be processed, in words for MeshLab's log, or "" when it can.
//
// Input:  any vcg triangle mesh.
// Output: "" when the mesh has at least one live face and every vertex used by a live face has finite
//         coordinates; otherwise a sentence naming the first problem found (with counts).
//         Degenerate and non-manifold faces are not problems here: every algorithm of common/ copes
//         with them, and real scans have a few.
// Cost:   O(F).
#ifndef PRIMITIVE_EDIT_MESH_INPUT_PROBLEM_H
#define PRIMITIVE_EDIT_MESH_INPUT_PROBLEM_H

#include <vcg/complex/complex.h>

#include <cmath>
#include <string>

namespace primitive_edit {

template <class MeshType>
std::string mesh_input_problem(const MeshType& m)
{
  if (m.fn == 0)
    return m.vn == 0 ? "the mesh is empty" : "the mesh has no faces (it is a point cloud)";
  size_t bad_faces = 0;
  for (const auto& f : m.face) {
    if (f.IsD())
      continue;
    for (int k = 0; k < 3; ++k) {
      const auto& p = f.cV(k)->cP();
      if (!std::isfinite(double(p[0])) || !std::isfinite(double(p[1])) || !std::isfinite(double(p[2]))) {
        ++bad_faces;
        break;
      }
    }
  }
  if (bad_faces > 0)
    return std::to_string(bad_faces) + " faces have NaN or infinite vertex coordinates; "
           "remove them first (e.g. Filters > Cleaning and Repairing)";
  return "";
}

} // namespace primitive_edit

#endif
