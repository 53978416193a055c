// snap_onto_primitive.h: moves some faces of a segmented mesh onto one (edited) primitive, as
// "Primitive: Snap Segment" and the edit tool's Apply do.
//
// Input:  a vcg triangle mesh, its face labels (index = vcg::tri::Index(m, face), -1 = none), the labels to
//         move (`targets`: segments, or a label given to selected faces), the primitive, SnapOptions and the
//         number of segments recorded on the mesh (segment_primitive_attribute.h).
// Output: the SnapReport of snap_segments. The target faces' vertices lie on the primitive, on its edge
//         with a recorded neighbour (with sharp_edges) or at a corner. Targets below `segment_count` are
//         recorded as snapped onto the primitive, so that later snaps keep sharp edges against them; other
//         labels (a selection) are not. Normals and bounding box are updated. An invalid primitive
//         (primitive_is_valid) moves nothing and is not recorded.
// Method: snap_segments with the target labels given the primitive and, with sharp edges, every other
//         segment its recorded primitive (its vertices stay: only the shared ones move onto the edges).
// Cost:   that of snap_segments, plus O(F + V + K).
#ifndef PRIMITIVE_EDIT_SNAP_ONTO_PRIMITIVE_H
#define PRIMITIVE_EDIT_SNAP_ONTO_PRIMITIVE_H

#include "common/mesh/segment_primitive_attribute.h"
#include "common/mesh/update_normals_and_bounds.h"
#include "common/snap/snap_segments.h"

#include <algorithm>
#include <vector>

namespace primitive_edit {

template <class MeshType>
SnapReport snap_onto_primitive(MeshType& m, const std::vector<int>& labels, const std::vector<int>& targets,
                               const Primitive& primitive, const SnapOptions& options, int segment_count)
{
  if (!primitive_is_valid(primitive))
    return {};
  int label_count = segment_count;
  for (int t : targets)
    label_count = std::max(label_count, t + 1);
  SegmentPrimitives recorded = read_segment_primitives(m, segment_count);
  SegmentPrimitives primitives(static_cast<size_t>(label_count));
  if (options.sharp_edges)
    std::copy(recorded.begin(), recorded.end(), primitives.begin());
  for (int t : targets)
    if (t >= 0)
      primitives[size_t(t)] = primitive;
  const SnapReport report = snap_segments(m, labels, primitives, options);

  bool recorded_any = false;
  for (int t : targets)
    if (t >= 0 && t < segment_count) {
      recorded[size_t(t)] = primitive;
      recorded_any = true;
    }
  if (recorded_any)
    write_segment_primitives(m, recorded);
  update_normals_and_bounds(m);
  return report;
}

} // namespace primitive_edit

#endif
