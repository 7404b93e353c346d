// SPDX-License-Identifier: BSD-3-Clause
// The body: the paper's dynamic parameters (Moran & McLennan 1995), validated once, then const.
#pragma once

#include <string>

#include "flexrock/core/types.hpp"

namespace flexrock {

/// How material damping of the deformation modes is given.
enum class DampingKind {
  kNone,      // no material damping
  kRayleigh,  // C = a*mu + b*K, K = (g/h)*kappa
  kModal,     // damping ratios of the pinned-base modes
};

struct Damping {
  DampingKind kind = DampingKind::kNone;
  double rayleigh_mass = 0.0;       // a [1/s], coefficient on mu
  double rayleigh_stiffness = 0.0;  // b [s], coefficient on K = (g/h) kappa
  VectorX modal_ratios;             // [-] one ratio per pinned-base mode, ascending frequency
};

/// The paper's parameters of a deformable body on two tipping points. Every integral is over
/// the body with rho0 measured from the undeformed centre of mass and phi_i the assumed modes
/// (vanishing at both tipping points); q_i are dimensionless.
struct BodyParameters {
  double mass = 0.0;    // M [kg]
  double height = 0.0;  // h [m] height of the undeformed c.g. above the base
  double b1 = 0.0;      // [m] horizontal distance from the c.g. to the left tipping point 1
  double b2 = 0.0;      // [m] horizontal distance from the c.g. to the right tipping point 2
  double zeta2 = 0.0;   // zeta^2 = I_zz/(M h^2) [-] about the c.g.
  MatrixX mu;           // mu_ij = int phi_i.phi_j dm/(M h^2) [-], symmetric positive definite
  MatrixX kappa;        // kappa_ij = k_ij/(M g h) [-], symmetric positive definite
  MatrixX gamma;        // gamma_ij = k.int phi_i x phi_j dm/(M h^2) [-], antisymmetric
  VectorX psi_x;        // psi_xi = i.int phi_i dm/(M h) [-]
  VectorX psi_y;        // psi_yi = j.int phi_i dm/(M h) [-]
  VectorX delta;        // delta_i = int rho0.phi_i dm/(M h^2) [-]
  VectorX beta;         // beta_i = k.int rho0 x phi_i dm/(M h^2) [-]
  Damping damping;      // material damping of the modes
  double gravity = kStandardGravity;  // g [m/s^2]

  /// A rigid body (n = 0) from its mass, c.g. height, base distances and radius of gyration.
  static BodyParameters rigid(double mass, double height, double b1, double b2, double zeta2);
  /// Housner's uniform rectangular block: half-width b, half-height h (c.g. at h).
  static BodyParameters rectangular_block(double mass, double half_width, double half_height);
};

/// A validated body with the constants the simulation needs. Construct with Body(params); bad
/// parameters throw InputError naming the value and the reason.
class Body {
 public:
  explicit Body(BodyParameters params);

  const BodyParameters& params() const { return p_; }
  int modes() const { return n_; }
  double alpha1() const { return p_.b1 / p_.height; }  // alpha_1 = b1/h
  double alpha2() const { return p_.b2 / p_.height; }  // alpha_2 = b2/h
  double g() const { return p_.gravity; }
  double g_over_h() const { return p_.gravity / p_.height; }  // [1/s^2]

  const MatrixX& mu_inverse() const { return mu_inv_; }
  /// (mu - psi_x psi_x^T - psi_y psi_y^T)^-1: the modal mass about the deformed c.g. (flight)
  const MatrixX& flight_mu_inverse() const { return mu_cg_inv_; }
  const MatrixX& stiffness() const { return stiffness_; }          // K = (g/h) kappa [1/s^2]
  const MatrixX& damping_matrix() const { return damping_; }       // C [1/s]
  const VectorX& natural_frequencies() const { return omega_; }    // pinned-base [rad/s], ascending
  const VectorX& damping_ratios() const { return ratios_; }        // of the pinned-base modes [-]
  const VectorX& static_deformation() const { return q_static_; }  // q under gravity at rest
  /// The pinned-base mode shapes Phi as columns, ascending frequency, Phi^T mu Phi = I.
  const MatrixX& pinned_base_modes() const { return phi_; }
  /// The same body with the pinned-base modal coordinates eta as its deformation, q = Phi eta
  /// (docs/theory.md, "Modal coordinates"): mu = I, kappa and the damping diagonal, the other
  /// parameters by the congruence (gamma' = Phi^T gamma Phi, psi' = Phi^T psi, ...). Its motions
  /// are this body's, mapped by Phi.
  Body in_modal_coordinates() const;
  double rocking_frequency() const { return p_rock_; }  // p = sqrt(g h_pivot / r^2) [rad/s]
  /// Static overturning angle about edge 1 (theta > 0) and edge 2 (returned positive): the tilt
  /// at which the deformed c.g. under gravity stands above the pivot (paper, eq. 5 and above).
  double tipping_angle(int edge) const { return edge == 1 ? theta_c1_ : theta_c2_; }

 private:
  BodyParameters p_;
  int n_ = 0;
  MatrixX mu_inv_, mu_cg_inv_, stiffness_, damping_, phi_;
  VectorX omega_, ratios_, q_static_;
  double p_rock_ = 0.0, theta_c1_ = 0.0, theta_c2_ = 0.0;
};

/// The solution x of a x = b for a symmetric positive definite a, to a few ulp of x however
/// ill-conditioned a is (Cholesky, then refinement on residuals in long double). The static sag
/// of a body whose modes are decades apart is the soft modes' large deflection: a plain solve
/// is off by ~cond(a) ulp (1e-8 of it at 0.1 Hz beside 1 kHz), and so is every equilibrium
/// built on it.
VectorX solve_refined(const MatrixX& a, const VectorX& b);

}  // namespace flexrock
