// snap_checked.h: a snap as Fit All + snap and the edit tool's Apply run it, with the invariants the fuzz
// targets check after it.
//
// Input:  a mesh, its dense segment ids (K segments), every segment's primitive (std::nullopt: not snapped),
//         the snap options, and target >= 0 to snap that one segment onto target_primitive instead (the edit
//         tool's Apply: snap_onto_primitive; the others keep what the mesh's attribute holds).
// Checks: no vertex becomes non-finite and a non-finite one is left as it was; vertices on no snapped segment
//         stay where they are unless the fold repair slid them; flip prevention leaves no fold, and without it
//         nothing is repaired or held back; only vertices held back come part of the way; the report is finite;
//         the edit tool's target keeps its primitive.
#ifndef PRIMITIVE_EDIT_FUZZ_SNAP_CHECKED_H
#define PRIMITIVE_EDIT_FUZZ_SNAP_CHECKED_H

#include "common/mesh/segment_primitive_attribute.h"
#include "common/pipeline/snap_onto_primitive.h"
#include "common/snap/snap_segments.h"
#include "fuzz/fuzz_input.h"

#include <cmath>
#include <cstring>
#include <optional>
#include <vector>

namespace fuzz {

template <class MeshType>
void snap_checked(MeshType& m, const std::vector<int>& seg, const std::vector<std::optional<Primitive>>& primitives,
                  int target, const Primitive& target_primitive, const SnapOptions& options, int K)
{
  std::vector<typename MeshType::CoordType> before(m.vert.size());
  for (size_t v = 0; v < m.vert.size(); ++v)
    before[v] = m.vert[v].cP();
  std::vector<char> on_snapped(m.vert.size(), 0);
  for (size_t f = 0; f < m.face.size(); ++f) {
    if (m.face[f].IsD() || seg[f] < 0)
      continue;
    const auto& pr = primitives[size_t(seg[f])];
    if (pr && primitive_is_valid(*pr))
      for (int k = 0; k < 3; ++k)
        on_snapped[vcg::tri::Index(m, m.face[f].cV(k))] = 1;
  }
  const SnapReport report = target >= 0 ? snap_onto_primitive(m, seg, {target}, target_primitive, options, K)
                                        : snap_segments(m, seg, primitives, options);
  if (target >= 0 && primitive_is_valid(target_primitive))
    FUZZ_CHECK(read_segment_primitives(m, K)[size_t(target)].has_value());
  FUZZ_CHECK(std::isfinite(report.mean_displacement) && std::isfinite(report.max_displacement));
  for (size_t v = 0; v < m.vert.size(); ++v) {
    const auto& p = m.vert[v].cP();
    const bool was_finite = std::isfinite(double(before[v][0])) && std::isfinite(double(before[v][1])) &&
                            std::isfinite(double(before[v][2]));
    if (was_finite)
      FUZZ_CHECK(std::isfinite(double(p[0])) && std::isfinite(double(p[1])) && std::isfinite(double(p[2])));
    else
      FUZZ_CHECK(std::memcmp(&p, &before[v], sizeof p) == 0);
    if (!on_snapped[v] && report.repaired_vertices == 0)
      FUZZ_CHECK(std::memcmp(&p, &before[v], sizeof p) == 0);
  }
  FUZZ_CHECK(report.partway_vertices >= 0 && report.partway_vertices <= report.reverted_vertices);
  if (options.prevent_flips)
    FUZZ_CHECK(report.folded_faces == 0);
  else
    FUZZ_CHECK(report.repaired_vertices == 0 && report.reverted_vertices == 0);
}

} // namespace fuzz

#endif
