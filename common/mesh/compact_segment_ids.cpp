#include "common/mesh/compact_segment_ids.h"

namespace primitive_edit {

int compact_segment_ids(std::vector<int>& segment_of_face)
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
