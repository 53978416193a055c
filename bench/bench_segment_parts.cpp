// bench_segment_parts: segment_by_primitive_growing (the filter's defaults unless overridden) on a part with
// known surfaces, timed per phase and scored.
//
// The truth is one surface id per face, either the peer part's <stem>.labels.txt ("face surface type" lines,
// ../shared/peer-part/gen_part.py) or a PLY of the same mesh with face quality = surface id
// (bench/true_segmentation.py for the bracket scan).
// Prints the median over --runs runs of each phase's wall-clock time (adjacency and each phase the
// segmentation reports: normals, roughness, grow, merge, dissolve, assign, relax) and of the total; then,
// for the last run, the roughness and tolerance, the segment count and the scores of eval_labels.py: per
// true surface the best IoU with one segment (by faces), the surfaces recovered at IoU >= 0.5 and 0.8, the
// majority accuracy (each segment votes for its majority surface; by faces), the same by area
// ("labelled", as bench/score_segmentation.py counts it), and, with the peer part's types, how many of the
// surfaces recovered at IoU >= 0.5 got a segment primitive of the right type.
// Each run segments once on 1 thread and once on all (--threads N: on 1 and N), alternating, and the medians
// are printed per thread count; the segmentations must be identical (the bench fails otherwise).
// --method normal runs segment_by_normal_angle instead (the paper's method; --angle, --smoothing and
// --min-faces set its parameters, defaults the filter's), timed as one phase.
// Usage: bench_segment_parts MESH.ply --truth LABELS.txt|TRUTH.ply [--runs N] [--tolerance MM] [--angle DEG]
//        [--method growing|normal] [--smoothing N] [--min-faces N] [--threads N] [--segmented OUT.ply]
#include "bracket/bracket_mesh.h"

#include "common/base/describe_primitive.h"
#include "common/base/parallel_for.h"
#include "common/mesh/face_adjacency.h"
#include "common/mesh/face_centroids_and_areas.h"
#include "common/segment/segment_by_normal_angle.h"
#include "common/segment/segment_by_primitive_growing.h"
#include "median.h"
#include "read_number.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

using primitive_edit::PrimitiveType;

struct Truth
{
  std::vector<int> surface;            // per face, -1: none
  std::map<int, std::string> type_of;  // per surface, when known
};

bool ends_with(const std::string& s, const std::string& end)
{
  return s.size() >= end.size() && s.compare(s.size() - end.size(), end.size(), end) == 0;
}

bool read_truth(const std::string& path, std::size_t face_count, Truth& truth, std::string& message)
{
  truth.surface.assign(face_count, -1);
  if (ends_with(path, ".ply")) {
    bracket::BMesh t;
    if (!bracket::load_ply(t, path, true, &message))
      return false;
    if (t.face.size() != face_count) {
      message = path + ": " + std::to_string(t.face.size()) + " faces, the mesh has " + std::to_string(face_count);
      return false;
    }
    for (std::size_t f = 0; f < face_count; ++f)
      truth.surface[f] = int(t.face[f].Q());
    return true;
  }
  std::ifstream in(path);
  if (!in) {
    message = path + ": cannot be read";
    return false;
  }
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#')
      continue;
    std::istringstream fields(line);
    long face = -1;
    int surface = -1;
    std::string type;
    if (!(fields >> face >> surface) || face < 0 || std::size_t(face) >= face_count) {
      message = path + ": bad line '" + line + "'";
      return false;
    }
    truth.surface[std::size_t(face)] = surface;
    if (surface >= 0 && (fields >> type))
      truth.type_of[surface] = type;
  }
  return true;
}

const char* type_word(PrimitiveType t)
{
  switch (t) {
  case PrimitiveType::Plane: return "plane";
  case PrimitiveType::Sphere: return "sphere";
  case PrimitiveType::Cylinder: return "cylinder";
  case PrimitiveType::Cone: return "cone";
  case PrimitiveType::Torus: return "torus";
  }
  return "?";
}

void print_scores(const bracket::BMesh& m, const Truth& truth, const std::vector<int>& segment, int K,
                  const primitive_edit::SegmentByPrimitiveGrowingReport& report)
{
  const std::vector<double> area = primitive_edit::face_centroids_and_areas(m).area;
  int G = 0;
  for (int s : truth.surface)
    G = std::max(G, s + 1);
  std::vector<std::vector<long>> count(std::size_t(G), std::vector<long>(std::size_t(K), 0));
  std::vector<std::vector<double>> overlap(std::size_t(G), std::vector<double>(std::size_t(K), 0.0));
  std::vector<long> surface_size(std::size_t(G), 0), segment_size(std::size_t(K), 0);
  long truth_faces = 0;
  double truth_area = 0;
  for (std::size_t f = 0; f < segment.size(); ++f) {
    const int s = truth.surface[f], k = segment[f];
    if (s < 0)
      continue;
    ++truth_faces;
    truth_area += area[f];
    ++surface_size[std::size_t(s)];
    if (k < 0)
      continue;
    ++count[std::size_t(s)][std::size_t(k)];
    overlap[std::size_t(s)][std::size_t(k)] += area[f];
    ++segment_size[std::size_t(k)];
  }
  int recovered50 = 0, recovered80 = 0, typed = 0;
  std::string per_surface;
  for (int s = 0; s < G; ++s) {
    double best = 0;
    int best_k = -1;
    for (int k = 0; k < K; ++k) {
      const long inter = count[std::size_t(s)][std::size_t(k)];
      const long uni = surface_size[std::size_t(s)] + segment_size[std::size_t(k)] - inter;
      const double iou = uni > 0 ? double(inter) / double(uni) : 0.0;
      if (iou > best) {
        best = iou;
        best_k = k;
      }
    }
    recovered50 += best >= 0.5;
    recovered80 += best >= 0.8;
    const auto known = truth.type_of.find(s);
    if (best >= 0.5 && known != truth.type_of.end() && best_k < int(report.primitive_of_segment.size()) &&
        report.primitive_of_segment[std::size_t(best_k)] &&
        known->second == type_word(report.primitive_of_segment[std::size_t(best_k)]->type))
      ++typed;
    char buf[64];
    std::snprintf(buf, sizeof buf, " %d:%.2f", s, best);
    per_surface += buf;
  }
  long correct = 0;
  double labelled = 0;
  for (int k = 0; k < K; ++k) {
    int by_count = 0, by_area = 0;
    for (int s = 1; s < G; ++s) {
      if (count[std::size_t(s)][std::size_t(k)] > count[std::size_t(by_count)][std::size_t(k)])
        by_count = s;
      if (overlap[std::size_t(s)][std::size_t(k)] > overlap[std::size_t(by_area)][std::size_t(k)])
        by_area = s;
    }
    if (G > 0) {
      correct += count[std::size_t(by_count)][std::size_t(k)];
      labelled += overlap[std::size_t(by_area)][std::size_t(k)];
    }
  }
  std::printf("roughness %.4g, tolerance %.4g, grown regions %d, segments %d\n", report.roughness,
              report.tolerance, report.grown_regions, K);
  std::printf("surfaces at IoU >= 0.5: %d/%d, at IoU >= 0.8: %d/%d", recovered50, G, recovered80, G);
  if (!truth.type_of.empty())
    std::printf(", right type: %d/%d", typed, recovered50);
  std::printf("\nmajority accuracy %.3f (faces), labelled %.1f%% (area)\n",
              truth_faces ? double(correct) / double(truth_faces) : 0.0,
              truth_area > 0 ? 100.0 * labelled / truth_area : 0.0);
  std::printf("best IoU per surface:%s\n", per_surface.c_str());
}

// The command line; see the top of this file.
struct Options
{
  std::string mesh_path, truth_path, segmented_path;
  int runs = 3, threads = primitive_edit::resolve_thread_count(0);
  primitive_edit::SegmentByPrimitiveGrowingParams params;
  primitive_edit::SegmentByNormalAngleParams normal_params;
  bool normal_angle = false;
};

// False (with the offending option printed) when an option is not understood.
bool parse_options(int argc, char** argv, Options& o)
{
  o.mesh_path = argv[1];
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    bool read = true;
    if (key == "--truth")
      o.truth_path = value;
    else if (key == "--runs")
      read = read_number("--runs", value.c_str(), 1, kMaxRuns, o.runs);
    else if (key == "--tolerance")
      read = read_number("--tolerance", value.c_str(), o.params.tolerance);
    else if (key == "--angle")
      read = read_number("--angle", value.c_str(), o.params.normal_angle_deg) &&
             read_number("--angle", value.c_str(), o.normal_params.angle_deg);
    else if (key == "--method" && (value == "growing" || value == "normal"))
      o.normal_angle = value == "normal";
    else if (key == "--smoothing")
      read = read_number("--smoothing", value.c_str(), o.params.smoothing_iterations) &&
             read_number("--smoothing", value.c_str(), o.normal_params.smoothing_iterations);
    else if (key == "--min-faces")
      read = read_number("--min-faces", value.c_str(), o.normal_params.min_segment_faces);
    else if (key == "--threads")
      read = read_number("--threads", value.c_str(), 1, kMaxThreads, o.threads);
    else if (key == "--segmented")
      o.segmented_path = value;
    else {
      std::fprintf(stderr, "unknown option %s\n", key.c_str());
      return false;
    }
    if (!read)
      return false;
  }
  const primitive_edit::Status checked = o.normal_angle ? primitive_edit::check_normal_angle_params(o.normal_params)
                                                        : primitive_edit::check_primitive_growing_params(o.params);
  if (!checked)
    std::fprintf(stderr, "%s\n", checked.error.c_str());
  return checked.ok();
}

// The segmentations of every run on every thread count, timed phase by phase.
struct TimedRuns
{
  std::map<int, std::map<std::string, std::vector<double>>> times;  // threads -> phase -> seconds
  std::vector<std::string> phase_order{"adjacency"};
  std::vector<int> segment;
  primitive_edit::SegmentByPrimitiveGrowingReport report;
  int K = 0;
};

// Runs the segmentation o.runs times on each thread count, alternating; false when a segmentation differs from
// the first one.
bool time_segmentations(const bracket::BMesh& m, Options o, const std::vector<int>& thread_counts, TimedRuns& out)
{
  std::vector<int> first_segment;
  for (int run = 0; run < o.runs; ++run) {
    for (const int t : thread_counts) {
      o.params.threads = t;
      const auto t0 = std::chrono::steady_clock::now();
      const primitive_edit::FaceAdjacency adj = primitive_edit::build_face_adjacency(m, t);
      const auto t1 = std::chrono::steady_clock::now();
      if (o.normal_angle) {
        out.K = primitive_edit::segment_by_normal_angle(m, adj, o.normal_params, out.segment);
        out.report = {};
        out.report.primitive_of_segment.resize(std::size_t(out.K));
        out.report.phase_times.push_back(
            {"normal angle", std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count()});
      } else {
        out.K = primitive_edit::segment_by_primitive_growing(m, adj, o.params, out.segment, &out.report);
      }
      const auto t2 = std::chrono::steady_clock::now();
      if (first_segment.empty())
        first_segment = out.segment;
      else if (out.segment != first_segment) {
        std::fprintf(stderr, "the segmentation on %d threads differs from the first run's\n", t);
        return false;
      }
      out.times[t]["adjacency"].push_back(std::chrono::duration<double>(t1 - t0).count());
      out.times[t]["total"].push_back(std::chrono::duration<double>(t2 - t0).count());
      for (const auto& phase : out.report.phase_times) {
        if (run == 0 && t == 1)
          out.phase_order.push_back(phase.phase);
        out.times[t][phase.phase].push_back(phase.seconds);
      }
    }
  }
  out.phase_order.push_back("total");
  return true;
}

} // namespace

int main(int argc, char** argv)
{
  Options o;
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s MESH.ply --truth LABELS.txt|TRUTH.ply [--runs N] [--tolerance MM] "
                         "[--angle DEG] [--segmented OUT.ply]\n", argv[0]);
    return 2;
  }
  if (!parse_options(argc, argv, o))
    return 2;
  bracket::BMesh m;
  std::string message;
  if (!bracket::load_ply(m, o.mesh_path, false, &message)) {
    std::fprintf(stderr, "%s\n", message.c_str());
    return 1;
  }
  Truth truth;
  if (!o.truth_path.empty() && !read_truth(o.truth_path, m.face.size(), truth, message)) {
    std::fprintf(stderr, "%s\n", message.c_str());
    return 1;
  }
  std::vector<int> thread_counts{1};
  if (o.threads > 1)
    thread_counts.push_back(o.threads);
  std::printf("%s: %zu faces, %d run(s) per thread count\n", o.mesh_path.c_str(), m.face.size(), o.runs);

  TimedRuns r;
  if (!time_segmentations(m, o, thread_counts, r))
    return 1;
  for (const int t : thread_counts) {
    std::printf("median seconds, %d thread%s:", t, t > 1 ? "s" : "");
    for (const std::string& phase : r.phase_order)
      std::printf(" %s %.3f", phase.c_str(), median(r.times[t][phase]));
    std::printf("\n");
  }
  if (thread_counts.size() > 1)
    std::printf("identical segmentations on 1 and %d threads; total ratio %.2fx\n", o.threads,
                median(r.times[1]["total"]) / median(r.times[o.threads]["total"]));
  if (!o.truth_path.empty())
    print_scores(m, truth, r.segment, r.K, r.report);
  if (!o.segmented_path.empty()) {
    for (std::size_t f = 0; f < m.face.size(); ++f)
      m.face[f].Q() = r.segment[f];
    if (!bracket::save_ply(m, o.segmented_path, true)) {
      std::fprintf(stderr, "%s: cannot be written\n", o.segmented_path.c_str());
      return 1;
    }
  }
  return 0;
}
