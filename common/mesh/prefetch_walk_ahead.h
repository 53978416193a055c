// prefetch_walk_ahead.h: the loads of a breadth-first walk over faces, asked for a few faces ahead.
//
// Input:  the FaceAdjacency, the walk's queue of faces and its head (the next face to be walked from), the distance
//         `ahead` in faces (>= 4), and touch(h), called for each neighbour h of the face ahead / 4 places on, which
//         prefetches (prefetch.h) whatever the walk will read of h.
// Output: none; what the walk computes does not change.
// Why:    a walk over a mesh larger than the caches waits on dependent loads: a face's offset into the neighbour
//         lists, then its list, then each neighbour's flags and geometry. The faces ahead in the queue are known, so
//         those loads are asked for in three steps, each using only what the step before brought in: the offset
//         `ahead` faces on, the list ahead / 2 on, the neighbours' data ahead / 4 on. On the 4M-face bracket scan
//         (bench/README.md) growth ran about 10% faster on one thread and two, the roughness's patches 5-11%.
// Cost:   O(neighbours of one face) per call.
#ifndef PRIMITIVE_EDIT_PREFETCH_WALK_AHEAD_H
#define PRIMITIVE_EDIT_PREFETCH_WALK_AHEAD_H

#include "common/base/prefetch.h"
#include "common/mesh/face_adjacency.h"

#include <cstddef>
#include <vector>

namespace primitive_edit {

template <class Touch>
void prefetch_walk_ahead(const FaceAdjacency& adj, const std::vector<int>& queue, std::size_t head, std::size_t ahead,
                         Touch touch)
{
  if (head + ahead < queue.size())
    prefetch(adj.offset.data() + queue[head + ahead]);
  if (head + ahead / 2 < queue.size())
    prefetch(adj.neighbour.data() + adj.offset[std::size_t(queue[head + ahead / 2])]);
  if (head + ahead / 4 < queue.size()) {
    const std::size_t f = std::size_t(queue[head + ahead / 4]);
    for (int k = adj.offset[f]; k < adj.offset[f + 1]; ++k)
      touch(std::size_t(adj.neighbour[std::size_t(k)]));
  }
}

} // namespace primitive_edit

#endif
