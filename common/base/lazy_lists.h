// lazy_lists.h: a list of ints per index, built the first time the index is asked for and then kept.
//
// Input:  the number of indices; per request, an index and a function that appends that index's list to the
//         vector it is given (and touches nothing else of it).
// Output: the list as a [begin, end) range, valid until the next request that builds a list (the pool grows).
//         built(index) reads a list built before (an empty range if there is none) and changes nothing, so
//         threads may read lists side by side while none is being built.
// Why:    loops that visit the same few indices many times (fold repair's Gauss-Seidel sweeps revisit each
//         vertex of their region dozens of times, asking for the same neighbours and surfaces) pay for each
//         list once, and nothing for the indices they never visit.
// Cost:   O(index count) memory for the starts, plus the lists built; O(1) per repeated request.
#ifndef PRIMITIVE_EDIT_LAZY_LISTS_H
#define PRIMITIVE_EDIT_LAZY_LISTS_H

#include "common/base/huge_page_vector.h"

#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace primitive_edit {

class LazyLists
{
public:
  explicit LazyLists(std::size_t count) : start_(huge_page_vector(count, kNotBuilt)) {}

  template <class Build>
  std::pair<const int*, const int*> get(std::size_t index, Build&& build)
  {
    std::size_t& start = start_[index];
    if (start == kNotBuilt) {
      start = pool_.size();
      pool_.push_back(0);  // the length, set below
      build(pool_);
      pool_[start] = int(pool_.size() - start - 1);
    }
    const int* list = pool_.data() + start + 1;
    return {list, list + list[-1]};
  }

  std::pair<const int*, const int*> built(std::size_t index) const
  {
    if (start_[index] == kNotBuilt)
      return {nullptr, nullptr};
    const int* list = pool_.data() + start_[index] + 1;
    return {list, list + list[-1]};
  }

private:
  static constexpr std::size_t kNotBuilt = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> start_;  // where each index's length, then its list, is in pool_
  std::vector<int> pool_;
};

} // namespace primitive_edit

#endif
