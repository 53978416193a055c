// face_adjacency.h: which faces of a triangle mesh share an edge, as a compressed (CSR) table.
//
// Input:  a vcg triangle mesh (any MeshType; no adjacency component needed: CMeshO's FFAdj is optional).
// Output: FaceAdjacency; the neighbours of face f (f = vcg::tri::Index(m, face)) are
//         neighbour[offset[f] .. offset[f+1]). Two faces are neighbours when they share an edge, i.e. both
//         endpoints. A non-manifold edge links all of its faces to each other; a neighbour is listed once
//         even when it shares several edges. Deleted faces and edges of a degenerate face that join a vertex
//         to itself link nothing. Faces with a null or out-of-range vertex pointer are treated as isolated.
// Complexity: O(F + sum over face edges of the valence of one endpoint), i.e. linear for bounded valence.
//         Vertex->face incidence is built by a counting sort (vertex_faces.h); no per-face heap allocation, no maps.
#ifndef PRIMITIVE_EDIT_FACE_ADJACENCY_H
#define PRIMITIVE_EDIT_FACE_ADJACENCY_H

#include "common/base/huge_page_vector.h"
#include "common/mesh/vertex_faces.h"

#include <vcg/complex/complex.h>

#include <cstddef>
#include <vector>

namespace primitive_edit {

struct FaceAdjacency
{
  std::vector<int> offset;    // size face_count() + 1
  std::vector<int> neighbour; // neighbours of face f: neighbour[offset[f] .. offset[f+1])

  int face_count() const { return offset.empty() ? 0 : int(offset.size()) - 1; }
};

namespace detail {

// The vertex indices of face f into idx; false for a deleted face or one with a null or out-of-range vertex.
template <class MeshType>
bool face_corner_indices(const MeshType& m, std::size_t f, int idx[3])
{
  const auto& face = m.face[f];
  if (face.IsD() || m.vert.empty())
    return false;
  for (int k = 0; k < 3; ++k) {
    const auto* v = face.cV(k);
    if (v == nullptr)
      return false;
    const std::ptrdiff_t i = v - &m.vert[0];
    if (i < 0 || std::size_t(i) >= m.vert.size())
      return false;
    idx[k] = int(i);
  }
  return true;
}

// Vertex indices of every face, 3 per face; -1 for deleted faces and faces with invalid vertex pointers.
template <class MeshType>
std::vector<int> face_vertex_indices(const MeshType& m)
{
  const std::size_t face_count = m.face.size();
  std::vector<int> fv = huge_page_vector(3 * face_count, -1);
  for (std::size_t f = 0; f < face_count; ++f) {
    int idx[3];
    if (face_corner_indices(m, f, idx))
      for (int k = 0; k < 3; ++k)
        fv[3 * f + k] = idx[k];
  }
  return fv;
}

} // namespace detail

template <class MeshType>
FaceAdjacency build_face_adjacency(const MeshType& m)
{
  const int face_count = int(m.face.size());
  const int vertex_count = int(m.vert.size());
  const std::vector<int> fv = detail::face_vertex_indices(m);

  // A face with a repeated vertex is listed once per corner; the duplicate check below makes that harmless.
  const VertexFaces incident = build_vertex_faces(fv, std::size_t(vertex_count));
  const std::vector<int>& vf_offset = incident.offset;
  const std::vector<int>& vf = incident.face;

  FaceAdjacency adj;
  assign_on_huge_pages(adj.offset, std::size_t(face_count) + 1, 0);
  reserve_on_huge_pages(adj.neighbour, 3 * std::size_t(face_count));
  for (int f = 0; f < face_count; ++f) {
    adj.offset[std::size_t(f)] = int(adj.neighbour.size());
    const int* corners = &fv[3 * std::size_t(f)];
    if (corners[0] < 0)
      continue;
    const std::size_t first = adj.neighbour.size();
    for (int k = 0; k < 3; ++k) {
      int a = corners[k];
      int b = corners[(k + 1) % 3];
      if (a == b)
        continue;
      // Scan the shorter incidence list of the two endpoints.
      if (vf_offset[std::size_t(a) + 1] - vf_offset[std::size_t(a)] >
          vf_offset[std::size_t(b) + 1] - vf_offset[std::size_t(b)])
        std::swap(a, b);
      for (int i = vf_offset[std::size_t(a)]; i < vf_offset[std::size_t(a) + 1]; ++i) {
        const int g = vf[std::size_t(i)];
        if (g == f)
          continue;
        const int* gc = &fv[3 * std::size_t(g)];
        if (gc[0] != b && gc[1] != b && gc[2] != b)
          continue;
        bool listed = false;
        for (std::size_t j = first; j < adj.neighbour.size(); ++j)
          if (adj.neighbour[j] == g) {
            listed = true;
            break;
          }
        if (!listed)
          adj.neighbour.push_back(g);
      }
    }
  }
  adj.offset[std::size_t(face_count)] = int(adj.neighbour.size());
  return adj;
}

} // namespace primitive_edit

#endif
