// SPDX-License-Identifier: BSD-3-Clause
// A rigid body rocking freely on a floor at rest, in closed form (docs/theory.md, "Free rocking
// in closed form"). With phi = alpha_t - |theta| the equation is phi'' = P^2 sin(phi), an inverted
// pendulum: below the upright energy its arc from the floor to the peak and back is
// sin(phi/2) = s / dn(P (t - t_peak), k), k^2 = 1 - s^2, s = sin(phi_m/2) at the peak, and the
// times of the peak and of the impact are incomplete elliptic integrals of the first kind. One
// step covers the arc up to the impact (or the run's end) exactly; the dense output is Jacobi's
// functions. Same interface as Dopri5 for the event loop (t0, t1, x0, x1, restep_to, dense).
// Boost.Math supplies Carlson's R_F (for F(phi, k)) and sn, cn, dn. Internal header.
#pragma once

#include <algorithm>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <cmath>
#include <limits>

namespace flexrock::detail {

template <class State>
class FreeRockingArc {
  // in double throughout (Boost.Math promotes to long double by default)
  using Policy = boost::math::policies::policy<boost::math::policies::promote_double<false>>;

 public:
  /// Smallest s^2 = sin^2(phi_m/2) the arc takes: nearer the upright energy the closed form's
  /// modulus is 1 to rounding, and the series steps the motion as before (it then decides whether
  /// the body goes over).
  static constexpr double kMinS2 = 1e-12;
  /// Below this s^2 the dense output refines Jacobi's functions by Newton's method on F.
  static constexpr double kNearUpright = 1e-4;

  /// The pivot of the series' equation theta'' = k (alpha cos theta + sin theta), k = gh/m
  /// (RockingSeries::set_pivot; gh = g/h, m = 1 + zeta^2 + alpha^2), and its constants. These
  /// depend on |alpha| alone, so they are kept while |alpha|, m and gh stay: the two edges of a
  /// symmetric body, which alternate at every impact, share them (an atan, an atan2, a sincos and
  /// a sin an impact otherwise).
  void set_pivot(double alpha, double m, double gh) {
    alpha_ = alpha;
    if (std::abs(alpha) == beta_ && m == m_ && gh == gh_) return;
    m_ = m;
    gh_ = gh;
    beta_ = std::abs(alpha);
    c_ = std::sqrt(1.0 + beta_ * beta_);
    alpha_t_ = std::atan(beta_);
    sa_ = std::sin(0.5 * alpha_t_);
    ca_ = std::cos(0.5 * alpha_t_);
    p_ = std::sqrt(gh / m * c_);  // P^2 = k sqrt(1 + beta^2)
    inv_p_ = 1.0 / p_;
    // the reaction's constants as the factors it takes (a product where a quotient would wait on
    // a division, three of them an impact's samples): 1/kappa = c^2/m, cos(alpha_t) = 1/c
    inv_kappa_ = c_ * c_ / m;
    inv_c_ = 1.0 / c_;
    lambda_ = c_ / m;
    phi_moment_ = std::atan2(beta_ * (inv_c_ - lambda_), inv_c_ + 2.0 * lambda_);
  }

  /// Starts an arc at (t, x) on the pivot (set_pivot), the body on its edge of sign sg (theta sg
  /// >= 0). False where the arc does not apply: the state is not strictly on the edge (theta = 0
  /// moving down, the impact is the loop's), past the tipping angle, or its energy reaches the
  /// upright one.
  bool start(double t, const State& x, double sg) {
    if (!(alpha_ * sg < 0.0) || !(p_ > 0.0)) return false;
    const double th = sg * x(0), om = sg * x(1);  // vartheta >= 0 and its rate
    if (th < 0.0 || (th == 0.0 && !(om > 0.0))) return false;
    if (!(th < alpha_t_)) return false;  // past the tipping angle gravity overturns it
    sg_ = sg;
    const double w = 0.5 * om * inv_p_;  // phi0'/(2 P) up to its sign
    const double sh0 = th == 0.0 ? sa_ : std::sin(0.5 * (alpha_t_ - th));
    s2_ = sh0 * sh0 - w * w;  // sin^2(phi_m/2) by the energy, without cos's cancellation
    if (!(s2_ > kMinS2)) return false;
    s_ = std::sqrt(s2_);
    k_ = std::sqrt(1.0 - s2_);
    inv_k_ = 1.0 / k_;
    cm_ = 1.0 - 2.0 * s2_;  // cos(phi_m)
    // the impact, phi = alpha_t: sn^2 = (sin^2(alpha_t/2) - s^2)/(k^2 sin^2(alpha_t/2)), the
    // difference of squares as sin(theta0/2) sin(alpha_t - theta0/2) + w^2 (no cancellation)
    gap_ = th == 0.0 ? w * w : std::sin(0.5 * th) * std::sin(alpha_t_ - 0.5 * th) + w * w;
    const double v_impact = ellint(sa_, ca_, gap_);
    // from the start to the peak: sn(v0) = |phi0'|/(2 P k sin(phi0/2)), the impact's by symmetry
    // where the arc starts on the floor; past the peak when falling
    const double v0 = th == 0.0 ? v_impact : ellint(sh0, std::cos(0.5 * (alpha_t_ - th)), w * w);
    t_peak_ = om > 0.0 ? t + v0 * inv_p_ : t - v0 * inv_p_;
    t_impact_ = t_peak_ + v_impact * inv_p_;
    // the impact's rate by the energy: vartheta'^2 = om^2 + 2 P^2 (cos phi0 - cos alpha_t)
    impact_rate_ = -2.0 * p_ * std::sqrt(gap_);
    // the peak's |theta|, alpha_t - phi_m = 2 (A - B), A = alpha_t/2, B = phi_m/2, from
    // sin(A - B) = (sin^2 A - sin^2 B)/sin(A + B): relative to the tilt, however small
    // (sin(A + B) = sin A cos B + cos A sin B, cos B = k)
    peak_tilt_ = 2.0 * std::asin(std::min(1.0, gap_ / (sa_ * k_ + ca_ * s_)));
    x0_ = x1_ = x;
    t0_ = t1_ = t;
    return true;
  }

  /// The next step: to t_stop or the impact, whichever comes first.
  void step(double t_stop) {
    t0_ = t1_;
    x0_ = x1_;
    t1_ = std::min(t_stop, t_impact_);
    at(t1_, x1_);
  }

  /// Ends the last step at t_target (within it).
  template <class System>
  void restep_to(System&&, double t_target) {
    t1_ = t_target;
    at(t1_, x1_);
  }

  void dense(double t, State& out) const {
    out = x0_;
    at(t, out);
  }

  double t0() const { return t0_; }
  double t1() const { return t1_; }
  const State& x0() const { return x0_; }
  const State& x1() const { return x1_; }
  double peak_time() const { return t_peak_; }
  double impact_time() const { return t_impact_; }
  /// The peak's |theta|, alpha_t - phi_m.
  double peak_tilt() const { return peak_tilt_; }
  double alpha_t() const { return alpha_t_; }
  /// phi where the moment's bracket is stationary (set_pivot).
  double phi_moment() const { return phi_moment_; }

  /// The reaction on the arc, a function of phi alone (theta_dot^2 by the energy; derive.py,
  /// derive_free_rocking_arc, arc_reaction), from sin(phi) and cos(phi): F_I over M g, F_J over
  /// M g and the moment about the c.g.'s projection over M g h, signed as the rocking equations
  /// give them on the edge of sign sg, with kappa = m/c^2 = I_O/(M R^2) and lambda = c/m; shear
  /// and moment are their sizes.
  double fi(double sp, double cp) const { return sg_ * sp * (3.0 * cp - 2.0 * cm_) * inv_kappa_; }
  double press(double cp) const {
    return 1.0 - (1.0 - 3.0 * cp * cp + 2.0 * cm_ * cp) * inv_kappa_;
  }
  double signed_moment(double sp, double cp) const {
    return -sg_ * beta_ * ((cp + beta_ * sp) * inv_c_ - lambda_ * (beta_ * sp + 2.0 * (cm_ - cp)));
  }
  double shear(double sp, double cp) const { return std::abs(fi(sp, cp)); }
  double moment(double sp, double cp) const { return std::abs(signed_moment(sp, cp)); }
  /// sin(phi) and cos(phi) on the floor (phi = alpha_t): beta/c and 1/c.
  double floor_sin() const { return beta_ * inv_c_; }
  double floor_cos() const { return inv_c_; }
  /// The least F_J over cos(phi) in [c_lo, c_hi]: a quadratic in cos(phi), least at an end or at
  /// its vertex cm/3.
  double least_press(double c_lo, double c_hi) const {
    double least = std::min(press(c_lo), press(c_hi));
    if (cm_ / 3.0 > c_lo && cm_ / 3.0 < c_hi) least = std::min(least, press(cm_ / 3.0));
    return least;
  }
  /// cos(phi_m): the arc's energy, phi'^2/2 + P^2 cos(phi) = P^2 cm.
  double energy_cosine() const { return cm_; }
  /// sin(phi_m) = 2 sin(phi_m/2) cos(phi_m/2).
  double sin_phi_m() const { return 2.0 * s_ * k_; }
  /// phi at t on the arc.
  double phi(double t) const {
    double cn = 0.0, dn = 1.0;
    boost::math::jacobi_elliptic(k_, p_ * (t - t_peak_), &cn, &dn, Policy());
    return 2.0 * std::asin(std::min(1.0, s_ / dn));
  }
  /// The time on the arc within [t0, t1] where phi takes the value ph (phi_m <= ph <= alpha_t):
  /// two such times (rising and falling) give the same reaction, as it holds theta_dot^2 only.
  double time_of(double ph) const {
    const double v = ellint(std::sin(0.5 * ph), std::cos(0.5 * ph),
                            (std::sin(0.5 * ph) - s_) * (std::sin(0.5 * ph) + s_)) /
                     p_;
    const double rising = t_peak_ - v;
    return rising >= t0_ && rising <= t1_ ? rising : std::clamp(t_peak_ + v, t0_, t1_);
  }

 private:
  // P |t - t_peak| where phi = 2 asin(S), C = cos(phi/2), d = S^2 - s^2 (formed by the caller
  // without cancellation): F(asin(sn), k) with sn^2 = d/(k^2 S^2), as Carlson's
  // sn R_F(1 - sn^2, 1 - k^2 sn^2, 1), whose arguments are s^2 C^2/(k^2 S^2) and s^2/S^2 exactly:
  // near the floor and near the peak neither loses digits to 1 - x (Boost's ellint_1 would form
  // the angle and 1 - sn^2); one division, 1/S (1/k is the arc's)
  double ellint(double S, double C, double d) const {
    const double inv_s = 1.0 / S, y = s2_ * inv_s * inv_s;
    const double sn = std::min(1.0, std::sqrt(std::max(0.0, d)) * inv_s * inv_k_);
    return sn * boost::math::ellint_rf(y * C * C * inv_k_ * inv_k_, y, 1.0, Policy());
  }

  // sin(A + Phi), A = alpha_t/2, from S = sin(Phi) (Phi in [0, pi/2]): sin A cos Phi + cos A S
  double sin_a_plus(double S) const {
    S = std::min(1.0, S);
    return sa_ * std::sqrt((1.0 - S) * (1.0 + S)) + ca_ * S;
  }

  void at(double t, State& out) const {
    if (t == t_impact_) {  // the impact exactly: theta = 0, the rate by the energy
      out(0) = 0.0;
      out(1) = sg_ * impact_rate_;
      return;
    }
    if (t == t_peak_) {  // the peak exactly (the loop records it)
      out(0) = sg_ * peak_tilt();
      out(1) = 0.0;
      return;
    }
    double cn = 0.0, dn = 1.0;
    const double sn = boost::math::jacobi_elliptic(k_, p_ * (t - t_peak_), &cn, &dn, Policy());
    if (s2_ < kNearUpright) {
      // k near 1 (an arc from near upright): Jacobi's functions lose digits there (5e-10 of dn
      // at s^2 = 2.5e-9, measured against mpmath), so S = sin(phi/2) = s/dn takes Newton steps
      // on P |t - t_p| = F(S) (Carlson's form, to rounding), dS/dF = C sqrt(S^2 - s^2)
      const double v = p_ * std::abs(t - t_peak_);
      double S = std::min(1.0, s_ / dn);
      for (int i = 0; i < 2; ++i) {
        const double d = (S - s_) * (S + s_), C = std::sqrt((1.0 - S) * (1.0 + S));
        if (!(d > 0.0)) break;
        S += (v - ellint(S, C, d)) * C * std::sqrt(d);
        S = std::clamp(S, s_, 1.0);
      }
      // vartheta = 2 (A - Phi), sin(A - Phi) = (sin A - S)(sin A + S)/sin(A + Phi); |phi'| =
      // 2 P sqrt(S^2 - s^2), falling after the peak
      out(0) = sg_ * 2.0 * std::asin(std::clamp((sa_ - S) * (sa_ + S) / sin_a_plus(S), 0.0, 1.0));
      const double rate = 2.0 * p_ * std::sqrt(std::max(0.0, (S - s_) * (S + s_)));
      out(1) = t > t_peak_ ? -sg_ * rate : sg_ * rate;
      return;
    }
    // vartheta = 2 (A - Phi), Phi = phi/2, sin(Phi) = s/dn: sin(A - Phi) = (sin^2 A - s^2/dn^2)/
    // sin(A + Phi), and sin^2 A dn^2 - s^2 = gap - sin^2 A k^2 sn^2 keeps it relative to the arc
    const double d = (gap_ - sa_ * sa_ * k_ * k_ * sn * sn) / (dn * dn * sin_a_plus(s_ / dn));
    out(0) = sg_ * 2.0 * std::asin(std::clamp(d, 0.0, 1.0));
    out(1) = -sg_ * 2.0 * p_ * s_ * k_ * sn / dn;  // vartheta' = -phi' = -2 P s k sn/dn
  }

  // the pivot (set_pivot)
  double alpha_ = 0.0, m_ = 0.0, gh_ = 0.0;
  // (beta_ < 0: no pivot yet)
  double beta_ = -1.0, c_ = 1.0, alpha_t_ = 0.0, p_ = 0.0, inv_kappa_ = 1.0, lambda_ = 0.0;
  double inv_c_ = 1.0, inv_p_ = 0.0;
  double phi_moment_ = 0.0;
  double sa_ = 0.0, ca_ = 1.0;  // sin(alpha_t/2), cos(alpha_t/2)
  // the arc
  double sg_ = 1.0, s2_ = 0.0, s_ = 0.0, k_ = 0.0, inv_k_ = 0.0, cm_ = 0.0, peak_tilt_ = 0.0;
  double gap_ = 0.0;  // sin^2(alpha_t/2) - s^2, formed without cancellation
  double t_peak_ = 0.0, t_impact_ = 0.0, impact_rate_ = 0.0;
  double t0_ = 0.0, t1_ = 0.0;
  State x0_, x1_;
};

}  // namespace flexrock::detail
