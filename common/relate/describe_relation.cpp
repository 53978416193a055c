#include "common/relate/describe_relation.h"

namespace primitive_edit {

std::string describe_relation(const Relation& r, const std::vector<std::optional<Primitive>>& primitives)
{
  const auto at = [&](int s) -> const Primitive* {
    return s >= 0 && std::size_t(s) < primitives.size() && primitives[std::size_t(s)] ? &*primitives[std::size_t(s)]
                                                                                       : nullptr;
  };
  const Primitive* a = at(r.a);
  const Primitive* b = at(r.b);
  const double value = a && b ? relation_value(r, *a, *b) : 0.0;
  char text[160];
  switch (r.kind) {
  case RelationKind::Parallel:
  case RelationKind::Perpendicular:
    std::snprintf(text, sizeof text, "%s: segments %d and %d", relation_kind_name(r.kind), r.a, r.b);
    break;
  case RelationKind::Angle:
    std::snprintf(text, sizeof text, "angle: segments %d and %d at %.4g degrees", r.a, r.b, value);
    break;
  case RelationKind::Coaxial:
    std::snprintf(text, sizeof text, "coaxial: segments %d and %d (axes %.4g apart)", r.a, r.b, value);
    break;
  case RelationKind::Concentric:
    std::snprintf(text, sizeof text, "concentric: segments %d and %d (centres %.4g apart)", r.a, r.b, value);
    break;
  case RelationKind::Coplanar:
    std::snprintf(text, sizeof text, "coplanar: segments %d and %d (%.4g apart)", r.a, r.b, value);
    break;
  case RelationKind::EqualRadius:
    std::snprintf(text, sizeof text, "equal radius: segments %d and %d (radius %.4g)", r.a, r.b, value);
    break;
  case RelationKind::Tangent:
    std::snprintf(text, sizeof text, "tangent: segment %d (fillet, radius %.4g) and segment %d", r.a, value, r.b);
    break;
  }
  return text;
}

} // namespace primitive_edit
