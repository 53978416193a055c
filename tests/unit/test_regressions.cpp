// Regression tests for bugs found by fuzzing common/ (fuzz/fuzz_common.cpp); each names its reproducer.
#include "common/measure/measure_accuracy.h"
#include "test_mesh.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace primitive_edit;

namespace {

// A unit square of two triangles in the plane z = 0, as a reference surface.
void make_unit_square(test_mesh::TMesh& m)
{
  vcg::tri::Allocator<test_mesh::TMesh>::AddVertices(m, 4);
  m.vert[0].P() = vcg::Point3d(0, 0, 0);
  m.vert[1].P() = vcg::Point3d(1, 0, 0);
  m.vert[2].P() = vcg::Point3d(1, 1, 0);
  m.vert[3].P() = vcg::Point3d(0, 1, 0);
  vcg::tri::Allocator<test_mesh::TMesh>::AddFaces(m, 2);
  m.face[0].V(0) = &m.vert[0]; m.face[0].V(1) = &m.vert[1]; m.face[0].V(2) = &m.vert[2];
  m.face[1].V(0) = &m.vert[0]; m.face[1].V(1) = &m.vert[2]; m.face[1].V(2) = &m.vert[3];
}

// fuzz crash-9c307f55 (UBSan: float->int overflow in vcg::BasicGrid::PToIP via GridClosest) and
// timeout-ba5ce65c (GridClosest walking O(d^4) cells): a sample far from the reference, e.g. a measured mesh
// with absurd coordinates or not aligned, must give its distance (or a refusal) quickly, never UB or a hang.
TEST(Regression, AccuracyQueryFarFromReference)
{
  test_mesh::TMesh reference;
  make_unit_square(reference);
  SurfaceDistanceIndex index(reference);
  ASSERT_TRUE(index.status().ok()) << index.status().error;
  for (const double far : {1e5, 1e7, 1e9, 1e30}) {
    Eigen::MatrixX3d samples(1, 3);
    samples << far, 0.5, 0.0;
    const AccuracyReport r = measure_accuracy(samples, index, 0.1);
    if (r.status.ok()) {
      EXPECT_NEAR(r.max, far - 1.0, 1e-9 * far) << "query at " << far;
    } else {
      EXPECT_FALSE(r.status.error.empty());
    }
  }
}

} // namespace
