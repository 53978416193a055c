// fit_segments and fit_segment: every segment gets the type it is, or the type it is given, whatever the thread
// count; too small a segment is refused with its point count; progress reaches the total on the calling thread.
#include "common/base/constants.h"
#include "common/pipeline/fit_segments.h"
#include "test_fit_data.h"

#include <gtest/gtest.h>

#include <thread>

using namespace primitive_edit;
using namespace test_fit;

namespace {

SegmentSamples segment_of(const Primitive& p, const Patch& patch, int n, unsigned seed)
{
  Sample s = sample_primitive(p, patch, n, seed);
  add_noise(&s, 0.005, 2.0, seed + 1);
  SegmentSamples out;
  out.points = s.points;
  out.normals = s.normals;
  out.weights = Eigen::VectorXd::Ones(s.points.rows());
  return out;
}

std::vector<SegmentSamples> five_segments_and_a_tiny_one()
{
  Patch half;
  half.sweep = kPi;
  half.extent = 2;
  Patch cap;
  cap.cap = kPi / 3;
  Patch frustum;
  frustum.near = 1;
  frustum.far = 2;
  frustum.sweep = kPi;
  std::vector<SegmentSamples> segments = {
      segment_of(make_plane({0, 0, 0}, {0.2, 0.1, 1}), Patch(), 3000, 1),
      segment_of(make_sphere({1, 0, 0}, 1), cap, 800, 3),
      segment_of(make_cylinder({0, 0, 0}, {0, 0.3, 1}, 1), half, 5000, 5),
      segment_of(make_cone({0, 0, 0}, {0.1, 0, 1}, 0.4), frustum, 1200, 7),
      segment_of(make_torus({0, 0, 0}, {0, 0, 1}, 2, 0.5), Patch(), 2000, 9),
  };
  SegmentSamples tiny;
  tiny.points = Eigen::MatrixX3d::Random(2, 3);
  tiny.normals = Eigen::MatrixX3d::Zero(2, 3);
  tiny.normals.col(2).setOnes();
  tiny.weights = Eigen::VectorXd::Ones(2);
  segments.push_back(tiny);
  return segments;
}

} // namespace

TEST(FitSegments, EachSegmentGetsItsTypeAndTheTinyOneIsFreeForm)
{
  const std::vector<SegmentSamples> segments = five_segments_and_a_tiny_one();
  const std::vector<FitResult> fits = fit_segments(segments, {}, {}, 2);
  ASSERT_EQ(fits.size(), segments.size());
  const PrimitiveType expected[] = {PrimitiveType::Plane, PrimitiveType::Sphere, PrimitiveType::Cylinder,
                                    PrimitiveType::Cone, PrimitiveType::Torus};
  for (int s = 0; s < 5; ++s) {
    ASSERT_TRUE(fits[size_t(s)].status.ok()) << "segment " << s << ": " << fits[size_t(s)].status.error;
    EXPECT_EQ(fits[size_t(s)].primitive.type, expected[s]) << "segment " << s;
  }
  EXPECT_FALSE(fits[5].status.ok());
  EXPECT_EQ(fits[5].status.error, "2 points; a Plane needs at least 3");
}

TEST(FitSegments, ResultsDoNotDependOnTheThreadCount)
{
  const std::vector<SegmentSamples> segments = five_segments_and_a_tiny_one();
  const std::vector<FitResult> one = fit_segments(segments, {}, {}, 1);
  const std::vector<FitResult> four = fit_segments(segments, {}, {}, 4);
  ASSERT_EQ(one.size(), four.size());
  for (size_t s = 0; s < one.size(); ++s) {
    EXPECT_EQ(one[s].status.ok(), four[s].status.ok());
    EXPECT_EQ(one[s].primitive.type, four[s].primitive.type);
    EXPECT_EQ(one[s].rms, four[s].rms) << "segment " << s;
    EXPECT_EQ(one[s].primitive.origin, four[s].primitive.origin) << "segment " << s;
  }
}

TEST(FitSegments, ProgressIsReportedOnTheCallingThreadUpToTheTotal)
{
  const std::vector<SegmentSamples> segments = five_segments_and_a_tiny_one();
  const std::thread::id caller = std::this_thread::get_id();
  int calls = 0, last = 0;
  bool other_thread = false;
  fit_segments(segments, {}, {}, 3, [&](int percent, const char*) {
    ++calls;
    other_thread = other_thread || std::this_thread::get_id() != caller;
    EXPECT_GE(percent, last);
    last = percent;
    return true;
  });
  EXPECT_GE(calls, 1);
  EXPECT_LE(last, 100);
  EXPECT_FALSE(other_thread);
}

TEST(FitSegments, NoSegmentsGiveNoResults)
{
  EXPECT_TRUE(fit_segments({}, {}, {}, 4).empty());
}

TEST(FitSegments, AGivenTypeIsFittedEvenWhereAnotherFitsBetter)
{
  const std::vector<SegmentSamples> segments = five_segments_and_a_tiny_one();
  std::vector<std::optional<PrimitiveType>> types(segments.size());
  types[2] = PrimitiveType::Cone;      // the cylinder, as a cone: a valid cone close to it
  types[4] = PrimitiveType::Cylinder;  // the torus, as a cylinder
  types[5] = PrimitiveType::Sphere;    // 2 points: refused for the sphere's minimum
  const std::vector<FitResult> fits = fit_segments(segments, types, {}, 2);
  ASSERT_TRUE(fits[2].status.ok()) << fits[2].status.error;
  EXPECT_EQ(fits[2].primitive.type, PrimitiveType::Cone);
  ASSERT_TRUE(fits[4].status.ok()) << fits[4].status.error;
  EXPECT_EQ(fits[4].primitive.type, PrimitiveType::Cylinder);
  EXPECT_EQ(fits[5].status.error, "2 points; a Sphere needs at least 4");
  EXPECT_EQ(fits[0].primitive.type, PrimitiveType::Plane);  // no type given: automatic
}

TEST(FitSegment, AFreeFormSegmentIsRefusedWithTheReasonAndKeepsTheBestFitForInformation)
{
  SegmentSamples wavy;
  const int n = 40;
  wavy.points.resize(n * n, 3);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      wavy.points.row(i * n + j) = Eigen::RowVector3d(i, j, 4 * std::sin(0.5 * i) * std::cos(0.4 * j));
  wavy.normals = Eigen::MatrixX3d::Zero(n * n, 3);
  wavy.weights = Eigen::VectorXd::Ones(n * n);
  const FitResult fit = fit_segment(wavy, std::nullopt);
  EXPECT_FALSE(fit.status.ok());
  EXPECT_EQ(fit.status.error.rfind("free-form", 0), 0u) << fit.status.error;
}
