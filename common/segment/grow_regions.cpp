#include "common/segment/grow_regions.h"

#include "common/mesh/prefetch_walk_ahead.h"

namespace primitive_edit {

namespace grow_detail {

void grow_while_agreeing(const GrowingFaces& g, const FaceAdjacency& adj, const GrowingScale& scale, int id,
                         Primitive& prim, std::size_t& fitted_size, std::vector<int>& region,
                         std::vector<int>& label, FaceStamps& stamps, std::vector<int>& queue,
                         std::vector<int>& open_faces)
{
  auto unassigned = [&](int f) { return g.valid[std::size_t(f)] && label[std::size_t(f)] < 0; };
  const FaceAgreement agrees(scale.tolerance, scale.angle);
  open_faces = region;
  for (;;) {
    const int grow_mark = ++stamps.mark;
    queue.swap(open_faces);
    open_faces.clear();
    std::size_t head = 0;
    while (head < queue.size()) {
      prefetch_walk_ahead(adj, queue, head, 16, [&](std::size_t h) {
        prefetch(g.valid.data() + h);
        prefetch(label.data() + h);
        prefetch(stamps.stamp.data() + h);
        prefetch(g.centroid.data() + h);
        prefetch(g.normal.data() + h);
      });
      const int f = queue[head++];
      bool open = false;
      for (int k = adj.offset[std::size_t(f)]; k < adj.offset[std::size_t(f) + 1]; ++k) {
        const int h = adj.neighbour[std::size_t(k)];
        if (!unassigned(h))
          continue;
        if (stamps.stamp[std::size_t(h)] != grow_mark) {
          stamps.stamp[std::size_t(h)] = grow_mark;
          if (agrees(g, prim, h)) {
            label[std::size_t(h)] = id;
            region.push_back(h);
            queue.push_back(h);
            continue;
          }
        }
        open = true; // h was rejected, now or earlier in this walk
      }
      if (open)
        open_faces.push_back(f);
      if (region.size() >= fitted_size + fitted_size / 2)
        break;
    }
    if (region.size() < fitted_size + fitted_size / 2)
      return;
    open_faces.insert(open_faces.end(), queue.begin() + std::ptrdiff_t(head), queue.end()); // not walked from yet
    fitted_size = region.size();
    if (const std::optional<Primitive> refined =
            fit_region_primitive(g, region, &prim, scale.tolerance, scale.angle, 0.9))
      prim = *refined;
  }
}

std::optional<Primitive> wider_type(const GrowingFaces& g, const FaceAdjacency& adj, const GrowingScale& scale,
                                    const Primitive& prim, const std::vector<int>& region,
                                    const std::vector<int>& open_faces, const std::vector<int>& label,
                                    FaceStamps& stamps, std::vector<int>& band, int threads)
{
  const int mark = ++stamps.mark;
  band = region;
  const std::size_t inner = band.size();
  auto add_unassigned_neighbours = [&](int f) {
    for (int k = adj.offset[std::size_t(f)]; k < adj.offset[std::size_t(f) + 1]; ++k) {
      const int h = adj.neighbour[std::size_t(k)];
      if (stamps.stamp[std::size_t(h)] != mark && g.valid[std::size_t(h)] && label[std::size_t(h)] < 0) {
        stamps.stamp[std::size_t(h)] = mark;
        band.push_back(h);
      }
    }
  };
  // The first ring: only the open faces have unassigned neighbours, and they are in region order.
  for (int f : open_faces)
    add_unassigned_neighbours(f);
  for (std::size_t ring = 1, begin = inner; ring < std::size_t(kBandRings); ++ring) {
    const std::size_t end = band.size();
    for (std::size_t i = begin; i < end; ++i)
      add_unassigned_neighbours(band[i]);
    begin = end;
  }
  if (band.size() == inner)
    return std::nullopt;
  std::optional<Primitive> wider =
      fit_region_primitive(g, band, nullptr, scale.tolerance, scale.angle, 0.95, threads);
  if (!wider || wider->type == prim.type)
    return std::nullopt;
  // Fitted to the rings as well, a type can bend to them at the region's cost: then it is a compromise across an
  // edge, not the wider surface the region is part of.
  if (sampled_rms(g, *wider, region) > sampled_rms(g, prim, region))
    return std::nullopt;
  return wider;
}

} // namespace grow_detail

GrowingRegions grow_regions(const GrowingFaces& g, const FaceAdjacency& adj, const GrowingScale& scale,
                            const Progress& progress, int threads)
{
  using namespace grow_detail;
  const std::size_t face_count = g.valid.size();
  GrowingRegions out;
  assign_on_huge_pages(out.label, face_count, -1);
  std::vector<int>& label = out.label;
  std::vector<char> failed = huge_page_vector(face_count, char(0)); // faces no seed should be tried from
  FaceStamps stamps;
  assign_on_huge_pages(stamps.stamp, face_count, 0);
  std::vector<int> patch, region, queue, open_faces, band;
  auto unassigned = [&](int f) { return g.valid[std::size_t(f)] && label[std::size_t(f)] < 0; };
  // A face once assigned or failed never seeds again, as SeedQueue requires.
  auto may_seed = [&](int f) { return unassigned(f) && !failed[std::size_t(f)]; };
  if (!(scale.tolerance > 0))
    return out;
  SeedQueue seeds(g, adj, threads);
  int reported = 0;
  for (int seed = seeds.next(may_seed); seed >= 0; seed = seeds.next(may_seed)) {
    if (const int percent = int(100.0 * seeds.share_passed()); percent > reported)
      report_progress(progress, reported = percent, "Growing regions");
    bfs_patch(adj, {seed}, std::size_t(scale.seed_patch_faces), unassigned, stamps, patch);
    std::optional<Primitive> prim;
    if (int(patch.size()) >= scale.seed_patch_faces / 2)
      prim = fit_region_primitive(g, patch, nullptr, scale.tolerance, scale.angle, 0.9);
    if (!prim) {
      for (int f : patch)
        failed[std::size_t(f)] = 1;
      continue;
    }
    const int id = int(out.primitive.size());
    region.assign(1, seed);
    label[std::size_t(seed)] = id;
    std::size_t fitted_size = patch.size();
    for (int type_changes = 0;; ++type_changes) {
      grow_while_agreeing(g, adj, scale, id, *prim, fitted_size, region, label, stamps, queue, open_faces);
      if (type_changes >= 2 || int(region.size()) < scale.min_region_faces)
        break;
      const std::optional<Primitive> wider =
          wider_type(g, adj, scale, *prim, region, open_faces, label, stamps, band, threads);
      if (!wider)
        break;
      prim = wider;
    }
    if (int(region.size()) < scale.min_region_faces || curvature_radius(*prim) < scale.min_curvature_radius) {
      for (int f : region) {
        label[std::size_t(f)] = -1;
        failed[std::size_t(f)] = 1;
      }
      continue;
    }
    out.primitive.push_back(*prim);
    out.faces.push_back(region);
  }
  return out;
}

} // namespace primitive_edit
