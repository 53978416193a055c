// mesh_document.h (MeshLab 2020.09): the document and mesh classes, and the calls whose names differ
// between MeshLab generations, under one name each.
#ifndef PRIMITIVE_EDIT_PLUGIN_API_MESH_DOCUMENT_H
#define PRIMITIVE_EDIT_PLUGIN_API_MESH_DOCUMENT_H

#include <common/meshmodel.h>

#include <vector>

namespace primitive_edit::meshlab {

constexpr const char* kMeshLabGeneration = "2020.09";

inline std::vector<MeshModel*> document_meshes(MeshDocument& document)
{
  return std::vector<MeshModel*>(document.meshList.begin(), document.meshList.end());
}

inline void update_box_and_normals(MeshModel& mesh) { mesh.UpdateBoxAndNormals(); }

} // namespace primitive_edit::meshlab

#endif
