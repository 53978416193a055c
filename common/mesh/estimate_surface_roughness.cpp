#include "common/mesh/estimate_surface_roughness.h"

#include "common/base/prefetch.h"
#include "common/mesh/prefetch_walk_ahead.h"

namespace primitive_edit {

double quadric_patch_rms(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights, const WeightedPca& pca)
{
  if (!pca.ok)
    return -1.0;
  // Coordinates scaled by the patch's extent keep the 6 x 6 normal equations well conditioned.
  const double inverse_scale = 1.0 / std::sqrt(std::max(pca.eigenvalues[2], 1e-300));
  const Eigen::Vector3d normal = pca.axes.col(0), across = pca.axes.col(1) * inverse_scale,
                        along = pca.axes.col(2) * inverse_scale;
  // The normal equations of the rows (u^2, uv, v^2, u, v, 1) hold the 15 weighted moments of u^a v^b, a + b <= 4,
  // and the right side the 6 of h u^a v^b, a + b <= 2: summed point by point, not over stored rows (a patch is
  // thousands of points).
  double m[5][5] = {};  // m[a][b] = sum w u^a v^b
  double mh[3][3] = {}; // mh[a][b] = sum w h u^a v^b
  // Point i's height h over the PCA plane and its scaled coordinates (u, v) in it.
  auto local = [&](Eigen::Index i, double& h, double& u, double& v) {
    const Eigen::Vector3d d = points.row(i).transpose() - pca.centroid;
    h = d.dot(normal);
    u = d.dot(along);
    v = d.dot(across);
  };
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    double h, u, v;
    local(i, h, u, v);
    const double w = weights[i], u2 = u * u, v2 = v * v;
    const double wu = w * u, wv = w * v, wu2 = w * u2, wv2 = w * v2, wuv = wu * v;
    m[0][0] += w;
    m[1][0] += wu;
    m[0][1] += wv;
    m[2][0] += wu2;
    m[1][1] += wuv;
    m[0][2] += wv2;
    m[3][0] += wu2 * u;
    m[2][1] += wu2 * v;
    m[1][2] += wv2 * u;
    m[0][3] += wv2 * v;
    m[4][0] += wu2 * u2;
    m[3][1] += wu2 * u * v;
    m[2][2] += wu2 * v2;
    m[1][3] += wv2 * u * v;
    m[0][4] += wv2 * v2;
    mh[0][0] += w * h;
    mh[1][0] += wu * h;
    mh[0][1] += wv * h;
    mh[2][0] += wu2 * h;
    mh[1][1] += wuv * h;
    mh[0][2] += wv2 * h;
  }
  const double sum_w = m[0][0];
  if (!(sum_w > 0))
    return -1.0;
  static constexpr int kPowers[6][2] = {{2, 0}, {1, 1}, {0, 2}, {1, 0}, {0, 1}, {0, 0}};  // row i is u^a v^b
  Eigen::Matrix<double, 6, 6> A;
  Eigen::Matrix<double, 6, 1> rhs;
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j)
      A(i, j) = m[kPowers[i][0] + kPowers[j][0]][kPowers[i][1] + kPowers[j][1]];
    rhs[i] = mh[kPowers[i][0]][kPowers[i][1]];
  }
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt(A);
  if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().cwiseAbs().minCoeff() > 1e-12 * ldlt.vectorD().cwiseAbs().maxCoeff()))
    return -1.0;
  const Eigen::Matrix<double, 6, 1> c = ldlt.solve(rhs);
  // The residuals themselves, not sum w h^2 - c . rhs, which cancels on a surface the quadric fits exactly.
  double sum_r2 = 0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    double h, u, v;
    local(i, h, u, v);
    const double r = h - (((c[0] * u + c[1] * v + c[3]) * u + (c[2] * v + c[4]) * v) + c[5]);
    sum_r2 += weights[i] * r * r;
  }
  // The fit's 6 parameters take 6 of the N degrees of freedom.
  const double n = double(points.rows());
  return std::sqrt(sum_r2 / sum_w * n / (n - 6.0));
}

namespace roughness_detail {

void grow_patch(const FaceAdjacency& adj, int seed, int mark, int patch_faces, std::vector<int>& stamp,
                std::vector<int>& patch)
{
  patch.assign(1, seed);
  stamp[std::size_t(seed)] = mark;
  for (std::size_t head = 0; head < patch.size() && int(patch.size()) < patch_faces; ++head) {
    prefetch_walk_ahead(adj, patch, head, 8, [&](std::size_t h) { prefetch(stamp.data() + h); });
    const int f = patch[head];
    for (int k = adj.offset[std::size_t(f)]; k < adj.offset[std::size_t(f) + 1] && int(patch.size()) < patch_faces;
         ++k) {
      const int h = adj.neighbour[std::size_t(k)];
      if (stamp[std::size_t(h)] < mark) {
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
    for (std::size_t f = 0; f < n; ++f)
      if (!(area[f] > 0))
        stamp[f] = roughness_detail::kUnusableFace;
    for (std::size_t i = begin; i < end; ++i) {
      roughness_detail::grow_patch(adj, seeds[i], int(i), patch_faces, stamp, patch);
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
