// fuzz_snap.cpp: libFuzzer target over the snap and its fold repair (common/snap/, the edit tool's Apply) on
// small meshes, so that a long run covers them at many inputs a second.
//
// The bytes are decoded (fuzz_input.h) into a mesh of at most 12 x 12 vertices of a patch of a shape plus
// arbitrary faces (MeshLab's float CMeshO or a double mesh), up to 5 segments (bands of the grid or faces
// labelled one by one), every segment's primitive (its fit, the shape's own primitive moved a little, a
// decoded one valid or not, or none) and the snap options. Entry points: fit_primitive on the segments'
// samples, snap_segments (edges, corners, flip prevention, the fold repair) or snap_onto_primitive.
// Invariants: those of snap_checked.h.
#include "common/fit/fit_primitive.h"
#include "common/mesh/compact_segment_ids.h"
#include "common/mesh/gather_segment_samples.h"
#include "fuzz/decoded_mesh_type.h"
#include "fuzz/fuzz_input.h"
#include "fuzz/snap_checked.h"

#include <cstdint>
#include <optional>

using namespace primitive_edit;
using namespace fuzz;

namespace {

constexpr MeshLimits kLimits{12, 144, 300};
constexpr int kMaxSegments = 5;

template <class MeshType>
void run(Decoder& in)
{
  MeshType m;
  const AttributeCleaner<MeshType> cleaner{m};
  build_mesh(in, m, kLimits);

  // Labels: bands of faces in face order (the grid's rows) or each face decoded; deleted faces -1.
  const int wanted = 1 + in.u8() % kMaxSegments;
  const bool banded = in.bit();
  std::vector<int> seg(m.face.size(), -1);
  for (size_t f = 0; f < m.face.size(); ++f)
    if (!m.face[f].IsD())
      seg[f] = banded ? int(f * size_t(wanted) / m.face.size()) : int(in.u8() % wanted);
  const int K = compact_segment_ids(seg);
  check_dense(seg, K);

  const std::vector<SegmentSamples> samples = gather_segment_samples(m, seg, K);
  std::vector<std::optional<Primitive>> primitives(static_cast<size_t>(K));
  const Primitive shape = clean_primitive(fuzz_primitive(in));
  for (int s = 0; s < K; ++s) {
    switch (in.u8() % 5) {
    case 0: break;
    case 1: primitives[size_t(s)] = fuzz_primitive(in); break;
    case 2: primitives[size_t(s)] = shape; break;
    default: {
      FitOptions options;
      options.max_iterations = int(in.u8() % 12);
      const SegmentSamples& ss = samples[size_t(s)];
      const FitResult r = fit_primitive(static_cast<PrimitiveType>(in.u8() % kPrimitiveTypeCount), ss.points,
                                        ss.normals, ss.weights, options);
      check_fit(r);
      if (r.status.ok())
        primitives[size_t(s)] = r.primitive;
    }
    }
  }
  SnapOptions options;
  options.sharp_edges = !in.bit();
  options.max_edge_distance = in.special(1.0);
  options.prevent_flips = !in.bit();
  options.repair_folds = !in.bit();
  options.wide_repair = !in.bit();
  options.threads = in.bit() ? 2 : 1; // the repair's parts side by side once its region is large enough
  int target = -1;
  Primitive target_primitive;
  if (K > 0 && in.u8() % 4 == 0) {
    target = int(in.u16() % K);
    target_primitive = primitives[size_t(target)] ? *primitives[size_t(target)] : fuzz_primitive(in);
    primitives[size_t(target)] = target_primitive;
  }
  snap_checked(m, seg, primitives, target, target_primitive, options, K);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  Decoder in(data, size);
  on_decoded_mesh_type(in, [&](auto tag) { run<typename decltype(tag)::Mesh>(in); });
  return 0;
}
