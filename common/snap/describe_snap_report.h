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

std::string describe_snap_report(const SnapReport& r);

} // namespace primitive_edit

#endif
