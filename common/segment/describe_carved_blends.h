// describe_carved_blends.h: what the segmentation's step 5 carved, in words for MeshLab's log (the Segment filter
// and the edit tool print the same).
//
// Input:  the segments carved as fillets or chamfers (SegmentByPrimitiveGrowingReport::blends).
// Output: empty when there is none; else e.g. "2 fillets and chamfers carved from the planes they join: segment 15
//         between 1 and 13; segment 16 between 1 and 12" ("1 fillet or chamfer carved from the planes it joins: ..."
//         for one). Without it a user sees narrow segments appear along edges and does not know why.
// Cost:   O(blends).
#ifndef PRIMITIVE_EDIT_DESCRIBE_CARVED_BLENDS_H
#define PRIMITIVE_EDIT_DESCRIBE_CARVED_BLENDS_H

#include "common/mesh/segment_blends_attribute.h"

#include <string>
#include <vector>

namespace primitive_edit {

std::string describe_carved_blends(const std::vector<SegmentBlendRecord>& blends);

} // namespace primitive_edit

#endif
