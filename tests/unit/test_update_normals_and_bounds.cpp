// Tests of common/mesh/update_normals_and_bounds.h: the normals are vcg's own (the face normals computed once and
// normalised in place give the same bits as computing them again), and the box holds the live vertices.
#include "common/mesh/update_normals_and_bounds.h"
#include "test_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {

using test_mesh::TMesh;

// A wavy grid with random jitter, and one face deleted.
void build_wavy_grid(TMesh& m)
{
  const int n = 20;
  std::mt19937 random(5);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  auto vi = vcg::tri::Allocator<TMesh>::AddVertices(m, (n + 1) * (n + 1));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i, ++vi)
      vi->P() = TMesh::CoordType(i + jitter(random), j + jitter(random), std::sin(0.4 * i) * std::cos(0.3 * j));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      vcg::tri::Allocator<TMesh>::AddFace(m, &m.vert[std::size_t(a)], &m.vert[std::size_t(b)], &m.vert[std::size_t(d)]);
      vcg::tri::Allocator<TMesh>::AddFace(m, &m.vert[std::size_t(a)], &m.vert[std::size_t(d)], &m.vert[std::size_t(c)]);
    }
  vcg::tri::Allocator<TMesh>::DeleteFace(m, m.face[7]);
}

TEST(UpdateNormalsAndBounds, GivesVcgsNormalsAndTheBox)
{
  TMesh ours, theirs;
  build_wavy_grid(ours);
  build_wavy_grid(theirs);
  primitive_edit::update_normals_and_bounds(ours);
  vcg::tri::UpdateNormal<TMesh>::PerVertexNormalizedPerFace(theirs);
  vcg::tri::UpdateNormal<TMesh>::PerFaceNormalized(theirs);
  for (std::size_t f = 0; f < ours.face.size(); ++f)
    if (!ours.face[f].IsD()) {
      EXPECT_EQ(ours.face[f].N(), theirs.face[f].N()) << "face " << f;
      EXPECT_NEAR(ours.face[f].N().Norm(), 1.0, 1e-12) << "face " << f;
    }
  for (std::size_t v = 0; v < ours.vert.size(); ++v) {
    EXPECT_EQ(ours.vert[v].N(), theirs.vert[v].N()) << "vertex " << v;
    EXPECT_NEAR(ours.vert[v].N().Norm(), 1.0, 1e-12) << "vertex " << v;
  }
  EXPECT_NEAR(ours.bbox.min[0], -0.2, 0.2);
  EXPECT_NEAR(ours.bbox.max[0], 20.2, 0.2);
  EXPECT_LE(ours.bbox.max[2], 1.0);
  EXPECT_GE(ours.bbox.min[2], -1.0);
}

} // namespace
