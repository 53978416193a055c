#include "filter_primitive_fit.h"

#include "common/base/constants.h"
#include "common/base/describe_primitive.h"
#include "common/mesh/check_mesh_input.h"
#include "common/mesh/count_segments.h"
#include "common/mesh/surface_roughness_attribute.h"
#include "common/mesh/face_adjacency.h"
#include "common/mesh/gather_segment_samples.h"
#include "common/mesh/segment_attribute.h"
#include "common/pipeline/fit_all_segments.h"
#include "common/pipeline/fit_segment.h"
#include "common/pipeline/snap_onto_primitive.h"
#include "common/pipeline/write_fits_json.h"
#include "common/relate/describe_relation.h"
#include "common/snap/describe_snap_report.h"
#include "meshlab_api/load_segments.h"

#include <QFile>

#include <cmath>
#include <fstream>
#include <optional>

using namespace primitive_edit;
using namespace primitive_edit::meshlab;

namespace {

// Type parameter: index 0 is Auto, then PrimitiveType in order.
const QStringList kTypeNames = {"Auto", "Plane", "Sphere", "Cylinder", "Cone", "Torus"};

// Method parameter: FitMethod in order.
QStringList method_names()
{
  QStringList names;
  for (int i = 0; i < kFitMethodCount; ++i)
    names << fit_method_name(FitMethod(i));
  return names;
}

QString primitive_filter_name(int filter)
{
  switch (filter) {
  case PrimitiveFitFilters::PRIMITIVE_FIT_SEGMENT: return "Primitive: Fit Segment";
  case PrimitiveFitFilters::PRIMITIVE_SNAP_SEGMENT: return "Primitive: Snap Segment";
  case PrimitiveFitFilters::PRIMITIVE_FIT_ALL_SEGMENTS: return "Primitive: Fit All Segments";
  }
  return "";
}

QString snap_summary(const SnapReport& r)
{
  return QString::fromStdString(describe_snap_report(r));
}

} // namespace

QString PrimitiveFitFilters::pluginName() const { return "FilterPrimitiveFit"; }

std::vector<FilterDefinition> PrimitiveFitFilters::filters() const
{
  const QString method =
      "<br><br>Fitting starts algebraically (a sphere by the normalised algebraic fit that the type-constrained "
      "quadric fit of <i>J. Andrews, C. H. Séquin</i>, <b>\"Type-constrained direct fitting of quadric "
      "surfaces\"</b>, CAD&A 11(1), 2014, gives for that type; cylinder, cone and torus axes from the normals, "
      "estimated by a quadric fit when absent) and is refined on orthogonal distances, with outliers near the "
      "segment's border down-weighted. The segments come from "
      "the <i>Segment:</i> filters.";
  const auto def = [](int id, const char* python_name, int menus, int post, const QString& info) {
    FilterDefinition d;
    d.id = id;
    d.name = primitive_filter_name(id);
    d.python_name = python_name;
    d.info = info;
    d.menus = menus;
    d.preconditions = MeshModel::MM_FACENUMBER;
    d.postconditions = post;
    return d;
  };
  // Stored ids that are not dense are renumbered and written back (load_segments.h): quality and colours.
  const int ids = MeshModel::MM_FACEQUALITY | MeshModel::MM_FACECOLOR;
  const int moved = ids | MeshModel::MM_VERTCOORD | MeshModel::MM_VERTNORMAL | MeshModel::MM_FACENORMAL;
  return {
    def(PRIMITIVE_FIT_SEGMENT, "primitive_fit_segment", MenuMeasure, ids,
        "Fits a primitive (plane, sphere, cylinder, cone or torus; Auto picks the type) to a segment and "
           "logs its parameters (radius, axis, centre, half-angle...) with the RMS and maximum residual. Moves "
        "nothing." + method),
    def(PRIMITIVE_SNAP_SEGMENT, "primitive_snap_segment", MenuSmoothing | MenuMeasure, moved,
        "Fits a primitive to a segment, replaces the parameters you give (a value of 0 keeps the fitted "
           "one) and moves the segment's vertices to their closest point on the edited primitive: entering "
           "radius 5 where 4.8 was fitted makes a 5 mm hole. A cone's half-angle is changed about its apex.<br>"
           "With <i>Sharp Edges</i>, vertices shared with segments snapped before go to the intersection of "
           "the primitives (or their common point at corners), so blurred edges come out sharp; triangles are "
        "kept from flipping." + method),
    def(PRIMITIVE_FIT_ALL_SEGMENTS, "primitive_fit_all_segments", MenuSmoothing | MenuMeasure, moved,
        "Fits every segment with the type that explains it best (residual with a penalty for extra "
           "parameters); segments no primitive fits within the tolerance are free-form and left alone. "
           "Optionally snaps every fitted segment, with sharp edges and corners, and exports the primitives "
        "as JSON (id, type, parameters, RMS, point count, area) for CAD." + method),
  };
}

void PrimitiveFitFilters::parameters(int id, MeshDocument&, ParameterList& parlst) const
{
  if (id == PRIMITIVE_FIT_SEGMENT || id == PRIMITIVE_SNAP_SEGMENT) {
    parlst.addInt("Segment", -1, "Segment",
                            "Id of the segment; -1 takes the selected faces.");
    parlst.addEnum("Type", 0, kTypeNames, "Type",
                             "The primitive to fit; Auto picks the type that explains the points best.");
    parlst.addEnum("Method", 0, method_names(), "Method",
                             "Refined starts: several starts (algebraic, from normals, principal axes) refined "
                             "on orthogonal distances with robust weights; the most accurate on rough and "
                             "partial patches. Direct (paper): Andrews and Sequin's type-constrained direct "
                             "quadric fit, as the paper estimates a segment's quadric; exact on exact data, "
                             "biased by noise and outliers. Direct, refined: that fit refined geometrically. "
                             "A torus is not a quadric and always takes the refined starts.");
  }
  if (id == PRIMITIVE_SNAP_SEGMENT) {
    parlst.addFloat("Radius", 0, "Radius",
                              "New radius of a sphere or cylinder; 0 keeps the fitted radius.");
    parlst.addFloat("Angle", 0, "Cone Half-Angle (degrees)",
                              "New half-angle of a cone, between 0 and 90, about its apex; 0 keeps the fitted one.");
    parlst.addFloat("MajorRadius", 0, "Major Radius",
                              "New major radius of a torus (axis to tube centre); 0 keeps the fitted one.");
    parlst.addFloat("MinorRadius", 0, "Minor Radius",
                              "New minor (tube) radius of a torus; 0 keeps the fitted one.");
  }
  if (id == PRIMITIVE_FIT_ALL_SEGMENTS) {
    parlst.addFloat("Tolerance", 0, "Fit Tolerance",
                              "Largest RMS residual, in mesh units, for a segment to count as a primitive; "
                              "0 uses the larger of 1% of each segment's size and 3 times the scan's "
                              "roughness (the RMS of the surface about local planes, estimated here).");
    parlst.addBool("Relations", true, "Relations",
                             "Find the relations a machined part's primitives share (parallel, perpendicular "
                             "and 45 degree faces, coaxial and concentric features, coplanar faces, equal radii, "
                             "fillets tangent to the faces they round) and refit all primitives together under "
                             "them. A relation is kept only if it raises no segment's fit error by more than "
                             "Relation Cost; tilted or free features stay as fitted. Then a sphere, cone or torus "
                             "turning about a cylinder's axis (a boss's fillet about its bore) is refitted about "
                             "that axis as the type its profile is, and a segment lying between "
                             "two planes, along their edge, becomes the fillet (cylinder) or chamfer (plane) "
                             "tangent to both, where its borders with them lie, when that explains it as well as "
                             "its own fit.");
    parlst.addFloat("RelationAngle", 10, "Relation Angle (degrees)",
                              "Directions within this angle of parallel, perpendicular or 45 degrees are "
                              "tested as related (between 0 and 90).");
    parlst.addFloat("RelationDistance", 0, "Relation Distance",
                              "Axes, centres and planes within this distance, in mesh units, are tested as "
                              "coaxial, concentric or coplanar, radii within it as equal; 0 uses 3 times the "
                              "scan's roughness.");
    parlst.addFloat("RelationCost", RelationOptions().max_cost_increase, "Relation Cost",
                              "The largest rise of a segment's fit error (sum of squared distances), as a share "
                              "of it, that the relations may cause: 1 lets it double (RMS x 1.41), which the "
                              "roughness of a scan explains; a deliberately tilted or offset feature costs far "
                              "more and keeps its own fit.");
    parlst.addBool("Snap", true, "Snap Segments",
                             "Move every fitted segment onto its primitive.");
    parlst.addString("Export", "", "Export JSON",
                               "File to write the fitted primitives to, as JSON; empty writes nothing.");
  }
  if (id != PRIMITIVE_FIT_SEGMENT)
    parlst.addBool("SharpEdges", true, "Sharp Edges",
                             "Vertices shared by snapped segments go to the intersection of their primitives "
                             "(edges) or their common point (corners).");
}

Status PrimitiveFitFilters::apply(int id, FilterRun& run)
{
  MeshModel& mm = run.mesh;
  if (const Status usable = check_mesh_input(mm.cm); !usable)
    return fail(primitive_filter_name(id), usable);
  switch (id) {
  case PRIMITIVE_FIT_SEGMENT: return fitOrSnapSegment(mm, run.arguments, false, run);
  case PRIMITIVE_SNAP_SEGMENT: return fitOrSnapSegment(mm, run.arguments, true, run);
  case PRIMITIVE_FIT_ALL_SEGMENTS: return fitAllSegments(mm, run.arguments, run);
  }
  return fail("Unknown filter.");
}

Status PrimitiveFitFilters::fitOrSnapSegment(MeshModel& mm, const Arguments& parlst, bool snap, Run& run)
{
  const QString name = snap ? "Primitive: Snap Segment" : "Primitive: Fit Segment";
  CMeshO& m = mm.cm;
  const int segment = parlst.getInt("Segment");
  const int type_index = parlst.getEnum("Type");
  if (type_index < 0 || type_index > kPrimitiveTypeCount)
    return fail(name + QString(": Type %1 does not exist.").arg(type_index));
  const int method_index = parlst.getEnum("Method");
  if (method_index < 0 || method_index >= kFitMethodCount)
    return fail(name + QString(": Method %1 does not exist.").arg(method_index));

  const LoadedSegments loaded = read_segments(mm);
  const bool segmented = loaded.found;
  std::vector<int> segment_of_face = loaded.segment_of_face;
  const int count = segmented ? count_segments(segment_of_face) : 0;
  // The faces to fit carry label `target`: an existing segment, or a new id for the selected faces.
  std::vector<int> labels = segment_of_face;
  int target = segment;
  if (segment == -1) {
    target = count;
    int selected = 0;
    for (size_t i = 0; i < m.face.size(); ++i)
      if (!m.face[i].IsD() && m.face[i].IsS()) {
        labels[i] = target;
        ++selected;
      }
    if (selected == 0)
      return fail(name + ": Segment is -1 but no face is selected; select faces or give a segment id.");
  } else if (!segmented) {
    return fail(name + ": the mesh has no segments; run Segment: Auto by Normal Angle first, or select faces "
                       "and use Segment -1.");
  } else if (segment < 0 || segment >= count) {
    return fail(name + QString(": there is no segment %1; ids go from 0 to %2.").arg(segment).arg(count - 1));
  }
  const QString what = segment == -1 ? QString("the selected faces") : QString("segment %1").arg(segment);

  std::vector<int> faces;
  for (size_t f = 0; f < labels.size(); ++f)
    if (labels[f] == target)
      faces.push_back(int(f));
  const SegmentSamples samples = gather_face_samples(m, faces);
  AutoFitOptions options;
  options.fit.method = FitMethod(method_index);
  if (type_index == 0) {  // as in Fit All: a segment of a rough scan is a primitive within the scan's roughness
    options.roughness = surface_roughness(m);
  }
  const std::optional<PrimitiveType> type =
      type_index == 0 ? std::nullopt : std::optional<PrimitiveType>(PrimitiveType(type_index - 1));
  const FitResult fit = fit_segment(samples, type, options);
  if (!fit.status.ok())
    return fail(name + ": " + what + (type ? " cannot be fitted" : " fits no primitive"), fit.status);
  run.logf("%s: %s (%d points, area %.6g): %s; RMS %.4g, max residual %.4g; method: %s.", qUtf8Printable(name),
      qUtf8Printable(what), fit.point_count, samples.area, describe_primitive(fit.primitive).c_str(), fit.rms,
      fit.max_residual, fit_method_name(options.fit.method));
  if (!snap) {
    keep_segment_ids(run, name, loaded);
    return Status::success();
  }

  Primitive edited = fit.primitive;
  const double radius = parlst.getFloat("Radius"), angle = parlst.getFloat("Angle");
  const double major = parlst.getFloat("MajorRadius"), minor = parlst.getFloat("MinorRadius");
  if (!std::isfinite(radius) || !std::isfinite(angle) || !std::isfinite(major) || !std::isfinite(minor))
    return fail(name + ": the parameter overrides must be finite numbers.");
  if (radius > 0 && (edited.type == PrimitiveType::Sphere || edited.type == PrimitiveType::Cylinder))
    edited.radius = radius;
  if (angle > 0) {
    if (angle >= 90)
      return fail(name + QString(": a cone half-angle must be below 90 degrees, not %1.").arg(angle));
    if (edited.type == PrimitiveType::Cone)
      edited.half_angle = radians_from_degrees(angle);
  }
  if (edited.type == PrimitiveType::Torus) {
    edited.radius = major > 0 ? major : edited.radius;
    edited.minor_radius = minor > 0 ? minor : edited.minor_radius;
  }
  if (!primitive_is_valid(edited))
    return fail(name + ": the edited primitive is not valid: " + QString::fromStdString(describe_primitive(edited)));

  SnapOptions snap_options;
  snap_options.sharp_edges = parlst.getBool("SharpEdges");
  keep_segment_ids(run, name, loaded);
  const SnapReport report = snap_onto_primitive(m, labels, {target}, edited, snap_options, count);
  run.logf("%s: %s snapped onto %s; %s.", qUtf8Printable(name), qUtf8Printable(what),
      describe_primitive(edited).c_str(), qUtf8Printable(snap_summary(report)));
  return Status::success();
}

Status PrimitiveFitFilters::fitAllSegments(MeshModel& mm, const Arguments& parlst, Run& run)
{
  const QString name = "Primitive: Fit All Segments";
  FitAllSegmentsOptions options;
  options.tolerance = parlst.getFloat("Tolerance");
  options.relations = parlst.getBool("Relations");
  options.relation_options.angle_deg = parlst.getFloat("RelationAngle");
  options.relation_options.distance = parlst.getFloat("RelationDistance");
  options.relation_options.max_cost_increase = parlst.getFloat("RelationCost");
  options.snap = parlst.getBool("Snap");
  options.snap_options.sharp_edges = parlst.getBool("SharpEdges");
  const QString path = parlst.getString("Export").trimmed();
  if (!std::isfinite(options.tolerance) || options.tolerance < 0)
    return fail(name + QString(": Fit Tolerance must be 0 (automatic) or positive, not %1.").arg(options.tolerance));
  const double angle = options.relation_options.angle_deg, distance = options.relation_options.distance;
  if (!(angle > 0 && angle < 90))
    return fail(name + QString(": Relation Angle must be between 0 and 90 degrees, not %1.").arg(angle));
  if (!std::isfinite(distance) || distance < 0)
    return fail(name + QString(": Relation Distance must be 0 (automatic) or positive, not %1.").arg(distance));
  const double cost = options.relation_options.max_cost_increase;
  if (!(cost > 0) || !std::isfinite(cost))
    return fail(name + QString(": Relation Cost must be positive, not %1.").arg(cost));
  const LoadedSegments loaded = read_segments(mm);
  if (!loaded.found)
    return fail(name + ": the mesh has no segments; run Segment: Auto by Primitive Fit first.");
  const std::vector<int>& segment_of_face = loaded.segment_of_face;
  std::ofstream file;
  if (!path.isEmpty()) {
    file.open(QFile::encodeName(path).toStdString(), std::ios::out | std::ios::trunc);
    if (!file)
      return fail(name + ": cannot write the export file " + path + ".");
  }

  const FitAllSegmentsResult r = fit_all_segments(mm.cm, segment_of_face, options, run.progress);
  if (!r.status.ok())
    return fail(name, r.status);
  keep_segment_ids(run, name, loaded);
  if (options.tolerance == 0)
    run.logf("%s: estimated surface roughness %.4g (RMS about local planes): segments within %.4g RMS of a primitive "
        "(or 1%% of their size) are fitted.",
        qUtf8Printable(name), r.roughness, 3 * r.roughness);
  for (int s = 0; s < r.segment_count() && s < 100; ++s) {
    const FitResult& fit = r.fits[size_t(s)];
    if (fit.status.ok())
      run.logf("  segment %d: %s; RMS %.4g, %d points", s, describe_primitive(fit.primitive).c_str(), fit.rms,
          fit.point_count);
    else
      run.logf("  segment %d: free-form (%s)", s, fit.status.error.c_str());
  }
  run.logf("%s: %d of %d segments fitted (%.1f%% of the area): %d planes, %d spheres, %d cylinders, %d cones, %d tori; "
      "%d free-form. Fitting took %.0f ms.",
      qUtf8Printable(name), r.fitted, r.segment_count(), r.total_area > 0 ? 100.0 * r.fitted_area / r.total_area : 0.0,
      r.per_type[0], r.per_type[1], r.per_type[2], r.per_type[3], r.per_type[4], r.segment_count() - r.fitted,
      1000 * r.fit_seconds);
  if (options.relations)
    logRelations(name, r, run);
  if (!path.isEmpty()) {
    write_fits_json(file, r, mm.label().toStdString(), options.snap);
    file.close();
    if (!file)
      return fail(name + ": writing the export file " + path + " failed.");
    run.logf("%s: primitives exported to %s.", qUtf8Printable(name), qUtf8Printable(path));
  }
  if (r.snap) {
      run.logf("%s: %d segments snapped; %s. Snapping took %.0f ms.", qUtf8Printable(name), r.fitted,
        qUtf8Printable(snap_summary(*r.snap)), 1000 * r.snap_seconds);
  }
  return Status::success();
}

void PrimitiveFitFilters::logRelations(const QString& name, const FitAllSegmentsResult& r, Run& run)
{
  int per_kind[kRelationKindCount] = {};
  for (const Relation& relation : r.relations)
    ++per_kind[int(relation.kind)];
  QString counts;
  for (int k = 0; k < kRelationKindCount; ++k)
    if (per_kind[k] > 0)
      counts += QString("%1%2 %3").arg(counts.isEmpty() ? ": " : ", ").arg(per_kind[k]).arg(
          relation_kind_name(RelationKind(k)));
  run.logf("%s: %d relations kept%s (%d found but dropped: they raised a segment's fit error too much). "
      "Refitting under them took %.0f ms.", qUtf8Printable(name), int(r.relations.size()), qUtf8Printable(counts),
      r.relations_dropped, 1000 * r.relation_seconds);
  for (std::size_t i = 0; i < r.relations.size() && i < 100; ++i)
    run.logf("  relation: %s", describe_relation(r.relations[i], r.primitives).c_str());
  if (!r.profiles_about_directions.empty())
    run.logf("%s: %d curved segments whose axis followed none of the part's directions fitted about one:",
        qUtf8Printable(name), int(r.profiles_about_directions.size()));
  for (std::size_t i = 0; i < r.profiles_about_directions.size() && i < 100; ++i) {
    const SegmentProfile& q = r.profiles_about_directions[i];
    run.logf("  segment %d, along the normal of segment %d: %s", q.segment, q.axis_segment,
        describe_primitive(q.primitive).c_str());
  }
  if (!r.profiles.empty())
    run.logf("%s: %d segments turning about a cylinder segment's axis fitted about it:", qUtf8Printable(name),
        int(r.profiles.size()));
  for (std::size_t i = 0; i < r.profiles.size() && i < 100; ++i)
    run.logf("  segment %d, about the axis of segment %d: %s", r.profiles[i].segment, r.profiles[i].axis_segment,
        describe_primitive(r.profiles[i].primitive).c_str());
  if (r.blends.empty())
    return;
  run.logf("%s: %d segments between two planes, or a plane and a cylinder or cone turning about its normal, fitted "
      "as the fillet or chamfer tangent to both:", qUtf8Printable(name), int(r.blends.size()));
  for (std::size_t i = 0; i < r.blends.size() && i < 100; ++i) {
    const SegmentEdgeBlend& b = r.blends[i];
    const char* about = b.meridian ? " (about the axis of the second)" : "";
    if (b.form == BlendForm::Fillet)
      run.logf("  segment %d: fillet of segments %d and %d%s, radius %.4g", b.segment, b.plane_a, b.plane_b, about,
          b.primitive.type == PrimitiveType::Torus ? b.primitive.minor_radius : b.primitive.radius);
    else
      run.logf("  segment %d: chamfer of segments %d and %d%s, %.4g from their edge", b.segment, b.plane_a,
          b.plane_b, about, b.setback);
  }
}
