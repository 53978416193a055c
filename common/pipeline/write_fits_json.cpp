#include "common/pipeline/write_fits_json.h"

namespace primitive_edit {

namespace write_fits_json_detail {

std::string number(double x)
{
  if (!std::isfinite(x))
    return "null";  // JSON has no NaN; fits never give one, but a reader must not choke
  char buffer[32];
  const std::to_chars_result r = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, r.ptr);
}

std::string text(const std::string& s)
{
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", unsigned(static_cast<unsigned char>(c)));
      out += escaped;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string vector(const Eigen::Vector3d& v)
{
  return "[" + number(v.x()) + ", " + number(v.y()) + ", " + number(v.z()) + "]";
}

std::string parameters(const Primitive& p)
{
  switch (p.type) {
  case PrimitiveType::Plane:
    return "{\"normal\": " + vector(p.axis) + ", \"offset\": " + number(p.axis.dot(p.origin)) +
           ", \"point\": " + vector(p.origin) + "}";
  case PrimitiveType::Sphere: return "{\"center\": " + vector(p.origin) + ", \"radius\": " + number(p.radius) + "}";
  case PrimitiveType::Cylinder:
    return "{\"axis_point\": " + vector(p.origin) + ", \"axis\": " + vector(p.axis) +
           ", \"radius\": " + number(p.radius) + "}";
  case PrimitiveType::Cone:
    return "{\"apex\": " + vector(p.origin) + ", \"axis\": " + vector(p.axis) +
           ", \"half_angle_deg\": " + number(degrees_from_radians(p.half_angle)) + "}";
  case PrimitiveType::Torus:
    return "{\"center\": " + vector(p.origin) + ", \"axis\": " + vector(p.axis) +
           ", \"major_radius\": " + number(p.radius) + ", \"minor_radius\": " + number(p.minor_radius) + "}";
  }
  return "{}";
}

} // namespace write_fits_json_detail

void write_fits_json(std::ostream& out, const FitAllSegmentsResult& result, const std::string& mesh_name,
                     bool snapped)
{
  using namespace write_fits_json_detail;
  out << "{\n  \"mesh\": " << text(mesh_name) << ",\n  \"segment_count\": " << result.segment_count()
      << ",\n  \"snapped\": " << (snapped ? "true" : "false") << ",\n  \"segments\": [";
  for (int s = 0; s < result.segment_count(); ++s) {
    const FitResult& fit = result.fits[size_t(s)];
    out << (s == 0 ? "\n" : ",\n") << "    {\"id\": " << s << ", \"point_count\": " << result.point_count[size_t(s)]
        << ", \"area\": " << number(result.area[size_t(s)]);
    if (fit.status.ok())
      out << ", \"type\": " << text(primitive_type_name(fit.primitive.type))
          << ", \"parameters\": " << parameters(fit.primitive) << ", \"rms\": " << number(fit.rms)
          << ", \"max_residual\": " << number(fit.max_residual) << "}";
    else
      out << ", \"type\": \"FreeForm\", \"reason\": " << text(fit.status.error) << "}";
  }
  out << "\n  ],\n  \"relations\": [";
  for (std::size_t i = 0; i < result.relations.size(); ++i) {
    const Relation& r = result.relations[i];
    const std::size_t a = std::size_t(r.a), b = std::size_t(r.b);
    const double value = a < result.primitives.size() && b < result.primitives.size() && result.primitives[a] &&
                                 result.primitives[b]
                             ? relation_value(r, *result.primitives[a], *result.primitives[b])
                             : 0.0;
    out << (i == 0 ? "\n" : ",\n") << "    {\"kind\": " << text(relation_kind_name(r.kind)) << ", \"segments\": ["
        << r.a << ", " << r.b << "], \"value\": " << number(value) << "}";
  }
  out << (result.relations.empty() ? "]\n}\n" : "\n  ]\n}\n");
}

} // namespace primitive_edit
