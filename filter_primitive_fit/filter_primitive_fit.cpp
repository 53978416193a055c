#include "filter_primitive_fit.h"

#include "common/base/constants.h"
#include "common/mesh/count_segments.h"
#include "common/base/describe_primitive.h"
#include "common/mesh/estimate_surface_roughness.h"
#include "common/mesh/face_adjacency.h"
#include "common/fit/fit_primitive.h"
#include "common/fit/fit_primitive_auto.h"
#include "common/pipeline/fit_segments_auto.h"
#include "common/mesh/gather_segment_samples.h"
#include "common/mesh/mesh_input_problem.h"
#include "common/fit/minimum_points_for.h"
#include "common/mesh/segment_attribute.h"
#include "common/mesh/segment_primitive_attribute.h"
#include "common/snap/snap_segments.h"

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>

#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <numeric>
#include <cmath>

using namespace primitive_edit;
using namespace primitive_edit::meshlab;

namespace {

// Type parameter: index 0 is Auto, then PrimitiveType in order.
const QStringList kTypeNames = {"Auto", "Plane", "Sphere", "Cylinder", "Cone", "Torus"};

QJsonArray json_vector(const Eigen::Vector3d& v) { return QJsonArray{v.x(), v.y(), v.z()}; }

QJsonObject json_parameters(const Primitive& p)
{
  switch (p.type) {
  case PrimitiveType::Plane:
    return {{"normal", json_vector(p.axis)}, {"offset", p.axis.dot(p.origin)}, {"point", json_vector(p.origin)}};
  case PrimitiveType::Sphere: return {{"center", json_vector(p.origin)}, {"radius", p.radius}};
  case PrimitiveType::Cylinder:
    return {{"axis_point", json_vector(p.origin)}, {"axis", json_vector(p.axis)}, {"radius", p.radius}};
  case PrimitiveType::Cone:
    return {{"apex", json_vector(p.origin)}, {"axis", json_vector(p.axis)}, {"half_angle_deg", degrees_from_radians(p.half_angle)}};
  case PrimitiveType::Torus:
    return {{"center", json_vector(p.origin)}, {"axis", json_vector(p.axis)}, {"major_radius", p.radius},
            {"minor_radius", p.minor_radius}};
  }
  return {};
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

void update_geometry(MeshModel& mm)
{
  // PerVertexNormalizedPerFace recomputes face normals unnormalised: normalise them after it.
  vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(mm.cm);
  vcg::tri::UpdateNormal<CMeshO>::PerFaceNormalized(mm.cm);
  vcg::tri::UpdateBounding<CMeshO>::Box(mm.cm);
}

QString snap_summary(const SnapReport& r)
{
  return QString("%1 vertices moved (%2 onto edges, %3 onto corners, %4 held back to keep triangles from "
                 "flipping), mean displacement %5, max %6")
      .arg(r.moved_vertices).arg(r.edge_vertices).arg(r.corner_vertices).arg(r.reverted_vertices)
      .arg(r.mean_displacement, 0, 'g', 4).arg(r.max_displacement, 0, 'g', 4);
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
  const int moved = MeshModel::MM_VERTCOORD | MeshModel::MM_VERTNORMAL | MeshModel::MM_FACENORMAL;
  return {
    def(PRIMITIVE_FIT_SEGMENT, "primitive_fit_segment", MenuMeasure, MeshModel::MM_NONE,
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
  const std::string problem = mesh_input_problem(mm.cm);
  if (!problem.empty())
    return fail(primitive_filter_name(id) + ": " + QString::fromStdString(problem) + ".");
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

  std::vector<int> segment_of_face;
  const bool segmented = read_segment_ids(m, segment_of_face);
  const int count = segmented ? count_segments(segment_of_face) : 0;
  if (!segmented)
    segment_of_face.assign(m.face.size(), -1);
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

  const SegmentSamples samples = std::move(gather_segment_samples(m, labels, target + 1)[size_t(target)]);
  FitResult fit;
  if (type_index == 0) {
    // As in Fit All: a segment of a rough scan is a primitive within the scan's roughness.
    AutoFitOptions options;
    options.roughness = estimate_surface_roughness(m, build_face_adjacency(m));
    const AutoFitResult automatic = fit_primitive_auto(samples.points, samples.normals, samples.weights, options);
    if (!automatic.ok)
      return fail(name + ": " + what + (segment == -1 ? " fit" : " fits") + " no primitive: " +
                  QString::fromStdString(automatic.message));
    fit = automatic.best;
  } else {
    const PrimitiveType type = PrimitiveType(type_index - 1);
    if (samples.points.rows() < minimum_points_for(type))
      return fail(name + QString(": %1 has %2 points; a %3 needs at least %4.")
                             .arg(what).arg(samples.points.rows()).arg(primitive_type_name(type))
                             .arg(minimum_points_for(type)));
    fit = fit_primitive(type, samples.points, samples.normals, samples.weights);
    if (!fit.ok)
      return fail(name + ": " + what + " cannot be fitted: " + QString::fromStdString(fit.message));
  }
  run.logf("%s: %s (%d points, area %.6g): %s; RMS %.4g, max residual %.4g.", qUtf8Printable(name),
      qUtf8Printable(what), fit.point_count, samples.area, describe_primitive(fit.primitive).c_str(), fit.rms,
      fit.max_residual);
  if (!snap)
    return Status::success();

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

  SnapOptions options;
  options.sharp_edges = parlst.getBool("SharpEdges");
  SegmentPrimitives recorded = read_segment_primitives(m, count);
  SegmentPrimitives primitives(size_t(std::max(count, target + 1)));
  if (options.sharp_edges)
    std::copy(recorded.begin(), recorded.end(), primitives.begin());
  primitives[size_t(target)] = edited;
  const SnapReport report = snap_segments(m, labels, primitives, options);
  if (segment >= 0) {
    recorded[size_t(segment)] = edited;
    write_segment_primitives(m, recorded);
  }
  update_geometry(mm);
  run.logf("%s: %s snapped onto %s; %s.", qUtf8Printable(name), qUtf8Printable(what),
      describe_primitive(edited).c_str(), qUtf8Printable(snap_summary(report)));
  return Status::success();
}

Status PrimitiveFitFilters::fitAllSegments(MeshModel& mm, const Arguments& parlst, Run& run)
{
  const Progress& progress = run.progress;
  const QString name = "Primitive: Fit All Segments";
  CMeshO& m = mm.cm;
  const double tolerance = parlst.getFloat("Tolerance");
  const bool snap = parlst.getBool("Snap");
  const QString path = parlst.getString("Export").trimmed();
  if (!std::isfinite(tolerance) || tolerance < 0)
    return fail(name + QString(": Fit Tolerance must be 0 (automatic) or positive, not %1.").arg(tolerance));
  std::vector<int> segment_of_face;
  if (!read_segment_ids(m, segment_of_face))
    return fail(name + ": the mesh has no segments; run Segment: Auto by Normal Angle first.");
  QFile file(path);
  if (!path.isEmpty() && !file.open(QIODevice::WriteOnly | QIODevice::Truncate))
    return fail(name + ": cannot write the export file " + path + ": " + file.errorString());

  QElapsedTimer timer;
  timer.start();
  const int count = count_segments(segment_of_face);
  const std::vector<SegmentSamples> samples = gather_segment_samples(m, segment_of_face, count);
  AutoFitOptions options;
  options.tolerance = tolerance;
  if (tolerance == 0) {
    options.roughness = estimate_surface_roughness(m, build_face_adjacency(m));
    run.logf("%s: estimated surface roughness %.4g (RMS about local planes): segments within %.4g RMS of a primitive "
        "(or 1%% of their size) are fitted.",
        qUtf8Printable(name), options.roughness, 3 * options.roughness);
  }
  const std::vector<AutoFitResult> fits =
      fit_segments_auto(samples, options, 0, progress_range(progress, 0, snap ? 80 : 100));
  SegmentPrimitives primitives(static_cast<size_t>(count));
  int per_type[kPrimitiveTypeCount] = {0, 0, 0, 0, 0};
  double fitted_area = 0, total_area = 0;
  for (int s = 0; s < count; ++s) {
    total_area += samples[size_t(s)].area;
    const AutoFitResult& fit = fits[size_t(s)];
    if (fit.ok) {
      primitives[size_t(s)] = fit.best.primitive;
      ++per_type[int(fit.best.primitive.type)];
      fitted_area += samples[size_t(s)].area;
    }
  }
  const qint64 fit_ms = timer.elapsed();

  if (!path.isEmpty()) {
    QJsonArray segments;
    for (int s = 0; s < count; ++s) {
      const AutoFitResult& fit = fits[size_t(s)];
      QJsonObject o{{"id", s}, {"point_count", int(samples[size_t(s)].points.rows())},
                    {"area", samples[size_t(s)].area}};
      if (fit.ok) {
        o["type"] = primitive_type_name(fit.best.primitive.type);
        o["parameters"] = json_parameters(fit.best.primitive);
        o["rms"] = fit.best.rms;
        o["max_residual"] = fit.best.max_residual;
      } else {
        o["type"] = "FreeForm";
        o["reason"] = QString::fromStdString(fit.message);
      }
      segments.append(o);
    }
    const QJsonObject doc{{"mesh", mm.label()}, {"segment_count", count}, {"snapped", snap}, {"segments", segments}};
    file.write(QJsonDocument(doc).toJson());
    file.close();
  }

  for (int s = 0; s < count && s < 100; ++s) {
    const AutoFitResult& fit = fits[size_t(s)];
    if (fit.ok)
      run.logf("  segment %d: %s; RMS %.4g, %d points", s, describe_primitive(fit.best.primitive).c_str(), fit.best.rms,
          fit.best.point_count);
    else
      run.logf("  segment %d: free-form (%s)", s, fit.message.c_str());
  }
  const int fitted = std::accumulate(per_type, per_type + kPrimitiveTypeCount, 0);
  run.logf("%s: %d of %d segments fitted (%.1f%% of the area): %d planes, %d spheres, %d cylinders, %d cones, %d tori; "
      "%d free-form. Fitting took %lld ms.",
      qUtf8Printable(name), fitted, count, total_area > 0 ? 100.0 * fitted_area / total_area : 0.0, per_type[0],
      per_type[1], per_type[2], per_type[3], per_type[4], count - fitted, fit_ms);
  if (!path.isEmpty())
    run.logf("%s: primitives exported to %s.", qUtf8Printable(name), qUtf8Printable(path));
  if (!snap)
    return Status::success();

  report_progress(progress, 85, "Snapping segments");
  timer.restart();
  SnapOptions snap_options;
  snap_options.sharp_edges = parlst.getBool("SharpEdges");
  const SnapReport report = snap_segments(m, segment_of_face, primitives, snap_options);
  write_segment_primitives(m, primitives);
  update_geometry(mm);
  run.logf("%s: %d segments snapped; %s. Snapping took %lld ms.", qUtf8Printable(name), fitted,
      qUtf8Printable(snap_summary(report)), timer.elapsed());
  return Status::success();
}
