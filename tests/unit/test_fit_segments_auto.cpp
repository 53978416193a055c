// fit_segments_auto: every segment gets the type it is, whatever the thread count; too small a segment is
// free-form; progress reaches the total on the calling thread.
#include "common/base/constants.h"
#include "common/pipeline/fit_segments_auto.h"
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

TEST(FitSegmentsAuto, EachSegmentGetsItsTypeAndTheTinyOneIsFreeForm)
{
  const std::vector<SegmentSamples> segments = five_segments_and_a_tiny_one();
  const std::vector<AutoFitResult> fits = fit_segments_auto(segments, {}, 2);
  ASSERT_EQ(fits.size(), segments.size());
  const PrimitiveType expected[] = {PrimitiveType::Plane, PrimitiveType::Sphere, PrimitiveType::Cylinder,
                                    PrimitiveType::Cone, PrimitiveType::Torus};
  for (int s = 0; s < 5; ++s) {
    ASSERT_TRUE(fits[size_t(s)].ok) << "segment " << s << ": " << fits[size_t(s)].message;
    EXPECT_EQ(fits[size_t(s)].best.primitive.type, expected[s]) << "segment " << s;
  }
  EXPECT_FALSE(fits[5].ok);
  EXPECT_EQ(fits[5].message, "too few points");
}

TEST(FitSegmentsAuto, ResultsDoNotDependOnTheThreadCount)
{
  const std::vector<SegmentSamples> segments = five_segments_and_a_tiny_one();
  const std::vector<AutoFitResult> one = fit_segments_auto(segments, {}, 1);
  const std::vector<AutoFitResult> four = fit_segments_auto(segments, {}, 4);
  ASSERT_EQ(one.size(), four.size());
  for (size_t s = 0; s < one.size(); ++s) {
    EXPECT_EQ(one[s].ok, four[s].ok);
    EXPECT_EQ(one[s].best.primitive.type, four[s].best.primitive.type);
    EXPECT_EQ(one[s].best.rms, four[s].best.rms) << "segment " << s;
    EXPECT_EQ(one[s].best.primitive.origin, four[s].best.primitive.origin) << "segment " << s;
  }
}

TEST(FitSegmentsAuto, ProgressIsReportedOnTheCallingThreadUpToTheTotal)
{
  const std::vector<SegmentSamples> segments = five_segments_and_a_tiny_one();
  const std::thread::id caller = std::this_thread::get_id();
  int calls = 0, last = 0;
  bool other_thread = false;
  fit_segments_auto(segments, {}, 3, [&](int percent, const char*) {
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

TEST(FitSegmentsAuto, NoSegmentsGiveNoResults)
{
  EXPECT_TRUE(fit_segments_auto({}, {}, 4).empty());
}
