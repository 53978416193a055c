// fuzz_relate.cpp: libFuzzer target over the relations and the joint refit (common/relate/) on small parts.
//
// The bytes are decoded (fuzz_input.h) into a part of up to 6 segments whose primitives share structure as a
// machined part's do (axes along a frame or at 45 degrees to it, origins on a coarse grid, radii from a few
// values), so that relations are found and the refit runs; each segment gets up to 120 points of a patch of
// its primitive with noise and special values, and a "fitted" primitive: its own, slightly tilted and moved, or
// a decoded one (valid or not), or none. Contacts between segments, the noise, the options and the fixed
// segments are decoded too. Entry point: relate_primitives (direction and position detection, the refits, the check),
// then fit_edge_blends, fit_profiles_about_axes and fit_profiles_about_directions on the refitted primitives.
// Invariants: bad options are refused with the primitives untouched; otherwise every relation joins two distinct
// segments that had a valid primitive, a segment without one stays without, every relation kept holds after the refit,
// the refitted primitives are valid, and held segments do not move; each fillet or chamfer lies between two planes, or
// a plane and a cylinder or cone it turns about, that are no blends (check_edge_blends, and on a decoded boss's foot,
// check_blends_about_axis); each profile about an axis lies on a cylinder segment's axis (check_profiles), each about a
// direction along a large plane's normal (check_profiles_about_directions).
#include "common/fit/fit_primitive.h"
#include "common/relate/fit_edge_blends.h"
#include "common/relate/fit_profiles_about_axes.h"
#include "common/relate/fit_profiles_about_directions.h"
#include "common/relate/relate_primitives.h"
#include "fuzz/fuzz_input.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <optional>

using namespace primitive_edit;
using namespace fuzz;

namespace {

constexpr int kMaxSegments = 6;
constexpr int kMaxPoints = 120;

Eigen::Vector3d frame_direction(Decoder& in)
{
  const double h = std::sqrt(0.5);
  switch (in.u8() % 8) {
  case 0: return Eigen::Vector3d::UnitX();
  case 1: return Eigen::Vector3d::UnitY();
  case 2: return Eigen::Vector3d::UnitZ();
  case 3: return Eigen::Vector3d(h, h, 0);
  case 4: return Eigen::Vector3d(0, -h, h);
  case 5: return -Eigen::Vector3d::UnitZ();
  default: return unit_vector(in);
  }
}

Primitive part_primitive(Decoder& in)
{
  static constexpr double kRadii[] = {0.5, 1.0, 1.5, 2.5, 4.0};
  Primitive p;
  p.type = static_cast<PrimitiveType>(in.u8() % kPrimitiveTypeCount);
  p.axis = frame_direction(in);
  p.origin = Eigen::Vector3d(int(in.u8() % 5) - 2, int(in.u8() % 5) - 2, int(in.u8() % 5) - 2);
  p.radius = kRadii[in.u8() % 5];
  p.minor_radius = std::min(kRadii[in.u8() % 5], 0.8 * p.radius);
  p.half_angle = in.bit() ? 0.7853981634 : 0.05 + 1.4 * in.unit();
  if (p.type == PrimitiveType::Torus && p.minor_radius >= p.radius)
    p.minor_radius = 0.5 * p.radius;
  return p;
}

// The segment's primitive moved as a per-segment fit of a rough scan moves it: a small tilt and shift.
Primitive perturbed(Decoder& in, Primitive p)
{
  const double tilt = 0.2 * in.unit() * in.unit();
  p.axis = (p.axis + tilt * unit_vector(in)).normalized();
  p.origin += 0.1 * in.unit() * unit_vector(in);
  p.radius *= 1 + 0.05 * in.signed_unit();
  p.minor_radius *= 1 + 0.05 * in.signed_unit();
  return p;
}

// Bit for bit (a NaN parameter of an invalid primitive equals itself).
bool same(const Primitive& a, const Primitive& b)
{
  auto bits = [](double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; };
  for (int k = 0; k < 3; ++k)
    if (!bits(a.origin[k], b.origin[k]) || !bits(a.axis[k], b.axis[k]))
      return false;
  return a.type == b.type && bits(a.radius, b.radius) && bits(a.minor_radius, b.minor_radius) &&
         bits(a.half_angle, b.half_angle);
}

// Each blend is a distinct segment between two distinct valid segments that are no blends, a plane and a plane or,
// about an axis, a cylinder or cone; of the form the type asked allows, valid, with a finite RMS, a positive setback
// and finite contacts.
void check_blends(const std::vector<SegmentEdgeBlend>& blends, const std::vector<std::optional<Primitive>>& primitives,
                  const std::vector<std::optional<PrimitiveType>>& types, double axis_angle)
{
  const int count = int(primitives.size());
  std::vector<char> blend(std::size_t(count), 0);
  for (const SegmentEdgeBlend& b : blends) {
    FUZZ_CHECK(b.segment >= 0 && b.segment < count && !blend[std::size_t(b.segment)]);
    blend[std::size_t(b.segment)] = 1;
  }
  for (const SegmentEdgeBlend& b : blends) {
    for (int p : {b.plane_a, b.plane_b}) {
      FUZZ_CHECK(p >= 0 && p < count && p != b.segment && !blend[std::size_t(p)] && primitives[std::size_t(p)]);
      FUZZ_CHECK(primitive_is_valid(*primitives[std::size_t(p)]));
    }
    FUZZ_CHECK(b.plane_a != b.plane_b && b.setback > 0 && std::isfinite(b.rms) && primitive_is_valid(b.primitive));
    FUZZ_CHECK(b.contact_a.allFinite() && b.contact_b.allFinite());
    const PrimitiveType joined = primitives[std::size_t(b.plane_b)]->type;
    FUZZ_CHECK(primitives[std::size_t(b.plane_a)]->type == PrimitiveType::Plane);
    if (b.meridian) {
      // About an axis: a plane and a cylinder or cone turning about its normal; a fillet is a torus, a chamfer a cone
      // (or the cylinder or plane of a line parallel or square to the axis).
      FUZZ_CHECK(axis_angle > 0 && (joined == PrimitiveType::Cylinder || joined == PrimitiveType::Cone));
      FUZZ_CHECK(b.form == BlendForm::Fillet ? b.primitive.type == PrimitiveType::Torus
                                             : b.primitive.type != PrimitiveType::Torus &&
                                                   b.primitive.type != PrimitiveType::Sphere);
    } else {
      FUZZ_CHECK(joined == PrimitiveType::Plane);
      FUZZ_CHECK(b.primitive.type == (b.form == BlendForm::Fillet ? PrimitiveType::Cylinder : PrimitiveType::Plane));
    }
    if (std::size_t(b.segment) < types.size() && types[std::size_t(b.segment)])
      FUZZ_CHECK(*types[std::size_t(b.segment)] == b.primitive.type);
  }
}

std::vector<std::optional<PrimitiveType>> decode_types(Decoder& in, int count)
{
  std::vector<std::optional<PrimitiveType>> types(in.u8() % (count + 1));
  for (auto& t : types)
    if (in.bit())
      t = static_cast<PrimitiveType>(in.u8() % kPrimitiveTypeCount);
  return types;
}

// Fillets and chamfers between the refitted segments, with decoded types, tolerance and axis angle (check_blends).
void check_edge_blends(Decoder& in, const std::vector<std::optional<Primitive>>& primitives,
                       const std::vector<SegmentSamples>& samples, const std::vector<SegmentContact>& contacts,
                       double noise)
{
  const std::vector<std::optional<PrimitiveType>> types = decode_types(in, int(primitives.size()));
  const double tolerance = in.special(0.1), axis_angle = in.special(10);
  check_blends(fit_edge_blends(primitives, samples, contacts, noise, tolerance, types, {}, axis_angle), primitives,
               types, axis_angle);
}

// A boss's foot, as random parts seldom pair a plane with a cylinder about its normal: a plane (tilted up to 0.2
// radians from the axis), a cylinder or cone about the axis, and a fillet or chamfer band between them, each
// sampled from its meridian profile with decoded noise (special values too); the band's primitive decoded (none, any,
// a sphere fitted to it), its borders rings of points (or none) whose means lie on the axis. check_blends on what
// fit_edge_blends makes of it.
void check_blends_about_axis(Decoder& in)
{
  static constexpr double kSizes[] = {0.5, 1.0, 2.0, 4.0, 8.0};
  const Eigen::Vector3d axis = frame_direction(in);
  const Eigen::Vector3d centre(int(in.u8() % 5) - 2, int(in.u8() % 5) - 2, int(in.u8() % 5) - 2);
  const Eigen::Vector3d e1 = axis.unitOrthogonal(), e2 = axis.cross(e1);
  const double radius = kSizes[in.u8() % 5], setback = 0.5 * kSizes[in.u8() % 5];
  const bool fillet = !in.bit(), cone = in.bit();
  const double draft = cone ? 0.05 + 0.5 * in.unit() : 0.0;  // the turned surface's half-angle, widening downwards
  const double noise = in.bit() ? in.special(0.05) : 0.05 * in.unit();
  // (r, h) of the profile: the plane h = 0 for r >= radius + setback, the turned surface from (radius, setback) up.
  auto at = [&](double r, double h, double phi) {
    return Eigen::Vector3d(centre + h * axis + r * (std::cos(phi) * e1 + std::sin(phi) * e2));
  };
  auto sampled = [&](const std::function<Eigen::Vector2d(double)>& profile, int n) {
    SegmentSamples ss;
    ss.points.resize(n, 3);
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector2d rh = profile(in.unit());
      ss.points.row(i) = at(rh.x() + noise * in.signed_unit(), rh.y() + noise * in.signed_unit(), 2 * kPi * in.unit())
                             .transpose();
    }
    ss.normals = Eigen::MatrixX3d::Zero(n, 3);
    ss.weights = Eigen::VectorXd::Ones(n);
    ss.area = n;
    return ss;
  };
  const double r0 = radius + setback;
  const Eigen::Vector2d on_plane(r0, 0), on_turned(radius, setback);
  std::vector<SegmentSamples> samples;
  samples.push_back(sampled([&](double u) { return Eigen::Vector2d(r0 + 5 * u, 0); }, 60));
  samples.push_back(
      sampled([&](double u) { return Eigen::Vector2d(radius - std::tan(draft) * 5 * u, setback + 5 * u); }, 60));
  samples.push_back(sampled(
      [&](double u) -> Eigen::Vector2d {
        if (!fillet)
          return on_plane + u * (on_turned - on_plane);
        const double a = u * kPi / 2;
        return Eigen::Vector2d(r0, setback) - setback * Eigen::Vector2d(std::sin(a), std::cos(a));
      },
      int(20 + in.u8() % 100)));
  const double tilt = 0.2 * in.unit();
  Primitive plane;
  plane.type = PrimitiveType::Plane;
  plane.origin = centre;
  plane.axis = (std::cos(tilt) * axis + std::sin(tilt) * e1).normalized();
  Primitive turned;
  turned.type = cone ? PrimitiveType::Cone : PrimitiveType::Cylinder;
  turned.axis = cone ? Eigen::Vector3d(-axis) : axis;
  turned.origin = cone ? centre + (setback + radius / std::tan(draft)) * axis : centre;
  turned.radius = radius;
  turned.half_angle = draft;
  std::optional<Primitive> own;
  switch (in.u8() % 3) {
  case 0: break;
  case 1: own = fuzz_primitive(in); break;
  default: {
    const SegmentSamples& band = samples[2];
    const FitResult sphere = fit_primitive(PrimitiveType::Sphere, band.points, band.normals, band.weights);
    if (sphere.status.ok())
      own = sphere.primitive;
  }
  }
  const std::vector<std::optional<Primitive>> primitives{plane, turned, own};
  auto ring = [&](int a, const Eigen::Vector2d& rh) {
    SegmentContact c;
    c.a = a;
    c.b = 2;
    c.pairs = 64;
    c.mean = centre + rh.y() * axis;
    c.point = at(rh.x(), rh.y(), 0);
    if (in.bit())
      for (int k = 0; k < 16; ++k)
        c.points.push_back(at(rh.x() + noise * in.signed_unit(), rh.y() + noise * in.signed_unit(), 2 * kPi * k / 16));
    return c;
  };
  const std::vector<SegmentContact> contacts{ring(0, on_plane), ring(1, on_turned)};
  const std::vector<std::optional<PrimitiveType>> types = decode_types(in, 3);
  const double tolerance = in.bit() ? in.special(0.1) : 0.0, axis_angle = in.bit() ? in.special(10) : 10.0;
  check_blends(fit_edge_blends(primitives, samples, contacts, noise, tolerance, types, {}, axis_angle), primitives,
               types, axis_angle);
}

// fit_profiles_about_axes on the refitted primitives, with decoded types, tolerance, angle and distance: each
// profile is a distinct segment that had a valid sphere, cone or torus, now a valid one of those (the type asked,
// if any) on the axis of a distinct valid cylinder segment.
void check_profiles(Decoder& in, const std::vector<std::optional<Primitive>>& primitives,
                    const std::vector<SegmentSamples>& samples, double noise)
{
  const int count = int(primitives.size());
  const std::vector<std::optional<PrimitiveType>> types = decode_types(in, count);
  const double tolerance = in.special(0.1), angle = in.special(10), distance = in.special(0.5);
  const std::vector<SegmentProfile> profiles =
      fit_profiles_about_axes(primitives, samples, noise, tolerance, angle, distance, types);
  std::vector<char> seen(std::size_t(count), 0);
  for (const SegmentProfile& q : profiles) {
    FUZZ_CHECK(q.segment >= 0 && q.segment < count && !seen[std::size_t(q.segment)]);
    seen[std::size_t(q.segment)] = 1;
    FUZZ_CHECK(q.axis_segment >= 0 && q.axis_segment < count && q.axis_segment != q.segment);
    const std::optional<Primitive>& own = primitives[std::size_t(q.segment)];
    const std::optional<Primitive>& c = primitives[std::size_t(q.axis_segment)];
    FUZZ_CHECK(own && primitive_is_valid(*own) && own->type != PrimitiveType::Plane &&
               own->type != PrimitiveType::Cylinder);
    FUZZ_CHECK(c && c->type == PrimitiveType::Cylinder && primitive_is_valid(*c));
    const Primitive& p = q.primitive;
    FUZZ_CHECK(primitive_is_valid(p) && p.type != PrimitiveType::Plane && p.type != PrimitiveType::Cylinder);
    FUZZ_CHECK(std::isfinite(q.rms) && q.rms >= 0);
    if (std::size_t(q.segment) < types.size() && types[std::size_t(q.segment)])
      FUZZ_CHECK(*types[std::size_t(q.segment)] == p.type);
    const Eigen::Vector3d d = p.origin - c->origin;
    const double scale = 1 + d.norm() + c->origin.norm();
    FUZZ_CHECK((d - d.dot(c->axis) * c->axis).norm() <= 1e-6 * scale);
    if (p.type != PrimitiveType::Sphere)
      FUZZ_CHECK(std::abs(std::abs(p.axis.dot(c->axis)) - 1) <= 1e-9);
  }
}

} // namespace

// part_directions and fit_profiles_about_directions on the refitted primitives, with decoded types, tolerance and
// angle: each direction is a distinct plane segment's unit normal, no two within the angle; each profile is a
// distinct segment that had a valid cylinder, cone or torus whose axis lies beyond the angle from every direction,
// now a valid plane, cylinder, cone or ring torus (the type asked, if any) along a direction's plane's normal.
void check_profiles_about_directions(Decoder& in, const std::vector<std::optional<Primitive>>& primitives,
                                     const std::vector<SegmentSamples>& samples, double noise)
{
  const int count = int(primitives.size());
  std::vector<double> area;  // a point per unit of area: the decoded parts' samples have none
  for (const SegmentSamples& s : samples)
    area.push_back(double(s.points.rows()));
  const std::vector<std::optional<PrimitiveType>> types = decode_types(in, count);
  const double tolerance = in.bit() ? in.special(0.1) : 0.0, angle = in.bit() ? in.special(10) : 10.0;
  const std::vector<PartDirection> directions = part_directions(primitives, area, angle);
  const double cos_angle = angle >= 0 && angle < 90 ? std::cos(radians_from_degrees(angle)) : 1.0;
  for (std::size_t i = 0; i < directions.size(); ++i) {
    const PartDirection& d = directions[i];
    FUZZ_CHECK(d.segment >= 0 && d.segment < count && primitives[std::size_t(d.segment)] &&
               primitives[std::size_t(d.segment)]->type == PrimitiveType::Plane);
    FUZZ_CHECK(std::abs(d.direction.norm() - 1) <= 1e-9);
    for (std::size_t j = 0; j < i; ++j)
      FUZZ_CHECK(directions[j].segment != d.segment && std::abs(directions[j].direction.dot(d.direction)) < cos_angle);
  }
  const std::vector<SegmentProfile> profiles =
      fit_profiles_about_directions(primitives, samples, noise, tolerance, directions, angle, types, 1 + in.bit());
  std::vector<char> seen(std::size_t(count), 0);
  for (const SegmentProfile& q : profiles) {
    FUZZ_CHECK(q.segment >= 0 && q.segment < count && !seen[std::size_t(q.segment)]);
    seen[std::size_t(q.segment)] = 1;
    const std::optional<Primitive>& own = primitives[std::size_t(q.segment)];
    FUZZ_CHECK(own && primitive_is_valid(*own) && has_axis(*own));
    const auto along = std::find_if(directions.begin(), directions.end(),
                                    [&](const PartDirection& d) { return d.segment == q.axis_segment; });
    FUZZ_CHECK(along != directions.end() && q.axis_segment != q.segment);
    for (const PartDirection& d : directions)
      FUZZ_CHECK(std::abs(d.direction.dot(own->axis)) < cos_angle);
    const Primitive& p = q.primitive;
    FUZZ_CHECK(primitive_is_valid(p) && p.type != PrimitiveType::Sphere);
    FUZZ_CHECK(std::abs(std::abs(p.axis.dot(along->direction)) - 1) <= 1e-9);
    FUZZ_CHECK(p.type != PrimitiveType::Torus || p.radius > p.minor_radius);
    FUZZ_CHECK(std::isfinite(q.rms) && q.rms >= 0);
    if (std::size_t(q.segment) < types.size() && types[std::size_t(q.segment)])
      FUZZ_CHECK(*types[std::size_t(q.segment)] == p.type);
  }
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  Decoder in(data, size);
  const int count = 1 + in.u8() % kMaxSegments;
  std::vector<std::optional<Primitive>> fitted(static_cast<std::size_t>(count));
  std::vector<SegmentSamples> samples(static_cast<std::size_t>(count));
  for (int s = 0; s < count; ++s) {
    const Primitive truth = part_primitive(in);
    SegmentSamples& ss = samples[std::size_t(s)];
    ss.points = points_on(in, int(truth.type) + 1, truth, kMaxPoints);
    ss.normals = Eigen::MatrixX3d::Zero(ss.points.rows(), 3);
    ss.weights = decode_weights(in, ss.points.rows());
    if (ss.weights.size() != ss.points.rows())
      ss.weights = Eigen::VectorXd::Ones(ss.points.rows());
    switch (in.u8() % 8) {
    case 0: break;  // free-form: no primitive
    case 1: fitted[std::size_t(s)] = fuzz_primitive(in); break;
    case 2: fitted[std::size_t(s)] = truth; break;
    default: fitted[std::size_t(s)] = perturbed(in, truth);
    }
  }
  std::vector<SegmentContact> contacts(in.u8() % 8);
  for (SegmentContact& c : contacts) {
    // Ids from -1 to count: one beyond each end.
    const int a = int(in.u8() % (count + 1));
    c.a = in.u8() % 8 == 0 ? a - 1 : a;
    c.b = int(in.u8() % (count + 1));
    c.pairs = 1 + in.u8();
    c.point = Eigen::Vector3d(in.special(2), in.special(2), in.special(2));
    c.mean = in.bit() ? c.point : Eigen::Vector3d(in.special(2), in.special(2), in.special(2));
    c.points.resize(in.u8() % 4);
    for (Eigen::Vector3d& p : c.points)
      p = Eigen::Vector3d(in.special(2), in.special(2), in.special(2));
  }
  const double noise = in.special(0.05);
  RelationOptions options;
  if (in.bit()) {
    options.angle_deg = in.special(45);
    options.distance = in.special(0.5);
    options.max_cost_increase = in.special(2);
  }
  std::vector<char> fixed;
  if (in.bit())
    for (int s = 0; s < count; ++s)
      fixed.push_back(char(in.u8() % 4 == 0));

  const RelatedPrimitives r = relate_primitives(fitted, samples, contacts, noise, options, fixed);
  FUZZ_CHECK(r.primitives.size() == fitted.size());
  if (!r.status.ok()) {
    FUZZ_CHECK(r.relations.empty());
    for (int s = 0; s < count; ++s)
      FUZZ_CHECK(r.primitives[std::size_t(s)].has_value() == fitted[std::size_t(s)].has_value() &&
                 (!fitted[std::size_t(s)] || same(*r.primitives[std::size_t(s)], *fitted[std::size_t(s)])));
    return 0;
  }
  FUZZ_CHECK(r.dropped >= 0 && std::isfinite(r.distance));
  auto related = [&](int s) {
    return s >= 0 && s < count && fitted[std::size_t(s)] && primitive_is_valid(*fitted[std::size_t(s)]) &&
           samples[std::size_t(s)].points.rows() > 0;
  };
  // The refit's own measure of a relation's violation: its residual, directions times the part's size.
  const double length = r.length;
  FUZZ_CHECK(std::isfinite(length) && length >= 0);
  for (const Relation& q : r.relations) {
    FUZZ_CHECK(q.a != q.b && related(q.a) && related(q.b));
    const Primitive& a = *r.primitives[std::size_t(q.a)];
    const Primitive& b = *r.primitives[std::size_t(q.b)];
    double residual[6] = {0, 0, 0, 0, 0, 0};
    const int n = relation_components(q, a, b);
    FUZZ_CHECK(n >= 1 && n <= 6);
    relation_residual(q, a, b, relation_frame(a), length, residual);
    for (int k = 0; k < n; ++k)
      FUZZ_CHECK(std::abs(residual[k]) <= 1e-5 * length);
  }
  for (int s = 0; s < count; ++s) {
    const std::optional<Primitive>& before = fitted[std::size_t(s)];
    const std::optional<Primitive>& after = r.primitives[std::size_t(s)];
    FUZZ_CHECK(before.has_value() == after.has_value());
    if (!related(s)) {
      FUZZ_CHECK(!before || same(*before, *after));
      continue;
    }
    FUZZ_CHECK(primitive_is_valid(*after) && after->type == before->type);
    if (std::size_t(s) < fixed.size() && fixed[std::size_t(s)])
      FUZZ_CHECK(same(*before, *after));
  }
  check_edge_blends(in, r.primitives, samples, contacts, noise);
  check_profiles(in, r.primitives, samples, noise);
  check_profiles_about_directions(in, r.primitives, samples, noise);
  check_blends_about_axis(in);
  return 0;
}
