// edge_blend_likelihood.h: whether the points about the edge of two planes lie on a fillet or chamfer, and of what
// setback, told by their likelihood under the scan's noise.
//
// Input:  an EdgeSection (edge_blend.h), the points about the edge and their weights (areas), the noise's spread
//         sigma > 0 (its standard deviation across the surface), the reach L > 0 (the profile runs from L along one
//         ray through the blend to L along the other; points beyond L along either ray are left out), and for the
//         search the largest setback (below L).
// Output: edge_blend_cost: the weighted negative log-likelihood of the points, per unit weight, under the profile
//         with a blend of the given form and setback (0: the sharp edge; +infinity for a setback outside [0, L),
//         which leaves the profile no legs in the window). best_edge_blend: the form and setback of
//         least cost, on a grid of kBlendSetbackSteps setbacks up to the largest refined by kBlendFineSteps on
//         each side of each form's best (a chamfer only when it gains kChamferGainMargin more than the fillet: near the noise
//         the two pass through nearly the same points), and its gain over the sharp edge
//         (the sharp edge's cost minus the blend's, times the points' weight in units of their mean: a
//         log-likelihood ratio over the points).
// Method: in the section the profile is a curve (two rays and the blend between them); a point is drawn uniformly by
//         length along it and moved by isotropic Gaussian noise, or, with probability kBlendOutlierShare, uniformly
//         over the window (faces of other surfaces). The density is the curve's convolution with the Gaussian divided
//         by the curve's length: without that normalisation the longer sharp profile wins everywhere. A straight
//         piece is convolved in closed form (the Gaussian across it times the difference of two normal CDFs along
//         it), an arc by summing samples spaced sigma / 2. Least squares of the distances would not do: at the noise
//         of a CT scan's roughness it finds a blend at a sharp edge and too small a blend at a fillet (isotropic
//         noise of 0.5 mm: setback 0.7 mm for a sharp edge, 0.8 for a 1.5 mm fillet; bench/bracket/README.md),
//         while the likelihood finds 0-0.1 and 1.3-1.5 mm.
// Cost:   O(points) per cost (an arc's samples within 4 sigma of a point); the search is
//         1 + 2 * (kBlendSetbackSteps + 2 * kBlendFineSteps) costs, and takes each point into the section and the
//         parts of its legs' densities that do not depend on the setback (the Gaussian across each ray, the CDF
//         beyond its far end) once, leaving one erfc per leg and cost.
#ifndef PRIMITIVE_EDIT_EDGE_BLEND_LIKELIHOOD_H
#define PRIMITIVE_EDIT_EDGE_BLEND_LIKELIHOOD_H

#include "common/geometry/edge_blend.h"

#include <Eigen/Core>

#include <optional>

namespace primitive_edit {

// The window a blend is judged in, in fit tolerances (the segmentation's carve, Fit All's found blends): the points
// within the reach of the planes' line, setbacks searched up to the largest; at most kBlendPoints of them; and the
// log-likelihood gain over the sharp edge that makes a blend.
constexpr double kBlendReachTolerances = 5.0;
constexpr double kBlendSetbackTolerances = 4.0;
constexpr int kBlendPoints = 1000;
constexpr double kMinBlendGain = 10.0;

constexpr double kBlendOutlierShare = 0.1;
constexpr double kChamferGainMargin = 0.1; // a chamfer's gain must exceed the fillet's by this share
constexpr int kBlendSetbackSteps = 10; // the coarse grid of setbacks up to the largest
constexpr int kBlendFineSteps = 3;     // finer steps on each side of a form's best, a quarter of the grid's apart

double edge_blend_cost(const EdgeSection& section, const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights,
                       double sigma, double reach, BlendForm form, double setback);

struct EdgeBlendEstimate
{
  BlendForm form = BlendForm::Fillet;
  double setback = 0;
  double gain = 0; // log-likelihood ratio of the blend over the sharp edge
};

// std::nullopt when sigma or the reach is not positive and finite, the largest setback is not within (0, reach), or
// no point lies within the reach.
std::optional<EdgeBlendEstimate> best_edge_blend(const EdgeSection& section, const Eigen::MatrixX3d& points,
                                                 const Eigen::VectorXd& weights, double sigma, double reach,
                                                 double max_setback);

} // namespace primitive_edit

#endif
