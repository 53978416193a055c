// update_normals_and_bounds.h: what a mesh needs after its vertices moved: unit face and vertex normals and
// the bounding box.
//
// Input:  a vcg triangle mesh with per-face and per-vertex normals.
// Output: face normals of unit length, vertex normals the normalised area-weighted sum of their faces'
//         normals, the bounding box of the live vertices.
// Method: vcg::tri::UpdateNormal::PerVertexNormalizedPerFaceNormalized: the face normals are computed once,
//         unnormalised (they carry the faces' areas for the vertex sum), then normalised in place (computing them
//         again to normalise them cost a pass over the faces: 1M faces per Fit All with snap at 1M).
// Cost:   O(F + V).
#ifndef PRIMITIVE_EDIT_UPDATE_NORMALS_AND_BOUNDS_H
#define PRIMITIVE_EDIT_UPDATE_NORMALS_AND_BOUNDS_H

// vcg's algorithm headers need its mesh types declared first.
#include <vcg/complex/complex.h>

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>

namespace primitive_edit {

template <class MeshType>
void update_normals_and_bounds(MeshType& m)
{
  vcg::tri::UpdateNormal<MeshType>::PerVertexNormalizedPerFaceNormalized(m);
  vcg::tri::UpdateBounding<MeshType>::Box(m);
}

} // namespace primitive_edit

#endif
