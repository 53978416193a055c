#include "common/snap/describe_snap_report.h"

namespace primitive_edit {

std::string describe_snap_report(const SnapReport& r)
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
