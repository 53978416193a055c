// test_mesh.h: a small vcg mesh type of the tests' own, and mesh builders shared by the unit tests.
// common/ must work on any vcg mesh; the tests run it on this type and on MeshLab's CMeshO (as MeshLabMesh).
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

// vcg's ~TriMesh leaves the attributes allocated (its ClearAttributes call is commented out in the vcglib
// of 2020.09 and of 2025.07); the core keeps results on the mesh as attributes, so the tests' meshes free
// them, so that the leak checker sees only leaks of ours.
template <class Mesh> class FreesAttributes : public Mesh
{
public:
  FreesAttributes() = default;
  FreesAttributes(const FreesAttributes&) = delete;
  FreesAttributes& operator=(const FreesAttributes&) = delete;
  ~FreesAttributes() { this->ClearAttributes(); }
};

class TMeshBase : public vcg::tri::TriMesh<std::vector<TVertex>, std::vector<TFace>> {};
using TMesh = FreesAttributes<TMeshBase>;

} // namespace test_mesh

#endif
