#include "common/segment/assign_leftover_faces.h"

namespace primitive_edit {

int assign_leftover_faces(const GrowingFaces& g, const FaceAdjacency& adj,
                          const std::vector<Primitive>& primitive_of_region, double tol, std::vector<int>& label)
{
  const std::vector<char>& deleted = g.deleted;
  const int face_count = int(label.size());
  using Item = std::pair<double, std::pair<int, int>>; // (cost, (face, region))
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
  auto push_neighbours = [&](int f, int r) {
    for (int k = adj.offset[std::size_t(f)]; k < adj.offset[std::size_t(f) + 1]; ++k) {
      const int h = adj.neighbour[std::size_t(k)];
      if (label[std::size_t(h)] < 0 && !deleted[std::size_t(h)])
        heap.push({face_cost(g, primitive_of_region[std::size_t(r)], h, tol), {h, r}});
    }
  };
  for (int f = 0; f < face_count; ++f)
    if (label[std::size_t(f)] >= 0)
      push_neighbours(f, label[std::size_t(f)]);
  while (!heap.empty()) {
    const auto [f, r] = heap.top().second;
    heap.pop();
    if (label[std::size_t(f)] >= 0)
      continue;
    label[std::size_t(f)] = r;
    push_neighbours(f, r);
  }

  int next_id = int(primitive_of_region.size());
  std::vector<int> queue;
  for (int seed = 0; seed < face_count; ++seed) {
    if (label[std::size_t(seed)] >= 0 || deleted[std::size_t(seed)])
      continue;
    const int id = next_id++;
    label[std::size_t(seed)] = id;
    queue.assign(1, seed);
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const int f = queue[head];
      for (int k = adj.offset[std::size_t(f)]; k < adj.offset[std::size_t(f) + 1]; ++k) {
        const int h = adj.neighbour[std::size_t(k)];
        if (label[std::size_t(h)] < 0 && !deleted[std::size_t(h)]) {
          label[std::size_t(h)] = id;
          queue.push_back(h);
        }
      }
    }
  }
  return next_id;
}

} // namespace primitive_edit
