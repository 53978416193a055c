// prefetch_walk_ahead: which faces' data a walk asks for, and nothing past the end of its queue.
#include "common/mesh/prefetch_walk_ahead.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

using namespace primitive_edit;

namespace {

// A strip of faces 0-1-2-...-(n-1), each the neighbour of the faces before and after it.
FaceAdjacency strip(int n)
{
  FaceAdjacency adj;
  adj.offset.push_back(0);
  for (int f = 0; f < n; ++f) {
    if (f > 0)
      adj.neighbour.push_back(f - 1);
    if (f + 1 < n)
      adj.neighbour.push_back(f + 1);
    adj.offset.push_back(int(adj.neighbour.size()));
  }
  return adj;
}

std::vector<std::size_t> touched(const FaceAdjacency& adj, const std::vector<int>& queue, std::size_t head,
                                 std::size_t ahead)
{
  std::vector<std::size_t> out;
  prefetch_walk_ahead(adj, queue, head, ahead, [&](std::size_t h) { out.push_back(h); });
  return out;
}

} // namespace

TEST(PrefetchWalkAhead, TouchesTheNeighboursOfTheFaceAQuarterAhead)
{
  const FaceAdjacency adj = strip(40);
  std::vector<int> queue;
  for (int f = 39; f >= 0; --f)
    queue.push_back(f);
  // head 2, ahead 16: the face 4 places on is queue[6] = 33, whose neighbours are 32 and 34.
  EXPECT_EQ(touched(adj, queue, 2, 16), (std::vector<std::size_t>{32, 34}));
  // Near the end of the queue there is no face a quarter ahead: nothing is touched, nothing read past the end.
  EXPECT_TRUE(touched(adj, queue, 36, 16).empty());
  EXPECT_TRUE(touched(adj, {}, 0, 16).empty());
  // Face 0, at the strip's end, has one neighbour.
  EXPECT_EQ(touched(adj, {5, 0}, 0, 4), (std::vector<std::size_t>{1}));
}
