// test_mesh.h: a small vcg mesh type of the tests' own, and mesh builders shared by the unit tests.
// common/ must work on any vcg mesh; the tests run it on this type and on MeshLab's CMeshO.
#ifndef PRIMITIVE_EDIT_TEST_MESH_H
#define PRIMITIVE_EDIT_TEST_MESH_H

#include <vcg/complex/complex.h>

namespace test_mesh {

class TVertex;
class TFace;
struct TUsedTypes : public vcg::UsedTypes<vcg::Use<TVertex>::AsVertexType, vcg::Use<TFace>::AsFaceType> {};
class TVertex : public vcg::Vertex<TUsedTypes, vcg::vertex::Coord3d, vcg::vertex::Normal3d,
                                   vcg::vertex::BitFlags> {};
class TFace : public vcg::Face<TUsedTypes, vcg::face::VertexRef, vcg::face::Normal3d,
                               vcg::face::BitFlags> {};
class TMesh : public vcg::tri::TriMesh<std::vector<TVertex>, std::vector<TFace>> {};

} // namespace test_mesh

#endif
