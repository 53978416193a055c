#include "common/mesh/face_adjacency.h"

#include <algorithm>
#include <utility>

namespace primitive_edit {

namespace {

// The neighbours of faces [begin, end) appended to `neighbour`, and after face f's the list's length in
// end_of[f - begin].
void list_neighbours(const std::vector<int>& fv, const VertexFaces& incident, std::size_t begin, std::size_t end,
                     std::vector<int>& neighbour, int* end_of)
{
  const std::vector<int>& vf_offset = incident.offset;
  const std::vector<int>& vf = incident.face;
  for (std::size_t f = begin; f < end; ++f) {
    const int* corners = &fv[3 * f];
    const std::size_t first = neighbour.size();
    for (int k = 0; k < 3 && corners[0] >= 0; ++k) {
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
        if (std::size_t(g) == f)
          continue;
        const int* gc = &fv[3 * std::size_t(g)];
        if (gc[0] != b && gc[1] != b && gc[2] != b)
          continue;
        if (std::find(neighbour.begin() + std::ptrdiff_t(first), neighbour.end(), g) == neighbour.end())
          neighbour.push_back(g);
      }
    }
    end_of[f - begin] = int(neighbour.size());
  }
}

} // namespace

FaceAdjacency face_adjacency_from_corners(const std::vector<int>& face_vertex, std::size_t vertex_count, int threads)
{
  const std::size_t face_count = face_vertex.size() / 3;
  // A face with a repeated vertex is listed once per corner; the duplicate check makes that harmless.
  const VertexFaces incident = build_vertex_faces(face_vertex, vertex_count);

  FaceAdjacency adj;
  assign_on_huge_pages(adj.offset, face_count + 1, 0);
  reserve_on_huge_pages(adj.neighbour, 3 * face_count);
  // Each range of faces lists its neighbours apart, the first straight into the table; the others' lists are then
  // appended in face order, so the table does not depend on the ranges. A closed manifold mesh fills the table's
  // 3 F reserved entries exactly, so appending does not move it.
  const std::size_t ranges =
      std::max<std::size_t>(1, std::min(std::size_t(resolve_thread_count(threads)), face_count / kFacesPerThread));
  auto range_begin = [&](std::size_t r) { return r * face_count / ranges; };
  std::vector<std::vector<int>> lists(ranges);
  parallel_for(ranges, int(ranges), 1, [&](std::size_t first, std::size_t last) {
    for (std::size_t r = first; r < last; ++r) {
      std::vector<int>& list = r == 0 ? adj.neighbour : lists[r];
      if (r > 0)
        reserve_on_huge_pages(list, 3 * (range_begin(r + 1) - range_begin(r)));
      list_neighbours(face_vertex, incident, range_begin(r), range_begin(r + 1), list, &adj.offset[range_begin(r) + 1]);
    }
  });
  for (std::size_t r = 1; r < ranges; ++r) {
    const int base = int(adj.neighbour.size());
    adj.neighbour.insert(adj.neighbour.end(), lists[r].begin(), lists[r].end());
    std::vector<int>().swap(lists[r]);
    for (std::size_t f = range_begin(r); f < range_begin(r + 1); ++f)
      adj.offset[f + 1] += base;
  }
  return adj;
}

} // namespace primitive_edit
