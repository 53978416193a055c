#include "common/geometry/edge_blend_likelihood.h"

#include "common/base/constants.h"

#include <algorithm>
#include <cmath>
#include <limits>
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

bool within_reach(const EdgeSection& e, const Eigen::Vector3d& q, double reach)
{
  return q.dot(e.ray_a) < reach && q.dot(e.ray_b) < reach;
}

// The legs run 3 sigma past the reach, so that a point near the window's limit sees a whole leg.
double far_end(double reach, double sigma) { return reach + 3 * sigma; }

// A point of the window in the section with the parts of its density along the legs that do not depend on the
// setback (the legs run from the tangent points, the setback s along each ray, to the far end): its coordinate
// along each ray, the Gaussian across it and the normal CDF beyond the far end. A leg's density at setback s is then
// across * (normal_cdf((along - s) / sigma) - beyond), one erfc instead of two and an exp.
struct SectionPoint
{
  Eigen::Vector3d q;
  double weight = 0;
  double along_a = 0, across_a = 0, beyond_a = 0;
  double along_b = 0, across_b = 0, beyond_b = 0;
};

// The window's points (within the reach of both rays, of positive weight), in their order.
std::vector<SectionPoint> section_points(const EdgeSection& e, const Eigen::MatrixX3d& points,
                                         const Eigen::VectorXd& weights, double sigma, double reach)
{
  std::vector<SectionPoint> out;
  const double far = far_end(reach, sigma);
  const double norm = 1.0 / (std::sqrt(2 * kPi) * sigma);
  auto leg = [&](const Eigen::Vector3d& q, const Eigen::Vector3d& ray, double& along, double& across,
                 double& beyond) {
    along = q.dot(ray);
    across = std::exp(-(q - along * ray).squaredNorm() / (2 * sigma * sigma)) * norm;
    beyond = normal_cdf((along - far) / sigma);
  };
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    SectionPoint p;
    p.q = in_section(e, points.row(i).transpose());
    if (!within_reach(e, p.q, reach) || !(weights[i] > 0))
      continue;
    p.weight = weights[i];
    leg(p.q, e.ray_a, p.along_a, p.across_a, p.beyond_a);
    leg(p.q, e.ray_b, p.along_b, p.across_b, p.beyond_b);
    out.push_back(p);
  }
  return out;
}

// The profile's blend in the section: the tangent points and, for a fillet, the arc between them.
struct Profile
{
  Eigen::Vector3d ta, tb; // tangent points
  bool arc = false;
  Eigen::Vector3d centre;
  Eigen::Vector3d e1, e2; // the arc: centre + r (cos t e1 + sin t e2), t in [0, sweep]
  double radius = 0, sweep = 0, blend_length = 0;
  int arc_samples = 0;
  std::vector<Eigen::Vector3d> arc_points; // the arc's samples, at the middles of arc_samples equal pieces
};

Profile profile(const EdgeSection& e, BlendForm form, double s, double sigma)
{
  Profile p;
  p.ta = s * e.ray_a;
  p.tb = s * e.ray_b;
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

double profile_density(const Profile& p, const SectionPoint& x, double setback, double sigma)
{
  const Eigen::Vector3d& q = x.q;
  double d = x.across_a * (normal_cdf((x.along_a - setback) / sigma) - x.beyond_a) +
             x.across_b * (normal_cdf((x.along_b - setback) / sigma) - x.beyond_b);
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

// edge_blend_cost over the window's points.
double window_cost(const EdgeSection& e, const std::vector<SectionPoint>& points, double sigma, double reach,
                   BlendForm form, double setback)
{
  // The density is normalised by the profile's length inside the window, where the points are.
  const Profile p = profile(e, form, setback, sigma);
  const double inside = 2 * (reach - setback) + p.blend_length;
  const double outlier = kBlendOutlierShare / (4 * reach * reach); // uniform over the square of side 2 L
  double cost = 0, weight = 0;
  for (const SectionPoint& x : points) {
    const double density = (1 - kBlendOutlierShare) * profile_density(p, x, setback, sigma) / inside + outlier;
    cost -= x.weight * std::log(density);
    weight += x.weight;
  }
  return weight > 0 ? cost / weight : 0.0;
}

} // namespace

double edge_blend_cost(const EdgeSection& e, const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights,
                       double sigma, double reach, BlendForm form, double setback)
{
  // A setback at or beyond the reach leaves no legs in the window: no profile to weigh the points by.
  if (!(setback >= 0 && setback < reach))
    return std::numeric_limits<double>::infinity();
  return window_cost(e, section_points(e, points, weights, sigma, reach), sigma, reach, form, setback);
}

std::optional<EdgeBlendEstimate> best_edge_blend(const EdgeSection& e, const Eigen::MatrixX3d& points,
                                                 const Eigen::VectorXd& weights, double sigma, double reach,
                                                 double max_setback)
{
  if (!(std::isfinite(sigma) && sigma > 0 && std::isfinite(reach) && reach > 0 && max_setback > 0 &&
        max_setback < reach) ||
      points.rows() != weights.size())
    return std::nullopt;
  const std::vector<SectionPoint> window = section_points(e, points, weights, sigma, reach);
  const auto used = Eigen::Index(window.size());
  if (used == 0)
    return std::nullopt;
  const double sharp = window_cost(e, window, sigma, reach, BlendForm::Fillet, 0.0);
  EdgeBlendEstimate best;
  double best_cost = sharp;
  const double coarse = max_setback / kBlendSetbackSteps;
  for (BlendForm form : {BlendForm::Fillet, BlendForm::Chamfer}) {
    // The coarse grid, then kBlendFineSteps finer steps on each side of this form's best.
    double form_setback = 0, form_cost = sharp;
    auto consider = [&](double s) {
      const double c = window_cost(e, window, sigma, reach, form, s);
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
