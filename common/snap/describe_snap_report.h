// describe_snap_report.h: one line for MeshLab's log saying what a snap did (the filters and the edit tool
// print the same words).
//
// Input:  a SnapReport. Output: e.g. "1200 vertices moved (64 onto edges and 8 onto corners of the 80 on borders
//         between segments; 96 slid along their surfaces to unfold triangles, 4 held back where that was not
//         enough, 3 of them part of the way), mean displacement 0.05, max 1": the share of the border on its
//         edge is how clean the edges came out (left out when no vertex is on a border). A fold left (only
//         without flip prevention) adds its face count and area. Cost: O(1).
#ifndef PRIMITIVE_EDIT_DESCRIBE_SNAP_REPORT_H
#define PRIMITIVE_EDIT_DESCRIBE_SNAP_REPORT_H

#include "common/snap/snap_segments.h"

#include <cstdio>
#include <string>

namespace primitive_edit {

inline std::string describe_snap_report(const SnapReport& r)
{
  char text[400];
  std::string out = std::to_string(r.moved_vertices) + " vertices moved (";
  if (r.border_vertices > 0) {
    std::snprintf(text, sizeof text, "%d onto edges and %d onto corners of the %d on borders between segments; ",
                  r.edge_vertices, r.corner_vertices, r.border_vertices);
    out += text;
  }
  std::snprintf(text, sizeof text,
                "%d slid along their surfaces to unfold triangles, %d held back where that was not enough",
                r.repaired_vertices, r.reverted_vertices);
  out += text;
  if (r.partway_vertices > 0)
    out += ", " + std::to_string(r.partway_vertices) + " of them part of the way";
  std::snprintf(text, sizeof text, "), mean displacement %.4g, max %.4g", r.mean_displacement, r.max_displacement);
  out += text;
  if (r.folded_faces > 0) {
    std::snprintf(text, sizeof text, "; %d triangles left folded (area %.4g)", r.folded_faces, r.folded_area);
    out += text;
  }
  return out;
}

} // namespace primitive_edit

#endif
