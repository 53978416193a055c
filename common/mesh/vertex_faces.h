// vertex_faces.h: the faces around each vertex, as a compressed (CSR) table.
//
// Input:  face_vertex, 3 vertex indices per face (-1 = a deleted or invalid face, as
//         detail::face_vertex_indices in face_adjacency.h gives them), and the vertex count.
// Output: VertexFaces; the faces of vertex v are face[offset[v] .. offset[v+1]), in increasing order. A face
//         with a repeated vertex is listed once per corner.
// Method: counting sort. Cost: O(V + F), two passes, no per-vertex allocation.
#ifndef PRIMITIVE_EDIT_VERTEX_FACES_H
#define PRIMITIVE_EDIT_VERTEX_FACES_H

#include "common/base/huge_page_vector.h"

#include <cstddef>
#include <vector>

namespace primitive_edit {

struct VertexFaces
{
  std::vector<int> offset; // size vertex_count + 1
  std::vector<int> face;   // faces of vertex v: face[offset[v] .. offset[v+1])
};

VertexFaces build_vertex_faces(const std::vector<int>& face_vertex, std::size_t vertex_count);

} // namespace primitive_edit

#endif
