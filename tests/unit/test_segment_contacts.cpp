// Unit tests of segment_contacts: the border pairs it finds without a face adjacency of the whole mesh are
// those of the face adjacency (face_adjacency.h), on a grid with a non-manifold fin, a degenerate face, a deleted
// face, faces of no segment and random segment ids; and the contacts of a grid cut into four quarters.
#include "test_mesh.h"
#include "meshlab_test_mesh.h"
#include "common/mesh/face_adjacency.h"
#include "common/mesh/face_centroids_and_areas.h"
#include "common/mesh/segment_contacts.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <tuple>
#include <vector>

using namespace primitive_edit;

namespace {

// An n x n grid of unit squares in z = 0, two triangles each; face 2 * (j * n + i) and the next one fill square (i, j).
template <class M>
void make_grid(M& m, int n)
{
  using S = typename M::ScalarType;
  auto vi = vcg::tri::Allocator<M>::AddVertices(m, std::size_t((n + 1) * (n + 1)));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i, ++vi)
      vi->P() = typename M::CoordType(S(i), S(j), S(0));
  auto* v = &m.vert[0];
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      vcg::tri::Allocator<M>::AddFace(m, v + id(i, j), v + id(i + 1, j), v + id(i + 1, j + 1));
      vcg::tri::Allocator<M>::AddFace(m, v + id(i, j), v + id(i + 1, j + 1), v + id(i, j + 1));
    }
}

// The contacts as the face adjacency gives them: each face f of segment a with a neighbour h of segment b > a.
template <class M>
std::vector<SegmentContact> contacts_by_adjacency(const M& m, const std::vector<int>& segment_of_face)
{
  const FaceAdjacency adj = build_face_adjacency(m);
  const FaceCentroidsAndAreas faces = face_centroids_and_areas(m);
  std::vector<std::tuple<int, int, int, int>> border;
  for (int f = 0; f < adj.face_count(); ++f)
    for (int k = adj.offset[std::size_t(f)]; k < adj.offset[std::size_t(f) + 1]; ++k) {
      const int h = adj.neighbour[std::size_t(k)];
      const int a = segment_of_face[std::size_t(f)], b = segment_of_face[std::size_t(h)];
      if (a >= 0 && b > a)
        border.emplace_back(a, b, f, h);
    }
  std::sort(border.begin(), border.end());
  std::vector<SegmentContact> out;
  for (std::size_t i = 0; i < border.size();) {
    SegmentContact c;
    c.a = std::get<0>(border[i]);
    c.b = std::get<1>(border[i]);
    std::vector<Eigen::Vector3d> mid;
    for (; i < border.size() && std::get<0>(border[i]) == c.a && std::get<1>(border[i]) == c.b; ++i)
      mid.push_back(0.5 * (faces.centroid[std::size_t(std::get<2>(border[i]))] +
                           faces.centroid[std::size_t(std::get<3>(border[i]))]));
    c.pairs = int(mid.size());
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& p : mid)
      mean += p;
    mean /= double(mid.size());
    c.mean = mean;
    double best = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3d& p : mid)
      if ((p - mean).squaredNorm() < best) {
        best = (p - mean).squaredNorm();
        c.point = p;
      }
    const std::size_t stride = (mid.size() + kContactPoints - 1) / kContactPoints;
    for (std::size_t j = 0; j < mid.size(); j += stride)
      c.points.push_back(mid[j]);
    out.push_back(c);
  }
  return out;
}

template <class M>
class SegmentContactsTest : public ::testing::Test {};
using ContactMeshTypes = ::testing::Types<test_mesh::TMesh, test_mesh::MeshLabMesh>;
TYPED_TEST_SUITE(SegmentContactsTest, ContactMeshTypes);

} // namespace

TYPED_TEST(SegmentContactsTest, QuartersOfAGridTouchAlongTheirCommonEdges)
{
  TypeParam m;
  const int n = 8;
  make_grid(m, n);
  std::vector<int> segment_of_face(m.face.size());
  for (std::size_t f = 0; f < m.face.size(); ++f) {
    const int square = int(f / 2), i = square % n, j = square / n;
    segment_of_face[f] = (i < n / 2 ? 0 : 1) + (j < n / 2 ? 0 : 2);
  }
  const std::vector<SegmentContact> contacts = segment_contacts(m, segment_of_face);
  // 0|1 and 2|3 share a vertical edge of 4 squares, 0|2 and 1|3 a horizontal one; 0 and 3 (1 and 2) meet at a
  // vertex only, which is no contact.
  ASSERT_EQ(contacts.size(), 4u);
  const int expected[4][2] = {{0, 1}, {0, 2}, {1, 3}, {2, 3}};
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(contacts[std::size_t(k)].a, expected[k][0]);
    EXPECT_EQ(contacts[std::size_t(k)].b, expected[k][1]);
    EXPECT_EQ(contacts[std::size_t(k)].pairs, n / 2) << "one face pair per square along the edge";
    // The point lies on the common edge's side of both quarters: within a square of the line x = 4 or y = 4.
    const Eigen::Vector3d& p = contacts[std::size_t(k)].point;
    EXPECT_LT(std::min(std::abs(p.x() - n / 2), std::abs(p.y() - n / 2)), 1.0) << k;
    // The mean of a straight border's points lies as far from the line as they do on average.
    const Eigen::Vector3d& mean = contacts[std::size_t(k)].mean;
    EXPECT_LT(std::min(std::abs(mean.x() - n / 2), std::abs(mean.y() - n / 2)), 1.0) << k;
  }
}

// A long border keeps at most kContactPoints of its midpoints, evenly strided along it: all on the border, spread
// over its length.
TYPED_TEST(SegmentContactsTest, ALongBorderKeepsEvenlyStridedPointsOfIt)
{
  TypeParam m;
  const int n = 300;
  make_grid(m, n);
  std::vector<int> segment_of_face(m.face.size());
  for (std::size_t f = 0; f < m.face.size(); ++f)
    segment_of_face[f] = int(f / 2) % n < n / 2 ? 0 : 1;
  const std::vector<SegmentContact> contacts = segment_contacts(m, segment_of_face);
  ASSERT_EQ(contacts.size(), 1u);
  const SegmentContact& c = contacts[0];
  EXPECT_EQ(c.pairs, n);
  ASSERT_GE(c.points.size(), std::size_t(kContactPoints) / 2);
  ASSERT_LE(c.points.size(), std::size_t(kContactPoints));
  double lo = n, hi = 0;
  for (const Eigen::Vector3d& p : c.points) {
    EXPECT_LT(std::abs(p.x() - n / 2), 1.0);
    lo = std::min(lo, p.y());
    hi = std::max(hi, p.y());
  }
  EXPECT_LT(lo, 0.05 * n);
  EXPECT_GT(hi, 0.95 * n);
}

TYPED_TEST(SegmentContactsTest, FindsTheFacePairsOfTheFaceAdjacency)
{
  TypeParam m;
  const int n = 12;
  make_grid(m, n);
  using S = typename TypeParam::ScalarType;
  // A fin on the interior edge of square (3, 3)'s diagonal makes it non-manifold; a face with a repeated
  // vertex, a deleted face, and faces of no segment (-1) take part too.
  auto* v = &m.vert[0];
  const int a = 3 * (n + 1) + 3, b = 4 * (n + 1) + 4;
  auto top = vcg::tri::Allocator<TypeParam>::AddVertices(m, 1);
  top->P() = typename TypeParam::CoordType(S(3.5), S(3.5), S(1));
  v = &m.vert[0];
  vcg::tri::Allocator<TypeParam>::AddFace(m, v + a, v + b, &*top);
  // vcg's AddFace asserts on a repeated vertex (in debug builds), so that face is filled in by hand.
  auto degenerate = vcg::tri::Allocator<TypeParam>::AddFaces(m, 1);
  degenerate->V(0) = v + a;
  degenerate->V(1) = v + a;
  degenerate->V(2) = v + b;
  vcg::tri::Allocator<TypeParam>::DeleteFace(m, m.face[40]);
  std::mt19937 rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<int> segment_of_face(m.face.size());
    const int segments = 2 + trial % 5;
    for (int& s : segment_of_face)
      s = int(rng() % unsigned(segments + 1)) - 1;
    segment_of_face[40] = -1;  // the deleted face
    const std::vector<SegmentContact> got = segment_contacts(m, segment_of_face);
    const std::vector<SegmentContact> want = contacts_by_adjacency(m, segment_of_face);
    ASSERT_EQ(got.size(), want.size()) << "trial " << trial;
    for (std::size_t k = 0; k < got.size(); ++k) {
      EXPECT_EQ(got[k].a, want[k].a);
      EXPECT_EQ(got[k].b, want[k].b);
      EXPECT_EQ(got[k].pairs, want[k].pairs) << "trial " << trial << ", contact " << k;
      EXPECT_EQ(got[k].point, want[k].point) << "trial " << trial << ", contact " << k;
      EXPECT_LT((got[k].mean - want[k].mean).norm(), 1e-9) << "trial " << trial << ", contact " << k;
      EXPECT_EQ(got[k].points, want[k].points) << "trial " << trial << ", contact " << k;
    }
  }
}

TYPED_TEST(SegmentContactsTest, FacesWithNonFiniteCoordinatesTakeNoPart)
{
  TypeParam m;
  make_grid(m, 2);
  std::vector<int> segment_of_face = {0, 0, 1, 1, 0, 0, 1, 1};
  ASSERT_EQ(segment_contacts(m, segment_of_face).size(), 1u);
  // Faces 0 (segment 0) and 3 (segment 1) pair across the bottom row's border, 4 and 7 across the top row's;
  // a NaN at vertex (1, 0), a corner of faces 0, 2 and 3 only, leaves the top row's pair.
  using S = typename TypeParam::ScalarType;
  m.vert[1].P() = typename TypeParam::CoordType(std::numeric_limits<S>::quiet_NaN(), S(0), S(0));
  const std::vector<SegmentContact> contacts = segment_contacts(m, segment_of_face);
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_EQ(contacts[0].pairs, 1);
  EXPECT_TRUE(contacts[0].point.allFinite());
  EXPECT_TRUE(segment_contacts(m, std::vector<int>(3, 0)).empty()) << "ids of the wrong length";
}
