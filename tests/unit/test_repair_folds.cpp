// Tests of repair_folds on a flat grid, where a vertex's surface is the plane z = 0.
#include "common/snap/repair_folds.h"
#include "triangle_grid.h"

#include <gtest/gtest.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <vector>

namespace {

using namespace primitive_edit;

// A flat TriangleGrid with each face's reference (its edge cross product) for the fold test.
struct FlatGrid : grid_fixture::TriangleGrid
{
  std::vector<Eigen::Vector3d> reference;

  FlatGrid(int nx_, int ny_) : TriangleGrid(nx_, ny_)
  {
    for (int f = 0; f < faces(); ++f)
      reference.push_back((corner(f, 1) - corner(f, 0)).cross(corner(f, 2) - corner(f, 0)));
  }
  bool on_border(int v) const
  {
    const int i = v % (nx + 1), j = v / (nx + 1);
    return i == 0 || j == 0 || i == nx || j == ny;
  }
  int folded_faces_near(int centre, int radius) const
  {
    const int ci = centre % (nx + 1), cj = centre / (nx + 1);
    int folded = 0;
    for (int f = 0; f < faces(); ++f) {
      const int v = face_vertex[3 * std::size_t(f)], i = v % (nx + 1), j = v / (nx + 1);
      if (std::abs(i - ci) <= radius && std::abs(j - cj) <= radius &&
          face_is_folded(reference[std::size_t(f)], corner(f, 0), corner(f, 1), corner(f, 2)))
        ++folded;
    }
    return folded;
  }
};

// Every movable vertex stays on the plane z = 0.
bool onto_plane(std::size_t, const Eigen::Vector3d& p, Eigen::Vector3d& out)
{
  out = Eigen::Vector3d(p.x(), p.y(), 0);
  return true;
}

// A vertex pushed 2.5 cells across its neighbours folds the faces around it; the grid's border is fixed.
// `far_fold` adds a second fold 40 cells away that cannot be undone: a vertex pushed the same way but pinned,
// with its own ring pinned too, so no region can reach it.
FlatGrid repaired_grid(bool far_fold, RepairFoldsReport& report)
{
  FlatGrid g(70, 30);
  const int pushed = g.id(15, 15), pinned = g.id(55, 15);
  g.points[std::size_t(pushed)].x() += 2.5;
  std::vector<bool> movable(g.points.size(), true);
  if (far_fold) {
    g.points[std::size_t(pinned)].x() += 2.5;
    for (int j = 13; j <= 17; ++j)
      for (int i = 53; i <= 57; ++i)
        movable[std::size_t(g.id(i, j))] = false;
  }
  RepairFoldsOptions options;
  options.widen = true;
  options.max_rounds = 1; // one ring, so the settle sweeps do the repair
  report = repair_folds(
      g.points, g.face_vertex, g.vertex_faces, g.reference,
      [&](std::size_t v) { return movable[v] && !g.on_border(int(v)); }, onto_plane, options);
  return g;
}

} // namespace

// Each connected part of the region settles on its own: a fold elsewhere that cannot be undone changes nothing
// about how a repairable one is repaired. When the whole region settled as one, the pinned fold kept it from
// ever being free of folds, so the repairable part stopped as soon as its folds were gone, before it had evened
// out (its vertices ended up to 4.5e-4 from where they settle alone).
TEST(RepairFolds, UnrepairableFoldElsewhereDoesNotCutTheSettleShort)
{
  RepairFoldsReport alone, beside;
  const FlatGrid a = repaired_grid(false, alone);
  const FlatGrid b = repaired_grid(true, beside);
  EXPECT_GT(alone.moved_vertices, 0);
  EXPECT_EQ(alone.folded_faces, 0);
  EXPECT_GT(beside.folded_faces, 0); // the pinned fold is still there
  EXPECT_EQ(a.folded_faces_near(a.id(15, 15), 14), 0);
  EXPECT_EQ(b.folded_faces_near(b.id(15, 15), 14), 0);
  double largest_difference = 0;
  for (int j = 0; j <= a.ny; ++j)
    for (int i = 0; i <= 35; ++i)
      largest_difference = std::max(largest_difference,
                                    (a.points[std::size_t(a.id(i, j))] - b.points[std::size_t(b.id(i, j))]).norm());
  EXPECT_EQ(largest_difference, 0.0);
}

// A fold that can be undone beside one that cannot, in one connected part of the region: the part keeps the
// repaired positions, which hold fewer folds than the snapped ones, instead of getting its snapped positions back
// whole (on the bundled scan that threw away a third of the folds the sweeps had undone).
TEST(RepairFolds, PartlyRepairedPartKeepsItsRepair)
{
  FlatGrid g(40, 30);
  const int pushed = g.id(15, 15), pinned = g.id(21, 15);
  g.points[std::size_t(pushed)].x() += 2.5;
  g.points[std::size_t(pinned)].x() += 2.5;
  std::vector<bool> movable(g.points.size(), true);
  movable[std::size_t(pinned)] = false;
  const int folded_before = g.folded_faces_near(pushed, 40);
  const int pinned_before = g.folded_faces_near(pinned, 1);
  RepairFoldsOptions options;
  options.widen = true;
  const RepairFoldsReport report = repair_folds(
      g.points, g.face_vertex, g.vertex_faces, g.reference,
      [&](std::size_t v) { return movable[v] && !g.on_border(int(v)); }, onto_plane, options);
  EXPECT_GT(pinned_before, 0);
  EXPECT_GT(report.moved_vertices, 0);
  EXPECT_EQ(report.folded_faces, g.folded_faces_near(pushed, 40));
  EXPECT_LT(report.folded_faces, folded_before);
  EXPECT_EQ(g.folded_faces_near(pushed, 2), 0);
}

// Many folds over a large grid, pushed different ways so that their regions meet in some places and not in
// others: the repair on several threads (the region's connected parts side by side) moves every vertex exactly
// as on one, and the region is large enough that the threads are used.
TEST(RepairFolds, SameRepairOnAnyThreadCount)
{
  auto repaired = [](int threads, RepairFoldsReport& report) {
    FlatGrid g(150, 100);
    for (int j = 8; j < 100; j += 12)
      for (int i = 8 + (j / 12) % 3; i < 150; i += 11) {
        Eigen::Vector3d& p = g.points[std::size_t(g.id(i, j))];
        p.x() += (i + j) % 2 ? 2.5 : -1.5;
        p.y() += (i / 11) % 2 ? 1.2 : -2.2;
      }
    RepairFoldsOptions options;
    options.widen = true;
    options.threads = threads;
    report = repair_folds(g.points, g.face_vertex, g.vertex_faces, g.reference,
                          [&](std::size_t v) { return !g.on_border(int(v)); }, onto_plane, options);
    return g;
  };
  RepairFoldsReport one, three;
  const FlatGrid a = repaired(1, one);
  const FlatGrid b = repaired(3, three);
  EXPECT_GT(one.moved_vertices, int(repair_detail::kVerticesPerSweepThread));
  EXPECT_EQ(one.rounds, three.rounds);
  EXPECT_EQ(one.moved_vertices, three.moved_vertices);
  EXPECT_EQ(one.folded_faces, three.folded_faces);
  int different = 0;
  for (std::size_t v = 0; v < a.points.size(); ++v)
    different += a.points[v] != b.points[v];
  EXPECT_EQ(different, 0);
}

// The fold counts of three repairs, check by check (printed by a scratch build): a widened hole's rim, whose first
// sweeps fold more faces than there were before they unfold them all, must not stall; a 1M-face scan's wide
// region, whose folds fall slowly and then rise as the growing region's sweeps fold new faces at its pinned
// borders, must stall at the first rise after the fall instead of growing on; a 4M-face scan's narrow region
// (MeshLab's segments), whose folds rise from the start, must stall once the first checks are past.
TEST(RepairFolds, FoldTrendTakesFoldsInOnlyAtFirst)
{
  repair_detail::FoldTrend rim(256);
  for (const std::size_t folds : {704, 338, 82, 0})
    EXPECT_FALSE(rim.stalled(folds)) << folds;

  repair_detail::FoldTrend scan(7250);
  for (const std::size_t folds : {9832, 8306, 7913, 7654, 7574})
    EXPECT_FALSE(scan.stalled(folds)) << folds;
  EXPECT_TRUE(scan.stalled(7665));

  repair_detail::FoldTrend rising(11962);
  for (const std::size_t folds : {17810, 18051, 18826, 19287})
    EXPECT_FALSE(rising.stalled(folds)) << folds;
  EXPECT_TRUE(rising.stalled(19742));
}
