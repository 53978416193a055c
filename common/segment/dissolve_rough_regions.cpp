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

int dissolve_rough_regions(const GrowingFaces& g, const RegionPairs& adjacent, const GrowingScale& scale,
                           GrowingRegions& regions)
{
  const int count = int(regions.primitive.size());
  auto size = [&](int r) { return regions.faces[std::size_t(r)].size(); };
  std::vector<std::vector<int>> larger_neighbours(static_cast<std::size_t>(count));
  for (const auto& [a, b] : adjacent) {
    if (size(b) > size(a))
      larger_neighbours[std::size_t(a)].push_back(b);
    else if (size(a) > size(b))
      larger_neighbours[std::size_t(b)].push_back(a);
  }
  std::vector<int> by_size;
  for (int r = 0; r < count; ++r)
    if (size(r) > 0)
      by_size.push_back(r);
  std::stable_sort(by_size.begin(), by_size.end(), [&](int a, int b) { return size(a) < size(b); });
  int dissolved = 0;
  for (int r : by_size) {
    std::vector<int>& faces = regions.faces[std::size_t(r)];
    const std::vector<int>& neighbours = larger_neighbours[std::size_t(r)];
    if (!neighbours.empty() && share_near_neighbours(g, regions, faces, neighbours, 2.0 * scale.tolerance,
                                                     scale.angle) >= kMergeShare) {
      for (int f : faces)
        regions.label[std::size_t(f)] = -1;
      std::vector<int>().swap(faces);
      ++dissolved;
    }
  }
  return dissolved;
}

} // namespace primitive_edit
