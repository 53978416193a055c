#include "common/mesh/segment_attribute.h"

namespace primitive_edit {

namespace detail {

bool compact_stored_ids(std::vector<int>& segment_of_face)
{
  const std::vector<int> stored = segment_of_face;
  compact_segment_ids(segment_of_face);
  return stored != segment_of_face;
}

} // namespace detail
} // namespace primitive_edit
