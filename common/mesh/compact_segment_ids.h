// compact_segment_ids.h: renumber segment ids to 0..K-1 in order of first appearance.
//
// Input:  segment_of_face, one id per face (indexed by vcg::tri::Index); negative ids mean "no segment".
// Output: the same partition with ids 0..K-1, numbered by the first face of each segment; every negative id
//         becomes -1. Returns K.
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

  int next = 0;
  if (std::size_t(max_id) <= 2 * segment_of_face.size() + 1024) {
    std::vector<int> new_id(std::size_t(max_id) + 1, -1);
    for (int& s : segment_of_face)
      if (s >= 0) {
        int& n = new_id[std::size_t(s)];
        if (n < 0)
          n = next++;
        s = n;
      }
    return next;
  }

  // Sparse huge ids (e.g. read from a file): a sorted table of the distinct ids instead of a dense one.
  std::vector<int> ids;
  ids.reserve(segment_of_face.size());
  for (int s : segment_of_face)
    if (s >= 0)
      ids.push_back(s);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  std::vector<int> new_id(ids.size(), -1);
  for (int& s : segment_of_face)
    if (s >= 0) {
      int& n = new_id[std::size_t(std::lower_bound(ids.begin(), ids.end(), s) - ids.begin())];
      if (n < 0)
        n = next++;
      s = n;
    }
  return next;
}

} // namespace primitive_edit

#endif
