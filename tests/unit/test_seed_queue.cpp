// SeedQueue: the seeds it hands out are those of a full stable sort of every valid face by its normal's variation,
// skipping the faces no longer eligible, on every thread count; ties keep the index order.
#include "test_mesh.h"

#include "common/mesh/face_adjacency.h"
#include "common/segment/growing_faces.h"
#include "common/segment/seed_queue.h"

#include <gtest/gtest.h>
#include <vcg/complex/algorithms/create/platonic.h>

#include <algorithm>
#include <random>
#include <vector>

using namespace primitive_edit;

namespace {

// The seeds taken while each taken seed makes itself and its neighbours' neighbours ineligible, as a grown region
// would; next(f) gives the next candidate, -1 at the end.
template <class Next>
std::vector<int> take_seeds(const FaceAdjacency& adj, std::size_t face_count, Next next)
{
  std::vector<char> taken(face_count, 0);
  auto eligible = [&](int f) { return !taken[std::size_t(f)]; };
  std::vector<int> seeds;
  for (int f = next(eligible); f >= 0; f = next(eligible)) {
    seeds.push_back(f);
    taken[std::size_t(f)] = 1;
    for (int k = adj.offset[std::size_t(f)]; k < adj.offset[std::size_t(f) + 1]; ++k) {
      const int h = adj.neighbour[std::size_t(k)];
      taken[std::size_t(h)] = 1;
      for (int j = adj.offset[std::size_t(h)]; j < adj.offset[std::size_t(h) + 1]; ++j)
        taken[std::size_t(adj.neighbour[std::size_t(j)])] = 1;
    }
  }
  return seeds;
}

void check_against_full_sort(double noise)
{
  test_mesh::TMesh m;
  vcg::tri::Sphere(m, 6); // 81920 faces: more than one thread's share
  std::mt19937 rng(5);
  std::normal_distribution<double> jitter(0.0, noise);
  for (auto& v : m.vert)
    v.P() *= 1.0 + jitter(rng);
  for (std::size_t f = 0; f < m.face.size(); f += 101)
    vcg::tri::Allocator<test_mesh::TMesh>::DeleteFace(m, m.face[f]);
  const FaceAdjacency adj = build_face_adjacency(m);
  const GrowingFaces g = growing_faces(m, adj, 2);

  // The order by definition: every valid face by the mean of 1 - cos to its neighbours (2 for an invalid one).
  std::vector<double> variation(m.face.size(), 0.0);
  std::vector<int> order;
  for (std::size_t f = 0; f < m.face.size(); ++f) {
    if (!g.valid[f])
      continue;
    double v = 0;
    for (int k = adj.offset[f]; k < adj.offset[f + 1]; ++k) {
      const std::size_t h = std::size_t(adj.neighbour[std::size_t(k)]);
      v += g.valid[h] ? 1.0 - g.normal[f].dot(g.normal[h]) : 2.0;
    }
    variation[f] = v / std::max(1, adj.offset[f + 1] - adj.offset[f]);
    order.push_back(int(f));
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return variation[std::size_t(a)] < variation[std::size_t(b)]; });
  std::size_t at = 0;
  const std::vector<int> expected = take_seeds(adj, m.face.size(), [&](auto eligible) {
    while (at < order.size())
      if (const int f = order[at++]; eligible(f))
        return f;
    return -1;
  });
  ASSERT_GT(expected.size(), 100u);

  for (int threads : {1, 2}) {
    SeedQueue queue(g, adj, threads);
    const std::vector<int> seeds = take_seeds(adj, m.face.size(), [&](auto eligible) { return queue.next(eligible); });
    EXPECT_EQ(seeds, expected) << "noise " << noise << ", " << threads << " threads";
    EXPECT_EQ(queue.share_passed(), 1.0);
  }
}

} // namespace

TEST(SeedQueue, HandsOutTheFullSortsSeedsOnNoisyFaces)
{
  check_against_full_sort(0.002);
}

// An exact subdivided icosahedron has many faces of equal variation: ties go in index order.
TEST(SeedQueue, KeepsTheIndexOrderOfTies)
{
  check_against_full_sort(0.0);
}
