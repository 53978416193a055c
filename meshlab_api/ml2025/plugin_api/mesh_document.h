// mesh_document.h (MeshLab 2025.07): the document and mesh classes, and the calls whose names differ
// between MeshLab generations, under one name each.
#ifndef PRIMITIVE_EDIT_PLUGIN_API_MESH_DOCUMENT_H
#define PRIMITIVE_EDIT_PLUGIN_API_MESH_DOCUMENT_H

#include <common/ml_document/mesh_document.h>

#include <vector>

namespace primitive_edit::meshlab {

constexpr const char* kMeshLabGeneration = "2025.07";

inline std::vector<MeshModel*> document_meshes(MeshDocument& document)
{
  std::vector<MeshModel*> meshes;
  for (MeshModel& m : document.meshIterator())
    meshes.push_back(&m);
  return meshes;
}

inline void update_box_and_normals(MeshModel& mesh) { mesh.updateBoxAndNormals(); }

} // namespace primitive_edit::meshlab

#endif
