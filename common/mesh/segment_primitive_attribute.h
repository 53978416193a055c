// segment_primitive_attribute.h: which segments of a mesh have been snapped, and onto what.
//
// A per-mesh attribute (vcg::tri::Allocator) named "SegmentPrimitives" holds, for each segment id, the
// primitive it was last snapped onto, if any. Snapping a segment makes its edges sharp against the
// neighbours recorded here. Segment ids change when the segmentation changes, so whoever rewrites
// the segmentation clears the record (clear_segment_primitives).
// Cost: O(K) per call for K segments.
#ifndef PRIMITIVE_EDIT_SEGMENT_PRIMITIVE_ATTRIBUTE_H
#define PRIMITIVE_EDIT_SEGMENT_PRIMITIVE_ATTRIBUTE_H

#include "common/base/primitive.h"

#include <vcg/complex/complex.h>

#include <optional>
#include <vector>

namespace primitive_edit {

using SegmentPrimitives = std::vector<std::optional<Primitive>>;

constexpr const char* kSegmentPrimitivesAttributeName = "SegmentPrimitives";

// The recorded primitives, resized to segment_count (segments never snapped are empty).
template <class MeshType>
SegmentPrimitives read_segment_primitives(MeshType& m, int segment_count)
{
  SegmentPrimitives out;
  if (vcg::tri::HasPerMeshAttribute(m, kSegmentPrimitivesAttributeName)) {
    auto h = vcg::tri::Allocator<MeshType>::template FindPerMeshAttribute<SegmentPrimitives>(
        m, kSegmentPrimitivesAttributeName);
    if (vcg::tri::Allocator<MeshType>::IsValidHandle(m, h))
      out = h();
  }
  out.resize(size_t(std::max(segment_count, 0)));
  return out;
}

template <class MeshType>
void write_segment_primitives(MeshType& m, const SegmentPrimitives& primitives)
{
  auto h = vcg::tri::Allocator<MeshType>::template GetPerMeshAttribute<SegmentPrimitives>(
      m, kSegmentPrimitivesAttributeName);
  h() = primitives;
}

template <class MeshType>
void clear_segment_primitives(MeshType& m)
{
  if (vcg::tri::HasPerMeshAttribute(m, kSegmentPrimitivesAttributeName))
    vcg::tri::Allocator<MeshType>::DeletePerMeshAttribute(m, kSegmentPrimitivesAttributeName);
}

} // namespace primitive_edit

#endif
