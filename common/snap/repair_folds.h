// repair_folds.h: undoes the folds that snapping leaves by sliding vertices along the surfaces they were
// snapped to, instead of sending them back to the scan.
//
// Input:  vertex positions (changed in place); face_vertex (3 vertex indices per face, -1 = dead face) and its
//         VertexFaces; the reference of each face, the cross product of its edges before snapping (zero or
//         non-finite: the face cannot fold); `movable(v)`, asked once per vertex near a fold; and
//         `constrain(v, p, out)`, which puts into `out` the point of vertex v's surface nearest to p (its
//         primitive, the edge of two primitives, its tangent plane) and returns false when it has none.
//         `movable` runs on the calling thread before any sweep moves its vertex, so it may build what
//         `constrain` reads for that vertex; `constrain` runs on options.threads threads at once, for vertices of
//         different connected parts of the region, and may write only what belongs to its vertex.
// Output: RepairFoldsReport. Only movable vertices within max_rounds rings of a fold move, each onto its
//         surface. A face is folded when its normal turned by more than 90 degrees from its reference or its
//         area fell below 1e-3 of the reference (snap_segments' guard uses the same test). A connected
//         part of the region that still holds a fold after the last round gets its snapped positions back
//         unless its repaired ones fold fewer of its faces, so the repair never leaves more folds than it
//         found (snap_segments then holds those back).
// Method: the region starts as the movable vertices around the folded faces; each round grows it by one
//         ring around the faces still folded (options.widen: and around the whole region), then runs
//         Gauss-Seidel sweeps of the umbrella operator (a region vertex goes to the mean of its neighbours,
//         then back onto its surface). With the region's border fixed this is Tutte's embedding on the
//         surface, which untangles a fold once the region holds it with some margin (the rim of a widened
//         hole pushes the plane's vertices outwards); beyond the region nothing moves. The rounds end early
//         when the folds stall (FoldTrend: they no longer fall by 5% a check). After the last round, each
//         connected part of the region gets up to settle_sweeps more sweeps while its folds have not stalled,
//         or while it still moves (unconverged, a part that has just unfolded leaves its first rings pressed
//         against its fixed border). A round's sweeps run the region's connected parts side by side
//         (for_each_largest_first): a sweep moves a vertex to the mean of its neighbours, which are in its own
//         part or fixed, so each part's Gauss-Seidel order and result are the same as in one sweep over all,
//         on any thread count.
// Cost:   O(F) to find the folds, then O(faces around the region x sweeps) per round and settle sweep, a round's
//         sweeps divided among the threads; the sweeps read each vertex's umbrella from a list built when it joins
//         the region (lazy_lists.h), the fold searches the region's faces from a list extended as the region
//         grows. The parts are kept as the region grows (a union-find over its vertices): O(added vertices'
//         faces) a round, plus O(region log region) to list them.
#ifndef PRIMITIVE_EDIT_REPAIR_FOLDS_H
#define PRIMITIVE_EDIT_REPAIR_FOLDS_H

#include "common/base/huge_page_vector.h"
#include "common/base/lazy_lists.h"
#include "common/base/parallel_for.h"
#include "common/mesh/vertex_faces.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

namespace primitive_edit {

struct RepairFoldsOptions
{
  int max_rounds = 12;      // the region reaches at most this many rings beyond a fold
  int sweeps_per_round = 4; // umbrella passes after each ring is added
  // Grow around the whole region each round, not only around the faces still folded: needed where folds sit
  // against pinned vertices (a widened hole's rim), but a wide region that fails is restored whole, with the
  // folds it had repaired, so snap_segments tries the narrow repair first.
  bool widen = false;
  // Sweeps over the grown region after the last round, while folds remain or the region still moves, before
  // giving up on it.
  int settle_sweeps = 100;
  // A part that still holds folds keeps its repaired positions when they fold fewer of its faces than its snapped
  // ones (off: it gets its snapped positions back, where a wider repair can start again).
  bool keep_partial = true;
  // The rounds' sweeps on this many threads (<= 0: every hardware thread), the region's connected parts side by
  // side; the result is the same on any count.
  int threads = 1;
};

struct RepairFoldsReport
{
  int moved_vertices = 0; // vertices that left their snapped position
  int rounds = 0;         // rounds run (0: nothing was folded)
  int folded_faces = 0;   // faces still folded at the end
};

// The fold test shared with snap_segments' guard: `reference` is the face's edge cross product before snapping.
bool face_is_folded(const Eigen::Vector3d& reference, const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                    const Eigen::Vector3d& p2);

namespace repair_detail {

// Below this many vertices a region's sweeps stay on one thread: its parts' lists and a thread's start would
// cost more than they save.
constexpr std::size_t kVerticesPerSweepThread = 1000;

// The growing region of vertices around the folds and the operations of one repair.
struct FoldRegion
{
  std::vector<Eigen::Vector3d>& position;
  const std::vector<int>& face_vertex;
  const VertexFaces& vertex_faces;
  const std::vector<Eigen::Vector3d>& reference;
  LazyLists& umbrella; // per vertex, the other corners of its faces: what a sweep averages
  // Per face, the id of the last region that listed it in its faces_around (regions and their parts have ids
  // of their own; a part's faces belong to no other part).
  std::vector<int>& lister;
  int id;
  std::vector<std::uint8_t> state; // 0: not asked yet, 1: in the region, 2: pinned
  std::vector<int> vertices;
  std::vector<int> folds;
  std::size_t last_ring_begin = 0; // vertices[last_ring_begin..] were added by the last grow
  // The faces around vertices[0..listed_vertices), each once, in the order a walk over the vertices' faces
  // meets them first: find_folds checks them in that order without walking the vertices again.
  std::vector<int> faces_around = {};
  std::size_t listed_vertices = 0;
  // A union-find over the region (link[v], v's parent; vertices[0..joined) are joined to their region
  // neighbours): its connected parts, which a round sweeps side by side.
  std::vector<int> link = {};
  std::size_t joined = 0;

  int corner(int f, int k) const { return face_vertex[3 * std::size_t(f) + std::size_t(k)]; }
  bool folded(int f) const
  {
    return corner(f, 0) >= 0 && face_is_folded(reference[std::size_t(f)], position[std::size_t(corner(f, 0))],
                                               position[std::size_t(corner(f, 1))], position[std::size_t(corner(f, 2))]);
  }
  template <class Visit>
  void for_faces_of(int v, Visit&& visit) const
  {
    for (int i = vertex_faces.offset[std::size_t(v)]; i < vertex_faces.offset[std::size_t(v) + 1]; ++i)
      visit(vertex_faces.face[std::size_t(i)]);
  }

  // Adds the movable vertices of the faces around the corners of the folded faces and, when `widen`, around
  // the ring added by the round before.
  template <class Movable>
  void grow(Movable& movable, bool widen)
  {
    const std::size_t last_ring = last_ring_begin;
    last_ring_begin = vertices.size();
    auto add_around = [&](int v) {
      for_faces_of(v, [&](int g) {
        for (int j = 0; j < 3; ++j) {
          const int b = corner(g, j);
          if (b < 0 || state[std::size_t(b)] != 0)
            continue;
          state[std::size_t(b)] = movable(std::size_t(b)) ? 1 : 2;
          if (state[std::size_t(b)] == 1)
            vertices.push_back(b);
        }
      });
    };
    for (int f : folds)
      for (int k = 0; k < 3; ++k)
        add_around(corner(f, k));
    if (widen)
      for (std::size_t i = last_ring; i < last_ring_begin; ++i)
        add_around(vertices[i]);
    for (std::size_t i = last_ring_begin; i < vertices.size(); ++i)
      build_umbrella(vertices[i]); // here, so that the sweeps only read the lists
  }

  // Lists the other corners of v's faces: what a sweep averages.
  void build_umbrella(int v)
  {
    umbrella.get(std::size_t(v), [&](std::vector<int>& pool) {
      for_faces_of(v, [&](int g) {
        for (int j = 0; j < 3; ++j)
          if (corner(g, j) >= 0 && corner(g, j) != v)
            pool.push_back(corner(g, j));
      });
    });
  }

  // Moves v to the mean of its neighbours, then onto its surface; returns how far it moved.
  template <class Constrain>
  double sweep_vertex(int v, Constrain& constrain)
  {
    const auto [begin, end] = umbrella.built(std::size_t(v));
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const int* u = begin; u != end; ++u)
      sum += position[std::size_t(*u)];
    const int count = int(end - begin);
    Eigen::Vector3d target;
    if (count > 0 && constrain(std::size_t(v), Eigen::Vector3d(sum / count), target) && target.allFinite()) {
      const double move = (target - position[std::size_t(v)]).norm();
      position[std::size_t(v)] = target;
      return move;
    }
    return 0;
  }

  // One Gauss-Seidel pass; returns the longest move.
  template <class Constrain>
  double sweep(Constrain& constrain)
  {
    double longest = 0;
    for (int v : vertices)
      longest = std::max(longest, sweep_vertex(v, constrain));
    return longest;
  }

  // `sweeps` passes, the connected parts side by side on `threads` threads (one pass over all when one thread
  // or a region too small to share: the result is the same).
  template <class Constrain>
  void sweep_parts(Constrain& constrain, int sweeps, int threads)
  {
    threads = resolve_thread_count(threads);
    if (threads <= 1 || vertices.size() < kVerticesPerSweepThread) {
      for (int s = 0; s < sweeps; ++s)
        sweep(constrain);
      return;
    }
    const std::vector<std::vector<int>> parts = connected_parts();
    std::vector<std::size_t> sizes(parts.size());
    for (std::size_t p = 0; p < parts.size(); ++p)
      sizes[p] = parts[p].size();
    for_each_largest_first(sizes, threads, [&](int, std::size_t p) {
      for (int s = 0; s < sweeps; ++s)
        for (int v : parts[p])
          sweep_vertex(v, constrain);
    });
  }

  int root(int v)
  {
    while (link[std::size_t(v)] != v)
      v = link[std::size_t(v)] = link[std::size_t(link[std::size_t(v)])];
    return v;
  }

  // The region's connected parts (parts share no face, so each can sweep and settle on its own), each in the
  // region's order; joins the vertices added since the last call.
  std::vector<std::vector<int>> connected_parts()
  {
    if (link.empty()) {
      link = huge_page_vector<int>(position.size());
      std::iota(link.begin(), link.end(), 0);
    }
    for (; joined < vertices.size(); ++joined) {
      const int v = vertices[joined];
      for_faces_of(v, [&](int g) {
        for (int j = 0; j < 3; ++j)
          if (corner(g, j) >= 0 && state[std::size_t(corner(g, j))] == 1)
            link[std::size_t(root(corner(g, j)))] = root(v);
      });
    }
    std::vector<int> roots(vertices.size()), order(vertices.size());
    for (std::size_t i = 0; i < vertices.size(); ++i)
      roots[i] = root(vertices[i]);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return roots[std::size_t(a)] < roots[std::size_t(b)]; });
    std::vector<std::vector<int>> parts;
    for (std::size_t k = 0; k < order.size(); ++k) {
      if (k == 0 || roots[std::size_t(order[k])] != roots[std::size_t(order[k - 1])])
        parts.emplace_back();
      parts.back().push_back(vertices[std::size_t(order[k])]);
    }
    return parts;
  }

  // The folded faces among `first` and the faces around the region, each looked at once (mark = round).
  void find_folds(const std::vector<int>& first, std::vector<int>& mark, int round)
  {
    for (; listed_vertices < vertices.size(); ++listed_vertices)
      for_faces_of(vertices[listed_vertices], [&](int f) {
        if (lister[std::size_t(f)] != id) {
          lister[std::size_t(f)] = id;
          faces_around.push_back(f);
        }
      });
    folds.clear();
    auto check = [&](int f) {
      if (mark[std::size_t(f)] == round)
        return;
      mark[std::size_t(f)] = round;
      if (folded(f))
        folds.push_back(f);
    };
    for (int f : first)
      check(f);
    for (int f : faces_around)
      check(f);
  }

  void save(std::vector<Eigen::Vector3d>& out) const
  {
    out.resize(vertices.size());
    for (std::size_t i = 0; i < vertices.size(); ++i)
      out[i] = position[std::size_t(vertices[i])];
  }
  void load(const std::vector<Eigen::Vector3d>& saved)
  {
    for (std::size_t i = 0; i < vertices.size(); ++i)
      position[std::size_t(vertices[i])] = saved[i];
  }

  // Gives the parts (connected_parts()) that still hold a fold their snapped positions back, unless
  // `keep_partial` and their repaired positions hold fewer folds than those.
  void restore_failed_parts(const std::vector<std::vector<int>>& parts, const std::vector<Eigen::Vector3d>& snapped,
                            bool keep_partial)
  {
    std::vector<std::uint8_t> at_fold(position.size(), 0);
    for (int f : folds)
      for (int k = 0; k < 3; ++k)
        at_fold[std::size_t(corner(f, k))] = 1;
    std::vector<int> seen = huge_page_vector(face_vertex.size() / 3, -1);
    std::vector<Eigen::Vector3d> repaired;
    for (std::size_t p = 0; p < parts.size(); ++p) {
      const std::vector<int>& part = parts[p];
      if (std::none_of(part.begin(), part.end(), [&](int v) { return at_fold[std::size_t(v)] != 0; }))
        continue;
      std::vector<int> faces;
      for (int v : part)
        for_faces_of(v, [&](int f) {
          if (seen[std::size_t(f)] != int(p)) {
            seen[std::size_t(f)] = int(p);
            faces.push_back(f);
          }
        });
      auto count = [&] { return std::count_if(faces.begin(), faces.end(), [&](int f) { return folded(f); }); };
      const auto folded_repaired = count();
      repaired.resize(part.size());
      for (std::size_t i = 0; i < part.size(); ++i) {
        repaired[i] = position[std::size_t(part[i])];
        position[std::size_t(part[i])] = snapped[std::size_t(part[i])];
      }
      if (keep_partial && folded_repaired < count())
        for (std::size_t i = 0; i < part.size(); ++i)
          position[std::size_t(part[i])] = repaired[i];
    }
  }
};

// Whether a region's folds still fall, check by check. A count under kStallFactor of the fewest so far is
// progress; a count above the last one, in the first kTakingInChecks checks and before the folds first fell,
// is a region still taking folds in as it grows onto them (the first sweeps fold more faces than they unfold);
// anything else is a stall, and two in a row end the region's repair. A widened hole's rim rises at the first
// check, then loses 4-60% a check. A scan's regions, which never unfold, either lose 0.2-5% a check and then
// rise again, or rise from the start, as the sweeps over a growing region fold new faces at its pinned borders
// (1M and 4M faces: 12 rounds for nothing, the wide region growing to 194k and 406k vertices).
constexpr double kStallFactor = 0.95;
constexpr int kTakingInChecks = 3;

class FoldTrend
{
public:
  explicit FoldTrend(std::size_t folds) : last_(folds), fewest_(folds) {}
  // Records this check's count; true once the folds have stalled twice in a row.
  bool stalled(std::size_t folds)
  {
    ++checks_;
    const bool taking_in = folds > last_ && !fell_ && checks_ <= kTakingInChecks;
    fell_ = fell_ || folds < last_;
    if (folds == 0 || taking_in || double(folds) < kStallFactor * double(fewest_)) {
      fewest_ = folds;
      stalls_ = 0;
    } else {
      ++stalls_;
    }
    last_ = folds;
    return stalls_ >= 2;
  }

private:
  std::size_t last_, fewest_;
  bool fell_ = false;
  int checks_ = 0;
  int stalls_ = 0;
};

// The region has stopped growing; Gauss-Seidel needs about as many sweeps as the region is rings deep squared
// to converge, more than the rounds gave it. Each connected part sweeps on (options.settle_sweeps at most)
// while it holds folds and they have not stalled (folds that stall are held by the border, not by a lack of
// sweeps), or, once they are gone, while it still moves, which only evens it out: the last state without
// folds is kept. Parts stop on their own, so a scan's unrepairable folds do not keep the others sweeping.
// `parts` is region.connected_parts(). Rounds (find_folds' marks) count on from `round`; returns the last round
// any part reached (`round` when none settled).
template <class Constrain>
int settle(const FoldRegion& region, const std::vector<std::vector<int>>& parts, Constrain& constrain,
           const RepairFoldsOptions& options, std::vector<int>& mark, int round)
{
  int last = round;
  if (options.settle_sweeps <= 0)
    return last;
  for (std::size_t p = 0; p < parts.size(); ++p) {
    FoldRegion part{region.position, region.face_vertex, region.vertex_faces, region.reference, region.umbrella,
                    region.lister, region.id + 1 + int(p), {}, parts[p], {}};
    int r = round;
    part.find_folds({}, mark, r++);
    double first_move = -1, move = 0;
    FoldTrend trend(part.folds.size());
    bool stalled = false;
    std::vector<Eigen::Vector3d> unfolded;
    for (int settled = 0;
         settled < options.settle_sweeps && !stalled && (!part.folds.empty() || move > 0.01 * first_move); ++r) {
      if (part.folds.empty())
        part.save(unfolded);
      for (int s = 0; s < options.sweeps_per_round; ++s, ++settled)
        move = part.sweep(constrain);
      first_move = first_move < 0 ? move : first_move;
      part.find_folds({}, mark, r);
      stalled = trend.stalled(part.folds.size());
    }
    if (!part.folds.empty() && !unfolded.empty())
      part.load(unfolded);
    last = std::max(last, r);
  }
  return last;
}

} // namespace repair_detail

template <class Movable, class Constrain>
RepairFoldsReport repair_folds(std::vector<Eigen::Vector3d>& position, const std::vector<int>& face_vertex,
                               const VertexFaces& vertex_faces, const std::vector<Eigen::Vector3d>& reference,
                               Movable&& movable, Constrain&& constrain, const RepairFoldsOptions& options = {})
{
  RepairFoldsReport report;
  LazyLists umbrella(0); // sized, as lister, once there is a fold to repair
  std::vector<int> lister;
  repair_detail::FoldRegion region{position, face_vertex, vertex_faces, reference, umbrella, lister, 0,
                                   std::vector<std::uint8_t>(position.size(), 0), {}, {}};
  for (int f = 0; f < int(reference.size()); ++f)
    if (region.folded(f))
      region.folds.push_back(f);
  if (region.folds.empty())
    return report;
  umbrella = LazyLists(position.size());
  assign_on_huge_pages(lister, reference.size(), -1);

  const std::vector<Eigen::Vector3d> snapped = [&] {
    std::vector<Eigen::Vector3d> copy = huge_page_vector<Eigen::Vector3d>(position.size());
    std::copy(position.begin(), position.end(), copy.begin());
    return copy;
  }();
  const std::vector<int> first_folds = region.folds; // those with no movable vertex stay on the list
  std::vector<int> mark = huge_page_vector(reference.size(), -1);
  repair_detail::FoldTrend trend(region.folds.size());
  for (bool stalled = false; report.rounds < options.max_rounds && !region.folds.empty() && !stalled;
       ++report.rounds) {
    region.grow(movable, options.widen);
    region.sweep_parts(constrain, options.sweeps_per_round, options.threads);
    region.find_folds(first_folds, mark, report.rounds);
    stalled = trend.stalled(region.folds.size());
  }
  std::vector<std::vector<int>> parts;
  if (options.settle_sweeps > 0 || !region.folds.empty())
    parts = region.connected_parts();
  const int settled = repair_detail::settle(region, parts, constrain, options, mark, report.rounds);
  if (settled > report.rounds) { // something moved since the last round's search
    report.rounds = settled;
    region.find_folds(first_folds, mark, report.rounds); // marks from here on are ones no find_folds has used
  }
  if (!region.folds.empty()) {
    region.restore_failed_parts(parts, snapped, options.keep_partial);
    region.find_folds(first_folds, mark, report.rounds + 1);
  }
  report.folded_faces = int(region.folds.size());
  for (int v : region.vertices)
    if (position[std::size_t(v)] != snapped[std::size_t(v)])
      ++report.moved_vertices;
  return report;
}

} // namespace primitive_edit

#endif
