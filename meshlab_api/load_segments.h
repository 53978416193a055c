// load_segments.h: a filter's view of the mesh's segment ids, kept equal to the ids the user sees.
//
// read_segments: the ids as read_segment_ids (common/mesh/segment_attribute.h) gives them, and whether
//   stored ids that were not dense had to be renumbered (in their order); false when the mesh has no
//   segments. The mesh is not changed, so a filter that then refuses its input leaves it untouched.
// keep_segment_ids: called once the filter has accepted its input: renumbered ids are written back (face
//   quality and colours too), so that the ids the user reads in the face quality are the ids every filter
//   takes (a Segment parameter, the JSON export), and the log says so.
// Cost: O(F) (plus recolouring when renumbered).
#ifndef PRIMITIVE_EDIT_MESHLAB_API_LOAD_SEGMENTS_H
#define PRIMITIVE_EDIT_MESHLAB_API_LOAD_SEGMENTS_H

#include "filter_suite.h"

#include "common/mesh/segment_attribute.h"

#include "plugin_api/mesh_document.h"

#include <vector>

namespace primitive_edit::meshlab {

struct LoadedSegments
{
  std::vector<int> segment_of_face;
  bool found = false;
  bool renumbered = false;
};

inline LoadedSegments read_segments(const MeshModel& mesh)
{
  LoadedSegments out;
  out.found = read_segment_ids(mesh.cm, out.segment_of_face, &out.renumbered);
  return out;
}

inline void keep_segment_ids(FilterRun& run, const QString& filter_name, const LoadedSegments& loaded)
{
  if (!loaded.found || !loaded.renumbered)
    return;
  write_segment_ids(run.mesh.cm, loaded.segment_of_face);
  run.logf("%s: the stored segment ids were not 0 to K-1; they were renumbered in their order and written "
           "back to the face quality.",
           qUtf8Printable(filter_name));
}

} // namespace primitive_edit::meshlab

#endif
