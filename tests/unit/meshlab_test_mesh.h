// meshlab_test_mesh.h: MeshLab's CMeshO as the tests use it, freeing its attributes (see test_mesh.h).
#ifndef PRIMITIVE_EDIT_MESHLAB_TEST_MESH_H
#define PRIMITIVE_EDIT_MESHLAB_TEST_MESH_H

#include "test_mesh.h"

#include <common/ml_mesh_type.h>

namespace test_mesh {
using MeshLabMesh = FreesAttributes<CMeshO>;
} // namespace test_mesh

#endif
