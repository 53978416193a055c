// decoded_mesh_type.h: the mesh type a mesh target runs on, decoded from the input's first byte: MeshLab's
// float CMeshO when it is odd, fuzz_input.h's double FMesh when even, so that both instantiations of the core
// are fuzzed. One place for the rule, since saved corpora depend on it.
//
// on_decoded_mesh_type(in, run) calls run(MeshTypeTag<M>()) for the decoded M; a target's lambda runs its
// own run<M>(in).
#ifndef PRIMITIVE_EDIT_FUZZ_DECODED_MESH_TYPE_H
#define PRIMITIVE_EDIT_FUZZ_DECODED_MESH_TYPE_H

#include "fuzz/fuzz_input.h"

#include <common/ml_mesh_type.h>

namespace fuzz {

template <class M>
struct MeshTypeTag
{
  using Mesh = M;
};

template <class Run>
void on_decoded_mesh_type(Decoder& in, const Run& run)
{
  if (in.u8() & 1)
    run(MeshTypeTag<CMeshO>());
  else
    run(MeshTypeTag<fuzz_mesh::FMesh>());
}

} // namespace fuzz

#endif
