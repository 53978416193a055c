#include "common/relate/constrained_step.h"

namespace primitive_edit {

Eigen::VectorXd constrained_step(const std::vector<StepBlock>& blocks, const Eigen::MatrixXd& C,
                                 const Eigen::VectorXd& c, double lambda)
{
  const Eigen::Index n = C.cols(), m = C.rows();
  Eigen::MatrixXd AinvCt = Eigen::MatrixXd::Zero(n, m);
  Eigen::VectorXd Ainvg = Eigen::VectorXd::Zero(n);
  for (const StepBlock& b : blocks) {
    const Eigen::Index k = b.H.rows();
    Eigen::MatrixXd A = b.H;
    const double floor = 1e-12 * std::max(A.diagonal().maxCoeff(), 1e-300);
    A.diagonal() += lambda * (A.diagonal().array() + floor).matrix();
    A.diagonal().array() += floor;
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(A);
    if (ldlt.info() != Eigen::Success)
      return {};
    if (m > 0)
      AinvCt.middleRows(b.offset, k) = ldlt.solve(C.middleCols(b.offset, k).transpose());
    Ainvg.segment(b.offset, k) = ldlt.solve(b.g);
  }
  Eigen::VectorXd d = -Ainvg;
  if (m > 0) {
    const Eigen::MatrixXd S = C * AinvCt;
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 * (S + S.transpose()));
    const Eigen::VectorXd& ev = eig.eigenvalues();
    const double cut = 1e-13 * std::max(ev.cwiseAbs().maxCoeff(), 1e-300);
    Eigen::VectorXd coef = eig.eigenvectors().transpose() * (c - C * Ainvg);
    for (Eigen::Index i = 0; i < coef.size(); ++i)
      coef[i] = ev[i] > cut ? coef[i] / ev[i] : 0.0;
    d -= AinvCt * (eig.eigenvectors() * coef);
  }
  if (!d.allFinite())
    return {};
  return d;
}

} // namespace primitive_edit
