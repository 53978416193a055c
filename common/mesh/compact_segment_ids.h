// compact_segment_ids.h: renumber segment ids to 0..K-1, keeping their order.
//
// Input:  segment_of_face, one id per face (indexed by vcg::tri::Index); negative ids mean "no segment".
// Output: the same partition with ids 0..K-1: the k-th smallest id becomes k, so ids that are already
//         dense are left as they are and sparse ones keep their order (a user who reads id 32 in the face
//         quality finds the same faces as segment 32 in every filter, when the ids were dense). Every negative
//         id becomes -1. Returns K.
// Complexity: O(F) when ids are below about 2F (the usual case), else O(F log F).
#ifndef PRIMITIVE_EDIT_COMPACT_SEGMENT_IDS_H
#define PRIMITIVE_EDIT_COMPACT_SEGMENT_IDS_H

#include <algorithm>
#include <cstddef>
#include <vector>

namespace primitive_edit {

inline int compact_segment_ids(std::vector<int>& segment_of_face)
{
  int max_id = -1;
  for (int& s : segment_of_face) {
    if (s < 0)
      s = -1;
    max_id = std::max(max_id, s);
  }
  if (max_id < 0)
    return 0;

  if (std::size_t(max_id) <= 2 * segment_of_face.size() + 1024) {
    // new_id[s] = number of distinct ids below s.
    std::vector<int> new_id(std::size_t(max_id) + 1, 0);
    for (int s : segment_of_face)
      if (s >= 0)
        new_id[std::size_t(s)] = 1;
    int next = 0;
    for (int& n : new_id) {
      const int present = n;
      n = next;
      next += present;
    }
    for (int& s : segment_of_face)
      if (s >= 0)
        s = new_id[std::size_t(s)];
    return next;
  }

  // Sparse huge ids (e.g. read from a file): ranks in a sorted table of the distinct ids.
  std::vector<int> ids;
  ids.reserve(segment_of_face.size());
  for (int s : segment_of_face)
    if (s >= 0)
      ids.push_back(s);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  for (int& s : segment_of_face)
    if (s >= 0)
      s = int(std::lower_bound(ids.begin(), ids.end(), s) - ids.begin());
  return int(ids.size());
}

} // namespace primitive_edit

#endif
