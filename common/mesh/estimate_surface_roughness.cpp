#include "common/mesh/estimate_surface_roughness.h"

#include "common/base/prefetch.h"
#include "common/mesh/prefetch_walk_ahead.h"

namespace primitive_edit {

double quadric_patch_rms(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights, const WeightedPca& pca)
{
  if (!pca.ok)
    return -1.0;
  // Coordinates scaled by the patch's extent keep the 6 x 6 normal equations well conditioned.
  const double scale = std::sqrt(std::max(pca.eigenvalues[2], 1e-300));
  const Eigen::MatrixX3d local = (points.rowwise() - pca.centroid.transpose()) * pca.axes;  // (n, v, u) per row
  Eigen::Matrix<double, Eigen::Dynamic, 6> rows(points.rows(), 6);
  rows.col(0) = local.col(2).array().square() / (scale * scale);
  rows.col(1) = local.col(2).array() * local.col(1).array() / (scale * scale);
  rows.col(2) = local.col(1).array().square() / (scale * scale);
  rows.col(3) = local.col(2) / scale;
  rows.col(4) = local.col(1) / scale;
  rows.col(5).setOnes();
  const double sum_w = weights.sum();
  if (!(sum_w > 0))
    return -1.0;
  const Eigen::Matrix<double, 6, 6> A = rows.transpose() * weights.asDiagonal() * rows;
  const Eigen::Matrix<double, 6, 1> rhs = rows.transpose() * weights.cwiseProduct(local.col(0));
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt(A);
  if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().cwiseAbs().minCoeff() > 1e-12 * ldlt.vectorD().cwiseAbs().maxCoeff()))
    return -1.0;
  const Eigen::VectorXd r = local.col(0) - rows * ldlt.solve(rhs);
  // The fit's 6 parameters take 6 of the N degrees of freedom.
  const double n = double(points.rows());
  return std::sqrt(weights.dot(r.cwiseAbs2()) / sum_w * n / (n - 6.0));
}

namespace roughness_detail {

void grow_patch(const FaceAdjacency& adj, const std::vector<double>& area, int seed, int mark, int patch_faces,
                std::vector<int>& stamp, std::vector<int>& patch)
{
  patch.assign(1, seed);
  stamp[std::size_t(seed)] = mark;
  for (std::size_t head = 0; head < patch.size() && int(patch.size()) < patch_faces; ++head) {
    prefetch_walk_ahead(adj, patch, head, 8, [&](std::size_t h) {
      prefetch(stamp.data() + h);
      prefetch(area.data() + h);
    });
    const int f = patch[head];
    for (int k = adj.offset[std::size_t(f)]; k < adj.offset[std::size_t(f) + 1] && int(patch.size()) < patch_faces;
         ++k) {
      const int h = adj.neighbour[std::size_t(k)];
      if (stamp[std::size_t(h)] != mark && area[std::size_t(h)] > 0) {
        stamp[std::size_t(h)] = mark;
        patch.push_back(h);
      }
    }
  }
}

std::pair<double, double> patch_rms(const std::vector<Eigen::Vector3d>& centroid,
                                    const std::vector<double>& area, const std::vector<int>& patch)
{
  constexpr double none = std::numeric_limits<double>::quiet_NaN();
  Eigen::MatrixX3d points(Eigen::Index(patch.size()), 3);
  Eigen::VectorXd weights(Eigen::Index(patch.size()));
  for (std::size_t j = 0; j < patch.size(); ++j) {
    if (j + 8 < patch.size()) {
      prefetch(centroid.data() + patch[j + 8]);
      prefetch(area.data() + patch[j + 8]);
    }
    points.row(Eigen::Index(j)) = centroid[std::size_t(patch[j])].transpose();
    weights[Eigen::Index(j)] = area[std::size_t(patch[j])];
  }
  const WeightedPca pca = weighted_pca(points, weights);
  const double plane = pca.ok && std::isfinite(pca.eigenvalues[0]) ? std::sqrt(std::max(0.0, pca.eigenvalues[0])) : none;
  const double q = patch.size() > 12 ? quadric_patch_rms(points, weights, pca) : -1.0;
  return {plane, q >= 0 && std::isfinite(q) ? q : none};
}

std::vector<int> evenly_spread_faces(const std::vector<double>& area, std::size_t usable, std::size_t count)
{
  std::vector<int> faces;
  faces.reserve(count);
  std::size_t rank = 0;
  for (std::size_t f = 0; f < area.size() && faces.size() < count; ++f) {
    if (!(area[f] > 0))
      continue;
    if (rank == (faces.size() * usable) / count)
      faces.push_back(int(f));
    ++rank;
  }
  return faces;
}

} // namespace roughness_detail

SurfaceRoughness measure_surface_roughness(const std::vector<Eigen::Vector3d>& centroid,
                                           const std::vector<double>& area, const FaceAdjacency& adj,
                                           int patch_faces, int threads)
{
  SurfaceRoughness out;
  const std::size_t n = centroid.size();
  if (area.size() != n || adj.face_count() != int(n) || n == 0)
    return out;
  const std::size_t usable = std::size_t(std::count_if(area.begin(), area.end(), [](double a) { return a > 0; }));
  if (patch_faces <= 0)
    patch_faces = std::max(60, int(usable / 200));

  // Each patch is measured alone and its figures kept at its own index, so the quantiles below see the same
  // values in the same order whatever the threads.
  const std::vector<int> seeds =
      roughness_detail::evenly_spread_faces(area, usable, std::min<std::size_t>(400, usable));
  std::vector<std::pair<double, double>> rms(seeds.size(), {std::nan(""), std::nan("")});
  parallel_for(seeds.size(), threads, 50, [&](std::size_t begin, std::size_t end) {
    std::vector<int> stamp = huge_page_vector(n, -1), patch; // advised: fewer faults on a first call
    for (std::size_t i = begin; i < end; ++i) {
      roughness_detail::grow_patch(adj, area, seeds[i], int(i), patch_faces, stamp, patch);
      if (int(patch.size()) >= std::max(3, patch_faces / 2))
        rms[i] = roughness_detail::patch_rms(centroid, area, patch);
    }
  });
  std::vector<double> plane_rms, quadric_rms;
  for (const auto& [plane, quadric] : rms) {
    if (!std::isnan(plane))
      plane_rms.push_back(plane);
    if (!std::isnan(quadric))
      quadric_rms.push_back(quadric);
  }
  if (plane_rms.empty())
    return out;
  auto quantile = [](std::vector<double>& v, std::size_t divisor) {
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / divisor), v.end());
    return v[v.size() / divisor];
  };
  out.waviness = quantile(plane_rms, 2);
  out.noise = quadric_rms.empty() ? out.waviness : quantile(quadric_rms, 4);
  out.roughness = out.waviness <= kMedianPatchSmoothRatio * out.noise ? out.waviness : out.noise;
  return out;
}

double estimate_surface_roughness(const std::vector<Eigen::Vector3d>& centroid, const std::vector<double>& area,
                                  const FaceAdjacency& adj, int patch_faces, int threads)
{
  return measure_surface_roughness(centroid, area, adj, patch_faces, threads).roughness;
}

} // namespace primitive_edit
