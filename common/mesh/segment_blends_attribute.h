// segment_blends_attribute.h: which segments the segmentation found to be the fillet or chamfer of two plane
// segments, kept on the mesh for Fit All (fit_all_segments.h), which makes them those blends.
//
// A per-mesh attribute (vcg::tri::Allocator) named "SegmentBlends" holds up to kMaxKeptBlends records with a hash of
// the vertex positions (vertex_positions_hash, surface_roughness_attribute.h); a plain array, as MeshLab may copy
// per-mesh attributes byte by byte. A record names its three segments (the blend and its two planes) by their
// faces, not their ids: the number of faces and a hash of their indices. So a record is read back, under the
// segments' ids of the moment, while those three segments are as they were: an edit elsewhere (a split, a merge,
// ids renumbered by it) keeps it, an edit of one of them drops it, and so does a filter that moves vertices.
// Cost: O(V) for the vertex hash and O(F + K log K) for the segments' signatures (K segments), at each write and
// read.
#ifndef PRIMITIVE_EDIT_SEGMENT_BLENDS_ATTRIBUTE_H
#define PRIMITIVE_EDIT_SEGMENT_BLENDS_ATTRIBUTE_H

#include "common/mesh/count_segments.h"
#include "common/mesh/surface_roughness_attribute.h"

#include <vcg/complex/complex.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <vector>

namespace primitive_edit {

// A segment that is the fillet or chamfer of the edge between two plane segments.
struct SegmentBlendRecord
{
  int segment = -1, plane_a = -1, plane_b = -1;
};

constexpr int kMaxKeptBlends = 256;
constexpr const char* kSegmentBlendsAttributeName = "SegmentBlends";

// A segment by its faces, whatever its id: their number and an FNV-1a hash of their indices, in order.
struct SegmentSignature
{
  int faces = 0;
  std::uint64_t hash = kFnvOffsetBasis;
  bool operator<(const SegmentSignature& o) const { return faces != o.faces ? faces < o.faces : hash < o.hash; }
};

struct KeptSegmentBlend
{
  SegmentSignature segment, plane_a, plane_b;
};

struct KeptSegmentBlends
{
  KeptSegmentBlend record[kMaxKeptBlends];
  int count = 0;
  std::uint64_t vertex_hash = 0;
  int face_count = -1;
};

// The signature of every segment id of a dense segmentation (count_segments.h; ids without faces have 0 faces).
inline std::vector<SegmentSignature> segment_signatures(const std::vector<int>& segment_of_face)
{
  std::vector<SegmentSignature> out(static_cast<std::size_t>(count_segments(segment_of_face)));
  for (std::size_t f = 0; f < segment_of_face.size(); ++f)
    if (const int s = segment_of_face[f]; s >= 0) {
      SegmentSignature& g = out[std::size_t(s)];
      ++g.faces;
      g.hash = (g.hash ^ std::uint64_t(f)) * kFnvPrime;
    }
  return out;
}

// Keeps the records (the first kMaxKeptBlends that name segments with faces) for the mesh as it is, with these
// segment ids.
template <class MeshType>
void write_segment_blends(MeshType& m, const std::vector<int>& segment_of_face,
                          const std::vector<SegmentBlendRecord>& blends)
{
  auto h = vcg::tri::Allocator<MeshType>::template GetPerMeshAttribute<KeptSegmentBlends>(
      m, kSegmentBlendsAttributeName);
  KeptSegmentBlends& kept = h();
  const std::vector<SegmentSignature> signature = segment_signatures(segment_of_face);
  auto has_faces = [&](int s) {
    return s >= 0 && std::size_t(s) < signature.size() && signature[std::size_t(s)].faces > 0;
  };
  kept.count = 0;
  for (const SegmentBlendRecord& b : blends)
    if (kept.count < kMaxKeptBlends && has_faces(b.segment) && has_faces(b.plane_a) && has_faces(b.plane_b))
      kept.record[kept.count++] = {signature[std::size_t(b.segment)], signature[std::size_t(b.plane_a)],
                                   signature[std::size_t(b.plane_b)]};
  kept.vertex_hash = vertex_positions_hash(m);
  kept.face_count = m.fn;
}

// The records kept for this mesh whose three segments are still among these segment ids, named by those ids; none
// when there are none or the vertices have moved.
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
      kept.vertex_hash != vertex_positions_hash(m))
    return {};
  const std::vector<SegmentSignature> signature = segment_signatures(segment_of_face);
  std::map<SegmentSignature, int> id_of;
  for (std::size_t s = 0; s < signature.size(); ++s)
    if (signature[s].faces > 0)
      id_of.emplace(signature[s], int(s));
  std::vector<SegmentBlendRecord> out;
  for (int i = 0; i < kept.count; ++i) {
    const KeptSegmentBlend& r = kept.record[i];
    const auto segment = id_of.find(r.segment), a = id_of.find(r.plane_a), b = id_of.find(r.plane_b);
    if (segment != id_of.end() && a != id_of.end() && b != id_of.end())
      out.push_back({segment->second, a->second, b->second});
  }
  return out;
}

} // namespace primitive_edit

#endif
