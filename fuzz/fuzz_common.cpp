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
#include "common/base/ordered_bits.h"
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
#include "common/pipeline/primitive_edit_session.h"
#include "common/pipeline/snap_onto_primitive.h"
#include "common/pipeline/write_fits_json.h"
#include "common/snap/snap_segments.h"
#include "common/segment/split_segments_by_plane.h"
#include "fuzz/check_growing_report.h"
#include "fuzz/decoded_mesh_type.h"
#include "fuzz/fuzz_input.h"
#include "fuzz/snap_checked.h"

#include <vcg/complex/complex.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <limits>
#include <numeric>
#include <optional>
#include <sstream>
#include <type_traits>
#include <vector>

using namespace primitive_edit;
using namespace fuzz;

namespace {

constexpr int kMaxFittedSegments = 4;

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


// The walk that keeps a slid vertex on the scan (snap's fold repair), over the live faces of finite corners
// from the first one, to a decoded point: it ends on such a face, at a finite point when the query is finite.
template <class MeshType>
void check_surface_walk(Decoder& in, const MeshType& m)
{
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
}

// The seed order's bucket key (seed_queue.h) keeps the order of decoded keys (ties, -0, infinities).
void check_ordered_bits(Decoder& in)
{
  if (in.bit()) {
    const double a = in.special(1.0), b = in.special(1.0);
    if (!std::isnan(a) && !std::isnan(b)) {
      FUZZ_CHECK((a < b) == (ordered_bits(a) < ordered_bits(b)));
      FUZZ_CHECK((a == b) == (ordered_bits(a) == ordered_bits(b)));
    }
  }
}

// Normal smoothing: a unit (or zero) normal per face.
template <class MeshType>
void check_smoothing(const MeshType& m, const FaceAdjacency& adj, const Params& params)
{
  const std::vector<Eigen::Vector3d> smoothed =
      smooth_face_normals(m, adj, std::max(0, params.segment.smoothing_iterations), std::abs(params.segment.angle_deg));
  FUZZ_CHECK(smoothed.size() == m.face.size());
  for (const auto& n : smoothed)
    FUZZ_CHECK(n.allFinite() && (n.isZero(0.0) || std::abs(n.norm() - 1.0) < 1e-6));
}

// The paper's segmentation into seg: dense ids, and the same with the adjacency built inside; returns the count.
template <class MeshType>
int check_normal_angle_segmentation(const MeshType& m, const FaceAdjacency& adj, const Params& params,
                                    std::vector<int>& seg)
{
  const int K = segment_by_normal_angle(m, adj, params.segment, seg);
  check_segmentation(m, seg, K);
  {
    std::vector<int> again;
    FUZZ_CHECK(segment_by_normal_angle(m, params.segment, again) == K && again == seg);
  }
  return K;
}

// Primitive growing (the scan segmentation) at its defaults: every live face labelled, deterministic, and
// the roughness it measured is the one kept on the mesh for the fits.
template <class MeshType>
void check_primitive_growing(Decoder& in, MeshType& m, const FaceAdjacency& adj)
{
  if (in.bit()) {
    SegmentByPrimitiveGrowingParams grow;
    std::vector<int> grown, again;
    SegmentByPrimitiveGrowingReport report;
    const int G = segment_by_primitive_growing(m, adj, grow, grown, &report);
    check_segmentation(m, grown, G);
    check_growing_report(report, G);
    FUZZ_CHECK(segment_by_primitive_growing(m, adj, grow, again) == G && again == grown);
    const double kept = surface_roughness(m, adj);
    FUZZ_CHECK(std::isfinite(kept) && kept >= 0 && read_surface_roughness(m) == kept);
  }
}

// Neighbouring segments never share a colour.
template <class MeshType>
void check_colours(const MeshType& m, const FaceAdjacency& adj, const std::vector<int>& seg, int K)
{
  if (K > 0) {
    const std::vector<vcg::Color4b> colour = color_segments(m, adj, seg);
    FUZZ_CHECK(colour.size() == size_t(K));
    for (int f = 0; f < adj.face_count(); ++f)
      for (int k = adj.offset[size_t(f)]; k < adj.offset[size_t(f) + 1]; ++k) {
        const int a = seg[size_t(f)], b = seg[size_t(adj.neighbour[size_t(k)])];
        FUZZ_CHECK(a == b || colour[size_t(a)] != colour[size_t(b)]);
      }
  }
}

// The segmentation survives write / read through the attribute (and face quality on CMeshO when enabled).
template <class MeshType>
void check_segment_ids_kept(MeshType& m, const std::vector<int>& seg)
{
  write_segment_ids(m, seg);
  {
    std::vector<int> back;
    FUZZ_CHECK(read_segment_ids(m, back));
    FUZZ_CHECK(back == seg);
  }
}

// Manual edits: merge, split by plane, move the selected faces to a new segment.
template <class MeshType>
int check_manual_edits(Decoder& in, const MeshType& m, const FaceAdjacency& adj, const Params& params,
                       std::vector<int>& seg, int K)
{
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
  const std::vector<int> former = seg;
  K = split_segments_by_plane(m, adj, seg, listed, params.plane_point, params.plane_normal, split_options);
  check_segmentation(m, seg, K);
  // Every piece has min_piece_faces faces or is all of its former segment.
  std::vector<int> former_size(former.size() + 1, 0), piece_size(std::size_t(std::max(K, 0)), 0);
  for (size_t f = 0; f < seg.size(); ++f)
    if (former[f] >= 0 && seg[f] >= 0) {
      ++former_size[std::size_t(former[f])];
      ++piece_size[std::size_t(seg[f])];
    }
  for (size_t f = 0; f < seg.size(); ++f)
    if (former[f] >= 0 && seg[f] >= 0)
      FUZZ_CHECK(piece_size[std::size_t(seg[f])] >= std::min(split_options.min_piece_faces,
                                                              former_size[std::size_t(former[f])]));
  K = move_faces_to_new_segment(seg, selection);
  check_segmentation(m, seg, K);
  return K;
}

// Arbitrary labels (huge, negative, sparse) through compact_segment_ids.
template <class MeshType>
void check_compaction(Decoder& in, const MeshType& m)
{
  {
    std::vector<int> labels(m.face.size());
    const bool huge = in.bit();
    for (int& s : labels)
      s = huge ? int(in.u32()) : int(in.u8() % 8) - 1;
    const int L = compact_segment_ids(labels);
    check_dense(labels, L);
  }
}

// Fits on the segments' samples, then the user's overrides: returns each segment's primitive, or none.
template <class MeshType>
std::vector<std::optional<Primitive>> fit_segments_checked(Decoder& in, const MeshType& m, const std::vector<int>& seg,
                                                             int K, const Params& params)
{
  const std::vector<SegmentSamples> samples = gather_segment_samples(m, seg, K);
  FUZZ_CHECK(samples.size() == size_t(K));
  {
    const std::vector<SegmentSamples> on_two = gather_segment_samples(m, seg, K, 2); // same on any thread count
    for (int s = 0; s < K; ++s) {
      const SegmentSamples &a = samples[size_t(s)], &b = on_two[size_t(s)];
      FUZZ_CHECK(a.vertex == b.vertex && a.points == b.points && a.normals == b.normals && a.weights == b.weights);
    }
  }
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
  return prim_of_segment;
}

// Sharp edges and corners directly, on fuzzed primitives and points.
void check_edges_and_corners(Decoder& in)
{
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
}

// Fit All without snapping (the mesh stays), its counts and its JSON export.
template <class MeshType>
void check_fit_all(Decoder& in, MeshType& m, const std::vector<int>& seg, int K, const Params& params)
{
  if (K > 0 && K <= kMaxFittedSegments && in.bit()) {
    FitAllSegmentsOptions options;
    options.tolerance = in.special(0.1);
    options.types.resize(size_t(in.u8() % (K + 1)));
    for (auto& t : options.types)
      if (in.bit())
        t = static_cast<PrimitiveType>(in.u8() % kPrimitiveTypeCount);
    options.fit = params.fit;
    options.threads = 1 + in.u8() % 2;
    // Blends kept on the mesh as the segmentation keeps them, naming any segments or none: Fit All checks each.
    std::vector<SegmentBlendRecord> given(size_t(in.u8() % 4));
    for (auto& b : given)
      b = {int(in.u8() % (K + 2)) - 1, int(in.u8() % (K + 2)) - 1, int(in.u8() % (K + 2)) - 1};
    write_segment_blends(m, seg, given);
    // The records name segments by their faces: read under every id shifted by one, each names the shifted ids.
    const std::vector<SegmentBlendRecord> kept = read_segment_blends(m, seg);
    std::vector<int> shifted = seg;
    for (int& s : shifted)
      s = s < 0 ? s : s + 1;
    const std::vector<SegmentBlendRecord> moved = read_segment_blends(m, shifted);
    FUZZ_CHECK(moved.size() == kept.size() && kept.size() <= given.size());
    for (std::size_t i = 0; i < kept.size() && i < moved.size(); ++i)
      FUZZ_CHECK(moved[i].segment == kept[i].segment + 1 && moved[i].plane_a == kept[i].plane_a + 1 &&
                 moved[i].plane_b == kept[i].plane_b + 1);
    const FitAllSegmentsResult r = fit_all_segments(m, seg, options);
    if (r.status.ok()) {
      FUZZ_CHECK(r.segment_count() == K && r.primitives.size() == size_t(K) && !r.snap);
      int fitted = 0;
      for (int s = 0; s < K; ++s) {
        FUZZ_CHECK(r.fits[size_t(s)].status.ok() == r.primitives[size_t(s)].has_value());
        fitted += r.primitives[size_t(s)] ? 1 : 0;
      }
      FUZZ_CHECK(fitted == r.fitted && r.fitted_area <= r.total_area && std::isfinite(r.total_area));
      FUZZ_CHECK(std::accumulate(std::begin(r.per_type), std::end(r.per_type), 0) == r.fitted);
      // A blend's relations are its tangencies, a profile's its one relation to its axis.
      auto relations_of = [&](int s) {
        std::vector<Relation> of;
        for (const Relation& rel : r.relations)
          if (rel.a == s || rel.b == s)
            of.push_back(rel);
        return of;
      };
      for (const SegmentEdgeBlend& b : r.blends) {
        const std::optional<Primitive>& p = r.primitives[size_t(b.segment)];
        FUZZ_CHECK(p && p->type == b.primitive.type && primitive_is_valid(*p));
        if (size_t(b.segment) < options.types.size() && options.types[size_t(b.segment)])
          FUZZ_CHECK(*options.types[size_t(b.segment)] == p->type);
        for (const Relation& rel : relations_of(b.segment))
          FUZZ_CHECK(rel.kind == RelationKind::Tangent && rel.a == b.segment && b.form == BlendForm::Fillet);
      }
      for (const SegmentProfile& q : r.profiles) {
        const std::optional<Primitive>& p = r.primitives[size_t(q.segment)];
        FUZZ_CHECK(p && p->type == q.primitive.type && primitive_is_valid(*p));
        const std::vector<Relation> of = relations_of(q.segment);
        const bool axis_blended = std::any_of(r.blends.begin(), r.blends.end(), [&](const SegmentEdgeBlend& b) {
          return b.segment == q.axis_segment;
        });  // then the axis is a fillet's, and the coaxiality was dropped with its relations
        FUZZ_CHECK(of.size() == (axis_blended ? 0u : 1u));
        for (const Relation& rel : of)
          FUZZ_CHECK(rel.a == q.axis_segment && rel.b == q.segment);
      }
      std::ostringstream json;
      write_fits_json(json, r, "fuzz \"mesh\"\n", false);
      const std::string text = json.str();
      FUZZ_CHECK(std::count(text.begin(), text.end(), '{') == std::count(text.begin(), text.end(), '}'));
    } else {
      FUZZ_CHECK(!std::isfinite(options.tolerance) || options.tolerance < 0);
    }
  }
}

// Snap (every segment with a primitive, or one segment as the edit tool's Apply does): no vertex may become
// non-finite; vertices not on a snapped segment stay where they are, unless the fold repair slid them;
// with flip prevention no face is left folded.
template <class MeshType>
void check_snap(Decoder& in, MeshType& m, const std::vector<int>& seg, int K, const Params& params,
                std::vector<std::optional<Primitive>> prim_of_segment)
{
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
  snap_checked(m, seg, prim_of_segment, target, target_primitive, params.snap, K);
}

// Accuracy: sample the mesh, measure against itself and against fuzzed points.
template <class MeshType>
void check_accuracy(Decoder& in, const MeshType& m, const Params& params)
{
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

// The edit tool's fit of one or two picked segments, alone or with the relations to the others (Fit All on the
// picks joined): it moves no vertex and changes no segment id; a fit with ok == true gives a valid primitive with
// finite residuals, and relations are either held (listed) or refused with a reason, never both.
template <class MeshType>
void check_edit_fit(Decoder& in, MeshType& m, const std::vector<int>& seg, int K, const Params& params)
{
  // Runs unless a byte says not: at the end of the decoding, most inputs have run out of bytes (then 0).
  if (K < 1 || K > kMaxFittedSegments || m.face.empty() || in.bit())
    return;
  write_segment_ids(m, seg);
  std::vector<typename MeshType::CoordType> before(m.vert.size());
  for (std::size_t v = 0; v < m.vert.size(); ++v)
    before[v] = m.vert[v].cP();
  PrimitiveEditSession<MeshType> session;
  if (!session.attach(m).status.ok())
    return;
  const std::vector<int> ids = session.segment_of_face();
  session.pick(int(in.u16() % m.face.size()), false);
  if (in.bit())
    session.pick(int(in.u16() % m.face.size()), true);
  const std::optional<PrimitiveType> type =
      in.bit() ? std::optional<PrimitiveType>(static_cast<PrimitiveType>(in.u8() % kPrimitiveTypeCount)) : std::nullopt;
  const FitResult fit = session.fit(type, params.fit.method, !in.bit());
  if (fit.status.ok()) {
    FUZZ_CHECK(primitive_is_valid(fit.primitive) && std::isfinite(fit.rms) && std::isfinite(fit.max_residual));
    FUZZ_CHECK(session.edited().has_value());
  } else {
    FUZZ_CHECK(!fit.status.error.empty() && !session.edited());
  }
  FUZZ_CHECK(session.fit_relations().empty() || session.relations_refused().empty());
  for (const std::string& line : session.fit_relations())
    FUZZ_CHECK(!line.empty());
  FUZZ_CHECK(session.segment_of_face() == ids);
  for (std::size_t v = 0; v < m.vert.size(); ++v)
    FUZZ_CHECK(m.vert[v].cP() == before[v] || !(m.vert[v].cP() == m.vert[v].cP()));  // NaN != NaN
  session.detach();
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
  const AttributeCleaner<MeshType> cleaner{m};
  build_mesh(in, m);
  const Params params = decode_params(in);

  (void)check_mesh_input(m);

  const FaceAdjacency adj = build_face_adjacency(m);
  check_adjacency(m, adj);

  check_surface_walk(in, m);
  check_ordered_bits(in);
  check_smoothing(m, adj, params);
  std::vector<int> seg;
  int K = check_normal_angle_segmentation(m, adj, params, seg);
  check_primitive_growing(in, m, adj);
  check_colours(m, adj, seg, K);
  check_segment_ids_kept(m, seg);
  K = check_manual_edits(in, m, adj, params, seg, K);
  check_compaction(in, m);
  std::vector<std::optional<Primitive>> prim_of_segment = fit_segments_checked(in, m, seg, K, params);
  check_edges_and_corners(in);
  check_fit_all(in, m, seg, K, params);
  check_snap(in, m, seg, K, params, std::move(prim_of_segment));
  check_accuracy(in, m, params);
  check_edit_fit(in, m, seg, K, params);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  Decoder in(data, size);
  on_decoded_mesh_type(in, [&](auto tag) { run<typename decltype(tag)::Mesh>(in); });
  return 0;
}
