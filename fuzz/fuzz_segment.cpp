// fuzz_segment.cpp: libFuzzer target over the segmentations (common/segment/) on small meshes, so that a long
// run covers them at many inputs a second.
//
// The bytes are decoded (fuzz_input.h) into a mesh of at most 16 x 16 vertices of a patch of a shape plus
// arbitrary faces (MeshLab's float CMeshO or a double mesh) and the parameters of both segmentations, kept in
// the ranges the filters accept (the filters refuse others: check_primitive_growing_params). Entry points:
// segment_by_primitive_growing (normals, roughness, seed, grow, merge, dissolve, assign, relax, blends) and
// segment_by_normal_angle. Invariants: dense ids with every live face labelled and deleted ones -1, one
// primitive per segment, carved blends between two other segments and named in the log's line, a finite roughness
// kept on the mesh, and the same result on a second run with another thread count.
#include "common/mesh/surface_roughness_attribute.h"
#include "common/segment/describe_carved_blends.h"
#include "common/segment/segment_by_normal_angle.h"
#include "common/segment/segment_by_primitive_growing.h"
#include "fuzz/check_growing_report.h"
#include "fuzz/decoded_mesh_type.h"
#include "fuzz/fuzz_input.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>

using namespace primitive_edit;
using namespace fuzz;

namespace {

constexpr MeshLimits kLimits{16, 256, 600};

template <class MeshType>
void run(Decoder& in)
{
  MeshType m;
  const AttributeCleaner<MeshType> cleaner{m};
  build_mesh(in, m, kLimits);
  const FaceAdjacency adj = build_face_adjacency(m);
  check_adjacency(m, adj);

  SegmentByPrimitiveGrowingParams grow;
  if (in.bit()) {
    grow.tolerance = in.bit() ? 0.0 : std::abs(in.special(0.1));
    const double angle_range = kMaxGrowingNormalAngleDeg - kMinGrowingNormalAngleDeg;
    grow.normal_angle_deg = kMinGrowingNormalAngleDeg + in.unit() * angle_range;
    grow.seed_patch_faces = kMinSeedPatchFaces + in.u8() % 64;
    grow.min_region_faces = int(in.u8() % 80) - 1;
    grow.smoothing_iterations = in.u8() % 12;
    grow.roughness = in.bit() ? 0.0 : std::abs(in.special(0.05));
    grow.carve_blends = !in.bit();
  }
  grow.threads = 1;
  std::vector<int> grown, again;
  SegmentByPrimitiveGrowingReport report;
  if (check_primitive_growing_params(grow).ok()) {
    const int G = segment_by_primitive_growing(m, adj, grow, grown, &report);
    check_segmentation(m, grown, G);
    check_growing_report(report, G);
    // The log's line names every one of them (describe_carved_blends.h), and is empty without them.
    const std::string carved = describe_carved_blends(report.blends);
    FUZZ_CHECK(carved.empty() == report.blends.empty());
    FUZZ_CHECK(std::count(carved.begin(), carved.end(), ';') + (carved.empty() ? 0 : 1) ==
               std::ptrdiff_t(report.blends.size()));
    grow.threads = 2;
    FUZZ_CHECK(segment_by_primitive_growing(m, adj, grow, again) == G && again == grown);
    if (grow.roughness <= 0) {
      const double kept = surface_roughness(m, adj);
      FUZZ_CHECK(std::isfinite(kept) && kept >= 0 && read_surface_roughness(m) == kept);
    }
  }

  SegmentByNormalAngleParams angle;
  angle.angle_deg = in.special(100.0);
  angle.smoothing_iterations = int(in.u8() % 5) - 1;
  angle.min_segment_faces = int(in.u8() % 40) - 2;
  std::vector<int> seg;
  const int K = segment_by_normal_angle(m, adj, angle, seg);
  check_segmentation(m, seg, K);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  Decoder in(data, size);
  on_decoded_mesh_type(in, [&](auto tag) { run<typename decltype(tag)::Mesh>(in); });
  return 0;
}
