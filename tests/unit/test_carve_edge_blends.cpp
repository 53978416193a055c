// The fillets that a CT scan's roughness hides in their planes (common/segment/carve_edge_blends.h, through
// segment_by_primitive_growing) and Fit All making them the blends of those planes (segment_blends_attribute.h,
// fit_all_segments.h). The part: the edge of a plate, the top z = 0 for y < 0 and the side y = 0 below it, 40 mm
// long, rounded by a fillet of radius R or sharp, its surface moved along the normal by smooth waves of 0.3 mm RMS
// over 1.5-4 mm (a CT scan's roughness, as bench/bracket/README.md's preset paper: there a 1.5 mm fillet stands
// 0.44 mm off its sharp edge, less than the segmentation's tolerance, and goes to its planes).
#include "common/base/constants.h"
#include "common/mesh/segment_blends_attribute.h"
#include "common/pipeline/fit_all_segments.h"
#include "common/pipeline/primitive_edit_session.h"
#include "common/segment/carve_edge_blends.h"
#include "common/segment/describe_carved_blends.h"
#include "common/segment/segment_by_primitive_growing.h"

#include "test_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace primitive_edit;
using test_mesh::TMesh;

constexpr double kCarveFace = 8.0;   // of each plane, from the edge
constexpr double kCarveLength = 40.0; // along x
constexpr double kCarveStep = 0.25;
constexpr double kCarveRoughness = 0.3; // RMS of the waves

// The profile at arc length u from the top's far end: point (y, z) and outward normal; fillet radius r (0: sharp).
void carve_profile_at(double r, double u, double& y, double& z, double& ny, double& nz)
{
  const double top = kCarveFace - r, arc = 0.5 * kPi * r;
  if (u < top) {
    y = -kCarveFace + u, z = 0, ny = 0, nz = 1;
  } else if (u < top + arc) {
    const double a = (u - top) / r; // 0 at the top's tangent line
    ny = std::sin(a), nz = std::cos(a);
    y = -r + r * ny, z = -r + r * nz;
  } else {
    y = 0, z = -r - (u - top - arc), ny = 1, nz = 0;
  }
}

// The rough plate edge, its side `side` mm tall; truth[f] = 1 for the faces whose noise-free centroid lies on the
// fillet, else 0.
void make_rough_plate_edge(TMesh& m, double r, std::vector<int>& truth, double side = kCarveFace)
{
  m.Clear();
  const double length = (kCarveFace - r) + 0.5 * kPi * r + (side - r);
  const int nu = int(std::ceil(length / kCarveStep)), nx = int(std::ceil(kCarveLength / kCarveStep));
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  struct CarveWave { double kx, ku, phase; };
  std::vector<CarveWave> waves;
  for (int k = 0; k < 12; ++k) {
    const double wavelength = 1.5 + 2.5 * U(rng), angle = 2 * kPi * U(rng);
    waves.push_back({2 * kPi / wavelength * std::cos(angle), 2 * kPi / wavelength * std::sin(angle), 2 * kPi * U(rng)});
  }
  auto vi = vcg::tri::Allocator<TMesh>::AddVertices(m, std::size_t(nu + 1) * std::size_t(nx + 1));
  std::vector<char> on_fillet;
  for (int i = 0; i <= nu; ++i)
    for (int j = 0; j <= nx; ++j, ++vi) {
      const double u = length * i / nu, x = kCarveLength * j / nx;
      double y, z, ny, nz;
      carve_profile_at(r, u, y, z, ny, nz);
      double d = 0;
      for (const CarveWave& w : waves)
        d += std::sin(w.kx * x + w.ku * u + w.phase);
      d *= kCarveRoughness * std::sqrt(2.0 / double(waves.size()));
      vi->P() = TMesh::CoordType(x, y + d * ny, z + d * nz);
      on_fillet.push_back(r > 0 && u > kCarveFace - r && u < kCarveFace - r + 0.5 * kPi * r ? 1 : 0);
    }
  truth.clear();
  auto at = [&](int i, int j) { return std::size_t(i) * std::size_t(nx + 1) + std::size_t(j); };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nx; ++j) {
      vcg::tri::Allocator<TMesh>::AddFace(m, &m.vert[at(i, j)], &m.vert[at(i + 1, j)], &m.vert[at(i + 1, j + 1)]);
      vcg::tri::Allocator<TMesh>::AddFace(m, &m.vert[at(i, j)], &m.vert[at(i + 1, j + 1)], &m.vert[at(i, j + 1)]);
      const int fillet = on_fillet[at(i, j)] + on_fillet[at(i + 1, j)] + on_fillet[at(i + 1, j + 1)];
      truth.push_back(fillet >= 2 ? 1 : 0);
      truth.push_back(fillet >= 2 ? 1 : 0);
    }
}

// The share of the fillet's faces in segment s, and of s's faces on the fillet.
void carved_fillet_overlap(const std::vector<int>& seg, const std::vector<int>& truth, int s, double& recall,
                    double& precision)
{
  int both = 0, in_s = 0, in_fillet = 0;
  for (std::size_t f = 0; f < seg.size(); ++f) {
    in_s += seg[f] == s ? 1 : 0;
    in_fillet += truth[f];
    both += seg[f] == s && truth[f] ? 1 : 0;
  }
  recall = in_fillet ? double(both) / in_fillet : 0;
  precision = in_s ? double(both) / in_s : 0;
}

// The rough plate edge with a fillet of radius r (0: sharp), segmented at the defaults; returns the segment count.
int segment_rough_plate_edge(TMesh& m, double r, std::vector<int>& truth, std::vector<int>& seg,
                             SegmentByPrimitiveGrowingReport& report)
{
  make_rough_plate_edge(m, r, truth);
  return segment_by_primitive_growing(m, SegmentByPrimitiveGrowingParams(), seg, &report);
}

TEST(CarveEdgeBlends, RoughFilletBecomesItsOwnSegmentAndFitAllKeepsItABlend)
{
  TMesh m;
  std::vector<int> truth, seg;
  SegmentByPrimitiveGrowingReport report;
  const int K = segment_rough_plate_edge(m, 1.5, truth, seg, report);
  // The fillet stands 0.44 mm off the sharp edge, about the tolerance: growth gives it to its planes.
  EXPECT_GT(report.tolerance, 0.4);
  ASSERT_EQ(report.blends.size(), 1u) << K << " segments";
  const SegmentBlendRecord b = report.blends[0];
  double recall = 0, precision = 0;
  carved_fillet_overlap(seg, truth, b.segment, recall, precision);
  EXPECT_GT(recall, 0.6);
  EXPECT_GT(precision, 0.7);
  ASSERT_TRUE(report.primitive_of_segment[std::size_t(b.segment)].has_value());

  write_segment_blends(m, seg, report.blends);
  FitAllSegmentsOptions options;
  const FitAllSegmentsResult fit = fit_all_segments(m, seg, options);
  ASSERT_TRUE(fit.status.ok()) << fit.status.error;
  ASSERT_EQ(fit.blends.size(), 1u);
  EXPECT_EQ(fit.blends[0].segment, b.segment);
  const Primitive& blend = fit.blends[0].primitive;
  if (blend.type == PrimitiveType::Cylinder) {
    EXPECT_NEAR(blend.radius, 1.5, 0.6);
    EXPECT_GT(std::abs(blend.axis.x()), 0.99);
  } else {
    ASSERT_EQ(blend.type, PrimitiveType::Plane); // a chamfer through about the same points
    EXPECT_NEAR(std::abs(blend.axis.y()), std::sqrt(0.5), 0.1);
  }
}

TEST(CarveEdgeBlends, RoughSharpEdgeKeepsTwoSegments)
{
  TMesh m;
  std::vector<int> truth, seg;
  SegmentByPrimitiveGrowingReport report;
  EXPECT_EQ(segment_rough_plate_edge(m, 0.0, truth, seg, report), 2);
  EXPECT_TRUE(report.blends.empty());
}

// carve_edge_blends alone on the fillet's edge, labelled by hand: the top one plane region; the side a plane region
// down to a depth, the rest of it a third. Down to 8 mm the fillet takes a
// fifth of the side's region and is carved; down to 3 mm it would take over a third, a region whose plane its
// faces bend, and it is not.
TEST(CarveEdgeBlends, BlendTakingOverAThirdOfAPlaneIsNotCarved)
{
  TMesh m;
  std::vector<int> truth, seg;
  SegmentByPrimitiveGrowingReport report;
  segment_rough_plate_edge(m, 1.5, truth, seg, report);
  const FaceAdjacency adj = build_face_adjacency(m);
  const GrowingFaces g = growing_faces(m, adj, 0);
  GrowingScale scale;
  scale.tolerance = report.tolerance;
  scale.min_region_faces = 60;
  scale.min_curvature_radius = 0.5;
  Primitive top, side, below;
  top.type = side.type = below.type = PrimitiveType::Plane;
  top.axis = Eigen::Vector3d::UnitZ();
  side.axis = below.axis = Eigen::Vector3d::UnitY();
  for (double depth : {8.0, 3.0}) {
    std::vector<int> label(m.face.size());
    for (std::size_t f = 0; f < label.size(); ++f) {
      const Eigen::Vector3d& c = g.centroid[f];
      label[f] = c.z() > c.y() ? 0 : c.z() > -depth ? 1 : 2; // split at the bisector, as growth leaves it
    }
    const std::vector<CarvedBlend> blends = carve_edge_blends(g, adj, {top, side, below}, scale, label, 1);
    EXPECT_EQ(blends.size(), depth > 5 ? 1u : 0u) << "side region down to " << depth << " mm";
  }
}

// A record follows its three segments through edits elsewhere and renumbered ids, and goes with an edit of one of
// them or a move of the vertices.
TEST(SegmentBlendsAttribute, ReadBackWhileItsSegmentsAreAsTheyWere)
{
  TMesh m;
  std::vector<int> truth;
  make_rough_plate_edge(m, 0.0, truth);
  std::vector<int> seg(m.face.size(), 0);
  seg[0] = 1;
  seg[1] = 2;
  for (std::size_t f = seg.size() / 2; f < seg.size(); ++f)
    seg[f] = 3;
  const std::vector<SegmentBlendRecord> blends = {{2, 0, 1}};
  EXPECT_TRUE(read_segment_blends(m, seg).empty()); // none written
  write_segment_blends(m, seg, blends);
  ASSERT_EQ(read_segment_blends(m, seg).size(), 1u);
  EXPECT_EQ(read_segment_blends(m, seg)[0].segment, 2);

  std::vector<int> split = seg; // segment 3 split in two: the blend's segments are as they were
  for (std::size_t f = 3 * seg.size() / 4; f < seg.size(); ++f)
    split[f] = 4;
  ASSERT_EQ(read_segment_blends(m, split).size(), 1u);
  EXPECT_EQ(read_segment_blends(m, split)[0].segment, 2);

  std::vector<int> renumbered = seg; // ids compacted after a merge elsewhere: 0 -> 1, 1 -> 2, 2 -> 0
  for (int& s : renumbered)
    s = s == 3 ? 3 : (s + 1) % 3;
  const std::vector<SegmentBlendRecord> moved = read_segment_blends(m, renumbered);
  ASSERT_EQ(moved.size(), 1u);
  EXPECT_EQ(moved[0].segment, 0);
  EXPECT_EQ(moved[0].plane_a, 1);
  EXPECT_EQ(moved[0].plane_b, 2);

  std::vector<int> merged = seg;
  merged[1] = 1; // the blend's segment merged into one of its planes
  EXPECT_TRUE(read_segment_blends(m, merged).empty());
  std::vector<int> grown = seg;
  grown[2] = 2; // the blend's segment took a face of its plane
  EXPECT_TRUE(read_segment_blends(m, grown).empty());
  m.vert[0].P()[0] += 0.001f; // vertices moved (a snap)
  EXPECT_TRUE(read_segment_blends(m, seg).empty());
  m.ClearAttributes(); // vcg's ~TriMesh leaves per-mesh attributes allocated
}

TEST(DescribeCarvedBlends, OneLineForTheLog)
{
  EXPECT_EQ(describe_carved_blends({}), "");
  EXPECT_EQ(describe_carved_blends({{15, 1, 13}}), "1 fillet or chamfer carved from the planes it joins: segment 15 "
                                                   "between 1 and 13");
  EXPECT_EQ(describe_carved_blends({{15, 1, 13}, {16, 1, 12}}),
            "2 fillets and chamfers carved from the planes they join: segment 15 between 1 and 13; segment 16 "
            "between 1 and 12");
}

// The edit tool segments as the filter does and says what it carved, as the filter's log does; the blend is kept
// on the mesh for Fit All.
TEST(CarveEdgeBlends, EditToolSaysWhatItCarved)
{
  TMesh m;
  std::vector<int> truth, seg;
  SegmentByPrimitiveGrowingReport report;
  segment_rough_plate_edge(m, 1.5, truth, seg, report);
  ASSERT_EQ(report.blends.size(), 1u);
  PrimitiveEditSession<TMesh> session;
  ASSERT_TRUE(session.attach(m).status.ok());
  const EditOutcome outcome = session.auto_segment(SegmentByPrimitiveGrowingParams());
  ASSERT_TRUE(outcome.status.ok()) << outcome.status.error;
  EXPECT_EQ(session.segment_of_face(), seg);
  const std::string carved = describe_carved_blends(report.blends);
  EXPECT_NE(outcome.summary.find("; " + carved), std::string::npos) << outcome.summary;
  const std::vector<SegmentBlendRecord> kept = read_segment_blends(m, session.segment_of_face());
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(kept[0].segment, report.blends[0].segment);
  session.detach();
  m.ClearAttributes(); // vcg's ~TriMesh leaves per-mesh attributes allocated
}

} // namespace
