#include "common/segment/dissolve_rough_regions.h"

namespace primitive_edit {

double share_near_neighbours(const GrowingFaces& g, const GrowingRegions& regions, const std::vector<int>& faces,
                             const std::vector<int>& neighbours, double tol, double angle)
{
  const FaceAgreement agrees(tol, angle);
  return strided_share_where(g, faces, kShareSampleCount, [&](int f) {
    return std::any_of(neighbours.begin(), neighbours.end(),
                       [&](int q) { return agrees(g, regions.primitive[std::size_t(q)], f); });
  });
}

int dissolve_rough_regions(const GrowingFaces& g, const FaceAdjacency& adj, const GrowingScale& scale,
                           GrowingRegions& regions)
{
  std::vector<int>& label = regions.label;
  const int count = int(regions.primitive.size());
  std::vector<int> by_size;
  for (int r = 0; r < count; ++r)
    if (!regions.faces[std::size_t(r)].empty())
      by_size.push_back(r);
  std::stable_sort(by_size.begin(), by_size.end(), [&](int a, int b) {
    return regions.faces[std::size_t(a)].size() < regions.faces[std::size_t(b)].size();
  });
  std::vector<int> neighbours;
  int dissolved = 0;
  for (int r : by_size) {
    std::vector<int>& faces = regions.faces[std::size_t(r)];
    neighbours.clear();
    for (int f : faces)
      for (int k = adj.offset[std::size_t(f)]; k < adj.offset[std::size_t(f) + 1]; ++k) {
        const int q = label[std::size_t(adj.neighbour[std::size_t(k)])];
        if (q >= 0 && q != r && regions.faces[std::size_t(q)].size() > faces.size())
          neighbours.push_back(q);
      }
    std::sort(neighbours.begin(), neighbours.end());
    neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
    if (!neighbours.empty() && share_near_neighbours(g, regions, faces, neighbours, 2.0 * scale.tolerance,
                                                     scale.angle) >= kMergeShare) {
      for (int f : faces)
        label[std::size_t(f)] = -1;
      std::vector<int>().swap(faces);
      ++dissolved;
    }
  }
  return dissolved;
}

} // namespace primitive_edit
