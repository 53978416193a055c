// check_mesh_input: a mesh is refused only for what its live faces use. A NaN or infinite coordinate on a vertex
// no live face uses (left over, or used only by deleted faces) is no reason to refuse; on a vertex of live faces the
// message counts those faces. On the tests' mesh type and MeshLab's CMeshO.
#include "test_mesh.h"

#include "common/mesh/check_mesh_input.h"

#include "meshlab_test_mesh.h"
#include <gtest/gtest.h>

#include <limits>
#include <string>

using namespace primitive_edit;

namespace {

// Two triangles sharing the edge (1, 2), plus vertex 4, which no face uses.
template <class M>
void make_two_triangles_and_a_spare_vertex(M& m)
{
  using Coord = typename M::CoordType;
  auto v = vcg::tri::Allocator<M>::AddVertices(m, 5);
  v[0].P() = Coord(0, 0, 0);
  v[1].P() = Coord(1, 0, 0);
  v[2].P() = Coord(0, 1, 0);
  v[3].P() = Coord(1, 1, 0);
  v[4].P() = Coord(5, 5, 5);
  vcg::tri::Allocator<M>::AddFace(m, &m.vert[0], &m.vert[1], &m.vert[2]);
  vcg::tri::Allocator<M>::AddFace(m, &m.vert[1], &m.vert[3], &m.vert[2]);
}

template <class M>
class CheckMeshInputTest : public ::testing::Test
{
};
using CheckMeshTypes = ::testing::Types<test_mesh::TMesh, test_mesh::MeshLabMesh>;
TYPED_TEST_SUITE(CheckMeshInputTest, CheckMeshTypes);

} // namespace

TYPED_TEST(CheckMeshInputTest, RefusesOnlyWhatLiveFacesUse)
{
  using Scalar = typename TypeParam::ScalarType;
  const Scalar nan = std::numeric_limits<Scalar>::quiet_NaN(), inf = std::numeric_limits<Scalar>::infinity();

  TypeParam m;
  make_two_triangles_and_a_spare_vertex(m);
  EXPECT_TRUE(check_mesh_input(m).ok());

  m.vert[4].P()[1] = nan; // used by no face
  EXPECT_TRUE(check_mesh_input(m).ok()) << check_mesh_input(m).error;

  m.vert[3].P()[2] = inf; // used by the second face only
  const Status one = check_mesh_input(m);
  ASSERT_FALSE(one.ok());
  EXPECT_EQ(one.error.rfind("1 faces have NaN or infinite vertex coordinates", 0), 0u) << one.error;

  vcg::tri::Allocator<TypeParam>::DeleteFace(m, m.face[1]); // now used by a deleted face only
  EXPECT_TRUE(check_mesh_input(m).ok()) << check_mesh_input(m).error;

  m.vert[1].P()[0] = nan; // used by the live first face
  const Status again = check_mesh_input(m);
  ASSERT_FALSE(again.ok());
  EXPECT_EQ(again.error.rfind("1 faces have NaN", 0), 0u) << again.error;
}

TYPED_TEST(CheckMeshInputTest, EmptyMeshAndPointCloudAreRefused)
{
  TypeParam empty;
  const Status none = check_mesh_input(empty);
  ASSERT_FALSE(none.ok());
  EXPECT_EQ(none.error, "the mesh is empty");

  TypeParam cloud;
  vcg::tri::Allocator<TypeParam>::AddVertices(cloud, 3);
  const Status points = check_mesh_input(cloud);
  ASSERT_FALSE(points.ok());
  EXPECT_NE(points.error.find("point cloud"), std::string::npos) << points.error;
}
