// The whole batch path on a part with blurred edges: segment by normal angle, then fit_all_segments (what
// "Primitive: Fit All Segments" runs: the automatic type of every segment, snapped with sharp edges). The
// plate's chamfered rims must come out as exact sharp corners, as the filter promises. Then the filter's JSON
// export, its refusals, and snap_onto_primitive (Snap Segment and the edit tool's Apply).
#include "common/mesh/segment_primitive_attribute.h"
#include "common/pipeline/fit_all_segments.h"
#include "common/pipeline/snap_onto_primitive.h"
#include "common/pipeline/write_fits_json.h"
#include "common/segment/segment_by_normal_angle.h"
#include "plate_with_hole.h"
#include "test_mesh.h"

#include "meshlab_test_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <sstream>

using namespace primitive_edit;

namespace {

template <class M>
class SegmentFitSnapTest : public ::testing::Test
{};

using MeshTypes = ::testing::Types<test_mesh::TMesh, test_mesh::MeshLabMesh>;
TYPED_TEST_SUITE(SegmentFitSnapTest, MeshTypes);

TYPED_TEST(SegmentFitSnapTest, PlateWithHoleCornersComeOutExact)
{
  using M = TypeParam;
  const plate_fixture::PlateWithHole plate = plate_fixture::make_plate_with_hole(0.0);
  M m;
  plate_fixture::build_mesh(m, plate.soup);

  SegmentByNormalAngleParams params;
  params.angle_deg = 30;
  params.smoothing_iterations = 0;
  std::vector<int> segment_of_face;
  const int count = segment_by_normal_angle(m, params, segment_of_face);
  ASSERT_EQ(count, 7) << "six planes and the hole";

  FitAllSegmentsOptions options;
  options.snap = true;
  const FitAllSegmentsResult result = fit_all_segments(m, segment_of_face, options);
  ASSERT_TRUE(result.status.ok()) << result.status.error;
  ASSERT_EQ(result.segment_count(), count);
  for (int s = 0; s < count; ++s)
    ASSERT_TRUE(result.fits[size_t(s)].status.ok()) << "segment " << s << ": " << result.fits[size_t(s)].status.error;
  EXPECT_EQ(result.fitted, 7);
  EXPECT_EQ(result.per_type[int(PrimitiveType::Plane)], 6);
  EXPECT_EQ(result.per_type[int(PrimitiveType::Cylinder)], 1);
  EXPECT_DOUBLE_EQ(result.fitted_area, result.total_area);
  // The primitives are recorded on the mesh, for the sharp edges of a later Snap Segment.
  const SegmentPrimitives recorded = read_segment_primitives(m, count);
  for (int s = 0; s < count; ++s)
    EXPECT_TRUE(recorded[size_t(s)].has_value()) << "segment " << s;

  ASSERT_TRUE(result.snap.has_value());
  const SnapReport& report = *result.snap;
  EXPECT_EQ(report.corner_vertices, 8);
  int corners = 0;
  for (size_t v = 0; v < m.vert.size(); ++v) {
    if (plate.kind[v] != 4)
      continue;
    ++corners;
    const auto& p = m.vert[v].cP();
    EXPECT_NEAR(std::abs(double(p[0])), plate.half, 1e-4) << "corner vertex " << v;
    EXPECT_NEAR(std::abs(double(p[1])), plate.half, 1e-4) << "corner vertex " << v;
    EXPECT_TRUE(std::abs(double(p[2])) < 1e-4 || std::abs(double(p[2]) - plate.thick) < 1e-4)
        << "corner vertex " << v << " at z " << p[2];
  }
  EXPECT_EQ(corners, 8);
  // The hole's rims are sharp too: their vertices lie on the exact radius.
  for (size_t v = 0; v < m.vert.size(); ++v)
    if (plate.kind[v] == 1) {
      const auto& p = m.vert[v].cP();
      EXPECT_NEAR(std::hypot(double(p[0]), double(p[1])), plate.hole, 1e-4) << "hole rim vertex " << v;
    }
}

// A plate with hole, segmented, as the tests below start from.
template <class M>
int segmented_plate(M& m, std::vector<int>& segment_of_face)
{
  plate_fixture::build_mesh(m, plate_fixture::make_plate_with_hole(0.0).soup);
  SegmentByNormalAngleParams params;
  params.angle_deg = 30;
  params.smoothing_iterations = 0;
  return segment_by_normal_angle(m, params, segment_of_face);
}

// The same with face 1 deleted: the gathers must skip dead faces.
template <class M>
int segmented_plate_with_a_dead_face(M& m, std::vector<int>& segment_of_face)
{
  const int count = segmented_plate(m, segment_of_face);
  vcg::tri::Allocator<M>::DeleteFace(m, m.face[1]);
  return count;
}

// Fit All's samples are gathered segment by segment on every thread: the same samples on 1 and 3 threads, each
// live face's area counted once, and a face of no segment (or a dead one) in none.
TYPED_TEST(SegmentFitSnapTest, SegmentSamplesAreTheSameOnAnyThreadCount)
{
  using M = TypeParam;
  M m;
  std::vector<int> segment_of_face;
  const int count = segmented_plate_with_a_dead_face(m, segment_of_face);
  ASSERT_GE(count, 3);
  segment_of_face[0] = -1;
  double live_area = 0;
  for (std::size_t f = 2; f < m.face.size(); ++f)
    if (segment_of_face[f] >= 0)
      live_area += 0.5 * double(vcg::DoubleArea(m.face[f]));
  const std::vector<SegmentSamples> one = gather_segment_samples(m, segment_of_face, count, 1);
  const std::vector<SegmentSamples> three = gather_segment_samples(m, segment_of_face, count, 3);
  ASSERT_EQ(one.size(), std::size_t(count));
  ASSERT_EQ(three.size(), std::size_t(count));
  double area = 0;
  for (int s = 0; s < count; ++s) {
    const SegmentSamples &a = one[std::size_t(s)], &b = three[std::size_t(s)];
    EXPECT_EQ(a.vertex, b.vertex);
    EXPECT_TRUE(a.points == b.points && a.normals == b.normals && a.weights == b.weights);
    EXPECT_EQ(a.area, b.area);
    EXPECT_NEAR(a.weights.sum(), a.area, 1e-9 * a.area);
    area += a.area;
  }
  EXPECT_NEAR(area, live_area, 1e-6 * live_area);
}

TYPED_TEST(SegmentFitSnapTest, FaceSamplesAreTheSegmentsSamples)
{
  using M = TypeParam;
  M m;
  std::vector<int> segment_of_face;
  const int count = segmented_plate_with_a_dead_face(m, segment_of_face);
  ASSERT_GE(count, 2);
  const std::vector<SegmentSamples> all = gather_segment_samples(m, segment_of_face, count);
  for (int s = 0; s < count; ++s) {
    // The segment's faces, the deleted one and indices out of range among them: those add nothing.
    std::vector<int> faces = {-1, int(m.face.size())};
    for (std::size_t f = 0; f < m.face.size(); ++f)
      if (segment_of_face[f] == s || f == 1)
        faces.push_back(int(f));
    const SegmentSamples one = gather_face_samples(m, faces);
    const SegmentSamples& expected = all[std::size_t(s)];
    EXPECT_EQ(one.vertex, expected.vertex) << "segment " << s;
    EXPECT_TRUE(one.points == expected.points && one.normals == expected.normals && one.weights == expected.weights)
        << "segment " << s;
    EXPECT_EQ(one.area, expected.area) << "segment " << s;
  }
  EXPECT_EQ(gather_face_samples(m, {}).points.rows(), 0);
}

TYPED_TEST(SegmentFitSnapTest, FitAllWithoutSnapLeavesTheMeshAndExportsEverySegment)
{
  TypeParam m;
  std::vector<int> labels;
  const int count = segmented_plate(m, labels);
  std::vector<typename TypeParam::CoordType> before;
  for (const auto& v : m.vert)
    before.push_back(v.cP());

  FitAllSegmentsOptions options;
  // One face made a segment of its own and given the type Cylinder: 3 points, refused (free-form). The top
  // face's segment is given the type Sphere: fitted as given, though a plane explains it.
  int top = -1;
  for (size_t f = 0; f < m.face.size() && top < 0; ++f)
    if (vcg::NormalizedTriangleNormal(m.face[f])[2] > 0.999)
      top = labels[f];
  ASSERT_GE(top, 0);
  labels[0] = count;
  options.types.assign(size_t(count + 1), std::nullopt);
  options.types[size_t(top)] = PrimitiveType::Sphere;
  options.types[size_t(count)] = PrimitiveType::Cylinder;
  const FitAllSegmentsResult r = fit_all_segments(m, labels, options);
  ASSERT_TRUE(r.status.ok()) << r.status.error;
  EXPECT_FALSE(r.snap.has_value());
  for (size_t v = 0; v < m.vert.size(); ++v)
    EXPECT_EQ(m.vert[v].cP(), before[v]) << "vertex " << v;
  for (const auto& p : read_segment_primitives(m, count))
    EXPECT_FALSE(p.has_value()) << "recorded without a snap";

  std::ostringstream json;
  write_fits_json(json, r, "plate \"A\"", false);
  const std::string text = json.str();
  EXPECT_NE(text.find("\"mesh\": \"plate \\\"A\\\"\""), std::string::npos) << text;
  EXPECT_NE(text.find("\"segment_count\": " + std::to_string(count + 1)), std::string::npos);
  EXPECT_NE(text.find("\"snapped\": false"), std::string::npos);
  for (int s = 0; s <= count; ++s)
    EXPECT_NE(text.find("{\"id\": " + std::to_string(s) + ","), std::string::npos) << "segment " << s;
  // Each fitted plane's parameters; the free-form segments with their reason.
  int planes = 0, free_form = 0;
  for (size_t at = text.find("\"type\": \"Plane\""); at != std::string::npos; at = text.find("\"type\": \"Plane\"", at + 1))
    ++planes;
  for (size_t at = text.find("\"reason\": "); at != std::string::npos; at = text.find("\"reason\": ", at + 1))
    ++free_form;
  EXPECT_EQ(planes, r.per_type[int(PrimitiveType::Plane)]);
  EXPECT_EQ(free_form, r.segment_count() - r.fitted);
  EXPECT_TRUE(r.fits[size_t(top)].status.ok()) << r.fits[size_t(top)].status.error;
  EXPECT_EQ(r.fits[size_t(top)].primitive.type, PrimitiveType::Sphere);
  EXPECT_EQ(free_form, 1);
  EXPECT_NE(text.find("\"reason\": \"3 points; a Cylinder needs at least 6\""), std::string::npos) << text;
  EXPECT_EQ(std::count(text.begin(), text.end(), '{'), std::count(text.begin(), text.end(), '}'));
}

TYPED_TEST(SegmentFitSnapTest, FitAllRefusesBadInputAndLeavesTheMeshUntouched)
{
  TypeParam m;
  std::vector<int> labels;
  const int count = segmented_plate(m, labels);
  ASSERT_GT(count, 0);
  const auto first = m.vert[0].cP();
  FitAllSegmentsOptions options;
  options.snap = true;
  for (double bad : {-1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    options.tolerance = bad;
    const FitAllSegmentsResult r = fit_all_segments(m, labels, options);
    EXPECT_EQ(r.status.error, "the fit tolerance must be 0 (automatic) or positive") << bad;
  }
  options.tolerance = 0;
  options.relation_options.angle_deg = 95;
  EXPECT_EQ(fit_all_segments(m, labels, options).status.error,
            "relations: the relation angle must be between 0 and 90 degrees, the distance finite and the cost share "
            "positive");
  options.relation_options = RelationOptions();
  const std::vector<int> none(m.face.size(), -1);
  EXPECT_EQ(fit_all_segments(m, none, options).status.error, "the mesh has no segments");
  EXPECT_EQ(m.vert[0].cP(), first);
}

TYPED_TEST(SegmentFitSnapTest, SnapOntoPrimitiveRecordsSegmentsButNotASelection)
{
  TypeParam m;
  std::vector<int> labels;
  const int count = segmented_plate(m, labels);
  const plate_fixture::PlateWithHole plate = plate_fixture::make_plate_with_hole(0.0);
  // The hole's segment: the one whose faces' vertices are all on the hole's rim or wall.
  int hole = -1;
  for (size_t f = 0; f < m.face.size() && hole < 0; ++f) {
    const auto c = (m.face[f].cP(0) + m.face[f].cP(1) + m.face[f].cP(2)) / 3;
    if (std::hypot(double(c[0]), double(c[1])) < plate.hole + 0.1)
      hole = labels[f];
  }
  ASSERT_GE(hole, 0);
  Primitive wider;
  wider.type = PrimitiveType::Cylinder;
  wider.origin = Eigen::Vector3d::Zero();
  wider.axis = Eigen::Vector3d::UnitZ();
  wider.radius = plate.hole + 0.5;

  SnapOptions options;
  options.sharp_edges = false;
  const SnapReport r = snap_onto_primitive(m, labels, {hole}, wider, options, count);
  EXPECT_GT(r.moved_vertices, 0);
  // Inside the hole's segment (not on its border with the unsnapped planes) every vertex is on the new radius.
  std::vector<char> on_hole(m.vert.size(), 0), on_other(m.vert.size(), 0);
  for (size_t f = 0; f < m.face.size(); ++f)
    for (int k = 0; k < 3; ++k)
      (labels[f] == hole ? on_hole : on_other)[vcg::tri::Index(m, m.face[f].cV(k))] = 1;
  int inside = 0;
  for (size_t v = 0; v < m.vert.size(); ++v)
    if (on_hole[v] && !on_other[v]) {
      ++inside;
      EXPECT_NEAR(std::hypot(double(m.vert[v].cP()[0]), double(m.vert[v].cP()[1])), wider.radius, 1e-4);
    }
  EXPECT_GT(inside, 0);
  SegmentPrimitives recorded = read_segment_primitives(m, count);
  ASSERT_TRUE(recorded[size_t(hole)].has_value());
  EXPECT_DOUBLE_EQ(recorded[size_t(hole)]->radius, wider.radius);

  // A selection (label count, beyond the segments) moves but is not recorded.
  std::vector<int> with_selection = labels;
  for (size_t f = 0; f < m.face.size(); ++f)
    if (labels[f] == hole)
      with_selection[f] = count;
  wider.radius += 0.25;
  snap_onto_primitive(m, with_selection, {count}, wider, options, count);
  recorded = read_segment_primitives(m, count);
  EXPECT_EQ(recorded.size(), size_t(count));
  EXPECT_DOUBLE_EQ(recorded[size_t(hole)]->radius, wider.radius - 0.25);

  // An invalid primitive moves nothing and records nothing.
  const auto before = m.vert[0].cP();
  Primitive invalid = wider;
  invalid.radius = -1;
  EXPECT_EQ(snap_onto_primitive(m, labels, {0}, invalid, options, count).moved_vertices, 0);
  EXPECT_EQ(m.vert[0].cP(), before);
  EXPECT_FALSE(read_segment_primitives(m, count)[0].has_value());
}

} // namespace
