// The whole batch path on a part with blurred edges: segment by normal angle, fit every segment
// (automatic type, from the mesh's own samples), snap with sharp edges. The plate's chamfered rims
// must come out as exact sharp corners, as Primitive: Fit All Segments promises.
#include "common/fit/fit_primitive_auto.h"
#include "common/mesh/gather_segment_samples.h"
#include "common/segment/segment_by_normal_angle.h"
#include "common/snap/snap_segments.h"
#include "plate_with_hole.h"
#include "test_mesh.h"

#include <common/ml_mesh_type.h>

#include <gtest/gtest.h>

#include <map>

using namespace primitive_edit;

namespace {

template <class M>
class SegmentFitSnapTest : public ::testing::Test
{};

using MeshTypes = ::testing::Types<test_mesh::TMesh, CMeshO>;
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

  const std::vector<SegmentSamples> samples = gather_segment_samples(m, segment_of_face, count);
  std::vector<std::optional<Primitive>> primitives(static_cast<size_t>(count));
  std::map<PrimitiveType, int> types;
  for (int s = 0; s < count; ++s) {
    const SegmentSamples& x = samples[static_cast<size_t>(s)];
    const AutoFitResult fit = fit_primitive_auto(x.points, x.normals, x.weights);
    ASSERT_TRUE(fit.ok) << "segment " << s << ": " << fit.message;
    primitives[static_cast<size_t>(s)] = fit.best.primitive;
    ++types[fit.best.primitive.type];
  }
  EXPECT_EQ(types[PrimitiveType::Plane], 6);
  EXPECT_EQ(types[PrimitiveType::Cylinder], 1);

  const SnapReport report = snap_segments(m, segment_of_face, primitives);
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

} // namespace
