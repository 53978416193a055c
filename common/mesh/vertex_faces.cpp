#include "common/mesh/vertex_faces.h"

namespace primitive_edit {

VertexFaces build_vertex_faces(const std::vector<int>& face_vertex, std::size_t vertex_count)
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
