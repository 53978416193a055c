// segment_blends_attribute.h: which segments the segmentation found to be the fillet or chamfer of two plane
// segments, kept on the mesh for Fit All (fit_all_segments.h), which makes them those blends.
//
// A per-mesh attribute (vcg::tri::Allocator) named "SegmentBlends" holds up to kMaxKeptBlends records (segment,
// plane_a, plane_b; a plain array, as MeshLab may copy per-mesh attributes byte by byte) with a hash of the vertex
// positions (vertex_positions_hash, surface_roughness_attribute.h) and of the segment ids they name. It is read back
// only while both still match: after a filter that moves vertices or an edit of the segments, the records name
// other faces and are not used.
// Cost: O(V) for the vertex hash and O(F) for the ids' hash, at each write and read.
#ifndef PRIMITIVE_EDIT_SEGMENT_BLENDS_ATTRIBUTE_H
#define PRIMITIVE_EDIT_SEGMENT_BLENDS_ATTRIBUTE_H

#include "common/mesh/surface_roughness_attribute.h"

#include <vcg/complex/complex.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace primitive_edit {

// A segment that is the fillet or chamfer of the edge between two plane segments.
struct SegmentBlendRecord
{
  int segment = -1, plane_a = -1, plane_b = -1;
};

constexpr int kMaxKeptBlends = 256;
constexpr const char* kSegmentBlendsAttributeName = "SegmentBlends";

struct KeptSegmentBlends
{
  SegmentBlendRecord record[kMaxKeptBlends];
  int count = 0;
  std::uint64_t vertex_hash = 0, segment_hash = 0;
  int face_count = -1;
};

// FNV-1a over the segment ids, as vertex_positions_hash over the coordinates.
inline std::uint64_t segment_ids_hash(const std::vector<int>& segment_of_face)
{
  std::uint64_t h = kFnvOffsetBasis;
  for (int s : segment_of_face)
    h = (h ^ std::uint64_t(std::uint32_t(s))) * kFnvPrime;
  return h;
}

// Keeps the records (the first kMaxKeptBlends) for the mesh as it is, with these segment ids.
template <class MeshType>
void write_segment_blends(MeshType& m, const std::vector<int>& segment_of_face,
                          const std::vector<SegmentBlendRecord>& blends)
{
  auto h = vcg::tri::Allocator<MeshType>::template GetPerMeshAttribute<KeptSegmentBlends>(
      m, kSegmentBlendsAttributeName);
  KeptSegmentBlends& kept = h();
  kept.count = int(std::min(blends.size(), std::size_t(kMaxKeptBlends)));
  std::copy(blends.begin(), blends.begin() + kept.count, kept.record);
  kept.vertex_hash = vertex_positions_hash(m);
  kept.segment_hash = segment_ids_hash(segment_of_face);
  kept.face_count = m.fn;
}

// The records kept for this mesh and these segment ids; none when there are none or they no longer match.
template <class MeshType>
std::vector<SegmentBlendRecord> read_segment_blends(MeshType& m, const std::vector<int>& segment_of_face)
{
  if (!vcg::tri::HasPerMeshAttribute(m, kSegmentBlendsAttributeName))
    return {};
  auto h = vcg::tri::Allocator<MeshType>::template FindPerMeshAttribute<KeptSegmentBlends>(
      m, kSegmentBlendsAttributeName);
  if (!vcg::tri::Allocator<MeshType>::IsValidHandle(m, h))
    return {};
  const KeptSegmentBlends& kept = h();
  if (kept.face_count != m.fn || kept.count < 0 || kept.count > kMaxKeptBlends ||
      kept.segment_hash != segment_ids_hash(segment_of_face) || kept.vertex_hash != vertex_positions_hash(m))
    return {};
  return std::vector<SegmentBlendRecord>(kept.record, kept.record + kept.count);
}

} // namespace primitive_edit

#endif
