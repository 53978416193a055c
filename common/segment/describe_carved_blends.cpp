#include "common/segment/describe_carved_blends.h"

namespace primitive_edit {

std::string describe_carved_blends(const std::vector<SegmentBlendRecord>& blends)
{
  if (blends.empty())
    return {};
  std::string out = blends.size() == 1
                        ? std::string("1 fillet or chamfer carved from the planes it joins: ")
                        : std::to_string(blends.size()) + " fillets and chamfers carved from the planes they join: ";
  for (std::size_t i = 0; i < blends.size(); ++i) {
    const SegmentBlendRecord& b = blends[i];
    out += (i == 0 ? "segment " : "; segment ") + std::to_string(b.segment) + " between " + std::to_string(b.plane_a) +
           " and " + std::to_string(b.plane_b);
  }
  return out;
}

} // namespace primitive_edit
