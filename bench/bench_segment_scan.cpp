// bench_segment_scan: segment_by_primitive_growing (default parameters unless overridden) on a scan PLY, then the whole
// reverse-engineering pipeline: fit every segment with fit_primitive_auto (as "Primitive: Fit All
// Segments" does, automatic tolerance) and snap them (snap_segments).
// Prints the median wall-clock time of `--runs` segmentations (adjacency included), the fit and snap times,
// and writes:
//   --segmented OUT.ply  the scan with face quality = segment id (for bench/score_segmentation.py),
//   --fits OUT.json      the fitted primitive of each segment (score_segmentation.py's FIT_EXPORT.json),
//   --snapped OUT.ply    the scan after snapping (for bench/bracket/measure_scan).
// --fit-tolerance MM is the fits' RMS limit (0, the default: automatic as in the filter, the larger of 1% of each
// segment's size and 3x the scan's roughness, estimate_surface_roughness.h).
// --labels SEGMENTED.ply skips the segmentation and fits/snaps the segments given as face quality of that
// PLY (the same scan, e.g. bench/true_segmentation.py's true surfaces: the ceiling of fit-and-snap).
// --carve-blends 0 leaves the segmentation's step 5 out (the filter's CarveBlends; default 1: carve_edge_blends.h).
// --relations 0 fits every segment alone (default 1: relations found and enforced, relate_primitives.h);
// --relation-angle DEG and --relation-cost SHARE set RelationOptions.
// --types TYPES.txt (lines "SEGMENT_ID TYPE", e.g. from true_segmentation.py --types) fits each listed segment
// with that type (fit_primitive, all points) instead of letting fit_primitive_auto choose: the ceiling with the
// true types.
// --primitives PRIMS.txt (lines "SEGMENT_ID TYPE ORIGIN(3) AXIS(3) RADIUS MINOR_RADIUS HALF_ANGLE", e.g. from
// true_segmentation.py --primitives) snaps onto those primitives instead of fitting: with --labels, the snap alone
// on the true segments and the true primitives (what the fits are measured against).
// --method 0|1|2 starts the fits of given types as FitMethod says (0 refined starts, 1 the paper's direct fit,
// 2 direct then refined; fit_result.h): with --labels and --types, the direct fit on the true segments.
// --repair 0 holds folded faces back without first sliding vertices along their surfaces (SnapOptions::repair_folds);
// --prevent-flips 0 leaves folds as they are (their area is printed either way).
// --wide-repair 1 follows the repair around each fold with the wide one (SnapOptions::wide_repair), as the edit
// tool's Apply and "Primitive: Snap Segment" do; Fit All's default (0) leaves it out.
// --fit-runs N runs Fit All with snap N times on the same segments, the scan's positions put back before each,
// and prints the median time of each stage and of the whole, and the first run's (issue 10's budget: median of 5
// at 1M). The roughness is measured once before, as the segmentation keeps it on the mesh for Fit All; its time
// is printed apart. The outputs come from the last run.
// --threads N runs the segmentation and Fit All on N threads (default 0: every hardware thread); the outputs are
// the same on any count.
// Usage: bench_segment_scan SCAN.ply [--runs N] [--tolerance MM] [--angle DEG] [--smoothing N] [--fit-tolerance MM]
//        [--carve-blends 0|1] [--labels SEGMENTED.ply] [--types TYPES.txt] [--primitives PRIMS.txt] [--segmented OUT.ply]
//        [--fits OUT.json] [--snapped OUT.ply] [--fit-runs N] [--threads N]
#include "bracket/bracket_mesh.h"

#include "common/pipeline/fit_all_segments.h"
#include "common/pipeline/write_fits_json.h"
#include "common/segment/segment_by_primitive_growing.h"
#include "median.h"
#include "read_number.h"

#include <algorithm>
#include <chrono>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Reads the segment of each face from the face quality of `path`, a PLY of the same scan (same face
// count and, checked here, the same vertex positions): ids must be integers in [-1, 1e7); -1 = none.
bool read_labels(const std::string& path, const bracket::BMesh& scan, std::vector<int>& segment_of_face, int& K,
                 std::string& message)
{
  bracket::BMesh labelled;
  if (!bracket::load_ply(labelled, path, true, &message))
    return false;
  if (labelled.face.size() != scan.face.size() || labelled.vert.size() != scan.vert.size()) {
    message = path + ": " + std::to_string(labelled.face.size()) + " faces, " + std::to_string(labelled.vert.size()) +
              " vertices; the scan has " + std::to_string(scan.face.size()) + ", " + std::to_string(scan.vert.size());
    return false;
  }
  for (std::size_t v = 0; v < scan.vert.size(); ++v)
    if ((labelled.vert[v].cP() - scan.vert[v].cP()).Norm() > 1e-4) {
      message = path + ": vertex " + std::to_string(v) + " differs from the scan's: not the same mesh";
      return false;
    }
  segment_of_face.assign(scan.face.size(), -1);
  K = 0;
  for (std::size_t f = 0; f < scan.face.size(); ++f) {
    const double q = labelled.face[f].cQ();
    if (!(q >= -1 && q < 1e7) || q != std::floor(q)) {
      message = path + ": face " + std::to_string(f) + " has quality " + std::to_string(q) + ", not a segment id";
      return false;
    }
    segment_of_face[f] = static_cast<int>(q);
    K = std::max(K, segment_of_face[f] + 1);
  }
  return true;
}

// The type whose lower-case name is `name` (plane, sphere, cylinder, cone, torus), or nothing.
std::optional<primitive_edit::PrimitiveType> type_named(const std::string& name)
{
  for (int t = 0; t < primitive_edit::kPrimitiveTypeCount; ++t) {
    const auto type = static_cast<primitive_edit::PrimitiveType>(t);
    std::string type_name = primitive_edit::primitive_type_name(type);
    std::transform(type_name.begin(), type_name.end(), type_name.begin(), [](unsigned char c) { return std::tolower(c); });
    if (type_name == name)
      return type;
  }
  return std::nullopt;
}

// Calls read_line(line) on each line of `path` but empty and '#' ones, until it returns false (having set
// `message`); false when the file cannot be read or a line was refused.
template <class ReadLine>
bool read_lines(const std::string& path, std::string& message, ReadLine read_line)
{
  std::ifstream in(path);
  if (!in) {
    message = path + ": cannot read";
    return false;
  }
  std::string line;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#' && !read_line(line))
      return false;
  return true;
}

// Reads "SEGMENT_ID TYPE" lines (type: plane, sphere, cylinder, cone, torus; any other word, e.g. other,
// leaves the segment to fit_primitive_auto; '#' lines are comments); ids outside the segments are ignored.
bool read_types(const std::string& path, std::vector<std::optional<primitive_edit::PrimitiveType>>& type_of_segment,
                std::string& message)
{
  return read_lines(path, message, [&](const std::string& line) {
    std::istringstream words(line);
    long id = -1;
    std::string name;
    if (!(words >> id >> name)) {
      message = path + ": not a \"SEGMENT_ID TYPE\" line: " + line;
      return false;
    }
    const auto type = type_named(name);
    if (type && id >= 0 && id < static_cast<long>(type_of_segment.size()))
      type_of_segment[static_cast<std::size_t>(id)] = *type;
    return true;
  });
}

// Reads --primitives lines into primitive_of_segment (ids outside the segments are ignored; '#' lines are
// comments). A line of an unknown type or with too few numbers is refused.
bool read_primitives(const std::string& path,
                     std::vector<std::optional<primitive_edit::Primitive>>& primitive_of_segment, std::string& message)
{
  return read_lines(path, message, [&](const std::string& line) {
    std::istringstream words(line);
    long id = -1;
    std::string name;
    primitive_edit::Primitive q;
    if (!(words >> id >> name >> q.origin.x() >> q.origin.y() >> q.origin.z() >> q.axis.x() >> q.axis.y() >>
          q.axis.z() >> q.radius >> q.minor_radius >> q.half_angle)) {
      message = path + ": not a primitive line: " + line;
      return false;
    }
    const auto type = type_named(name);
    if (!type) {
      message = path + ": unknown type in: " + line;
      return false;
    }
    q.type = *type;
    q.axis.normalize();
    if (id >= 0 && id < static_cast<long>(primitive_of_segment.size()))
      primitive_of_segment[static_cast<std::size_t>(id)] = q;
    return true;
  });
}

// The command line; see the top of this file.
struct Args
{
  std::string scan_path, labels_path, types_path, primitives_path, segmented_path, fits_path, snapped_path;
  int runs = 3, fit_runs = 1;
  double fit_tolerance = 0;
  bool relations = true;
  bool repair = true, prevent_flips = true, wide_repair = false;
  primitive_edit::RelationOptions relation_options;
  primitive_edit::SegmentByPrimitiveGrowingParams params;
  int method = 0;
  int threads = 0;
};

// The arguments, or nothing when they are not understood (main prints the usage).
std::optional<Args> parse_args(int argc, char** argv)
{
  Args g;
  bool read = true;
  for (int i = 1; i < argc && read; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if (a == "--runs" && has_value)
      read = read_number("--runs", argv[++i], 1, kMaxRuns, g.runs);
    else if (a == "--fit-runs" && has_value)
      read = read_number("--fit-runs", argv[++i], 1, kMaxRuns, g.fit_runs);
    else if (a == "--tolerance" && has_value)
      read = read_number("--tolerance", argv[++i], g.params.tolerance);
    else if (a == "--angle" && has_value)
      read = read_number("--angle", argv[++i], g.params.normal_angle_deg);
    else if (a == "--smoothing" && has_value)
      read = read_number("--smoothing", argv[++i], g.params.smoothing_iterations);
    else if (a == "--fit-tolerance" && has_value)
      read = read_number("--fit-tolerance", argv[++i], g.fit_tolerance);
    else if (a == "--repair" && has_value)
      read = read_switch("--repair", argv[++i], g.repair);
    else if (a == "--prevent-flips" && has_value)
      read = read_switch("--prevent-flips", argv[++i], g.prevent_flips);
    else if (a == "--wide-repair" && has_value)
      read = read_switch("--wide-repair", argv[++i], g.wide_repair);
    else if (a == "--relations" && has_value)
      read = read_switch("--relations", argv[++i], g.relations);
    else if (a == "--carve-blends" && has_value)
      read = read_switch("--carve-blends", argv[++i], g.params.carve_blends);
    else if (a == "--relation-angle" && has_value)
      read = read_number("--relation-angle", argv[++i], g.relation_options.angle_deg);
    else if (a == "--relation-cost" && has_value)
      read = read_number("--relation-cost", argv[++i], g.relation_options.max_cost_increase);
    else if (a == "--threads" && has_value)
      read = read_number("--threads", argv[++i], 0, kMaxThreads, g.threads);
    else if (a == "--method" && has_value)
      read = read_number("--method", argv[++i], 0, primitive_edit::kFitMethodCount - 1, g.method);
    else if (a == "--labels" && has_value)
      g.labels_path = argv[++i];
    else if (a == "--types" && has_value)
      g.types_path = argv[++i];
    else if (a == "--primitives" && has_value)
      g.primitives_path = argv[++i];
    else if (a == "--segmented" && has_value)
      g.segmented_path = argv[++i];
    else if (a == "--fits" && has_value)
      g.fits_path = argv[++i];
    else if (a == "--snapped" && has_value)
      g.snapped_path = argv[++i];
    else if (a.rfind("--", 0) != 0 && g.scan_path.empty())
      g.scan_path = a;
    else
      return std::nullopt;
  }
  g.params.threads = g.threads;
  if (!read || g.scan_path.empty() || !std::isfinite(g.fit_tolerance) || g.fit_tolerance < 0)
    return std::nullopt;
  if (const primitive_edit::Status checked = primitive_edit::check_primitive_growing_params(g.params); !checked) {
    std::fprintf(stderr, "%s\n", checked.error.c_str());
    return std::nullopt;
  }
  return g;
}

// The segments: read from --labels, or the segmentation run --runs times (its median time printed). Returns the
// segment count, or -1 (message set) when the labels cannot be read.
int segment_scan(bracket::BMesh& m, const Args& g, std::vector<int>& segment_of_face, std::string& message)
{
  using namespace primitive_edit;
  if (!g.labels_path.empty()) {
    int K = 0;
    if (!read_labels(g.labels_path, m, segment_of_face, K, message))
      return -1;
    std::printf("%s: %zu faces, %d segments read from %s\n", g.scan_path.c_str(), m.face.size(), K,
                g.labels_path.c_str());
    return K;
  }
  int K = 0;
  SegmentByPrimitiveGrowingReport report;
  std::vector<double> times;
  for (int r = 0; r < g.runs; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    K = segment_by_primitive_growing(m, g.params, segment_of_face, &report);
    times.push_back(seconds_since(t0));
  }
  const auto [fastest, slowest] = std::minmax_element(times.begin(), times.end());
  int typed = 0;
  for (const auto& p : report.primitive_of_segment)
    typed += p.has_value() ? 1 : 0;
  std::printf("%s: %zu faces, %d segments (%d with a grown primitive, %d regions grown), tolerance %.4g, "
              "roughness %.4g\n",
              g.scan_path.c_str(), m.face.size(), K, typed, report.grown_regions, report.tolerance, report.roughness);
  std::printf("segmentation: median %.3f s of %d runs (min %.3f, max %.3f), %.0f ns/face\n", median(times), g.runs,
              *fastest, *slowest, 1e9 * median(times) / double(m.face.size()));
  // As the filter does: Fit All makes the segments carved as blends the blends of their planes.
  write_segment_blends(m, segment_of_face, report.blends);
  std::printf("blends carved: %zu:", report.blends.size());
  for (const SegmentBlendRecord& b : report.blends)
    std::printf(" %d of (%d,%d)", b.segment, b.plane_a, b.plane_b);
  std::printf("\n");
  return K;
}

// --primitives: the segments snapped onto the given primitives, no fitting.
int snap_onto_given(bracket::BMesh& m, const Args& g, const std::vector<int>& segment_of_face, int K,
                    primitive_edit::SnapOptions snap_options)
{
  using namespace primitive_edit;
  std::string message;
  std::vector<std::optional<Primitive>> given(static_cast<std::size_t>(K));
  if (!read_primitives(g.primitives_path, given, message)) {
    std::fprintf(stderr, "bench_segment_scan: %s\n", message.c_str());
    return 1;
  }
  const auto t0 = std::chrono::steady_clock::now();
  snap_options.threads = g.threads;
  const SnapReport snap = snap_segments(m, segment_of_face, given, snap_options);
  std::printf("snap onto the given primitives: %.3f s, %d vertices moved (%d edge, %d corner of %d on borders, %d "
              "slid to unfold faces, %d held back, %d of them partway), %d faces left folded (area %.4g)\n",
              seconds_since(t0), snap.moved_vertices, snap.edge_vertices, snap.corner_vertices, snap.border_vertices,
              snap.repaired_vertices, snap.reverted_vertices, snap.partway_vertices, snap.folded_faces,
              snap.folded_area);
  if (!g.snapped_path.empty() && !bracket::save_ply(m, g.snapped_path, false))
    std::fprintf(stderr, "bench_segment_scan: cannot write %s\n", g.snapped_path.c_str());
  return 0;
}

// Fit All with snap, --fit-runs times from the scan's positions (the median of each stage printed when more than
// one); the last run's result, or its failure.
primitive_edit::FitAllSegmentsResult run_fit_all(bracket::BMesh& m, const Args& g, const std::vector<int>& segment_of_face,
                                                 const primitive_edit::FitAllSegmentsOptions& fit_all)
{
  using namespace primitive_edit;
  if (g.fit_runs > 1) {
    const auto t0 = std::chrono::steady_clock::now();
    surface_roughness(m);
    std::printf("roughness (kept on the mesh for the runs below): %.3f s\n", seconds_since(t0));
  }
  std::vector<bracket::BMesh::CoordType> scan_positions;
  for (const auto& v : m.vert)
    scan_positions.push_back(v.cP());
  FitAllSegmentsResult result;
  std::vector<double> stage_times[4];  // fit, relations, snap, whole
  for (int r = 0; r < g.fit_runs; ++r) {
    if (r > 0) {
      for (std::size_t v = 0; v < m.vert.size(); ++v)
        m.vert[v].P() = scan_positions[v];
      update_normals_and_bounds(m);
    }
    const auto t0 = std::chrono::steady_clock::now();
    result = fit_all_segments(m, segment_of_face, fit_all);
    stage_times[3].push_back(seconds_since(t0));
    if (!result.status)
      return result;
    stage_times[0].push_back(result.fit_seconds);
    stage_times[1].push_back(result.relation_seconds);
    stage_times[2].push_back(result.snap_seconds);
  }
  if (g.fit_runs > 1) {
    const auto [fastest, slowest] = std::minmax_element(stage_times[3].begin(), stage_times[3].end());
    std::printf("fit all with snap, median of %d runs: %.3f s (min %.3f, max %.3f, first %.3f): fits %.3f, relations "
                "%.3f, snap %.3f s\n",
                g.fit_runs, median(stage_times[3]), *fastest, *slowest, stage_times[3].front(),
                median(stage_times[0]), median(stage_times[1]), median(stage_times[2]));
  }
  return result;
}

// The relations, profiles and blends Fit All found, and its fit and snap counts.
void print_fit_all(const primitive_edit::FitAllSegmentsResult& result, int K, bool relations)
{
  using namespace primitive_edit;
  if (relations) {
    std::printf("relations: %zu kept, %d dropped by the check, %.3f s:", result.relations.size(), result.relations_dropped,
                result.relation_seconds);
    for (const Relation& r : result.relations)
      std::printf(" %s(%d,%d)", relation_kind_name(r.kind), r.a, r.b);
    std::printf("\nprofiles about a direction of the part: %zu:", result.profiles_about_directions.size());
    for (const SegmentProfile& q : result.profiles_about_directions)
      std::printf(" %d %s along %d", q.segment, primitive_type_name(q.primitive.type), q.axis_segment);
    std::printf("\nprofiles about a cylinder's axis: %zu:", result.profiles.size());
    for (const SegmentProfile& q : result.profiles)
      std::printf(" %d %s about %d", q.segment, primitive_type_name(q.primitive.type), q.axis_segment);
    std::printf("\nblends between planes or about an axis: %zu:", result.blends.size());
    for (const SegmentEdgeBlend& b : result.blends)
      std::printf(" %s %d of (%d,%d%s) setback %.3f", b.form == BlendForm::Fillet ? "fillet" : "chamfer", b.segment,
                  b.plane_a, b.plane_b, b.meridian ? ", about its axis" : "", b.setback);
    std::printf("\n");
  }
  const SnapReport& snap = *result.snap;
  std::printf("fit all segments: %.3f s, %d of %d fitted; snap: %.3f s, %d vertices moved (%d edge, %d corner of %d "
              "on borders, %d slid to unfold faces, %d held back, %d of them partway), %d faces left folded "
              "(area %.4g)\n",
              result.fit_seconds, result.fitted, K, result.snap_seconds, snap.moved_vertices, snap.edge_vertices,
              snap.corner_vertices, snap.border_vertices, snap.repaired_vertices, snap.reverted_vertices,
              snap.partway_vertices, snap.folded_faces, snap.folded_area);
}

} // namespace

int main(int argc, char** argv)
{
  using namespace primitive_edit;
  const std::optional<Args> parsed = parse_args(argc, argv);
  if (!parsed) {
    std::fprintf(stderr, "usage: bench_segment_scan SCAN.ply [--runs N] [--tolerance MM] [--angle DEG] [--smoothing N] [--fit-tolerance MM] "
                         "[--carve-blends 0|1] [--relations 0|1] [--repair 0|1] [--prevent-flips 0|1] [--wide-repair 0|1] [--relation-angle DEG] [--relation-cost SHARE] [--method 0|1|2] [--labels SEGMENTED.ply] [--types TYPES.txt] [--primitives PRIMS.txt] [--segmented OUT.ply] [--fits OUT.json] [--snapped OUT.ply] [--fit-runs N] [--threads N]\n");
    return 2;
  }
  const Args& g = *parsed;
  bracket::BMesh m;
  std::string message;
  if (!bracket::load_ply(m, g.scan_path, false, &message)) {
    std::fprintf(stderr, "bench_segment_scan: %s\n", message.c_str());
    return 1;
  }
  std::vector<int> segment_of_face;
  const int K = segment_scan(m, g, segment_of_face, message);
  if (K < 0) {
    std::fprintf(stderr, "bench_segment_scan: %s\n", message.c_str());
    return 1;
  }
  if (!g.segmented_path.empty()) {
    for (std::size_t f = 0; f < m.face.size(); ++f)
      m.face[f].Q() = segment_of_face[f];
    if (!bracket::save_ply(m, g.segmented_path, true))
      std::fprintf(stderr, "bench_segment_scan: cannot write %s\n", g.segmented_path.c_str());
  }

  std::vector<std::optional<PrimitiveType>> forced_type(static_cast<std::size_t>(K));
  if (!g.types_path.empty() && !read_types(g.types_path, forced_type, message)) {
    std::fprintf(stderr, "bench_segment_scan: %s\n", message.c_str());
    return 1;
  }
  SnapOptions snap_options = fitted_snap_options(); // the given primitives too are the scan's
  snap_options.repair_folds = g.repair;
  snap_options.prevent_flips = g.prevent_flips;
  snap_options.wide_repair = g.wide_repair;
  if (!g.primitives_path.empty())
    return snap_onto_given(m, g, segment_of_face, K, snap_options);

  FitAllSegmentsOptions fit_all;
  fit_all.tolerance = g.fit_tolerance;
  fit_all.types = forced_type;
  fit_all.fit.method = FitMethod(g.method);
  fit_all.relations = g.relations;
  fit_all.relation_options = g.relation_options;
  fit_all.snap = true;
  fit_all.snap_options = snap_options;
  fit_all.threads = g.threads;
  const FitAllSegmentsResult result = run_fit_all(m, g, segment_of_face, fit_all);
  if (!result.status) {
    std::fprintf(stderr, "bench_segment_scan: %s\n", result.status.error.c_str());
    return 1;
  }
  print_fit_all(result, K, g.relations);
  if (!g.fits_path.empty()) {
    std::ofstream out(g.fits_path);
    write_fits_json(out, result, g.scan_path, true);
    if (!out)
      std::fprintf(stderr, "bench_segment_scan: cannot write %s\n", g.fits_path.c_str());
  }
  if (!g.snapped_path.empty() && !bracket::save_ply(m, g.snapped_path, false))
    std::fprintf(stderr, "bench_segment_scan: cannot write %s\n", g.snapped_path.c_str());
  return 0;
}
