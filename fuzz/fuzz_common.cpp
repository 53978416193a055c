// fuzz_common.cpp: libFuzzer target running every entry point of common/ on a mesh built from the input bytes.
//
// The bytes are decoded (see Decoder and build_mesh) into: the mesh type (the fuzzer's own double mesh or
// MeshLab's float CMeshO), a vertex cloud (raw bytes or points of a plane / sphere / cylinder / cone / torus
// with special values mixed in: NaN, Inf, 1e6-scale, denormals, duplicates), faces (a grid triangulation of the
// shape plus arbitrary faces, indices modulo the vertex count, repeated vertices allowed, some deleted), a face
// selection, segment labels, and the parameters of segmentation, split, fits, snap overrides and accuracy
// measurement. Sizes are bounded (<= 2000 faces, few fitted segments, few LM iterations) so that an input runs
// in milliseconds. Invariants are checked and violations abort (libFuzzer then saves the input):
// dense segment ids with every live face labelled, fits with ok == true give valid primitives with finite
// residuals, snap_segments never writes a non-finite coordinate nor moves a vertex of an unsnapped segment (but
// to repair a fold) nor leaves a fold with flip prevention on,
// accuracy reports are finite.
#include "common/base/constants.h"
#include "common/base/sort_by_key.h"
#include "common/geometry/closest_point_on_intersection.h"
#include "common/mesh/color_segments.h"
#include "common/geometry/common_point_of_primitives.h"
#include "common/mesh/compact_segment_ids.h"
#include "common/mesh/face_adjacency.h"
#include "common/mesh/locate_on_surface.h"
#include "common/fit/fit_primitive.h"
#include "common/fit/fit_primitive_auto.h"
#include "common/mesh/gather_segment_samples.h"
#include "common/measure/measure_accuracy.h"
#include "common/segment/merge_segments.h"
#include "common/mesh/check_mesh_input.h"
#include "common/segment/move_faces_to_new_segment.h"
#include "common/fit/refine_primitive.h"
#include "common/mesh/sample_surface_uniform.h"
#include "common/mesh/segment_attribute.h"
#include "common/segment/segment_by_normal_angle.h"
#include "common/segment/segment_by_primitive_growing.h"
#include "common/mesh/surface_roughness_attribute.h"
#include "common/mesh/smooth_face_normals.h"
#include "common/fit/fit_quadric_direct.h"
#include "common/pipeline/fit_all_segments.h"
#include "common/pipeline/fit_segment.h"
#include "common/pipeline/snap_onto_primitive.h"
#include "common/pipeline/write_fits_json.h"
#include "common/snap/snap_segments.h"
#include "common/segment/split_segments_by_plane.h"

#include <common/ml_mesh_type.h>
#include <vcg/complex/complex.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <optional>
#include <sstream>
#include <type_traits>
#include <vector>

namespace fuzz_mesh {

class FVertex;
class FFace;
struct FUsedTypes : public vcg::UsedTypes<vcg::Use<FVertex>::AsVertexType, vcg::Use<FFace>::AsFaceType> {};
class FVertex : public vcg::Vertex<FUsedTypes, vcg::vertex::Coord3d, vcg::vertex::Normal3d, vcg::vertex::BitFlags> {};
class FFace : public vcg::Face<FUsedTypes, vcg::face::VertexRef, vcg::face::Normal3d, vcg::face::BitFlags> {};
class FMesh : public vcg::tri::TriMesh<std::vector<FVertex>, std::vector<FFace>> {};

} // namespace fuzz_mesh

using namespace primitive_edit;

namespace {

constexpr int kMaxVertices = 1200;
constexpr int kMaxFaces = 2000;
constexpr int kMaxFittedSegments = 4;

[[noreturn]] void fail(const char* what, const char* file, int line)
{
  std::fprintf(stderr, "INVARIANT VIOLATED at %s:%d: %s\n", file, line, what);
  std::abort();
}
#define FUZZ_CHECK(cond)                                                                                              \
  do {                                                                                                                \
    if (!(cond))                                                                                                      \
      fail(#cond, __FILE__, __LINE__);                                                                                \
  } while (0)

// Reads the input front to back; past the end every read gives 0, so any prefix is a valid input.
class Decoder
{
public:
  Decoder(const uint8_t* data, size_t size) : data_(data), size_(size) {}
  uint8_t u8() { return pos_ < size_ ? data_[pos_++] : 0; }
  uint16_t u16() { return uint16_t(u8() | (uint16_t(u8()) << 8)); }
  uint32_t u32() { return uint32_t(u16()) | (uint32_t(u16()) << 16); }
  bool bit() { return (u8() & 1) != 0; }
  double unit() { return u16() / 65535.0; }               // [0, 1]
  double signed_unit() { return 2.0 * unit() - 1.0; }    // [-1, 1]
  // A number that is usually ordinary but sometimes one of the patterns that break geometry code.
  double special(double scale)
  {
    const uint8_t kind = u8();
    switch (kind % 24) {
    case 0: return std::numeric_limits<double>::quiet_NaN();
    case 1: return std::numeric_limits<double>::infinity();
    case 2: return -std::numeric_limits<double>::infinity();
    case 3: return 1e6 * signed_unit();
    case 4: return 1e-40 * signed_unit();   // a float denormal
    case 5: return 0.0;
    case 6: {
      const uint32_t bits = u32();
      float f;
      std::memcpy(&f, &bits, sizeof f);
      return double(f);
    }
    case 7: return 1e30 * signed_unit();
    default: return scale * signed_unit();
    }
  }
  size_t remaining() const { return pos_ < size_ ? size_ - pos_ : 0; }

private:
  const uint8_t* data_;
  size_t size_;
  size_t pos_ = 0;
};

Eigen::Vector3d unit_vector(Decoder& in)
{
  Eigen::Vector3d d(in.signed_unit(), in.signed_unit(), in.signed_unit());
  if (d.norm() < 1e-3)
    d = Eigen::Vector3d::UnitZ();
  return d.normalized();
}

// A primitive with fuzzed parameters: mostly valid, sometimes invalid (zero axis, negative radius, NaN).
Primitive fuzz_primitive(Decoder& in)
{
  Primitive p;
  p.type = static_cast<PrimitiveType>(in.u8() % kPrimitiveTypeCount);
  const bool wild = (in.u8() % 4) == 0;
  if (wild) {
    p.origin = Eigen::Vector3d(in.special(2), in.special(2), in.special(2));
    p.axis = Eigen::Vector3d(in.special(1), in.special(1), in.special(1));
    p.radius = in.special(2);
    p.minor_radius = in.special(1);
    p.half_angle = in.special(2);
  } else {
    p.origin = Eigen::Vector3d(in.signed_unit(), in.signed_unit(), in.signed_unit()) * 2.0;
    p.axis = unit_vector(in);
    p.radius = 0.05 + 3.0 * in.unit();
    p.minor_radius = 0.02 + p.radius * 1.2 * in.unit();
    p.half_angle = 0.001 + 1.5687 * in.unit();
  }
  return p;
}

// A point of the given shape at surface parameters (u, v) in [0, 1]^2 (shape 0: raw fuzzed coordinates).
Eigen::Vector3d shape_point(int shape, double u, double v, const Primitive& p)
{
  const double pi = kPi;
  const Eigen::Vector3d a = p.axis;
  const Eigen::Vector3d e1 = any_orthogonal(a);
  const Eigen::Vector3d e2 = a.cross(e1);
  const double t = 2 * pi * u;
  switch (shape) {
  case 1: return p.origin + 3 * (u - 0.5) * e1 + 3 * (v - 0.5) * e2;
  case 2: {
    const double phi = pi * (0.05 + 0.9 * v);
    return p.origin + p.radius * (std::sin(phi) * (std::cos(t) * e1 + std::sin(t) * e2) + std::cos(phi) * a);
  }
  case 3: return p.origin + p.radius * (std::cos(t) * e1 + std::sin(t) * e2) + 2 * (v - 0.5) * a;
  case 4: {
    const double h = 0.1 + 2 * v;
    return p.origin + h * a + h * std::tan(p.half_angle) * (std::cos(t) * e1 + std::sin(t) * e2);
  }
  default: {
    const double s = 2 * pi * v;
    const Eigen::Vector3d radial = std::cos(t) * e1 + std::sin(t) * e2;
    return p.origin + (p.radius + p.minor_radius * std::cos(s)) * radial + p.minor_radius * std::sin(s) * a;
  }
  }
}

struct Params
{
  SegmentByNormalAngleParams segment;
  Eigen::Vector3d plane_point, plane_normal;
  FitOptions fit;
  AutoFitOptions auto_fit;
  SnapOptions snap;
  double tolerance = 0.1;
  int sample_count = 1;
  uint64_t seed = 0;
};

Params decode_params(Decoder& in)
{
  Params p;
  p.segment.angle_deg = in.special(100.0);
  p.segment.smoothing_iterations = int(in.u8() % 5) - 1;
  p.segment.min_segment_faces = int(in.u8() % 40) - 2;
  p.plane_point = Eigen::Vector3d(in.special(2), in.special(2), in.special(2));
  p.plane_normal = Eigen::Vector3d(in.special(1), in.special(1), in.special(1));
  p.fit.robust = in.bit();
  p.fit.max_iterations = int(in.u8() % 12);
  p.auto_fit.fit = p.fit;
  p.auto_fit.tolerance = in.special(0.1);
  p.snap.sharp_edges = !in.bit();
  p.snap.max_edge_distance = in.special(1.0);
  p.snap.prevent_flips = !in.bit();
  p.snap.repair_folds = !in.bit();
  p.tolerance = in.special(0.2);
  p.sample_count = int(in.u16() % 600) - 10;
  p.seed = in.u32();
  return p;
}

template <class MeshType>
void build_mesh(Decoder& in, MeshType& m)
{
  using Scalar = typename MeshType::ScalarType;
  const int shape = in.u8() % 6;
  const Primitive shape_prim = fuzz_primitive(in);
  Primitive clean = shape_prim;
  if (!primitive_is_valid(clean)) {
    clean.origin.setZero();
    clean.axis = Eigen::Vector3d::UnitZ();
    clean.radius = 1;
    clean.minor_radius = 0.4;
    clean.half_angle = 0.5;
  }
  const double scale = std::pow(10.0, int(in.u8() % 13) - 6);  // 1e-6 .. 1e6
  const double noise = in.unit() * in.unit() * 0.05;
  const int rows = 2 + in.u8() % 30;
  const int cols = 2 + in.u8() % 30;
  const double u_span = 0.02 + in.unit();  // a short arc of a cylinder, a cap of a sphere...
  const double v_span = 0.02 + in.unit();

  int nv = shape == 0 ? int(in.u16() % (kMaxVertices + 1)) : std::min(rows * cols, kMaxVertices);
  vcg::tri::Allocator<MeshType>::AddVertices(m, size_t(nv));
  for (int i = 0; i < nv; ++i) {
    Eigen::Vector3d p;
    if (shape == 0) {
      p = Eigen::Vector3d(in.special(1), in.special(1), in.special(1));
    } else {
      const int r = i / cols, c = i % cols;
      p = shape_point(shape, u_span * c / (cols - 1), v_span * r / std::max(rows - 1, 1), clean);
    }
    m.vert[size_t(i)].P() = typename MeshType::CoordType(Scalar(p.x() * scale), Scalar(p.y() * scale),
                                                         Scalar(p.z() * scale));
  }
  // Perturbations: noise, special values, duplicates of other vertices.
  const int perturbations = in.u8() % 32;
  for (int k = 0; k < perturbations && nv > 0; ++k) {
    const int i = in.u16() % nv;
    auto& P = m.vert[size_t(i)].P();
    switch (in.u8() % 4) {
    case 0: P[in.u8() % 3] = Scalar(in.special(1) * scale); break;
    case 1: P = m.vert[size_t(in.u16() % nv)].P(); break;
    default:
      for (int a = 0; a < 3; ++a)
        P[a] += Scalar(noise * scale * in.signed_unit());
    }
  }

  std::vector<std::array<int, 3>> faces;
  if (shape != 0 && nv == rows * cols) {
    const bool flip_some = in.bit();
    for (int r = 0; r + 1 < rows; ++r)
      for (int c = 0; c + 1 < cols; ++c) {
        const int a = r * cols + c, b = a + 1, d = a + cols, e = d + 1;
        std::array<int, 3> f1{a, b, e}, f2{a, e, d};
        if (flip_some && ((r * 7 + c) % 5 == 0))
          std::swap(f1[1], f1[2]);  // inconsistent orientation
        faces.push_back(f1);
        faces.push_back(f2);
      }
  }
  const int extra = nv > 0 ? int(in.u16() % (kMaxFaces + 1)) : 0;
  for (int k = 0; k < extra && int(faces.size()) < kMaxFaces && in.remaining() > 0; ++k)
    faces.push_back({int(in.u16() % nv), int(in.u16() % nv), int(in.u16() % nv)});
  if (int(faces.size()) > kMaxFaces)
    faces.resize(size_t(kMaxFaces));

  vcg::tri::Allocator<MeshType>::AddFaces(m, faces.size());
  for (size_t f = 0; f < faces.size(); ++f)
    for (int k = 0; k < 3; ++k)
      m.face[f].V(k) = &m.vert[size_t(faces[f][size_t(k)])];
  // Deleted faces: vcg keeps them in the vector, flagged.
  const int deletions = in.u8() % 8;
  for (int k = 0; k < deletions && !faces.empty(); ++k) {
    auto& f = m.face[in.u16() % faces.size()];
    if (!f.IsD())
      vcg::tri::Allocator<MeshType>::DeleteFace(m, f);
  }
}

// Dense ids 0..K-1, each used, -1 exactly on deleted faces.
template <class MeshType>
void check_segmentation(const MeshType& m, const std::vector<int>& seg, int K)
{
  FUZZ_CHECK(seg.size() == m.face.size());
  FUZZ_CHECK(K >= 0);
  std::vector<char> used(size_t(K), 0);
  for (size_t f = 0; f < seg.size(); ++f) {
    if (m.face[f].IsD()) {
      FUZZ_CHECK(seg[f] == -1);
      continue;
    }
    FUZZ_CHECK(seg[f] >= 0 && seg[f] < K);
    used[size_t(seg[f])] = 1;
  }
  FUZZ_CHECK(std::all_of(used.begin(), used.end(), [](char u) { return u != 0; }));
}

void check_dense(const std::vector<int>& seg, int K)
{
  std::vector<char> used(size_t(std::max(K, 0)), 0);
  for (int s : seg) {
    FUZZ_CHECK(s >= -1 && s < K);
    if (s >= 0)
      used[size_t(s)] = 1;
  }
  FUZZ_CHECK(std::all_of(used.begin(), used.end(), [](char u) { return u != 0; }));
}

void check_fit(const FitResult& r)
{
  if (!r.status.ok())
    return;
  FUZZ_CHECK(primitive_is_valid(r.primitive));
  FUZZ_CHECK(std::isfinite(r.rms) && r.rms >= 0);
  FUZZ_CHECK(std::isfinite(r.max_residual) && r.max_residual >= 0);
}

template <class MeshType>
void check_adjacency(const MeshType& m, const FaceAdjacency& adj)
{
  FUZZ_CHECK(adj.face_count() == int(m.face.size()));
  FUZZ_CHECK(adj.offset.empty() || adj.offset.front() == 0);
  std::vector<std::pair<int, int>> pairs;
  for (int f = 0; f < adj.face_count(); ++f) {
    FUZZ_CHECK(adj.offset[size_t(f)] <= adj.offset[size_t(f) + 1]);
    for (int k = adj.offset[size_t(f)]; k < adj.offset[size_t(f) + 1]; ++k) {
      const int g = adj.neighbour[size_t(k)];
      FUZZ_CHECK(g >= 0 && g < adj.face_count() && g != f);
      FUZZ_CHECK(!m.face[size_t(f)].IsD() && !m.face[size_t(g)].IsD());
      pairs.emplace_back(f, g);
    }
  }
  FUZZ_CHECK(adj.offset.empty() || adj.offset.back() == int(adj.neighbour.size()));
  // Symmetric: g lists f whenever f lists g.
  std::vector<std::pair<int, int>> reversed;
  for (const auto& p : pairs)
    reversed.emplace_back(p.second, p.first);
  std::sort(pairs.begin(), pairs.end());
  std::sort(reversed.begin(), reversed.end());
  FUZZ_CHECK(pairs == reversed);
}

template <class MeshType>
void run(Decoder& in)
{
  MeshType m;
  if constexpr (std::is_same_v<MeshType, CMeshO>) {
    // MeshLab's optional components: a mesh opened from PLY has face quality and colour, a new one not.
    if (in.bit()) {
      m.face.EnableQuality();
      m.face.EnableColor();
    }
  }
  // vcg's ~TriMesh does not free per-face attributes (ClearAttributes is commented out there): free them here
  // so that LeakSanitizer reports our leaks only.
  struct AttributeCleaner
  {
    MeshType& mesh;
    ~AttributeCleaner() { mesh.ClearAttributes(); }
  } cleaner{m};
  build_mesh(in, m);
  const Params params = decode_params(in);

  (void)check_mesh_input(m);

  const FaceAdjacency adj = build_face_adjacency(m);
  check_adjacency(m, adj);

  // The walk that keeps a slid vertex on the scan (snap's fold repair), over the live faces of finite corners
  // from the first one, to a decoded point: it ends on such a face, at a finite point when the query is finite.
  if (in.bit()) {
    const std::vector<int> fv = detail::face_vertex_indices(m);
    const VertexFaces vf = build_vertex_faces(fv, m.vert.size());
    auto position = [&](int v) {
      const auto& q = m.vert[std::size_t(v)].cP();
      return Eigen::Vector3d(double(q[0]), double(q[1]), double(q[2]));
    };
    auto enters = [&](int f) {
      if (fv[3 * std::size_t(f)] < 0)
        return false;
      for (int k = 0; k < 3; ++k)
        if (!position(fv[3 * std::size_t(f) + std::size_t(k)]).allFinite())
          return false;
      return true;
    };
    const Eigen::Vector3d p(in.special(2.0), in.special(2.0), in.special(2.0));
    const int max_steps = 1 + in.u8() % 64;
    for (int f = 0; f < int(m.face.size()); ++f)
      if (enters(f)) {
        const SurfaceLocation at = locate_on_surface(position, fv, vf, enters, f, p, max_steps);
        FUZZ_CHECK(at.face >= 0 && at.face < int(m.face.size()) && enters(at.face));
        FUZZ_CHECK(!p.allFinite() || at.point.allFinite());
        break;
      }
  }

  // The radix sort of the seed order, against std::stable_sort on decoded keys (ties, -0, infinities).
  if (in.bit()) {
    std::vector<double> key(1 + in.u8());
    for (double& k : key)
      k = std::isnan(k = in.special(1.0)) ? 0.0 : k;
    std::vector<int> order(key.size());
    for (std::size_t i = 0; i < order.size(); ++i)
      order[i] = int(i);
    std::vector<int> expected = order;
    std::stable_sort(expected.begin(), expected.end(),
                     [&](int a, int b) { return key[std::size_t(a)] < key[std::size_t(b)]; });
    sort_by_key(order, [&](int i) { return key[std::size_t(i)]; });
    FUZZ_CHECK(order == expected);
  }

  const std::vector<Eigen::Vector3d> smoothed =
      smooth_face_normals(m, adj, std::max(0, params.segment.smoothing_iterations), std::abs(params.segment.angle_deg));
  FUZZ_CHECK(smoothed.size() == m.face.size());
  for (const auto& n : smoothed)
    FUZZ_CHECK(n.allFinite() && (n.isZero(0.0) || std::abs(n.norm() - 1.0) < 1e-6));

  std::vector<int> seg;
  int K = segment_by_normal_angle(m, adj, params.segment, seg);
  check_segmentation(m, seg, K);
  {
    std::vector<int> again;
    FUZZ_CHECK(segment_by_normal_angle(m, params.segment, again) == K && again == seg);
  }

  // Primitive growing (the scan segmentation) at its defaults: every live face labelled, deterministic, and
  // the roughness it measured is the one kept on the mesh for the fits.
  if (in.bit()) {
    SegmentByPrimitiveGrowingParams grow;
    std::vector<int> grown, again;
    SegmentByPrimitiveGrowingReport report;
    const int G = segment_by_primitive_growing(m, adj, grow, grown, &report);
    check_segmentation(m, grown, G);
    FUZZ_CHECK(report.primitive_of_segment.size() == size_t(G));
    FUZZ_CHECK(std::isfinite(report.roughness) && report.roughness >= 0 && report.tolerance >= 0);
    FUZZ_CHECK(segment_by_primitive_growing(m, adj, grow, again) == G && again == grown);
    const double kept = surface_roughness(m, adj);
    FUZZ_CHECK(std::isfinite(kept) && kept >= 0 && read_surface_roughness(m) == kept);
  }

  if (K > 0) {
    const std::vector<vcg::Color4b> colour = color_segments(m, adj, seg);
    FUZZ_CHECK(colour.size() == size_t(K));
    for (int f = 0; f < adj.face_count(); ++f)
      for (int k = adj.offset[size_t(f)]; k < adj.offset[size_t(f) + 1]; ++k) {
        const int a = seg[size_t(f)], b = seg[size_t(adj.neighbour[size_t(k)])];
        FUZZ_CHECK(a == b || colour[size_t(a)] != colour[size_t(b)]);
      }
  }

  // The segmentation survives write / read through the attribute (and face quality on CMeshO when enabled).
  write_segment_ids(m, seg);
  {
    std::vector<int> back;
    FUZZ_CHECK(read_segment_ids(m, back));
    FUZZ_CHECK(back == seg);
  }

  // Manual edits: merge, split by plane, move the selected faces to a new segment.
  std::vector<int> selection;
  std::vector<int> listed;
  for (size_t f = 0; f < m.face.size(); ++f)
    if (in.u8() % 4 == 0)
      selection.push_back(int(f));
  const int listed_count = in.u8() % 6;
  for (int i = 0; i < listed_count; ++i)
    listed.push_back(int(in.u16() % uint16_t(K + 3)) - 1);
  K = merge_segments(seg, listed);
  check_segmentation(m, seg, K);
  K = split_segments_by_plane(m, adj, seg, listed, params.plane_point, params.plane_normal);
  check_segmentation(m, seg, K);
  for (int& s : listed)
    s = K > 0 ? s % K : s;
  // The edit tool's split: cut only where a stroke's mask allows, no piece under min_piece_faces.
  SplitOptions split_options;
  if (in.bit())
    for (size_t f = 0; f < m.face.size(); ++f)
      split_options.cuttable.push_back(char(in.bit()));
  split_options.min_piece_faces = in.u8() % 16;
  K = split_segments_by_plane(m, adj, seg, listed, params.plane_point, params.plane_normal, split_options);
  check_segmentation(m, seg, K);
  K = move_faces_to_new_segment(seg, selection);
  check_segmentation(m, seg, K);

  // Arbitrary labels (huge, negative, sparse) through compact_segment_ids.
  {
    std::vector<int> labels(m.face.size());
    const bool huge = in.bit();
    for (int& s : labels)
      s = huge ? int(in.u32()) : int(in.u8() % 8) - 1;
    const int L = compact_segment_ids(labels);
    check_dense(labels, L);
  }

  // Fits on the segments' samples.
  const std::vector<SegmentSamples> samples = gather_segment_samples(m, seg, K);
  FUZZ_CHECK(samples.size() == size_t(K));
  std::vector<std::optional<Primitive>> prim_of_segment(static_cast<size_t>(K));
  for (int s = 0; s < K; ++s) {
    const SegmentSamples& ss = samples[size_t(s)];
    FUZZ_CHECK(ss.points.rows() == ss.normals.rows() && ss.points.rows() == ss.weights.size());
    FUZZ_CHECK(ss.points.allFinite() && ss.normals.allFinite() && ss.weights.allFinite());
    FUZZ_CHECK(ss.vertex.size() == size_t(ss.points.rows()));
    FUZZ_CHECK(ss.area >= 0);
    if (s >= kMaxFittedSegments)
      continue;
    const int what = in.u8() % 8;
    const Eigen::MatrixX3d no_normals;
    const Eigen::MatrixX3d& normals = (what & 1) ? ss.normals : no_normals;
    const Eigen::VectorXd no_weights;
    const Eigen::VectorXd& weights = (what & 2) ? ss.weights : no_weights;
    if (what < 4) {
      const PrimitiveType type = static_cast<PrimitiveType>(in.u8() % kPrimitiveTypeCount);
      const FitResult r = fit_primitive(type, ss.points, normals, weights, params.fit);
      check_fit(r);
      if (r.status.ok()) {
        FUZZ_CHECK(r.primitive.type == type);
        prim_of_segment[size_t(s)] = r.primitive;
      }
      // The paper's type-constrained direct fit of the same points (a torus is refused: not a quadric).
      const FitResult direct = fit_quadric_direct(type, ss.points, weights);
      check_fit(direct);
      FUZZ_CHECK(!direct.status.ok() || direct.primitive.type == type);
      FUZZ_CHECK(type != PrimitiveType::Torus || !direct.status.ok());
    } else if (what >= 6) {
      // The filters' and the edit tool's fit: a given type or the automatic one, within the roughness.
      std::optional<PrimitiveType> type;
      if (in.bit())
        type = static_cast<PrimitiveType>(in.u8() % kPrimitiveTypeCount);
      AutoFitOptions options = params.auto_fit;
      options.roughness = in.special(0.05);
      const FitResult r = fit_segment(ss, type, options);
      check_fit(r);
      if (r.status.ok()) {
        FUZZ_CHECK(!type || r.primitive.type == *type);
        FUZZ_CHECK(primitive_is_valid(r.primitive));
        prim_of_segment[size_t(s)] = r.primitive;
      }
    } else {
      const AutoFitResult r = fit_primitive_auto(ss.points, normals, weights, params.auto_fit);
      for (const FitResult& c : r.candidates)
        check_fit(c);
      if (r.status.ok()) {
        FUZZ_CHECK(primitive_is_valid(r.best.primitive));
        prim_of_segment[size_t(s)] = r.best.primitive;
      }
    }
    // Refinement from a fuzzed start (the GUI's edited parameters).
    if (in.bit()) {
      const FitResult r = refine_primitive(fuzz_primitive(in), ss.points, weights, params.fit);
      check_fit(r);
    }
  }
  // Overrides: the user's edited primitives, valid or not.
  const int overrides = in.u8() % 4;
  for (int k = 0; k < overrides && K > 0; ++k)
    prim_of_segment[in.u16() % size_t(K)] = fuzz_primitive(in);

  // Sharp edges and corners directly, on fuzzed primitives and points.
  {
    const Primitive a = fuzz_primitive(in), b = fuzz_primitive(in), c = fuzz_primitive(in);
    const Eigen::Vector3d p(in.special(2), in.special(2), in.special(2));
    const double dist = in.special(3);
    Eigen::Vector3d result = Eigen::Vector3d::Constant(7.0);
    if (closest_point_on_intersection(a, b, p, dist, result))
      FUZZ_CHECK(result.allFinite());
    else
      FUZZ_CHECK(result == Eigen::Vector3d::Constant(7.0));
    std::vector<const Primitive*> three{&a, &b, &c};
    Eigen::Vector3d corner = Eigen::Vector3d::Constant(7.0);
    if (common_point_of_primitives(three, p, dist, corner))
      FUZZ_CHECK(corner.allFinite());
    else
      FUZZ_CHECK(corner == Eigen::Vector3d::Constant(7.0));
  }

  // Fit All without snapping (the mesh stays), its counts and its JSON export.
  if (K > 0 && K <= kMaxFittedSegments && in.bit()) {
    FitAllSegmentsOptions options;
    options.tolerance = in.special(0.1);
    options.types.resize(size_t(in.u8() % (K + 1)));
    for (auto& t : options.types)
      if (in.bit())
        t = static_cast<PrimitiveType>(in.u8() % kPrimitiveTypeCount);
    options.fit = params.fit;
    options.threads = 1 + in.u8() % 2;
    const FitAllSegmentsResult r = fit_all_segments(m, seg, options);
    if (r.status.ok()) {
      FUZZ_CHECK(r.segment_count() == K && r.primitives.size() == size_t(K) && !r.snap);
      int fitted = 0;
      for (int s = 0; s < K; ++s) {
        FUZZ_CHECK(r.fits[size_t(s)].status.ok() == r.primitives[size_t(s)].has_value());
        fitted += r.primitives[size_t(s)] ? 1 : 0;
      }
      FUZZ_CHECK(fitted == r.fitted && r.fitted_area <= r.total_area && std::isfinite(r.total_area));
      std::ostringstream json;
      write_fits_json(json, r, "fuzz \"mesh\"\n", false);
      const std::string text = json.str();
      FUZZ_CHECK(std::count(text.begin(), text.end(), '{') == std::count(text.begin(), text.end(), '}'));
    } else {
      FUZZ_CHECK(!std::isfinite(options.tolerance) || options.tolerance < 0);
    }
  }

  // Snap (every segment with a primitive, or one segment as the edit tool's Apply does): no vertex may become
  // non-finite; vertices not on a snapped segment stay where they are, unless the fold repair slid them;
  // with flip prevention no face is left folded.
  int target = -1;
  Primitive target_primitive;
  if (K > 0 && in.bit()) {
    target = int(in.u16() % K);
    target_primitive = prim_of_segment[size_t(target)] ? *prim_of_segment[size_t(target)] : fuzz_primitive(in);
    SegmentPrimitives effective(static_cast<size_t>(K));
    if (params.snap.sharp_edges)
      effective = read_segment_primitives(m, K);
    effective[size_t(target)] = target_primitive;
    prim_of_segment = effective;
  }
  {
    std::vector<typename MeshType::CoordType> before(m.vert.size());
    for (size_t v = 0; v < m.vert.size(); ++v)
      before[v] = m.vert[v].cP();
    std::vector<char> on_snapped(m.vert.size(), 0);
    for (size_t f = 0; f < m.face.size(); ++f) {
      if (m.face[f].IsD() || seg[f] < 0)
        continue;
      const auto& pr = prim_of_segment[size_t(seg[f])];
      if (pr && primitive_is_valid(*pr))
        for (int k = 0; k < 3; ++k)
          on_snapped[vcg::tri::Index(m, m.face[f].cV(k))] = 1;
    }
    const SnapReport report = target >= 0
                                  ? snap_onto_primitive(m, seg, {target}, target_primitive, params.snap, K)
                                  : snap_segments(m, seg, prim_of_segment, params.snap);
    if (target >= 0 && primitive_is_valid(target_primitive))
      FUZZ_CHECK(read_segment_primitives(m, K)[size_t(target)].has_value());
    FUZZ_CHECK(std::isfinite(report.mean_displacement) && std::isfinite(report.max_displacement));
    for (size_t v = 0; v < m.vert.size(); ++v) {
      const auto& p = m.vert[v].cP();
      const bool was_finite =
          std::isfinite(double(before[v][0])) && std::isfinite(double(before[v][1])) && std::isfinite(double(before[v][2]));
      if (was_finite)
        FUZZ_CHECK(std::isfinite(double(p[0])) && std::isfinite(double(p[1])) && std::isfinite(double(p[2])));
      else
        FUZZ_CHECK(std::memcmp(&p, &before[v], sizeof p) == 0);
      if (!on_snapped[v] && report.repaired_vertices == 0)
        FUZZ_CHECK(std::memcmp(&p, &before[v], sizeof p) == 0);
    }
    if (params.snap.prevent_flips)
      FUZZ_CHECK(report.folded_faces == 0);
    else
      FUZZ_CHECK(report.repaired_vertices == 0 && report.reverted_vertices == 0);
  }

  // Accuracy: sample the mesh, measure against itself and against fuzzed points.
  {
    Eigen::VectorXi faces;
    Eigen::MatrixX3d pts;
    if (!sample_surface_uniform(m, params.sample_count, params.seed, &pts, &faces).ok()) {
      FUZZ_CHECK(pts.rows() == 0);
    } else {
      FUZZ_CHECK(pts.rows() == params.sample_count && pts.allFinite() && faces.size() == pts.rows());
      for (Eigen::Index i = 0; i < faces.size(); ++i)
        FUZZ_CHECK(faces[i] >= 0 && size_t(faces[i]) < m.face.size() && !m.face[size_t(faces[i])].IsD());
    }
    SurfaceDistanceIndex index(m);
    if (index.status().ok()) {
      if (pts.rows() > 0) {
        const AccuracyReport r = measure_accuracy(pts, index, params.tolerance);
        if (r.status.ok()) {
          FUZZ_CHECK(std::isfinite(r.mean) && std::isfinite(r.rms) && std::isfinite(r.max));
          FUZZ_CHECK(r.within_tolerance_share >= 0 && r.within_tolerance_share <= 1);
        }
      }
      // A few query points near the mesh (fuzzed offsets, bounded to a few bounding boxes).
      const int queries = in.u8() % 8;
      Eigen::MatrixX3d q(queries, 3);
      for (int i = 0; i < queries; ++i)
        q.row(i) = Eigen::RowVector3d(in.special(2), in.special(2), in.special(2));
      if (queries > 0) {
        const AccuracyReport r = measure_accuracy(q, index, params.tolerance);
        if (r.status.ok())
          FUZZ_CHECK(std::isfinite(r.mean) && std::isfinite(r.max));
      }
      Eigen::VectorXd distances;
      if (vertex_distances(m, index, distances).ok())
        FUZZ_CHECK(distances.allFinite() && distances.size() == Eigen::Index(m.vert.size()));
    }
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  Decoder in(data, size);
  const uint8_t mesh_kind = in.u8();
  if (mesh_kind & 1) {
    run<CMeshO>(in);
  } else {
    run<fuzz_mesh::FMesh>(in);
  }
  return 0;
}
