// segment_attribute.h: where a segmentation lives on a mesh, so that it survives between filters and files.
//
// The id of each face is kept in a per-face int attribute named kSegmentAttributeName ("SegmentId") and
// mirrored into the face quality (when the mesh has it), which MeshLab saves in PLY files and shows with its
// quality tools; face colours (when the mesh has them) show the segments.
//
// read_segment_ids:  input a mesh; output segment_of_face (indexed by vcg::tri::Index, -1 for deleted faces,
//                    dense ids 0..K-1). Taken from the attribute when present and valid (every live face
//                    has an id >= 0), else from the face quality when the mesh has it and every live face's
//                    quality is a non-negative integer (a PLY saved with face quality and reopened; note that a
//                    quality left all zero reads as one segment). Stored ids that are dense are kept as they
//                    are; others are compacted keeping their order (compact_segment_ids.h), and *renumbered
//                    (if given) says so. Returns false, with segment_of_face all -1, when neither holds.
// write_segment_ids: input a mesh and segment_of_face (dense ids; entries missing or negative mean no
//                    segment); writes the attribute (replacing a non-int one of the same name), the face
//                    quality if HasPerFaceQuality(m), and colours from color_segments if HasPerFaceColor(m)
//                    (over the mesh's face adjacency, built unless the caller passes it).
// Complexity: O(F) (write: plus the adjacency build and colouring when the mesh has face colours).
#ifndef PRIMITIVE_EDIT_SEGMENT_ATTRIBUTE_H
#define PRIMITIVE_EDIT_SEGMENT_ATTRIBUTE_H

#include "common/base/huge_page_vector.h"
#include "common/mesh/color_segments.h"
#include "common/mesh/compact_segment_ids.h"
#include "common/mesh/face_adjacency.h"

#include <vcg/complex/complex.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <typeindex>
#include <typeinfo>
#include <vector>

namespace primitive_edit {

constexpr const char* kSegmentAttributeName = "SegmentId";

namespace detail {

// True when the mesh has a per-face attribute of that name whose type is not int.
template <class MeshType>
bool has_face_attribute_of_other_type(const MeshType& m, const std::string& name)
{
  for (const auto& attribute : m.face_attr)
    if (attribute._name == name)
      return attribute._type != std::type_index(typeid(int));
  return false;
}

template <class MeshType>
bool has_int_face_attribute(const MeshType& m, const std::string& name)
{
  for (const auto& attribute : m.face_attr)
    if (attribute._name == name)
      return attribute._type == std::type_index(typeid(int)) && attribute._sizeof == sizeof(int);
  return false;
}

// Compacts ids read from the mesh; true when that changed any of them.
bool compact_stored_ids(std::vector<int>& segment_of_face);

} // namespace detail

template <class MeshType>
bool read_segment_ids(const MeshType& m, std::vector<int>& segment_of_face, bool* renumbered = nullptr)
{
  const std::size_t face_count = m.face.size();
  segment_of_face.assign(face_count, -1);
  if (renumbered)
    *renumbered = false;
  const std::string name(kSegmentAttributeName);
  if (detail::has_int_face_attribute(m, name)) {
    // vcg's FindPerFaceAttribute takes a non-const mesh only because it may re-lay-out an attribute loaded
    // with padding; the ids themselves are not changed, so reading through const_cast keeps m logically const.
    auto handle = vcg::tri::Allocator<MeshType>::template FindPerFaceAttribute<int>(const_cast<MeshType&>(m), name);
    if (vcg::tri::Allocator<MeshType>::template IsValidHandle<int>(const_cast<MeshType&>(m), handle)) {
      bool valid = true;
      for (std::size_t f = 0; f < face_count && valid; ++f) {
        if (m.face[f].IsD())
          continue;
        segment_of_face[f] = handle[f];
        valid = segment_of_face[f] >= 0;
      }
      if (valid) {
        const bool changed = detail::compact_stored_ids(segment_of_face);
        if (renumbered)
          *renumbered = changed;
        return true;
      }
      segment_of_face.assign(face_count, -1);
    }
  }

  if (!vcg::tri::HasPerFaceQuality(m))
    return false;
  for (std::size_t f = 0; f < face_count; ++f) {
    if (m.face[f].IsD())
      continue;
    const double q = double(m.face[f].cQ());
    // 2^31 bounds the ids to int; fractional or negative quality is not a segmentation.
    if (!(q >= 0.0 && q < 2147483648.0 && q == std::floor(q))) {
      segment_of_face.assign(face_count, -1);
      return false;
    }
    segment_of_face[f] = int(q);
  }
  const bool changed = detail::compact_stored_ids(segment_of_face);
  if (renumbered)
    *renumbered = changed;
  return true;
}

template <class MeshType>
void write_segment_ids(MeshType& m, const std::vector<int>& segment_of_face, const FaceAdjacency* adjacency = nullptr)
{
  const std::size_t face_count = m.face.size();
  std::vector<int> ids = huge_page_vector(face_count, -1);  // fresh pages, faulted in 2 MiB at a time
  for (std::size_t f = 0; f < face_count && f < segment_of_face.size(); ++f)
    if (!m.face[f].IsD() && segment_of_face[f] >= 0)
      ids[f] = segment_of_face[f];

  const std::string name(kSegmentAttributeName);
  if (detail::has_face_attribute_of_other_type(m, name))
    vcg::tri::Allocator<MeshType>::DeletePerFaceAttribute(m, name);
  auto handle = vcg::tri::Allocator<MeshType>::template GetPerFaceAttribute<int>(m, name);
  for (std::size_t f = 0; f < face_count; ++f)
    handle[f] = ids[f];

  if (vcg::tri::HasPerFaceQuality(m))
    for (std::size_t f = 0; f < face_count; ++f)
      if (!m.face[f].IsD())
        m.face[f].Q() = typename MeshType::FaceType::QualityType(ids[f]);

  if (vcg::tri::HasPerFaceColor(m)) {
    // Not `adjacency ? *adjacency : build_face_adjacency(m)`: with a prvalue on one side, that copies the
    // caller's adjacency (64 MB at 4M faces, 0.17 s of fresh pages through meshlabserver).
    const FaceAdjacency built = adjacency != nullptr ? FaceAdjacency() : build_face_adjacency(m);
    const std::vector<vcg::Color4b> colour = color_segments(m, adjacency != nullptr ? *adjacency : built, ids);
    for (std::size_t f = 0; f < face_count; ++f)
      if (!m.face[f].IsD() && ids[f] >= 0 && std::size_t(ids[f]) < colour.size())
        m.face[f].C() = colour[std::size_t(ids[f])];
  }
}

} // namespace primitive_edit

#endif
