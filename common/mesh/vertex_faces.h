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

inline VertexFaces build_vertex_faces(const std::vector<int>& face_vertex, std::size_t vertex_count)
{
  VertexFaces vf;
  assign_on_huge_pages(vf.offset, vertex_count + 1, 0);
  for (int v : face_vertex)
    if (v >= 0 && std::size_t(v) < vertex_count)
      ++vf.offset[std::size_t(v) + 1];
  for (std::size_t v = 0; v < vertex_count; ++v)
    vf.offset[v + 1] += vf.offset[v];
  assign_on_huge_pages(vf.face, std::size_t(vf.offset[vertex_count]), 0);
  std::vector<int> cursor(vf.offset.begin(), vf.offset.end() - 1);
  for (std::size_t i = 0; i < face_vertex.size(); ++i) {
    const int v = face_vertex[i];
    if (v >= 0 && std::size_t(v) < vertex_count)
      vf.face[std::size_t(cursor[std::size_t(v)]++)] = int(i / 3);
  }
  return vf;
}

} // namespace primitive_edit

#endif
