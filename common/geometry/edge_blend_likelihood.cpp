#include "common/geometry/edge_blend_likelihood.h"

#include "common/base/constants.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace primitive_edit {

namespace {

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

// The Gaussian (spread sigma, in the plane of the section) integrated along the segment from a to b, at q.
double segment_density(const Eigen::Vector3d& q, const Eigen::Vector3d& a, const Eigen::Vector3d& b, double sigma)
{
  const Eigen::Vector3d ab = b - a;
  const double length = ab.norm();
  if (!(length > 0))
    return 0.0;
  const Eigen::Vector3d u = ab / length;
  const double t = (q - a).dot(u);
  const double across2 = (q - a - t * u).squaredNorm();
  return std::exp(-across2 / (2 * sigma * sigma)) / (std::sqrt(2 * kPi) * sigma) *
         (normal_cdf(t / sigma) - normal_cdf((t - length) / sigma));
}

// The profile in the section: the legs from the tangent points out to `far` along each ray, and the blend.
struct Profile
{
  Eigen::Vector3d ta, tb, fa, fb; // tangent points and the legs' far ends
  bool arc = false;
  Eigen::Vector3d centre;
  Eigen::Vector3d e1, e2; // the arc: centre + r (cos t e1 + sin t e2), t in [0, sweep]
  double radius = 0, sweep = 0, blend_length = 0;
  int arc_samples = 0;
  std::vector<Eigen::Vector3d> arc_points; // the arc's samples, at the middles of arc_samples equal pieces
};

Profile profile(const EdgeSection& e, BlendForm form, double s, double far, double sigma)
{
  Profile p;
  p.ta = s * e.ray_a;
  p.tb = s * e.ray_b;
  p.fa = far * e.ray_a;
  p.fb = far * e.ray_b;
  if (s > 0 && form == BlendForm::Fillet) {
    p.arc = true;
    p.centre = e.bisector * (s / std::cos(e.half_angle));
    p.radius = s * std::tan(e.half_angle);
    p.sweep = kPi - 2 * e.half_angle;
    p.e1 = (p.ta - p.centre) / p.radius;
    const Eigen::Vector3d to_b = (p.tb - p.centre) / p.radius;
    p.e2 = (to_b - p.e1 * to_b.dot(p.e1)).normalized();
    p.blend_length = p.radius * p.sweep;
    p.arc_samples = std::max(1, int(std::ceil(p.blend_length / (0.5 * sigma))));
    for (int k = 0; k < p.arc_samples; ++k) {
      const double t = (k + 0.5) * p.sweep / p.arc_samples;
      p.arc_points.push_back(p.centre + p.radius * (std::cos(t) * p.e1 + std::sin(t) * p.e2));
    }
  } else {
    p.blend_length = (p.tb - p.ta).norm();
  }
  return p;
}

double profile_density(const Profile& p, const Eigen::Vector3d& q, double sigma)
{
  double d = segment_density(q, p.ta, p.fa, sigma) + segment_density(q, p.tb, p.fb, sigma);
  if (p.arc) {
    // Only the samples within 4 sigma of q along the arc count; the others add less than exp(-8) each.
    const double step = p.sweep / p.arc_samples, piece = p.blend_length / p.arc_samples;
    const Eigen::Vector3d c = q - p.centre;
    // q's angle about the centre, measured from the arc's start with the cut opposite the arc's middle.
    const double at = 0.5 * p.sweep + std::remainder(std::atan2(c.dot(p.e2), c.dot(p.e1)) - 0.5 * p.sweep, 2 * kPi);
    const double window = 4 * sigma / p.radius;
    const bool all = window >= kPi - 0.5 * p.sweep; // q may be near the arc across the cut
    const int first = all ? 0 : std::max(0, int(std::floor((at - window) / step))),
              last = all ? p.arc_samples - 1 : std::min(p.arc_samples - 1, int(std::ceil((at + window) / step)));
    double sum = 0;
    for (int k = first; k <= last; ++k)
      sum += std::exp(-(q - p.arc_points[std::size_t(k)]).squaredNorm() / (2 * sigma * sigma));
    d += sum * piece / (2 * kPi * sigma * sigma);
  } else {
    d += segment_density(q, p.ta, p.tb, sigma);
  }
  return d;
}

bool within_reach(const EdgeSection& e, const Eigen::Vector3d& q, double reach)
{
  return q.dot(e.ray_a) < reach && q.dot(e.ray_b) < reach;
}

} // namespace

double edge_blend_cost(const EdgeSection& e, const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights,
                       double sigma, double reach, BlendForm form, double setback)
{
  // The legs run 3 sigma past the reach, so that a point near the window's limit sees a whole leg; the density is
  // normalised by the profile's length inside the window, where the points are.
  const Profile p = profile(e, form, setback, reach + 3 * sigma, sigma);
  const double inside = 2 * (reach - setback) + p.blend_length;
  const double outlier = kBlendOutlierShare / (4 * reach * reach); // uniform over the square of side 2 L
  double cost = 0, weight = 0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const Eigen::Vector3d q = in_section(e, points.row(i).transpose());
    if (!within_reach(e, q, reach) || !(weights[i] > 0))
      continue;
    const double density = (1 - kBlendOutlierShare) * profile_density(p, q, sigma) / inside + outlier;
    cost -= weights[i] * std::log(density);
    weight += weights[i];
  }
  return weight > 0 ? cost / weight : 0.0;
}

std::optional<EdgeBlendEstimate> best_edge_blend(const EdgeSection& e, const Eigen::MatrixX3d& points,
                                                 const Eigen::VectorXd& weights, double sigma, double reach,
                                                 double max_setback)
{
  if (!(std::isfinite(sigma) && sigma > 0 && std::isfinite(reach) && reach > 0 && max_setback > 0 &&
        max_setback < reach) ||
      points.rows() != weights.size())
    return std::nullopt;
  Eigen::Index used = 0;
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    used += weights[i] > 0 && within_reach(e, in_section(e, points.row(i).transpose()), reach) ? 1 : 0;
  if (used == 0)
    return std::nullopt;
  const double sharp = edge_blend_cost(e, points, weights, sigma, reach, BlendForm::Fillet, 0.0);
  EdgeBlendEstimate best;
  double best_cost = sharp;
  const double coarse = max_setback / kBlendSetbackSteps;
  for (BlendForm form : {BlendForm::Fillet, BlendForm::Chamfer}) {
    // The coarse grid, then kBlendFineSteps finer steps on each side of this form's best.
    double form_setback = 0, form_cost = sharp;
    auto consider = [&](double s) {
      const double c = edge_blend_cost(e, points, weights, sigma, reach, form, s);
      if (c < form_cost)
        form_cost = c, form_setback = s;
    };
    for (int k = 1; k <= kBlendSetbackSteps; ++k)
      consider(coarse * k);
    const double centre = form_setback;
    for (int k = -kBlendFineSteps; centre > 0 && k <= kBlendFineSteps; ++k)
      if (const double s = centre + coarse * k / (kBlendFineSteps + 1); k != 0 && s > 0 && s <= max_setback)
        consider(s);
    // A chamfer must gain kChamferGainMargin more than the fillet: below a few times the noise the two pass through
    // nearly the same points (a 1.5 mm fillet and a 1 mm chamfer), and the fillet is the commoner blend.
    const double margin = form == BlendForm::Chamfer ? kChamferGainMargin * (sharp - best_cost) : 0.0;
    if (form_cost < best_cost - margin) {
      best_cost = form_cost;
      best.form = form;
      best.setback = form_setback;
    }
  }
  // Per unit of the mean weight: a log-likelihood ratio over the points.
  best.gain = (sharp - best_cost) * double(used);
  return best;
}

} // namespace primitive_edit
