#include "common/base/find_root.h"

namespace primitive_edit {

int find_root(std::vector<int>& parent, int s)
{
  while (parent[std::size_t(s)] != s) {
    parent[std::size_t(s)] = parent[std::size_t(parent[std::size_t(s)])];
    s = parent[std::size_t(s)];
  }
  return s;
}

} // namespace primitive_edit
