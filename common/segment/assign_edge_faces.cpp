#include "common/segment/assign_edge_faces.h"

namespace primitive_edit {

void assign_edge_faces(const FaceAdjacency& adj, const std::vector<Eigen::Vector3d>& normal,
                       std::vector<int>& segment_of_face)
{
  std::vector<int> pending;
  for (std::size_t f = 0; f < segment_of_face.size(); ++f)
    if (segment_of_face[f] < 0)
      pending.push_back(int(f));
  std::vector<std::pair<int, int>> joins;  // (face, segment) decided in this round
  while (!pending.empty()) {
    joins.clear();
    std::size_t kept = 0;
    for (int f : pending) {
      int best = -1;
      double best_dot = 0;
      for (int k = adj.offset[std::size_t(f)]; k < adj.offset[std::size_t(f) + 1]; ++k) {
        const int g = adj.neighbour[std::size_t(k)];
        const int s = segment_of_face[std::size_t(g)];
        if (s < 0)
          continue;
        const double d = normal[std::size_t(f)].dot(normal[std::size_t(g)]);
        if (best < 0 || d > best_dot || (d == best_dot && s < best)) {
          best = s;
          best_dot = d;
        }
      }
      if (best >= 0)
        joins.emplace_back(f, best);
      else
        pending[kept++] = f;
    }
    if (joins.empty())
      return;  // the rest have no segment in their component
    pending.resize(kept);
    for (const auto& [f, s] : joins)
      segment_of_face[std::size_t(f)] = s;
  }
}

} // namespace primitive_edit
