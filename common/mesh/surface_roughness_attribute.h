// surface_roughness_attribute.h: a mesh's roughness (estimate_surface_roughness.h), measured once and kept on
// the mesh for the filters that come after.
//
// A per-mesh attribute (vcg::tri::Allocator) named "SurfaceRoughness" holds the roughness with a hash of the
// vertex positions and the face count it was measured on; it is read back only while both still match, so a
// filter that moves vertices (snapping, smoothing) or changes the faces makes the next reader measure again.
// surface_roughness() returns the kept value or measures, keeps and returns it (building the face adjacency
// only when it measures, unless the caller has one).
// Cost: O(V) for the hash; a measurement costs estimate_surface_roughness's O(F).
#ifndef PRIMITIVE_EDIT_SURFACE_ROUGHNESS_ATTRIBUTE_H
#define PRIMITIVE_EDIT_SURFACE_ROUGHNESS_ATTRIBUTE_H

#include "common/mesh/estimate_surface_roughness.h"
#include "common/mesh/face_adjacency.h"

#include <vcg/complex/complex.h>

#include <cstdint>
#include <cstring>
#include <optional>

namespace primitive_edit {

struct KeptSurfaceRoughness
{
  double roughness = 0;
  std::uint64_t vertex_hash = 0;
  int face_count = -1;
};

constexpr const char* kSurfaceRoughnessAttributeName = "SurfaceRoughness";

// FNV-1a's 64-bit offset basis and prime (vertex_positions_hash, segment_signatures in segment_blends_attribute.h).
constexpr std::uint64_t kFnvOffsetBasis = 1469598103934665603ull, kFnvPrime = 1099511628211ull;

// FNV-1a over every live vertex's coordinates (as doubles), a 64-bit word at a time: each step is a bijection of
// the hash, so a change of one coordinate always changes it. Byte by byte it took 15 ms on the peer part's 500k
// vertices, at each write and read of the attribute; a word at a time 2 ms.
template <class MeshType>
std::uint64_t vertex_positions_hash(const MeshType& m)
{
  std::uint64_t h = kFnvOffsetBasis;
  for (const auto& v : m.vert) {
    if (v.IsD())
      continue;
    const auto p = v.cP();
    for (int i = 0; i < 3; ++i) {
      const double c = double(p[i]);
      std::uint64_t word;
      std::memcpy(&word, &c, sizeof word);
      h = (h ^ word) * kFnvPrime;
    }
  }
  return h;
}

template <class MeshType>
std::optional<double> read_surface_roughness(MeshType& m)
{
  if (!vcg::tri::HasPerMeshAttribute(m, kSurfaceRoughnessAttributeName))
    return std::nullopt;
  auto h = vcg::tri::Allocator<MeshType>::template FindPerMeshAttribute<KeptSurfaceRoughness>(
      m, kSurfaceRoughnessAttributeName);
  if (!vcg::tri::Allocator<MeshType>::IsValidHandle(m, h))
    return std::nullopt;
  const KeptSurfaceRoughness kept = h();
  if (kept.face_count != m.fn || kept.vertex_hash != vertex_positions_hash(m))
    return std::nullopt;
  return kept.roughness;
}

template <class MeshType>
void write_surface_roughness(MeshType& m, double roughness)
{
  auto h = vcg::tri::Allocator<MeshType>::template GetPerMeshAttribute<KeptSurfaceRoughness>(
      m, kSurfaceRoughnessAttributeName);
  h() = KeptSurfaceRoughness{roughness, vertex_positions_hash(m), m.fn};
}

template <class MeshType>
double measure_and_keep_surface_roughness(MeshType& m, const FaceAdjacency& adj)
{
  const double roughness = estimate_surface_roughness(m, adj);
  write_surface_roughness(m, roughness);
  return roughness;
}

template <class MeshType>
double surface_roughness(MeshType& m, const FaceAdjacency& adj)
{
  if (const std::optional<double> kept = read_surface_roughness(m))
    return *kept;
  return measure_and_keep_surface_roughness(m, adj);
}

template <class MeshType>
double surface_roughness(MeshType& m)
{
  if (const std::optional<double> kept = read_surface_roughness(m))
    return *kept;
  return measure_and_keep_surface_roughness(m, build_face_adjacency(m));
}

} // namespace primitive_edit

#endif
