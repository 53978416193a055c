#include "filter_segment.h"

#include "common/mesh/count_segments.h"
#include "common/mesh/face_adjacency.h"
#include "common/segment/describe_carved_blends.h"
#include "common/segment/merge_segments.h"
#include "common/mesh/check_mesh_input.h"
#include "common/segment/move_faces_to_new_segment.h"
#include "common/mesh/segment_attribute.h"
#include "common/segment/segment_by_normal_angle.h"
#include "common/segment/segment_by_primitive_growing.h"
#include "common/mesh/segment_primitive_attribute.h"
#include "common/mesh/segment_blends_attribute.h"
#include "common/mesh/surface_roughness_attribute.h"
#include "common/segment/split_segments_by_plane.h"
#include "meshlab_api/load_segments.h"

#include <QElapsedTimer>

#include <algorithm>
#include <cmath>
#include <set>

using namespace primitive_edit;
using namespace primitive_edit::meshlab;

namespace {

// The segments of a mesh, or one segment holding every live face when it has none yet: the merge and
// split filters then work on an unsegmented mesh as on a one-segment one.
bool segments_or_whole_mesh(CMeshO& m, std::vector<int>& segment_of_face)
{
  if (read_segment_ids(m, segment_of_face))
    return true;
  segment_of_face.assign(m.face.size(), -1);
  for (size_t i = 0; i < m.face.size(); ++i)
    if (!m.face[i].IsD())
      segment_of_face[i] = 0;
  return false;
}

std::vector<int> selected_faces(const CMeshO& m)
{
  std::vector<int> faces;
  for (size_t i = 0; i < m.face.size(); ++i)
    if (!m.face[i].IsD() && m.face[i].IsS())
      faces.push_back(int(i));
  return faces;
}

std::vector<int> segments_of_faces(const std::vector<int>& segment_of_face, const std::vector<int>& faces)
{
  std::set<int> segments;
  for (int f : faces)
    if (segment_of_face[f] >= 0)
      segments.insert(segment_of_face[f]);
  return std::vector<int>(segments.begin(), segments.end());
}

} // namespace

QString SegmentFilters::pluginName() const { return "FilterSegment"; }

namespace {

QString segment_filter_name(int filter)
{
  switch (filter) {
  case SegmentFilters::SEGMENT_AUTO: return "Segment: Auto by Normal Angle";
  case SegmentFilters::SEGMENT_AUTO_PRIMITIVE: return "Segment: Auto by Primitive Fit";
  case SegmentFilters::SEGMENT_MERGE_SELECTED: return "Segment: Merge Selected";
  case SegmentFilters::SEGMENT_SPLIT_BY_PLANE: return "Segment: Split by Plane";
  case SegmentFilters::SEGMENT_SPLIT_BY_SELECTION: return "Segment: Split by Selection";
  case SegmentFilters::SEGMENT_SELECT: return "Segment: Select Segment";
  }
  return "";
}

QString segment_filter_info(int filter)
{
  const QString storage =
      "<br><br>The segment of each face is kept in the per-face attribute <i>SegmentId</i>, mirrored into face "
      "quality (save it with the PLY's face quality to keep it) and shown as face colour, neighbours in "
      "different colours. Ids are dense, from 0.";
  switch (filter) {
  case SegmentFilters::SEGMENT_AUTO:
    return "Splits the mesh into segments by shape: a flood fill over adjacent faces, where two neighbouring "
           "faces join the same segment when the angle between their normals is below <i>Angle</i>. A smaller "
           "angle gives more segments.<br>Raw scans have noisy normals: they are first smoothed over the "
           "surface, by default as much as the measured noise needs; on a noisy scan the fill then stops at "
           "faces where the smoothed normal turns as across an edge, and those faces go to the neighbouring "
           "segment with the closest normal. Segments smaller than <i>Min Segment Size</i> (by default a share "
           "of the faces) are absorbed by the neighbour they share the longest border with.<br><br>"
           "See: <i>J. Yang, K. Oh, H.-I. Choi</i>, <b>\"Mesh Editing "
           "with an Intuitive User Interface\"</b>, section 2.1." + storage;
  case SegmentFilters::SEGMENT_AUTO_PRIMITIVE:
    return "Splits a scan into segments that each fit one primitive (plane, sphere, cylinder, cone, torus), for "
           "scans whose blurred edges and fillets change the normal so gradually that <i>Auto by Normal "
           "Angle</i> walks across them. From the flattest faces, a patch is fitted and grown over the faces "
           "within <i>Tolerance</i> of its primitive whose normals agree with it, refitting as it grows; "
           "regions curved tighter than a seed patch (edges rounded by the scanner) are dissolved, and the "
           "faces left over go to the neighbouring region whose primitive is nearest, which splits a blurred "
           "edge at its bisector. Then the fillets and chamfers that the roughness hid in the two planes they "
           "join become segments of their own (Carve Fillets and Chamfers), which Fit All Segments makes the "
           "blends of those planes. They are kept on the mesh while the vertices, the blend's faces and its "
           "planes' stay as they are (merging or splitting other segments keeps them), not in a saved file: "
           "run Fit All Segments before saving." + storage;
  case SegmentFilters::SEGMENT_MERGE_SELECTED:
    return "Every segment touched by the face selection becomes one segment." + storage;
  case SegmentFilters::SEGMENT_SPLIT_BY_PLANE:
    return "Cuts a segment (or the segments of the selected faces) by a plane: the faces on each side, and "
           "each connected piece of them, become segments of their own. A face goes to the side of its "
           "centroid; a piece of fewer than " + QString::number(kMinSplitPieceFaces) + " faces (a sliver where "
           "the plane grazes the surface) joins the neighbouring piece of its segment. The batch form of drawing "
           "a split line in the edit tool." + storage;
  case SegmentFilters::SEGMENT_SPLIT_BY_SELECTION:
    return "The selected faces leave their segments and form one new segment." + storage;
  case SegmentFilters::SEGMENT_SELECT:
    return "Selects the faces (and their vertices) of one segment, so that later filters act on it.";
  }
  return "";
}

} // namespace

std::vector<FilterDefinition> SegmentFilters::filters() const
{
  const int segments_changed = MeshModel::MM_FACECOLOR | MeshModel::MM_FACEQUALITY;
  const auto def = [&](int id, const char* python_name, int menus, int post) {
    FilterDefinition d;
    d.id = id;
    d.name = segment_filter_name(id);
    d.python_name = python_name;
    d.info = segment_filter_info(id);
    d.menus = menus;
    d.preconditions = MeshModel::MM_FACENUMBER;
    d.postconditions = post;
    return d;
  };
  return {
      def(SEGMENT_AUTO, "segment_auto_by_normal_angle", MenuFaceColoring, segments_changed),
      def(SEGMENT_AUTO_PRIMITIVE, "segment_auto_by_primitive_fit", MenuFaceColoring, segments_changed),
      def(SEGMENT_MERGE_SELECTED, "segment_merge_selected", MenuFaceColoring, segments_changed),
      def(SEGMENT_SPLIT_BY_PLANE, "segment_split_by_plane", MenuFaceColoring, segments_changed),
      def(SEGMENT_SPLIT_BY_SELECTION, "segment_split_by_selection", MenuFaceColoring, segments_changed),
      def(SEGMENT_SELECT, "segment_select", MenuSelection, MeshModel::MM_FACEFLAGSELECT | MeshModel::MM_VERTFLAGSELECT),
  };
}

void SegmentFilters::parameters(int id, MeshDocument& document, ParameterList& parlst) const
{
  const SegmentByNormalAngleParams defaults;
  switch (id) {
  case SEGMENT_AUTO:
    parlst.addFloat("Angle", defaults.angle_deg, "Angle (degrees)",
                              "Two neighbouring faces join the same segment when the angle between their "
                              "(smoothed) normals is below this. Smaller gives more segments. Range 0-180.");
    parlst.addInt("NormalSmoothing", defaults.smoothing_iterations, "Normal Smoothing Steps",
                            "Passes of face normal averaging over neighbours before the fill. -1 (default): "
                            "automatic: 2 passes on a mesh without measurable noise; on a noisy scan as many "
                            "as its noise needs (measured against the triangle size), and the fill then stops "
                            "at faces where the normal turns as across an edge of the Angle; those faces go to "
                            "the neighbouring segment with the closest normal. 0 to 1000: that many passes "
                            "that skip neighbours beyond twice the Angle (at most 80 degrees), the paper's "
                            "method; 0 uses the raw face normals.");
    parlst.addInt("MinSegmentFaces", defaults.min_segment_faces, "Min Segment Size (faces)",
                            "Segments with fewer faces are absorbed by the neighbouring segment they share "
                            "the longest border with. -1 (default): automatic, 1/2000 of the faces (at least "
                            "30, and after noise-scaled smoothing at least 10 per pass). 0 or 1 keeps every "
                            "segment.");
    break;
  case SEGMENT_AUTO_PRIMITIVE: {
    const SegmentByPrimitiveGrowingParams growing;
    parlst.addFloat("Tolerance", growing.tolerance, "Tolerance",
                              "A face joins a primitive when it is this close to it, in mesh units; 0 estimates "
                              "it from the scan's roughness.");
    parlst.addFloat("NormalAngle", growing.normal_angle_deg, "Normal Angle (degrees)",
                              "...and when its smoothed normal is within this angle of the primitive's (1 to 89).");
    parlst.addInt("SeedPatchFaces", growing.seed_patch_faces, "Seed Patch Size (faces)",
                            "Faces of the patch each region starts from; regions curved tighter than such a "
                            "patch are taken for rounded edges (at least 8).");
    parlst.addInt("NormalSmoothing", growing.smoothing_iterations, "Normal Smoothing Steps",
                            "Passes of face normal averaging against scan noise.");
    parlst.addBool("CarveBlends", growing.carve_blends, "Carve Fillets and Chamfers",
                   "Fillets and chamfers that the scan's roughness hid in the two planes they join become "
                   "segments of their own, when the faces about the edge are clearly likelier under a blend "
                   "than under a sharp edge; Fit All Segments then makes them the blends of their planes. "
                   "Waves of the roughness as long as a blend can read as one: turn it off on such a scan.");
    break;
  }
  case SEGMENT_SPLIT_BY_PLANE:
    parlst.addInt("Segment", -1, "Segment",
                            "Id of the segment to cut; -1 cuts the segments of the selected faces.");
    {
      const Point3m centre = document.mm() != nullptr ? document.mm()->cm.bbox.Center() : Point3m(0, 0, 0);
      parlst.addPosition("PlanePoint", Eigen::Vector3d(centre[0], centre[1], centre[2]), "Plane Point",
                         "A point of the cutting plane.");
    }
    parlst.addDirection("PlaneNormal", Eigen::Vector3d::UnitX(), "Plane Normal",
                        "The normal of the cutting plane; need not be unit length, must not be zero.");
    break;
  case SEGMENT_SELECT:
    parlst.addInt("Segment", 0, "Segment", "Id of the segment to select (0 to segment count - 1).");
    break;
  default:
    break;
  }
}

Status SegmentFilters::apply(int id, FilterRun& run)
{
  MeshModel& mm = run.mesh;
  const QString name = segment_filter_name(id);
  if (const Status usable = check_mesh_input(mm.cm); !usable)
    return fail(name, usable);
  switch (id) {
  case SEGMENT_AUTO: return autoSegment(mm, run.arguments, run);
  case SEGMENT_AUTO_PRIMITIVE: return autoSegmentByPrimitives(mm, run.arguments, run);
  case SEGMENT_MERGE_SELECTED: return mergeSelected(mm, run);
  case SEGMENT_SPLIT_BY_PLANE: return splitByPlane(mm, run.arguments, run);
  case SEGMENT_SPLIT_BY_SELECTION: return splitBySelection(mm, run);
  case SEGMENT_SELECT: return selectSegment(mm, run.arguments, run);
  }
  return fail("Unknown filter.");
}

void SegmentFilters::storeSegments(MeshModel& mm, const std::vector<int>& segment_of_face,
                                   const FaceAdjacency* adjacency)
{
  mm.updateDataMask(MeshModel::MM_FACEQUALITY | MeshModel::MM_FACECOLOR);
  write_segment_ids(mm.cm, segment_of_face, adjacency);
  // Ids have changed meaning: primitives recorded for the old segments no longer apply.
  clear_segment_primitives(mm.cm);
}

Status SegmentFilters::autoSegment(MeshModel& mm, const Arguments& parlst, Run& run)
{
  SegmentByNormalAngleParams params;
  params.angle_deg = parlst.getFloat("Angle");
  params.smoothing_iterations = parlst.getInt("NormalSmoothing");
  params.min_segment_faces = parlst.getInt("MinSegmentFaces");
  if (const Status bad = check_normal_angle_params(params); !bad)
    return fail("Segment: Auto by Normal Angle: " + QString::fromStdString(bad.error));

  std::vector<int> before;
  const int segments_before = read_segment_ids(mm.cm, before) ? count_segments(before) : 0;
  QElapsedTimer timer;
  timer.start();
  std::vector<int> segment_of_face;
  SegmentByNormalAngleReport report;
  // Built once: the colouring of the segments needs it too.
  const FaceAdjacency adjacency = build_face_adjacency(mm.cm);
  const int k = segment_by_normal_angle(mm.cm, adjacency, params, segment_of_face, run.progress, &report);
  storeSegments(mm, segment_of_face, &adjacency);
  const QByteArray noise = report.edge_faces
      ? QString(" (for noise %1, edge faces handed out after the fill)").arg(report.noise, 0, 'g', 3).toUtf8()
      : QByteArray();
  run.logf("Segment: Auto by Normal Angle: %d faces split into %d segments (before: %d) at %.1f degrees, "
      "%d smoothing steps%s, min size %d faces, in %lld ms.",
      mm.cm.fn, k, segments_before, params.angle_deg, report.smoothing_passes, noise.constData(),
      report.min_segment_faces, timer.elapsed());
  return Status::success();
}

Status SegmentFilters::autoSegmentByPrimitives(MeshModel& mm, const Arguments& parlst, Run& run)
{
  const QString name = "Segment: Auto by Primitive Fit";
  SegmentByPrimitiveGrowingParams params;
  params.tolerance = parlst.getFloat("Tolerance");
  params.normal_angle_deg = parlst.getFloat("NormalAngle");
  params.seed_patch_faces = parlst.getInt("SeedPatchFaces");
  params.smoothing_iterations = parlst.getInt("NormalSmoothing");
  params.carve_blends = parlst.getBool("CarveBlends");
  if (const Status bad = check_primitive_growing_params(params); !bad)
    return fail(name + ": " + QString::fromStdString(bad.error));

  QElapsedTimer timer;
  timer.start();
  std::vector<int> segment_of_face;
  SegmentByPrimitiveGrowingReport report;
  params.roughness = read_surface_roughness(mm.cm).value_or(0.0);
  // Built once: the colouring of the segments needs it too.
  const FaceAdjacency adjacency = build_face_adjacency(mm.cm);
  const int k = segment_by_primitive_growing(mm.cm, adjacency, params, segment_of_face, &report, run.progress);
  storeSegments(mm, segment_of_face, &adjacency);
  write_surface_roughness(mm.cm, report.roughness);  // the fits that follow reuse it
  write_segment_blends(mm.cm, segment_of_face, report.blends);  // Fit All makes them blends of their planes
  run.logf("%s: %d faces split into %d segments (%d grown from primitives), tolerance %.4g (roughness %.4g), in %lld ms.",
      qUtf8Printable(name), mm.cm.fn, k, report.grown_regions, report.tolerance, report.roughness, timer.elapsed());
  if (!report.blends.empty())
    run.logf("%s: %s.", qUtf8Printable(name), describe_carved_blends(report.blends).c_str());
  return Status::success();
}

Status SegmentFilters::mergeSelected(MeshModel& mm, Run& run)
{
  const std::vector<int> faces = selected_faces(mm.cm);
  if (faces.empty())
    return fail("Segment: Merge Selected: no face is selected; select faces of the segments to merge.");
  std::vector<int> segment_of_face;
  if (!segments_or_whole_mesh(mm.cm, segment_of_face))
    run.logf("Segment: Merge Selected: the mesh has no segments yet; all faces are one segment.");
  const int before = count_segments(segment_of_face);
  const std::vector<int> segments = segments_of_faces(segment_of_face, faces);
  if (segments.size() < 2) {
    run.logf("Segment: Merge Selected: the selection touches one segment only; nothing to merge (%d segments).", before);
    return Status::success();
  }
  int moved = 0;
  for (int s : segment_of_face)
    moved += (s >= 0 && s != segments.front() && std::binary_search(segments.begin(), segments.end(), s));
  const int after = merge_segments(segment_of_face, segments);
  storeSegments(mm, segment_of_face);
  run.logf("Segment: Merge Selected: %d segments merged into one, %d faces moved; %d segments before, %d after.",
      int(segments.size()), moved, before, after);
  return Status::success();
}

Status SegmentFilters::splitByPlane(MeshModel& mm, const Arguments& parlst, Run& run)
{
  const int segment = parlst.getInt("Segment");
  const Eigen::Vector3d point = parlst.getVector("PlanePoint");
  Eigen::Vector3d normal = parlst.getVector("PlaneNormal");
  if (!point.allFinite() || !normal.allFinite() || normal.norm() < 1e-12)
    return fail("Segment: Split by Plane: the plane needs a finite point and a non-zero normal.");
  normal.normalize();

  std::vector<int> segment_of_face;
  if (!segments_or_whole_mesh(mm.cm, segment_of_face))
    run.logf("Segment: Split by Plane: the mesh has no segments yet; all faces are one segment.");
  const int before = count_segments(segment_of_face);
  std::vector<int> segments;
  if (segment == -1) {
    segments = segments_of_faces(segment_of_face, selected_faces(mm.cm));
    if (segments.empty())
      return fail("Segment: Split by Plane: Segment is -1 but no face is selected; select faces of the "
                  "segment to cut or give its id.");
  } else if (segment < 0 || segment >= before) {
    return fail(QString("Segment: Split by Plane: there is no segment %1; ids go from 0 to %2.")
                    .arg(segment).arg(before - 1));
  } else {
    segments.push_back(segment);
  }
  const FaceAdjacency adjacency = build_face_adjacency(mm.cm);
  SplitOptions options;
  options.min_piece_faces = kMinSplitPieceFaces;  // as the edit tool's cut: slivers join their neighbour
  const int after = split_segments_by_plane(mm.cm, adjacency, segment_of_face, segments, point, normal, options);
  storeSegments(mm, segment_of_face, &adjacency);
  run.logf("Segment: Split by Plane: %d segment(s) cut into %d pieces; %d segments before, %d after.",
      int(segments.size()), int(segments.size()) + after - before, before, after);
  return Status::success();
}

Status SegmentFilters::splitBySelection(MeshModel& mm, Run& run)
{
  const std::vector<int> faces = selected_faces(mm.cm);
  if (faces.empty())
    return fail("Segment: Split by Selection: no face is selected; select the faces of the new segment.");
  std::vector<int> segment_of_face;
  if (!segments_or_whole_mesh(mm.cm, segment_of_face))
    run.logf("Segment: Split by Selection: the mesh had no segments yet; the other faces are one segment.");
  const int before = count_segments(segment_of_face);
  const int after = move_faces_to_new_segment(segment_of_face, faces);
  storeSegments(mm, segment_of_face);
  run.logf("Segment: Split by Selection: %d faces moved to a new segment; %d segments before, %d after.",
      int(faces.size()), before, after);
  return Status::success();
}

Status SegmentFilters::selectSegment(MeshModel& mm, const Arguments& parlst, Run& run)
{
  const int segment = parlst.getInt("Segment");
  const LoadedSegments loaded = read_segments(mm);
  if (!loaded.found)
    return fail("Segment: Select Segment: the mesh has no segments; run Segment: Auto by Primitive Fit first.");
  const std::vector<int>& segment_of_face = loaded.segment_of_face;
  const int count = count_segments(segment_of_face);
  if (segment < 0 || segment >= count)
    return fail(QString("Segment: Select Segment: there is no segment %1; ids go from 0 to %2.")
                    .arg(segment).arg(count - 1));
  keep_segment_ids(run, "Segment: Select Segment", loaded);
  CMeshO& m = mm.cm;
  int selected = 0;
  for (auto& v : m.vert)
    v.ClearS();
  for (size_t i = 0; i < m.face.size(); ++i) {
    CFaceO& f = m.face[i];
    if (f.IsD())
      continue;
    if (segment_of_face[i] == segment) {
      f.SetS();
      for (int k = 0; k < 3; ++k)
        f.V(k)->SetS();
      ++selected;
    } else {
      f.ClearS();
    }
  }
  run.logf("Segment: Select Segment: segment %d selected, %d faces.", segment, selected);
  return Status::success();
}
