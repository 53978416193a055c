#include "common/segment/seed_queue.h"

#include "common/base/huge_page_vector.h"
#include "common/base/ordered_bits.h"
#include "common/base/parallel_for.h"

#include <algorithm>
#include <limits>

namespace primitive_edit {

SeedQueue::SeedQueue(const GrowingFaces& g, const FaceAdjacency& adj, int threads)
{
  const std::size_t n = g.valid.size();
  variation_ = huge_page_vector(n, std::numeric_limits<double>::infinity());
  parallel_for(n, threads, kFacesPerThread, [&](std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f) {
      if (!g.valid[f])
        continue;
      double v = 0;
      for (int k = adj.offset[f]; k < adj.offset[f + 1]; ++k) {
        const std::size_t h = std::size_t(adj.neighbour[std::size_t(k)]);
        v += 1.0 - (g.valid[h] ? g.normal[f].dot(g.normal[h]) : -1.0);
      }
      variation_[f] = v / std::max(1, adj.offset[f + 1] - adj.offset[f]);
    }
  });
  auto bucket_of = [&](std::size_t f) {
    return std::size_t(ordered_bits(variation_[f]) >> (64 - kSeedBucketBits));
  };
  std::vector<std::size_t> start(std::size_t(1) << kSeedBucketBits, 0);
  for (std::size_t f = 0; f < n; ++f)
    if (g.valid[f])
      ++start[bucket_of(f)];
  std::size_t total = 0;
  for (std::size_t& s : start) {
    const std::size_t size = s;
    s = total;
    total += size;
    if (size > 0)
      bucket_end_.push_back(total);
  }
  faces_ = huge_page_vector<int>(total);
  for (std::size_t f = 0; f < n; ++f)
    if (g.valid[f])
      faces_[start[bucket_of(f)]++] = int(f);
}

double SeedQueue::share_passed() const
{
  return faces_.empty() || bucket_ == 0 ? 0.0 : double(bucket_end_[bucket_ - 1]) / double(faces_.size());
}

void SeedQueue::sort_current()
{
  // By variation, ties (-0 and +0 too) in index order.
  std::stable_sort(current_.begin(), current_.end(),
                   [&](int a, int b) { return variation_[std::size_t(a)] < variation_[std::size_t(b)]; });
}

} // namespace primitive_edit
