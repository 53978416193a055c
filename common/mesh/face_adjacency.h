// face_adjacency.h: which faces of a triangle mesh share an edge, as a compressed (CSR) table.
//
// Input:  a vcg triangle mesh (any MeshType; no adjacency component needed: CMeshO's FFAdj is optional), or the
//         vertex indices of its faces; the threads (parallel_for.h; <= 0: all).
// Output: FaceAdjacency; the neighbours of face f (f = vcg::tri::Index(m, face)) are
//         neighbour[offset[f] .. offset[f+1]). Two faces are neighbours when they share an edge, i.e. both
//         endpoints. A non-manifold edge links all of its faces to each other; a neighbour is listed once
//         even when it shares several edges. Deleted faces and edges of a degenerate face that join a vertex
//         to itself link nothing. Faces with a null or out-of-range vertex pointer are treated as isolated.
// Complexity: O(F + sum over face edges of the valence of one endpoint), i.e. linear for bounded valence.
//         Vertex->face incidence is built by a counting sort (vertex_faces.h); no per-face heap allocation, no maps.
//         The faces' vertex indices and their neighbours are found by the threads over contiguous ranges of
//         faces, each range's lists joined in face order: the same table for every thread count.
#ifndef PRIMITIVE_EDIT_FACE_ADJACENCY_H
#define PRIMITIVE_EDIT_FACE_ADJACENCY_H

#include "common/base/huge_page_vector.h"
#include "common/base/parallel_for.h"
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
std::vector<int> face_vertex_indices(const MeshType& m, int threads = 0)
{
  const std::size_t face_count = m.face.size();
  std::vector<int> fv = huge_page_vector(3 * face_count, -1);
  parallel_for(face_count, threads, kFacesPerThread, [&](std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f) {
      int idx[3];
      if (face_corner_indices(m, f, idx))
        for (int k = 0; k < 3; ++k)
          fv[3 * f + k] = idx[k];
    }
  });
  return fv;
}

} // namespace detail

// The adjacency of faces given by their vertex indices (3 per face, as detail::face_vertex_indices gives them:
// a face whose first index is negative links nothing, the others' indices lie in [0, vertex_count)).
FaceAdjacency face_adjacency_from_corners(const std::vector<int>& face_vertex, std::size_t vertex_count,
                                          int threads = 0);

template <class MeshType>
FaceAdjacency build_face_adjacency(const MeshType& m, int threads = 0)
{
  return face_adjacency_from_corners(detail::face_vertex_indices(m, threads), m.vert.size(), threads);
}

} // namespace primitive_edit

#endif
