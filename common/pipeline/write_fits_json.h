// write_fits_json.h: the primitives of fit_all_segments as a JSON document, for CAD tools and scripts.
//
// Input:  a FitAllSegmentsResult (fit_all_segments.h), the mesh's name and whether it was snapped.
// Output: on `out`, {"mesh", "segment_count", "snapped", "segments": [...], "relations": [...]}; a segment is
//         {"id", "point_count", "area", "type", "parameters", "rms", "max_residual"}, or {"id", "point_count",
//         "area", "type": "FreeForm", "reason"}. Parameters by type: Plane {normal, offset, point}, Sphere {center, radius},
//         Cylinder {axis_point, axis, radius}, Cone {apex, axis, half_angle_deg}, Torus {center, axis,
//         major_radius, minor_radius}; vectors as [x, y, z]. A relation (relate_primitives.h) is {"kind",
//         "segments": [a, b], "value"}: kind as relation_kind_name, value as relation_value (degrees for
//         perpendicular and angle, the common or fillet radius, the distance between axes, centres or planes).
//         Numbers are the shortest text that reads back as the same double (std::to_chars); strings are
//         escaped per RFC 8259.
// Cost:   O(K + R) for K segments and R relations.
#ifndef PRIMITIVE_EDIT_WRITE_FITS_JSON_H
#define PRIMITIVE_EDIT_WRITE_FITS_JSON_H

#include "common/base/constants.h"
#include "common/pipeline/fit_all_segments.h"

#include <Eigen/Core>

#include <charconv>
#include <cstdio>
#include <ostream>
#include <string>

namespace primitive_edit {

namespace write_fits_json_detail {

std::string number(double x);

std::string text(const std::string& s);

std::string vector(const Eigen::Vector3d& v);

std::string parameters(const Primitive& p);

} // namespace write_fits_json_detail

void write_fits_json(std::ostream& out, const FitAllSegmentsResult& result, const std::string& mesh_name,
                     bool snapped);

} // namespace primitive_edit

#endif
