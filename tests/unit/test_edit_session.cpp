// Tests of the Primitive Edit tool's state logic (common/pipeline/primitive_edit_session.h) without a window,
// on the tests' mesh type and on MeshLab's CMeshO: pick, merge, split by a screen line with a given camera,
// fit, edit, apply with sharp edges, undo several steps, and bad input.
#include "common/base/constants.h"
#include "common/pipeline/primitive_edit_session.h"

#include "test_mesh.h"

#include "meshlab_test_mesh.h"
#include "plate_with_hole.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>
#include <vector>

namespace {

using namespace primitive_edit;

constexpr int kAround = 32, kRings = 8;
constexpr double kRadius = 2.0, kHeight = 4.0;
constexpr int kSideFaces = 2 * kAround * kRings;

// A closed cylinder around the z axis, z in [0, kHeight]: side faces first, then the bottom and top fans.
template <class M>
void make_closed_cylinder(M& m)
{
  m.Clear();
  auto vi = vcg::tri::Allocator<M>::AddVertices(m, (kRings + 1) * kAround + 2);
  for (int i = 0; i <= kRings; ++i)
    for (int j = 0; j < kAround; ++j, ++vi) {
      const double t = 2 * kPi * j / kAround;
      vi->P() = typename M::CoordType(kRadius * std::cos(t), kRadius * std::sin(t), kHeight * i / kRings);
    }
  const int bottom = (kRings + 1) * kAround, top = bottom + 1;
  m.vert[bottom].P() = typename M::CoordType(0, 0, 0);
  m.vert[top].P() = typename M::CoordType(0, 0, kHeight);
  auto v = [&](int i, int j) { return &m.vert[std::size_t(i * kAround + (j % kAround))]; };
  for (int i = 0; i < kRings; ++i)
    for (int j = 0; j < kAround; ++j) {
      vcg::tri::Allocator<M>::AddFace(m, v(i, j), v(i, j + 1), v(i + 1, j + 1));
      vcg::tri::Allocator<M>::AddFace(m, v(i, j), v(i + 1, j + 1), v(i + 1, j));
    }
  for (int j = 0; j < kAround; ++j)
    vcg::tri::Allocator<M>::AddFace(m, &m.vert[bottom], v(0, j + 1), v(0, j));
  for (int j = 0; j < kAround; ++j)
    vcg::tri::Allocator<M>::AddFace(m, &m.vert[top], v(kRings, j), v(kRings, j + 1));
  vcg::tri::UpdateNormal<M>::PerFaceNormalized(m);
  vcg::tri::UpdateNormal<M>::PerVertexNormalizedPerFace(m);
  vcg::tri::UpdateBounding<M>::Box(m);
}

constexpr int kFirstBottomFace = kSideFaces, kFirstTopFace = kSideFaces + kAround;

template <class M>
Eigen::Vector3d centroid(const M& m, int f)
{
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k)
    c += Eigen::Vector3d(m.face[std::size_t(f)].cP(k)[0], m.face[std::size_t(f)].cP(k)[1],
                         m.face[std::size_t(f)].cP(k)[2]);
  return c / 3.0;
}

// A camera at z = 20 looking down -z, 60 degree perspective, 800 x 800 viewport.
struct Camera
{
  Eigen::Matrix4d modelview = Eigen::Matrix4d::Identity();
  Eigen::Matrix4d projection = Eigen::Matrix4d::Zero();
  Eigen::Vector4d viewport{0, 0, 800, 800};
  Camera()
  {
    modelview(2, 3) = -20;
    const double f = 1 / std::tan(kPi / 6), n = 1, far = 100;
    projection(0, 0) = f;
    projection(1, 1) = f;
    projection(2, 2) = (far + n) / (n - far);
    projection(2, 3) = 2 * far * n / (n - far);
    projection(3, 2) = -1;
  }
  // Window y of an object point.
  double window_y(const Eigen::Vector3d& p) const
  {
    const Eigen::Vector4d c = projection * modelview * p.homogeneous();
    return viewport[1] + viewport[3] * (c.y() / c.w() + 1) / 2;
  }
};

template <class M>
class EditSessionTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    make_closed_cylinder(mesh);
    ASSERT_TRUE(session.attach(mesh).status.ok());
    SegmentByNormalAngleParams params;
    params.angle_deg = 30;
    ASSERT_TRUE(session.auto_segment(params).status.ok());
  }
  // vcg's ~TriMesh leaves per-face and per-mesh attributes allocated: free them for LeakSanitizer.
  void TearDown() override
  {
    session.detach();
    mesh.ClearAttributes();
  }
  int side() const { return session.segment_of(0); }
  int bottom() const { return session.segment_of(kFirstBottomFace); }
  int top() const { return session.segment_of(kFirstTopFace); }

  M mesh;
  PrimitiveEditSession<M> session;
};

using MeshTypes = ::testing::Types<test_mesh::TMesh, test_mesh::MeshLabMesh>;
TYPED_TEST_SUITE(EditSessionTest, MeshTypes);

TYPED_TEST(EditSessionTest, AutoSegmentationFindsSideAndCaps)
{
  EXPECT_EQ(this->session.segment_count(), 3);
  std::set<int> ids{this->side(), this->bottom(), this->top()};
  EXPECT_EQ(ids.size(), 3u);
  for (int f = 0; f < kSideFaces; ++f)
    ASSERT_EQ(this->session.segment_of(f), this->side());
  // The ids are on the mesh too, where the batch filters read them.
  std::vector<int> stored;
  ASSERT_TRUE(read_segment_ids(this->mesh, stored));
  EXPECT_EQ(stored, this->session.segment_of_face());
}

TYPED_TEST(EditSessionTest, PickAddsRemovesAndClears)
{
  auto& s = this->session;
  EXPECT_TRUE(s.pick(5, false));
  EXPECT_EQ(s.picked(), std::vector<int>{this->side()});
  EXPECT_TRUE(s.pick(kFirstTopFace, true));
  EXPECT_EQ(s.picked(), (std::vector<int>{this->side(), this->top()}));
  EXPECT_TRUE(s.pick(kFirstTopFace + 3, true)); // same segment again: removed
  EXPECT_EQ(s.picked(), std::vector<int>{this->side()});
  EXPECT_EQ(int(s.picked_faces().size()), kSideFaces);
  EXPECT_FALSE(s.pick(-1, true)); // Shift+click in empty space keeps the picks
  EXPECT_EQ(s.picked().size(), 1u);
  EXPECT_FALSE(s.pick(1 << 30, false)); // out of range: like empty space, clears
  EXPECT_TRUE(s.picked().empty());
}

// The lowest and highest distance from the z axis of the side's vertices.
template <class M>
std::pair<double, double> side_radius_range(const M& m)
{
  double lo = 1e9, hi = 0;
  for (int f = 0; f < kSideFaces; ++f)
    for (int k = 0; k < 3; ++k) {
      const auto& p = m.face[std::size_t(f)].cP(k);
      const double r = std::hypot(double(p[0]), double(p[1]));
      lo = std::min(lo, r);
      hi = std::max(hi, r);
    }
  return {lo, hi};
}

// The phases of one scripted session, in order; each asserts what the tool shows after it.
template <class M>
class EditSessionStoryTest : public EditSessionTest<M>
{
protected:
  // Splits the side by a horizontal screen line at window y = 430 (above the axis, which is at y = 400); sets
  // `above` and `below` to the two halves' ids.
  void split_side_by_screen_line()
  {
    auto& s = this->session;
    ASSERT_TRUE(s.pick(0, false));
    const EditOutcome split = s.split_picked_by_screen_line({50, 430}, {750, 430}, camera.modelview,
                                                            camera.projection, camera.viewport);
    ASSERT_TRUE(split.status.ok()) << split.status.error;
    EXPECT_EQ(s.segment_count(), 4);
    EXPECT_TRUE(s.picked().empty());
    // Every side face lands on the side of the line its centroid projects to; the caps stay whole.
    for (int f = 0; f < kSideFaces; ++f) {
      const bool is_above = camera.window_y(centroid(this->mesh, f)) >= 430;
      int& id = is_above ? above : below;
      if (id < 0)
        id = s.segment_of(f);
      ASSERT_EQ(s.segment_of(f), id) << "face " << f;
    }
    EXPECT_NE(above, below);
    EXPECT_EQ(s.segment_of(kFirstTopFace), s.segment_of(kFirstTopFace + kAround - 1));
  }

  // A line that misses the picked segment cuts nothing and adds no undo step.
  void split_by_a_line_that_misses()
  {
    auto& s = this->session;
    ASSERT_TRUE(s.pick(kFirstTopFace, false));
    const std::size_t depth = s.undo_depth();
    EXPECT_FALSE(s.split_picked_by_screen_line({0, 5}, {10, 5}, camera.modelview, camera.projection,
                                               camera.viewport).status.ok());
    EXPECT_EQ(s.undo_depth(), depth);
  }

  // Merges the two halves back (the second picked with Shift); sets a face of each.
  void merge_halves()
  {
    auto& s = this->session;
    for (int f = 0; f < kSideFaces; ++f)
      (s.segment_of(f) == above ? face_above : face_below) = f;
    ASSERT_TRUE(s.pick(face_above, false));
    ASSERT_TRUE(s.pick(face_below, true));
    const EditOutcome merged = s.merge_picked();
    ASSERT_TRUE(merged.status.ok()) << merged.status.error;
    EXPECT_EQ(s.segment_count(), 3);
    EXPECT_EQ(s.picked(), std::vector<int>{s.segment_of(0)});
    for (int f = 0; f < kSideFaces; ++f)
      ASSERT_EQ(s.segment_of(f), s.segment_of(0));
  }

  // Fits a cylinder to the side, changes its radius to 2.5 and applies: the side is moved onto it, the normals
  // follow, the primitive is recorded on the mesh.
  void fit_widen_and_apply()
  {
    auto& s = this->session;
    auto& m = this->mesh;
    const FitResult fit = s.fit(PrimitiveType::Cylinder);
    ASSERT_TRUE(fit.status.ok()) << fit.status.error;
    EXPECT_NEAR(fit.primitive.radius, kRadius, 1e-3);
    EXPECT_NEAR(std::abs(fit.primitive.axis.z()), 1.0, 1e-4);
    Primitive edited = *s.edited();
    edited.radius = 2.5;
    ASSERT_TRUE(s.set_edited(edited).status.ok());
    const ApplyOutcome applied = s.apply();
    ASSERT_TRUE(applied.status.ok()) << applied.status.error;
    EXPECT_GT(applied.report.moved_vertices, 0);
    const auto [lo, hi] = side_radius_range(m);
    EXPECT_NEAR(lo, 2.5, 1e-4);
    EXPECT_NEAR(hi, 2.5, 1e-4);
    EXPECT_NEAR(double(m.face[0].cN().Norm()), 1.0, 1e-5);
    const SegmentPrimitives recorded = read_segment_primitives(m, s.segment_count());
    ASSERT_TRUE(recorded[std::size_t(s.segment_of(0))].has_value());
    EXPECT_DOUBLE_EQ(recorded[std::size_t(s.segment_of(0))]->radius, 2.5);
  }

  // Undoes the apply: every vertex back to `original`, the record gone, the edited cylinder kept to apply again
  // (applied and undone once more).
  void undo_apply(const std::vector<typename M::CoordType>& original)
  {
    auto& s = this->session;
    auto& m = this->mesh;
    ASSERT_TRUE(s.undo());
    for (std::size_t v = 0; v < m.vert.size(); ++v)
      ASSERT_EQ(m.vert[v].cP(), original[v]) << "vertex " << v;
    EXPECT_FALSE(read_segment_primitives(m, s.segment_count())[std::size_t(s.segment_of(0))].has_value());
    ASSERT_TRUE(s.edited().has_value());
    EXPECT_DOUBLE_EQ(s.edited()->radius, 2.5);
    const ApplyOutcome applied = s.apply();
    ASSERT_TRUE(applied.status.ok()) << applied.status.error;
    EXPECT_NEAR(side_radius_range(m).first, 2.5, 1e-4);
    ASSERT_TRUE(s.undo());
  }

  // Several steps back: the merge, then the split, then the automatic segmentation.
  void undo_to_the_start()
  {
    auto& s = this->session;
    ASSERT_TRUE(s.undo());
    EXPECT_EQ(s.segment_count(), 4);
    EXPECT_NE(s.segment_of(face_above), s.segment_of(face_below));
    ASSERT_TRUE(s.undo());
    EXPECT_EQ(s.segment_count(), 3);
    ASSERT_TRUE(s.undo());
    EXPECT_FALSE(s.has_segments());
    EXPECT_FALSE(s.can_undo());
    EXPECT_FALSE(s.undo());
  }

  const Camera camera;
  int above = -1, below = -1;          // the halves' segment ids after the split
  int face_above = -1, face_below = -1; // a face of each half
};

TYPED_TEST_SUITE(EditSessionStoryTest, MeshTypes);

TYPED_TEST(EditSessionStoryTest, SplitByScreenLineMergeFitApplyAndUndo)
{
  std::vector<typename TypeParam::CoordType> original;
  for (const auto& v : this->mesh.vert)
    original.push_back(v.cP());
  ASSERT_NO_FATAL_FAILURE(this->split_side_by_screen_line());
  ASSERT_NO_FATAL_FAILURE(this->split_by_a_line_that_misses());
  ASSERT_NO_FATAL_FAILURE(this->merge_halves());
  ASSERT_NO_FATAL_FAILURE(this->fit_widen_and_apply());
  ASSERT_NO_FATAL_FAILURE(this->undo_apply(original));
  ASSERT_NO_FATAL_FAILURE(this->undo_to_the_start());
}

TYPED_TEST(EditSessionTest, ApplyMakesSharpEdgesAgainstSnappedNeighbours)
{
  auto& s = this->session;
  auto& m = this->mesh;
  ASSERT_TRUE(s.pick(0, false));
  ASSERT_TRUE(s.fit(PrimitiveType::Cylinder).status.ok());
  Primitive cylinder = *s.edited();
  cylinder.radius = 2.5;
  ASSERT_TRUE(s.set_edited(cylinder).status.ok());
  ASSERT_TRUE(s.apply().status.ok());

  // The top cap, raised to z = 4.2: its rim must land on the circle where plane and cylinder meet.
  ASSERT_TRUE(s.pick(kFirstTopFace, false));
  const FitResult plane_fit = s.fit(std::nullopt);
  ASSERT_TRUE(plane_fit.status.ok()) << plane_fit.status.error;
  ASSERT_EQ(plane_fit.primitive.type, PrimitiveType::Plane);
  Primitive plane = *s.edited();
  plane.origin = Eigen::Vector3d(0, 0, 4.2);
  ASSERT_TRUE(s.set_edited(plane).status.ok());
  const ApplyOutcome applied = s.apply();
  ASSERT_TRUE(applied.status.ok()) << applied.status.error;
  EXPECT_GE(applied.report.edge_vertices, kAround);
  for (int j = 0; j < kAround; ++j) {
    const auto& p = m.vert[std::size_t(kRings * kAround + j)].cP();
    EXPECT_NEAR(double(p[2]), 4.2, 1e-4);
    EXPECT_NEAR(std::hypot(double(p[0]), double(p[1])), 2.5, 1e-4);
  }

  // Merging the two caps keeps the side's record (under its id after the merge) and drops the caps'.
  ASSERT_TRUE(s.pick(kFirstTopFace, false));
  ASSERT_TRUE(s.pick(kFirstBottomFace, true));
  ASSERT_TRUE(s.merge_picked().status.ok());
  const SegmentPrimitives recorded = read_segment_primitives(m, s.segment_count());
  ASSERT_TRUE(recorded[std::size_t(s.segment_of(0))].has_value());
  EXPECT_EQ(recorded[std::size_t(s.segment_of(0))]->type, PrimitiveType::Cylinder);
  EXPECT_FALSE(recorded[std::size_t(s.segment_of(kFirstTopFace))].has_value());
}

TYPED_TEST(EditSessionTest, RefusesWhatCannotBeDone)
{
  auto& s = this->session;
  EXPECT_FALSE(s.merge_picked().status.ok());                       // nothing picked
  EXPECT_FALSE(s.split_picked_by_plane({0, 0, 1}, {0, 0, 1}).status.ok());
  EXPECT_FALSE(s.apply().status.ok());                              // nothing fitted
  EXPECT_FALSE(s.fit(PrimitiveType::Plane).status.ok());            // nothing picked
  ASSERT_TRUE(s.pick(0, false));
  EXPECT_FALSE(s.merge_picked().status.ok());                       // one segment only
  EXPECT_FALSE(s.split_picked_by_plane({0, 0, 1}, {0, 0, 0}).status.ok());
  EXPECT_FALSE(s.split_picked_by_plane({NAN, 0, 1}, {0, 0, 1}).status.ok());
  EXPECT_FALSE(s.set_edited(Primitive()).status.ok());              // no fit yet
  ASSERT_TRUE(s.fit(PrimitiveType::Cylinder).status.ok());
  Primitive bad = *s.edited();
  bad.radius = -1;
  EXPECT_FALSE(s.set_edited(bad).status.ok());
  bad.type = PrimitiveType::Sphere;
  bad.radius = 1;
  EXPECT_FALSE(s.set_edited(bad).status.ok());                      // another type needs another fit
  EXPECT_EQ(s.edited()->type, PrimitiveType::Cylinder);
  const Camera camera;
  EXPECT_FALSE(s.split_picked_by_screen_line({5, 5}, {5, 5}, camera.modelview, camera.projection,
                                             camera.viewport).status.ok());

  // The mesh changed behind the session's back: refuse, do not crash.
  vcg::tri::Allocator<TypeParam>::AddFace(this->mesh, &this->mesh.vert[0], &this->mesh.vert[1],
                                         &this->mesh.vert[2]);
  EXPECT_FALSE(s.merge_picked().status.ok());
  EXPECT_FALSE(s.apply().status.ok());
  EXPECT_FALSE(s.undo());
  s.detach();
  EXPECT_FALSE(s.attached());
  EXPECT_FALSE(s.pick(0, false));
}

TYPED_TEST(EditSessionTest, AttachRefusesEmptyMeshesAndPointClouds)
{
  TypeParam empty;
  PrimitiveEditSession<TypeParam> s;
  EXPECT_FALSE(s.attach(empty).status.ok());
  EXPECT_FALSE(s.attached());
  TypeParam cloud;
  vcg::tri::Allocator<TypeParam>::AddVertices(cloud, 10);
  const EditOutcome outcome = s.attach(cloud);
  EXPECT_FALSE(outcome.status.ok());
  EXPECT_NE(outcome.status.error.find("point cloud"), std::string::npos);
  EXPECT_FALSE(s.pick(0, false));
  EXPECT_FALSE(s.auto_segment(SegmentByNormalAngleParams()).status.ok());
}

TYPED_TEST(EditSessionTest, RepeatedSegmentationAddsNoStepAndTheStartStaysReachable)
{
  auto& s = this->session;
  auto& m = this->mesh;
  // The state the tool started on: no segments (SetUp segmented once after attaching).
  const std::vector<int> start(m.face.size(), -1);
  ASSERT_EQ(s.undo_depth(), 1u);
  SegmentByNormalAngleParams same;
  same.angle_deg = 30;
  for (int i = 0; i < 40; ++i) {
    const EditOutcome again = s.auto_segment(same);
    ASSERT_TRUE(again.status.ok()) << again.status.error;
    EXPECT_NE(again.summary.find("unchanged"), std::string::npos);
  }
  EXPECT_EQ(s.undo_depth(), 1u);

  // More steps than the history holds, each a real change: split the side, merge it back, ...
  const Camera camera;
  for (std::size_t step = 0; step < PrimitiveEditSession<TypeParam>::kMaxUndo + 8; ++step) {
    if (step % 2 == 0) {
      ASSERT_TRUE(s.pick(0, false));
      ASSERT_TRUE(s.split_picked_by_screen_line({50, 430}, {750, 430}, camera.modelview, camera.projection,
                                                camera.viewport).status.ok());
    } else {
      int other = -1;
      for (int f = 0; f < kSideFaces && other < 0; ++f)
        if (s.segment_of(f) != s.segment_of(0))
          other = f;
      ASSERT_TRUE(s.pick(0, false));
      ASSERT_TRUE(s.pick(other, true));
      ASSERT_TRUE(s.merge_picked().status.ok());
    }
  }
  EXPECT_EQ(s.undo_depth(), PrimitiveEditSession<TypeParam>::kMaxUndo);
  while (s.can_undo())
    ASSERT_TRUE(s.undo());
  EXPECT_EQ(s.segment_of_face(), start);
}

TYPED_TEST(EditSessionTest, PrimitiveFitSegmentationIsTheFiltersAndUndoable)
{
  auto& s = this->session;
  const std::vector<int> by_angle = s.segment_of_face();
  SegmentByPrimitiveGrowingParams params;
  const EditOutcome grown = s.auto_segment(params);
  ASSERT_TRUE(grown.status.ok()) << grown.status.error;
  std::vector<int> filter;
  segment_by_primitive_growing(this->mesh, params, filter);
  EXPECT_EQ(s.segment_of_face(), filter);
  SegmentByPrimitiveGrowingParams bad;
  bad.normal_angle_deg = 95;
  EXPECT_FALSE(s.auto_segment(bad).status.ok());
  EXPECT_EQ(s.segment_of_face(), filter);
  if (by_angle != filter) {
    ASSERT_TRUE(s.undo());
    EXPECT_EQ(s.segment_of_face(), by_angle);
  }
}

TYPED_TEST(EditSessionTest, StrokeCutsOnlyWhereItCrossesTheSegment)
{
  auto& s = this->session;
  const Camera camera;
  const std::vector<int> before = s.segment_of_face();
  ASSERT_TRUE(s.pick(0, false));
  // A stroke in empty space beside the cylinder (which spans about x 350-450 on screen): the infinite plane
  // through it would cut the side, the stroke does not.
  EXPECT_FALSE(s.split_picked_by_screen_line({600, 430}, {750, 430}, camera.modelview, camera.projection,
                                             camera.viewport).status.ok());
  EXPECT_EQ(s.segment_of_face(), before);
  // A stroke across half of the side only: the side stays connected around its other half.
  EXPECT_FALSE(s.split_picked_by_screen_line({400, 430}, {750, 430}, camera.modelview, camera.projection,
                                             camera.viewport).status.ok());
  EXPECT_EQ(s.segment_of_face(), before);
  // Across the whole side: two pieces, none a sliver.
  const EditOutcome split = s.split_picked_by_screen_line({300, 430}, {500, 430}, camera.modelview,
                                                          camera.projection, camera.viewport);
  ASSERT_TRUE(split.status.ok()) << split.status.error;
  EXPECT_EQ(s.segment_count(), 4);
  std::vector<int> size(4, 0);
  for (int id : s.segment_of_face())
    ++size[std::size_t(id)];
  for (int n : size)
    EXPECT_GE(n, kMinSplitPieceFaces);
}

TYPED_TEST(EditSessionTest, ApplyFarBeyondTheSegmentWaitsForConfirmation)
{
  auto& s = this->session;
  auto& m = this->mesh;
  ASSERT_TRUE(s.pick(kFirstTopFace, false));
  ASSERT_TRUE(s.fit(PrimitiveType::Plane).status.ok());
  EXPECT_TRUE(s.fit_warning().empty());
  Primitive far = *s.edited();
  far.origin += 1000.0 * far.axis;  // a typo: the top plane 1000 away from a part 4 high
  ASSERT_TRUE(s.set_edited(far).status.ok());
  EXPECT_NEAR(s.edited_rms(), 1000.0, 1e-2);
  std::vector<typename TypeParam::CoordType> before;
  for (const auto& v : m.vert)
    before.push_back(v.cP());
  const std::size_t depth = s.undo_depth();
  const ApplyOutcome refused = s.apply();
  EXPECT_FALSE(refused.status.ok());
  EXPECT_TRUE(refused.needs_confirmation);
  EXPECT_NEAR(refused.max_move, 1000.0, 1e-2);
  EXPECT_NEAR(refused.segment_size, 2 * kRadius * std::sqrt(2.0), 0.05);
  EXPECT_EQ(s.undo_depth(), depth);
  for (std::size_t v = 0; v < m.vert.size(); ++v)
    ASSERT_EQ(m.vert[v].cP(), before[v]);
  const ApplyOutcome confirmed = s.apply(true, true);
  ASSERT_TRUE(confirmed.status.ok()) << confirmed.status.error;
  EXPECT_NEAR(m.vert[m.vert.size() - 1].cP()[2], kHeight + 1000.0, 1e-3);
}

// Issue 12's wreck: a cylinder fitted to a noisy flat top comes out with a radius of about 1e9, lying on the
// top, so snapping moves nothing there; it still takes the top's shape, and asks first.
TYPED_TEST(EditSessionTest, ApplyOfAPrimitiveFarLargerThanTheSegmentWaitsForConfirmation)
{
  auto& s = this->session;
  auto& m = this->mesh;
  ASSERT_TRUE(s.pick(kFirstTopFace, false));
  ASSERT_TRUE(s.fit(PrimitiveType::Cylinder).status.ok());
  Primitive huge = *s.edited();
  huge.axis = Eigen::Vector3d::UnitX();
  huge.radius = 1e9;
  huge.origin = Eigen::Vector3d(0, 0, kHeight - huge.radius);  // touching the top along the x axis
  ASSERT_TRUE(s.set_edited(huge).status.ok());
  std::vector<typename TypeParam::CoordType> before;
  for (const auto& v : m.vert)
    before.push_back(v.cP());
  const std::size_t depth = s.undo_depth();
  const ApplyOutcome refused = s.apply();
  EXPECT_FALSE(refused.status.ok());
  EXPECT_TRUE(refused.needs_confirmation);
  EXPECT_LT(refused.max_move, refused.segment_size);
  EXPECT_NE(refused.status.error.find("confirm to apply"), std::string::npos) << refused.status.error;
  EXPECT_EQ(s.undo_depth(), depth);
  for (std::size_t v = 0; v < m.vert.size(); ++v)
    ASSERT_EQ(m.vert[v].cP(), before[v]);
  EXPECT_TRUE(s.apply(true, true).status.ok());
}

// The plate with a hole (its 7 faces as segments, noise along the normals, seed 5) and a session attached to it.
struct PlateSession
{
  explicit PlateSession(double noise) : plate(plate_fixture::make_plate_with_hole(noise, 5))
  {
    plate_fixture::build_mesh(m, plate.soup);
    write_segment_ids(m, plate.soup.labels);
    attached = s.attach(m).status.ok();
  }
  int first_face_of(int segment) const
  {
    return int(std::find(plate.soup.labels.begin(), plate.soup.labels.end(), segment) - plate.soup.labels.begin());
  }
  const plate_fixture::PlateWithHole plate;
  test_mesh::TMesh m;
  PrimitiveEditSession<test_mesh::TMesh> s;
  bool attached = false;
};

// With relations the picked face is fitted among all the segments, as Fit All does: on a noisy plate the side
// faces +x and -x come out parallel and square to the top (to the joint refit's convergence), which their own
// fits, tilted by the noise, are not;
// the relations are listed in the session's ids. Without relations the fit is the segment's own, as before.
TEST(EditSessionRelations, FitHoldsTheRelationsOfThePickedFace)
{
  PlateSession p(0.1);
  ASSERT_TRUE(p.attached);
  const plate_fixture::PlateWithHole& plate = p.plate;
  const test_mesh::TMesh& m = p.m;
  PrimitiveEditSession<test_mesh::TMesh>& s = p.s;
  ASSERT_EQ(s.segment_count(), 7);
  const int top = 0, plus_x = 3, minus_x = 5;
  auto fit_plane = [&](int segment, bool relations) {
    EXPECT_TRUE(s.pick(p.first_face_of(segment), false));
    const FitResult fit = s.fit(PrimitiveType::Plane, FitMethod::Refined, relations);
    EXPECT_TRUE(fit.status.ok()) << fit.status.error;
    EXPECT_TRUE(s.edited() && s.edited()->axis == fit.primitive.axis && s.edited()->origin == fit.primitive.origin);
    return fit.primitive;
  };
  auto angle = [](const Primitive& a, const Primitive& b) {
    return std::acos(std::min(1.0, std::abs(a.axis.dot(b.axis))));
  };

  const Primitive own_plus = fit_plane(plus_x, false);
  EXPECT_TRUE(s.fit_relations().empty());
  const Primitive own_minus = fit_plane(minus_x, false);
  const Primitive own_top = fit_plane(top, false);
  const Primitive held_top = fit_plane(top, true);
  const Primitive held_minus = fit_plane(minus_x, true);
  const Primitive held_plus = fit_plane(plus_x, true);
  std::printf("sides: %.4f degrees apart alone, %.2g with relations; +x and top %.4f off square alone, %.2g with\n",
              degrees_from_radians(angle(own_plus, own_minus)), degrees_from_radians(angle(held_plus, held_minus)),
              90 - degrees_from_radians(angle(own_plus, own_top)),
              90 - degrees_from_radians(angle(held_plus, held_top)));
  EXPECT_GT(angle(own_plus, own_minus), radians_from_degrees(0.05));
  EXPECT_LT(angle(held_plus, held_minus), 1e-9);
  EXPECT_GT(std::abs(own_plus.axis.dot(own_top.axis)), std::sin(radians_from_degrees(0.05)));
  EXPECT_LT(std::abs(held_plus.axis.dot(held_top.axis)), 1e-4);  // through the -x side's relation to the bottom
  EXPECT_NEAR(held_plus.origin.dot(held_plus.axis.normalized()) * (held_plus.axis.x() < 0 ? -1 : 1), plate.half,
              0.05);
  const std::vector<std::string>& relations = s.fit_relations();
  for (const std::string& line : relations)
    std::printf("  %s\n", line.c_str());
  EXPECT_EQ(std::count(relations.begin(), relations.end(), "parallel: segments 5 and 3") +
                std::count(relations.begin(), relations.end(), "parallel: segments 3 and 5"),
            1);

  // The mesh and the segments are untouched by the fits.
  for (std::size_t v = 0; v < m.vert.size(); ++v)
    ASSERT_EQ(m.vert[v].cP(), test_mesh::TMesh::CoordType(plate.soup.points[v].x(), plate.soup.points[v].y(),
                                                          plate.soup.points[v].z()));
  EXPECT_EQ(s.segment_of_face(), plate.soup.labels);
}

// On an exact part a face's fit of its own type is exact, with relations or without, and round-off may come out
// larger with them (1.3e-24 against 4e-28 for a side of this plate; the fuzz target found such cases): the
// relations are held, not refused. A type forced on a face it does not suit (a sphere on the flat top) may be
// refused: the fit among all segments comes out worse than the face's own.
TEST(EditSessionRelations, ExactPartHoldsItsRelations)
{
  PlateSession p(0.0);
  ASSERT_TRUE(p.attached);
  PrimitiveEditSession<test_mesh::TMesh>& s = p.s;
  int exact = 0, held = 0;
  for (int segment = 0; segment < s.segment_count(); ++segment)
    for (int t = -1; t < kPrimitiveTypeCount; ++t) {
      ASSERT_TRUE(s.pick(p.first_face_of(segment), false));
      const std::optional<PrimitiveType> type = t < 0 ? std::nullopt : std::optional<PrimitiveType>(PrimitiveType(t));
      const FitResult fit = s.fit(type, FitMethod::Refined, true);
      if (!fit.status.ok() || fit.rms > 1e-9)
        continue;  // a forced type the segment's points cannot take, or take only roughly
      ++exact;
      EXPECT_EQ(s.relations_refused(), "") << "segment " << segment << ", type " << t;
      held += !s.fit_relations().empty();
    }
  EXPECT_GE(exact, s.segment_count());  // every face by its automatic type at least
  EXPECT_GT(held, 0);
}

// A sphere forced on the plate's flat top fits its faces alone far better (RMS 0.0037) than among all segments
// (0.0194, beyond the allowance): the relations are refused with both RMS in the message, and the fit is the
// top's own, the one the session gives without relations.
TEST(EditSessionRelations, RefusedRelationsKeepTheOwnFit)
{
  PlateSession p(0.0);
  ASSERT_TRUE(p.attached);
  PrimitiveEditSession<test_mesh::TMesh>& s = p.s;
  const int top = 0;
  ASSERT_TRUE(s.pick(p.first_face_of(top), false));
  const FitResult own = s.fit(PrimitiveType::Sphere, FitMethod::Refined, false);
  ASSERT_TRUE(own.status.ok()) << own.status.error;
  const FitResult fit = s.fit(PrimitiveType::Sphere, FitMethod::Refined, true);
  ASSERT_TRUE(fit.status.ok()) << fit.status.error;
  EXPECT_EQ(s.relations_refused().rfind("the fit among all segments would raise the RMS to ", 0), 0u)
      << s.relations_refused();
  EXPECT_TRUE(s.fit_relations().empty());
  EXPECT_EQ(fit.rms, own.rms);
  ASSERT_TRUE(s.edited().has_value());
  EXPECT_EQ(s.edited()->type, PrimitiveType::Sphere);
}

} // namespace
