#include "common/segment/relax_region_borders.h"

#include "common/base/parallel_for.h"

namespace primitive_edit {

int best_region_for_face(const GrowingFaces& g, const FaceAdjacency& adj,
                         const std::vector<Primitive>& primitive_of_region, double tol,
                         const std::vector<int>& label, int f)
{
  const int regions = int(primitive_of_region.size());
  const int own = label[std::size_t(f)];
  if (own < 0 || own >= regions || !g.valid[std::size_t(f)])
    return own;
  auto cost = [&](int r) { return face_cost(g, primitive_of_region[std::size_t(r)], f, tol); };
  int best = own;
  double best_cost = -1;
  for (int k = adj.offset[std::size_t(f)]; k < adj.offset[std::size_t(f) + 1]; ++k) {
    const int r = label[std::size_t(adj.neighbour[std::size_t(k)])];
    if (r < 0 || r >= regions || r == best)
      continue;
    if (best_cost < 0)
      best_cost = cost(own);
    const double c = cost(r);
    if (c < best_cost) {
      best = r;
      best_cost = c;
    }
  }
  return best;
}

int relax_region_borders(const GrowingFaces& g, const FaceAdjacency& adj,
                         const std::vector<Primitive>& primitive_of_region, double tol, std::vector<int>& label,
                         int threads)
{
  const int face_count = int(label.size());
  // A face whose label and neighbours' labels are those it last stayed with would stay again: only faces
  // with a change in their 1-ring since are looked at, which gives the moves of looking at every face. At the
  // start that is the faces with a neighbour of another label (found on all threads): a face amid its own region
  // could move in the first pass only after a neighbour's move, which marks it.
  std::vector<char> changed = huge_page_vector(std::size_t(face_count), char(0));
  parallel_for(std::size_t(face_count), threads, kFacesPerThread, [&](std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f)
      for (int k = adj.offset[f]; k < adj.offset[f + 1]; ++k)
        if (label[std::size_t(adj.neighbour[std::size_t(k)])] != label[f]) {
          changed[f] = 1;
          break;
        }
  });
  int total = 0;
  for (int pass = 0; pass < kRelaxPasses; ++pass) {
    int moved = 0;
    for (int f = 0; f < face_count; ++f) {
      if (!changed[std::size_t(f)])
        continue;
      changed[std::size_t(f)] = 0;
      const int best = best_region_for_face(g, adj, primitive_of_region, tol, label, f);
      if (best != label[std::size_t(f)]) {
        label[std::size_t(f)] = best;
        changed[std::size_t(f)] = 1;
        for (int k = adj.offset[std::size_t(f)]; k < adj.offset[std::size_t(f) + 1]; ++k)
          changed[std::size_t(adj.neighbour[std::size_t(k)])] = 1;
        ++moved;
      }
    }
    total += moved;
    if (moved == 0)
      break;
  }
  return total;
}

} // namespace primitive_edit
