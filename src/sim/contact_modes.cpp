// SPDX-License-Identifier: BSD-3-Clause
// The modes of the full-contact state matrix, for the exact propagation (contact_propagator.hpp).
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <cmath>

#include "contact_propagator.hpp"

namespace flexrock::detail {

bool decompose_contact_matrix(const MatrixX& a, ContactModes& out) {
  Eigen::EigenSolver<MatrixX> es(a);
  if (es.info() != Eigen::Success) return false;
  out.v = es.eigenvectors();
  out.lambda = es.eigenvalues();
  out.v_inv = Eigen::PartialPivLU<Eigen::MatrixXcd>(out.v).inverse();
  // a nearly defective A (repeated eigenvalues, critical damping) has nearly parallel
  // eigenvectors: its exponential from them would lose digits
  const double cond =
      out.v.cwiseAbs().rowwise().sum().maxCoeff() * out.v_inv.cwiseAbs().rowwise().sum().maxCoeff();
  if (!(cond < 1e6)) return false;
  const Eigen::MatrixXcd back = out.v * out.lambda.asDiagonal() * out.v_inv;
  if (!((back.real() - a).cwiseAbs().maxCoeff() <= 1e-10 * a.cwiseAbs().maxCoeff())) return false;
  // A is singular only with a zero-frequency mode, which a body cannot have; guard anyway
  const Eigen::PartialPivLU<MatrixX> lu(a);
  if (!(lu.rcond() > 1e-12)) return false;
  out.a_inv = lu.inverse();
  out.scratch.setZero(a.rows());
  out.product.setZero(a.rows(), a.cols());
  out.full.setZero(a.rows(), a.cols());
  out.transition.setZero(a.rows(), a.cols());
  return true;
}

void contact_transition(ContactModes& modes, double tau) {
  for (Eigen::Index i = 0; i < modes.lambda.size(); ++i)
    modes.scratch(i) = std::exp(modes.lambda(i) * tau);
  modes.product.noalias() = modes.v * modes.scratch.asDiagonal();
  modes.full.noalias() = modes.product * modes.v_inv;
  modes.transition = modes.full.real();
}

}  // namespace flexrock::detail
