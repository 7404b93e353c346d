// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/model/body.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "flexrock/core/error.hpp"
#include "flexrock/core/format.hpp"

namespace flexrock {

namespace {

std::string num(double v) { return format_number(v, 6); }

void require_positive(double v, const char* name, const char* meaning) {
  FLEXROCK_THROW_UNLESS(std::isfinite(v) && v > 0.0, std::string("body: ") + name + " (" + meaning +
                                                         ") must be a positive " +
                                                         "finite number, got " + num(v));
}

void require_size(const MatrixX& m, int n, const char* name) {
  FLEXROCK_THROW_UNLESS(
      m.rows() == n && m.cols() == n,
      std::string("body: ") + name + " must be " + std::to_string(n) + "x" + std::to_string(n) +
          " (one row and column per mode, n = " + std::to_string(n) + " from mu), got " +
          std::to_string(m.rows()) + "x" + std::to_string(m.cols()));
  FLEXROCK_THROW_UNLESS(m.allFinite(), std::string("body: ") + name + " has a NaN or inf entry");
}

void require_size(const VectorX& v, int n, const char* name) {
  FLEXROCK_THROW_UNLESS(v.size() == n, std::string("body: ") + name + " must have " +
                                           std::to_string(n) + " entries (one per mode), got " +
                                           std::to_string(v.size()));
  FLEXROCK_THROW_UNLESS(v.allFinite(), std::string("body: ") + name + " has a NaN or inf entry");
}

void require_symmetric_positive_definite(const MatrixX& m, const char* name) {
  if (m.rows() == 0) return;
  const double scale = m.cwiseAbs().maxCoeff();
  for (int i = 0; i < m.rows(); ++i) {
    for (int j = 0; j < i; ++j) {
      FLEXROCK_THROW_UNLESS(std::abs(m(i, j) - m(j, i)) <= 1e-10 * scale,
                            std::string("body: ") + name + " must be symmetric, but entry (" +
                                std::to_string(i + 1) + "," + std::to_string(j + 1) +
                                ") = " + num(m(i, j)) + " differs from (" + std::to_string(j + 1) +
                                "," + std::to_string(i + 1) + ") = " + num(m(j, i)));
    }
  }
  Eigen::SelfAdjointEigenSolver<MatrixX> eig(m);
  const double lowest = eig.eigenvalues()(0);
  FLEXROCK_THROW_UNLESS(lowest > 1e-12 * scale,
                        std::string("body: ") + name + " must be positive definite, but its " +
                            "smallest eigenvalue is " + num(lowest) +
                            " (a mode with no mass or no stiffness, or modes that are not " +
                            "independent)");
}

}  // namespace

BodyParameters BodyParameters::rigid(double mass, double height, double b1, double b2,
                                     double zeta2) {
  BodyParameters p;
  p.mass = mass;
  p.height = height;
  p.b1 = b1;
  p.b2 = b2;
  p.zeta2 = zeta2;
  p.mu.resize(0, 0);
  p.kappa.resize(0, 0);
  p.gamma.resize(0, 0);
  return p;
}

BodyParameters BodyParameters::rectangular_block(double mass, double half_width,
                                                 double half_height) {
  // I_zz = M (4b^2 + 4h^2)/12, so zeta^2 = (1 + alpha^2)/3
  const double a = half_width / half_height;
  return rigid(mass, half_height, half_width, half_width, (1.0 + a * a) / 3.0);
}

Body::Body(BodyParameters params) : p_(std::move(params)) {
  require_positive(p_.mass, "M", "total mass [kg]");
  require_positive(p_.height, "h", "height of the c.g. above the base [m]");
  require_positive(p_.b1, "b1", "distance from the c.g. to the left tipping point [m]");
  require_positive(p_.b2, "b2", "distance from the c.g. to the right tipping point [m]");
  require_positive(p_.zeta2, "zeta2", "radius of gyration squared over h^2");
  require_positive(p_.gravity, "g", "gravity [m/s^2]");

  // derived quantities must not overflow or underflow (finite inputs can: M = 1e308 or 5e-324)
  const double mgh = p_.mass * p_.gravity * p_.height;
  const double inertia = p_.mass * p_.height * p_.height * (1.0 + p_.zeta2);
  for (const auto& [v, what] : {std::pair<double, const char*>{mgh, "M g h [J], the energy scale"},
                                {inertia, "M h^2 (1 + zeta2) [kg m^2], the rotary inertia"},
                                {p_.gravity / p_.height, "g/h [1/s^2]"}}) {
    FLEXROCK_THROW_UNLESS(
        std::isnormal(v),
        std::string("body: ") + what + " = " + num(v) + " is not a finite normal number (M = " +
            num(p_.mass) + " kg, h = " + num(p_.height) + " m, g = " + num(p_.gravity) +
            " m/s^2 overflow or underflow double precision); give the body " + "in physical sizes");
  }

  n_ = static_cast<int>(p_.mu.rows());
  require_size(p_.mu, n_, "mu");
  require_size(p_.kappa, n_, "kappa");
  require_size(p_.gamma, n_, "gamma");
  require_size(p_.psi_x, n_, "psi_x");
  require_size(p_.psi_y, n_, "psi_y");
  require_size(p_.delta, n_, "delta");
  require_size(p_.beta, n_, "beta");
  require_symmetric_positive_definite(p_.mu, "mu (modal mass)");
  require_symmetric_positive_definite(p_.kappa, "kappa (modal stiffness)");
  if (n_ > 0) {
    const double gscale = std::max(1.0, p_.gamma.cwiseAbs().maxCoeff());
    const MatrixX asym = p_.gamma + p_.gamma.transpose();
    FLEXROCK_THROW_UNLESS(asym.cwiseAbs().maxCoeff() <= 1e-10 * gscale,
                          "body: gamma (Coriolis parameters) must be antisymmetric, gamma_ij = "
                          "-gamma_ji, but gamma + gamma^T has an entry of size " +
                              num(asym.cwiseAbs().maxCoeff()));
  }

  const double gh = p_.gravity / p_.height;
  mu_inv_ = n_ > 0 ? MatrixX(p_.mu.llt().solve(MatrixX::Identity(n_, n_))) : MatrixX(0, 0);
  // the modal mass about the deformed c.g., for flight: the modes less their c.g. shift. It is
  // positive definite unless a mode moves the whole body as a rigid translation
  if (n_ > 0) {
    const MatrixX mu_cg = p_.mu - p_.psi_x * p_.psi_x.transpose() - p_.psi_y * p_.psi_y.transpose();
    const Eigen::LLT<MatrixX> llt(mu_cg);
    FLEXROCK_THROW_UNLESS(llt.info() == Eigen::Success,
                          "body: mu - psi_x psi_x^T - psi_y psi_y^T (the modal mass about the "
                          "centre of mass) is not positive definite: a mode moves the body as a "
                          "rigid translation; give modes that deform it");
    mu_cg_inv_ = llt.solve(MatrixX::Identity(n_, n_));
  } else {
    mu_cg_inv_ = MatrixX(0, 0);
  }
  stiffness_ = gh * p_.kappa;
  FLEXROCK_THROW_UNLESS(stiffness_.allFinite() && mu_inv_.allFinite(),
                        "body: (g/h) kappa or mu^-1 overflows double precision (largest kappa " +
                            num(p_.kappa.size() ? p_.kappa.cwiseAbs().maxCoeff() : 0.0) +
                            ", g/h = " + num(gh) + " 1/s^2); give the body in physical sizes");

  // pinned-base modes: K phi = omega^2 mu phi, phi mass-normalised
  omega_.resize(n_);
  phi_.resize(n_, n_);
  if (n_ > 0) {
    Eigen::GeneralizedSelfAdjointEigenSolver<MatrixX> ges(stiffness_, p_.mu);
    omega_ = ges.eigenvalues().cwiseSqrt();
    phi_ = ges.eigenvectors();
  }
  const MatrixX& phi = phi_;

  // material damping
  damping_ = MatrixX::Zero(n_, n_);
  ratios_ = VectorX::Zero(n_);
  const Damping& d = p_.damping;
  switch (d.kind) {
    case DampingKind::kNone:
      break;
    case DampingKind::kRayleigh:
      FLEXROCK_THROW_UNLESS(
          std::isfinite(d.rayleigh_mass) && d.rayleigh_mass >= 0.0,
          "body: Rayleigh mass coefficient a [1/s] must be >= 0, got " + num(d.rayleigh_mass));
      FLEXROCK_THROW_UNLESS(std::isfinite(d.rayleigh_stiffness) && d.rayleigh_stiffness >= 0.0,
                            "body: Rayleigh stiffness coefficient b [s] must be >= 0, got " +
                                num(d.rayleigh_stiffness));
      damping_ = d.rayleigh_mass * p_.mu + d.rayleigh_stiffness * stiffness_;
      for (int i = 0; i < n_; ++i)
        ratios_(i) = d.rayleigh_mass / (2.0 * omega_(i)) + d.rayleigh_stiffness * omega_(i) / 2.0;
      break;
    case DampingKind::kModal:
      FLEXROCK_THROW_UNLESS(d.modal_ratios.size() == n_,
                            "body: modal damping needs one ratio per mode (" + std::to_string(n_) +
                                "), got " + std::to_string(d.modal_ratios.size()));
      for (int i = 0; i < n_; ++i) {
        FLEXROCK_THROW_UNLESS(std::isfinite(d.modal_ratios(i)) && d.modal_ratios(i) >= 0.0,
                              "body: modal damping ratio " + std::to_string(i + 1) +
                                  " must be >= 0, got " + num(d.modal_ratios(i)));
      }
      ratios_ = d.modal_ratios;
      {
        // C = mu Phi diag(2 zeta omega) Phi^T mu, so Phi^T C Phi = diag(2 zeta omega)
        const VectorX c = 2.0 * ratios_.cwiseProduct(omega_);
        const MatrixX mp = p_.mu * phi;
        damping_ = mp * c.asDiagonal() * mp.transpose();
      }
      break;
  }

  q_static_ = n_ > 0 ? solve_refined(p_.kappa, VectorX(-p_.psi_y)) : VectorX(0);

  // the full mass matrix must be positive definite for a real body (Schur complement at q = 0)
  for (int edge = 1; edge <= 2; ++edge) {
    const double a = edge == 1 ? -alpha1() : alpha2();
    const VectorX b = p_.beta - a * p_.psi_y - p_.psi_x;
    const double m = 1.0 + p_.zeta2 + a * a;
    const double schur = n_ > 0 ? m - b.dot(mu_inv_ * b) : m;
    FLEXROCK_THROW_UNLESS(schur > 1e-12 * m,
                          "body: the parameters do not describe a real body: the rocking inertia "
                          "about edge " +
                              std::to_string(edge) +
                              " net of the modes (1 + zeta2 + alpha^2 - b^T mu^-1 b = " +
                              num(schur) + ") must be positive; check beta, psi and mu");
  }

  // at rest the resultant must lie between the tipping points
  if (n_ > 0) {
    const double rest = p_.psi_x.dot(q_static_) / (1.0 + p_.psi_y.dot(q_static_));
    FLEXROCK_THROW_UNLESS(rest > -alpha1() && rest < alpha2(),
                          "body: under gravity alone the reaction would act outside the base "
                          "(alpha = " +
                              num(rest) + ", base spans [" + num(-alpha1()) + ", " + num(alpha2()) +
                              "]): the body cannot stand");
  }

  // rocking frequency of the rigid part, p^2 = g R / (r_O^2), the stiffer side
  for (double a : {alpha1(), alpha2()}) {
    const double p2 = gh * std::sqrt(1.0 + a * a) / (1.0 + p_.zeta2 + a * a);
    p_rock_ = std::max(p_rock_, std::sqrt(p2));
  }

  // static overturning angle per edge: deformed c.g. above the pivot, q from static equilibrium
  const Eigen::LLT<MatrixX> kappa_llt = n_ > 0 ? p_.kappa.llt() : Eigen::LLT<MatrixX>();
  auto imbalance = [&](double theta, int edge) {
    // moment of gravity about the pivot, positive when it restores (edge 1: theta > 0)
    const double a = edge == 1 ? -alpha1() : alpha2();
    const double s = std::sin(theta), c = std::cos(theta);
    double wx = -a, wy = 1.0;
    if (n_ > 0) {
      const VectorX q = -kappa_llt.solve(p_.psi_x * s + p_.psi_y * c);
      wx += p_.psi_x.dot(q);
      wy += p_.psi_y.dot(q);
    }
    return wx * c - wy * s;  // k.(w x J): zero when the c.g. is above the pivot
  };
  for (int edge = 1; edge <= 2; ++edge) {
    const double sign = edge == 1 ? 1.0 : -1.0;
    auto f = [&](double mag) { return sign * imbalance(sign * mag, edge); };
    const int grid = 256;
    double lo = 0.0, flo = f(0.0), found = -1.0;
    FLEXROCK_THROW_UNLESS(flo > 0.0, "body: no restoring moment about edge " +
                                         std::to_string(edge) + " at rest; the body cannot stand");
    for (int k = 1; k <= grid && found < 0.0; ++k) {
      const double hi = 0.5 * std::numbers::pi * k / grid;
      const double fhi = f(hi);
      if (fhi <= 0.0) {
        std::uintmax_t iters = 100;
        auto r = boost::math::tools::toms748_solve(
            f, lo, hi, flo, fhi, boost::math::tools::eps_tolerance<double>(52), iters);
        found = 0.5 * (r.first + r.second);
      }
      lo = hi;
      flo = fhi;
    }
    FLEXROCK_THROW_UNLESS(found > 0.0, "body: no static overturning angle about edge " +
                                           std::to_string(edge) +
                                           " below 90 degrees; the body is too flexible");
    (edge == 1 ? theta_c1_ : theta_c2_) = found;
  }
}

Body Body::in_modal_coordinates() const {
  Body m(*this);
  if (n_ == 0) return m;
  // q = Phi eta in the energies (docs/theory.md, "Modal coordinates"): Phi^T mu Phi = I and
  // Phi^T K Phi = diag(omega^2) by the eigenproblem, so those are set exactly; the rest is the
  // congruence, gamma' kept antisymmetric to the last bit
  const MatrixX& f = phi_;
  const double gh = p_.gravity / p_.height;
  BodyParameters& p = m.p_;
  p.mu = MatrixX::Identity(n_, n_);
  p.kappa = (omega_.cwiseAbs2() / gh).asDiagonal();
  const MatrixX g = f.transpose() * p_.gamma * f;
  p.gamma = 0.5 * (g - g.transpose());
  p.psi_x = f.transpose() * p_.psi_x;
  // the static sag mapped, eta_s = Phi^T mu r, with psi_y' = -kappa' eta_s: the given body's
  // refined equilibrium exactly. Phi^T psi_y differs from it by the eigensolver's rounding,
  // cond(K) ulp, which would put a soft mode beside a stiff one at rest 1e-8 of its sag away
  // from where the given data hold it, and swing it about there
  const VectorX eta_s = f.transpose() * (p_.mu * q_static_);
  p.psi_y = -p.kappa.diagonal().cwiseProduct(eta_s);
  p.delta = f.transpose() * p_.delta;
  p.beta = f.transpose() * p_.beta;
  // Phi^T C Phi is diag(2 zeta omega) for Rayleigh and modal damping alike
  p.damping = p_.damping.kind == DampingKind::kNone
                  ? Damping{}
                  : Damping{DampingKind::kModal, 0.0, 0.0, ratios_};
  m.mu_inv_ = p.mu;
  m.stiffness_ = gh * p.kappa;
  m.damping_ = (2.0 * ratios_.cwiseProduct(omega_)).asDiagonal();
  const MatrixX mu_cg = p.mu - p.psi_x * p.psi_x.transpose() - p.psi_y * p.psi_y.transpose();
  m.mu_cg_inv_ = mu_cg.llt().solve(MatrixX::Identity(n_, n_));
  m.q_static_ = eta_s;
  m.phi_ = MatrixX::Identity(n_, n_);
  return m;
}

VectorX solve_refined(const MatrixX& a, const VectorX& b) {
  using Long = Eigen::Matrix<long double, Eigen::Dynamic, 1>;
  const Eigen::LLT<MatrixX> llt(a);
  VectorX x = llt.solve(b);
  const Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic> al = a.cast<long double>();
  const Long bl = b.cast<long double>();
  // each pass gains ~16 - log10(cond(a)) digits; three reach the double nearest x for cond(a)
  // up to ~1e10, and stop early once the correction is below an ulp
  for (int pass = 0; pass < 3; ++pass) {
    const VectorX r = (bl - al * x.cast<long double>()).cast<double>();
    const VectorX dx = llt.solve(r);
    x += dx;
    if (!(dx.cwiseAbs().maxCoeff() > 1e-17 * x.cwiseAbs().maxCoeff())) break;
  }
  return x;
}

}  // namespace flexrock
