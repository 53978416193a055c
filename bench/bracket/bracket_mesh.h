// bracket_mesh.h: the vcg mesh type of the bracket benchmark's programs, and PLY input/output for it.
// Per-face quality carries a B-rep face index (reference mesh and scan ground truth); it is a double
// because vcglib 2020.09 writes face quality with the size of the coordinate type; per-face mark
// lets vcg's spatial grid answer closest-face queries on it.
#ifndef PRIMITIVE_EDIT_BENCH_BRACKET_MESH_H
#define PRIMITIVE_EDIT_BENCH_BRACKET_MESH_H

#include <vcg/complex/complex.h>
#include <wrap/io_trimesh/export_ply.h>
#include <wrap/io_trimesh/import_ply.h>

#include <string>

namespace bracket {

class BVertex;
class BFace;
struct BUsedTypes : public vcg::UsedTypes<vcg::Use<BVertex>::AsVertexType, vcg::Use<BFace>::AsFaceType> {};
class BVertex : public vcg::Vertex<BUsedTypes, vcg::vertex::Coord3d, vcg::vertex::Normal3d,
                                   vcg::vertex::BitFlags, vcg::vertex::Mark> {};
class BFace : public vcg::Face<BUsedTypes, vcg::face::VertexRef, vcg::face::Normal3d, vcg::face::Qualityd,
                               vcg::face::BitFlags, vcg::face::Mark, vcg::face::FFAdj> {};
class BMesh : public vcg::tri::TriMesh<std::vector<BVertex>, std::vector<BFace>> {};

// Reads a PLY; `with_quality` asks for the per-face quality (fails when the file has none).
inline bool load_ply(BMesh& m, const std::string& path, bool with_quality, std::string* message)
{
  int mask = 0;
  const int err = vcg::tri::io::ImporterPLY<BMesh>::Open(m, path.c_str(), mask);
  if (err != 0 && vcg::tri::io::ImporterPLY<BMesh>::ErrorCritical(err)) {
    *message = path + ": " + vcg::tri::io::ImporterPLY<BMesh>::ErrorMsg(err);
    return false;
  }
  if (with_quality && !(mask & vcg::tri::io::Mask::IOM_FACEQUALITY)) {
    *message = path + ": no per-face quality (B-rep face index)";
    return false;
  }
  if (m.fn == 0) {
    *message = path + ": no faces";
    return false;
  }
  return true;
}

// Writes a binary PLY, with the per-face quality when `with_quality`.
inline bool save_ply(BMesh& m, const std::string& path, bool with_quality)
{
  const int mask = with_quality ? vcg::tri::io::Mask::IOM_FACEQUALITY : 0;
  return vcg::tri::io::ExporterPLY<BMesh>::Save(m, path.c_str(), mask, true) == 0;
}

} // namespace bracket

#endif
