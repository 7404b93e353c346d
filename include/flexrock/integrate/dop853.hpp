// SPDX-License-Identifier: BSD-3-Clause
// Dormand-Prince 8(5,3) with its 7th-order dense output (Hairer, Norsett & Wanner, "Solving ODEs
// I", II.10, code DOP853). Generic over the state type; knows nothing of bodies or contacts.
//
// Hand-written, as Dopri5 is (dopri5.hpp says why): Boost.Odeint has no 8th-order pair with dense
// output, and the event loop needs a step that ends exactly on a prescribed time, a re-step from
// the last accepted point to an event time and a per-step cap. Same interface as Dopri5. At the
// tolerances the engine runs (rtol 1e-8 and below) the 8th order takes about a quarter of
// DOPRI5's steps on a flexible body's rocking, for 14 evaluations a step instead of 6
// (bench/bounds.md has the measurement). The stages live in the object: a step allocates nothing
// for fixed-size states.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <limits>

#include "flexrock/integrate/dopri5.hpp"  // StepControl

namespace flexrock {

namespace dop853 {
// The method's coefficients as published (DOP853): stage nodes c_i, the stages' a_ij (k_1..k_12,
// k_13 = f(t + h, x_new) the first stage of the next step, k_14..k_16 the dense output's extra
// stages), the 8th-order weights b_i (= a_13,j), the 5th- and 3rd-order error estimators' weights
// and the dense output's four rows. tests/unit/dop853_test.cpp checks them: the row sums are the
// c_i, sum b_i c_i^(k-1) = 1/k for k <= 8, and the step's and the dense output's errors shrink as
// h^8 and h^7 (order 8 and 7) on a nonlinear problem.
inline constexpr std::array<double, 16> kC = {0.0,
                                              0.05260015195876773,
                                              0.0789002279381516,
                                              0.1183503419072274,
                                              0.2816496580927726,
                                              0.3333333333333333,
                                              0.25,
                                              0.3076923076923077,
                                              0.6512820512820513,
                                              0.6,
                                              0.8571428571428571,
                                              1.0,
                                              1.0,
                                              0.1,
                                              0.2,
                                              0.7777777777777778};
// a_ij by rows, zeros included (a few multiplications by zero are cheaper than an index table)
inline constexpr double kA[16][16] = {
    {},
    {0.05260015195876773},
    {0.0197250569845379, 0.0591751709536137},
    {0.02958758547680685, 0.0, 0.08876275643042054},
    {0.2413651341592667, 0.0, -0.8845494793282861, 0.924834003261792},
    {0.037037037037037035, 0.0, 0.0, 0.17082860872947386, 0.12546768756682242},
    {0.037109375, 0.0, 0.0, 0.17025221101954405, 0.06021653898045596, -0.017578125},
    {0.03709200011850479, 0.0, 0.0, 0.17038392571223998, 0.10726203044637328, -0.015319437748624402,
     0.008273789163814023},
    {0.6241109587160757, 0.0, 0.0, -3.3608926294469414, -0.868219346841726, 27.59209969944671,
     20.154067550477894, -43.48988418106996},
    {0.47766253643826434, 0.0, 0.0, -2.4881146199716677, -0.590290826836843, 21.230051448181193,
     15.279233632882423, -33.28821096898486, -0.020331201708508627},
    {-0.9371424300859873, 0.0, 0.0, 5.186372428844064, 1.0914373489967295, -8.149787010746927,
     -18.52006565999696, 22.739487099350505, 2.4936055526796523, -3.0467644718982196},
    {2.273310147516538, 0.0, 0.0, -10.53449546673725, -2.0008720582248625, -17.9589318631188,
     27.94888452941996, -2.8589982771350235, -8.87285693353063, 12.360567175794303,
     0.6433927460157636},
    {0.054293734116568765, 0.0, 0.0, 0.0, 0.0, 4.450312892752409, 1.8915178993145003,
     -5.801203960010585, 0.3111643669578199, -0.1521609496625161, 0.20136540080403034,
     0.04471061572777259},
    {0.056167502283047954, 0.0, 0.0, 0.0, 0.0, 0.0, 0.25350021021662483, -0.2462390374708025,
     -0.12419142326381637, 0.15329179827876568, 0.00820105229563469, 0.007567897660545699,
     -0.008298},
    {0.03183464816350214, 0.0, 0.0, 0.0, 0.0, 0.028300909672366776, 0.053541988307438566,
     -0.05492374857139099, 0.0, 0.0, -0.00010834732869724932, 0.0003825710908356584,
     -0.00034046500868740456, 0.1413124436746325},
    {-0.42889630158379194, 0.0, 0.0, 0.0, 0.0, -4.697621415361164, 7.683421196062599,
     4.06898981839711, 0.3567271874552811, 0.0, 0.0, 0.0, -0.0013990241651590145,
     2.9475147891527724, -9.15095847217987}};
// the error estimators, over k_1..k_12 (k_2..k_5 have weight zero in both)
inline constexpr std::array<double, 12> kE5 = {0.01312004499419488,
                                               0.0,
                                               0.0,
                                               0.0,
                                               0.0,
                                               -1.2251564463762044,
                                               -0.4957589496572502,
                                               1.6643771824549864,
                                               -0.35032884874997366,
                                               0.3341791187130175,
                                               0.08192320648511571,
                                               -0.022355307863886294};
inline constexpr std::array<double, 12> kE3 = {-0.18980075407240762,
                                               0.0,
                                               0.0,
                                               0.0,
                                               0.0,
                                               4.450312892752409,
                                               1.8915178993145003,
                                               -5.801203960010585,
                                               -0.4226823213237919,
                                               -0.1521609496625161,
                                               0.20136540080403034,
                                               0.02265179219836082};
// the dense output's rows over k_1..k_16 (k_2..k_5 have weight zero)
inline constexpr double kD[4][16] = {
    {-8.428938276109013, 0.0, 0.0, 0.0, 0.0, 0.5667149535193777, -3.0689499459498917,
     2.38466765651207, 2.117034582445028, -0.871391583777973, 2.2404374302607883,
     0.6315787787694688, -0.08899033645133331, 18.148505520854727, -9.194632392478356,
     -4.436036387594894},
    {10.427508642579134, 0.0, 0.0, 0.0, 0.0, 242.28349177525817, 165.20045171727028,
     -374.5467547226902, -22.113666853125306, 7.733432668472264, -30.674084731089398,
     -9.332130526430229, 15.697238121770845, -31.139403219565178, -9.35292435884448,
     35.81684148639408},
    {19.985053242002433, 0.0, 0.0, 0.0, 0.0, -387.0373087493518, -189.17813819516758,
     527.8081592054236, -11.57390253995963, 6.8812326946963, -1.0006050966910838,
     0.7777137798053443, -2.778205752353508, -60.19669523126412, 84.32040550667716,
     11.99229113618279},
    {-25.69393346270375, 0.0, 0.0, 0.0, 0.0, -154.18974869023643, -231.5293791760455,
     357.6391179106141, 93.40532418362432, -37.45832313645163, 104.0996495089623, 29.8402934266605,
     -43.53345659001114, 96.32455395918828, -39.17726167561544, -149.72683625798564}};
}  // namespace dop853

/// The coefficients of DOP853's stability polynomial R(z) = 1 + z b^T (I - z A)^-1 1 =
/// sum_k g_k z^k, g_0 = 1, g_k = b^T A^(k-1) 1 (A strictly lower triangular over the 12 stages:
/// degree 12); formed once.
inline const std::array<double, 13>& dop853_stability_polynomial() {
  static const std::array<double, 13> g = [] {
    std::array<double, 13> out{};
    std::array<double, 12> v{}, w{};
    v.fill(1.0);
    out[0] = 1.0;
    for (std::size_t k = 1; k <= 12; ++k) {
      double s = 0.0;
      for (std::size_t j = 0; j < 12; ++j) s += dop853::kA[12][j] * v[j];
      out[k] = s;
      for (std::size_t i = 0; i < 12; ++i) {
        w[i] = 0.0;
        for (std::size_t j = 0; j < i; ++j) w[i] += dop853::kA[i][j] * v[j];
      }
      v = w;
    }
    return out;
  }();
  return g;
}

/// The longest step h [s] with h mu inside DOP853's stability region for every h' in (0, h]:
/// |R(z)| <= 1 for its stability polynomial (dop853_stability_polynomial). About 6.0 / |mu| on
/// the negative real axis. Infinite for mu = 0 or a growing mode, as dopri5_stable_step.
inline double dop853_stable_step(std::complex<double> mu) {
  const double r = std::abs(mu);
  if (!(r > 0.0) || mu.real() > 0.0) return std::numeric_limits<double>::infinity();
  const std::complex<double> d = mu / r;
  const std::array<double, 13>& g = dop853_stability_polynomial();
  auto stable = [d, &g](double hr) {
    // Horner's scheme in real arithmetic (std::complex's product checks for infinities)
    const double zr = hr * d.real(), zi = hr * d.imag();
    double pr = g[12], pi = 0.0;
    for (int k = 11; k >= 0; --k) {
      const double nr = pr * zr - pi * zi + g[static_cast<std::size_t>(k)];
      pi = pr * zi + pi * zr;
      pr = nr;
    }
    return pr * pr + pi * pi <= (1.0 + 1e-12) * (1.0 + 1e-12);
  };
  // scan |h mu| up to 8 (the region ends before) by 0.05 for the first exit, then bisect it (a
  // run takes this for each rocking eigenvalue of each edge)
  return detail::stability_exit(stable, 8.0, 160) / r;
}

template <class State>
class Dop853 {
 public:
  enum class Status { kAccepted, kStepCollapsed };

  /// Starts at (t, x): evaluates f(t, x) and picks a first step unless `h` > 0 is given.
  template <class System>
  void start(System&& sys, const StepControl& ctl, double t, const State& x, double h = 0.0) {
    ctl_ = ctl;
    for (State& k : k_) k.setZero(x.size());
    for (State& r : r_) r.setZero(x.size());  // the dense output's: sized once, not on a step
    for (State* v : {&x0_, &xn_, &xs_, &k1s_}) v->setZero(x.size());
    t0_ = t1_ = t;
    hd_ = 0.0;
    x0_ = x;
    x1_ = x;
    sys(t, x, k_[12]);
    ++rhs_evals_;
    h_ = h > 0.0 ? h : initial_step(sys, t, x);
    facold_ = 1e-4;
  }

  /// One accepted step from the current point, ending at or before t_stop (exactly at t_stop when
  /// it is reached). Afterwards the dense output covers [t0(), t1()].
  template <class System>
  Status step(System&& sys, double t_stop) {
    const double t = t1_;
    k_[0] = k_[12];  // FSAL: the last step's f(t1, x1)
    for (;;) {
      double h = std::min(h_, ctl_.max_step);
      bool ends = false;
      if (t + h >= t_stop || t + 1.01 * h >= t_stop) {
        h = t_stop - t;
        ends = true;
      }
      if (!(h >= ctl_.min_step * std::max(1.0, std::abs(t)))) {
        if (!ends || !(h > 0.0)) return Status::kStepCollapsed;
      }
      stages(sys, t, h);
      const double err = error_norm(h);
      if (!(err <= 1.0)) {
        ++rejected_;
        const double fac11 = std::isfinite(err) ? std::pow(err, kExpo) : 1e10;
        h_ = h / std::min(kFacc1, fac11 / kSafe);
        continue;
      }
      const double fac = std::clamp(std::pow(err, kExpo) / kSafe, kFacc2, kFacc1);
      facold_ = std::max(err, 1e-4);
      const double h_new = h / fac;
      h_ = ends ? std::max(h_new, h_) : h_new;  // a step cut short by t_stop keeps its stride
      finish(sys, t, h, ends ? t_stop : t + h);
      return Status::kAccepted;
    }
  }

  /// Replaces the last accepted step by one from its start to `t_target` (within it), with no
  /// error control: used to land exactly on an event time found on the dense output.
  template <class System>
  void restep_to(System&& sys, double t_target) {
    const double t = t0_;
    const double h = t_target - t;
    k_[0] = k1s_;
    x1_ = x0_;
    stages(sys, t, h);
    finish(sys, t, h, t_target);
  }

  /// Re-evaluates f at the current point with time `t_eval`: after a step that ended on a jump
  /// of the forcing, the next step must start from the right-hand limit.
  template <class System>
  void refresh_derivative(System&& sys, double t_eval) {
    sys(t_eval, x1_, k_[12]);
    ++rhs_evals_;
  }

  /// State at t in [t0(), t1()] from the 7th-order continuous extension of the last step.
  void dense(double t, State& out) const {
    const double s = (t - t0_) / hd_, s1 = 1.0 - s;
    out = x0_ +
          s * (r_[0] +
               s1 * (r_[1] + s * (r_[2] + s1 * (r_[3] + s * (r_[4] + s1 * (r_[5] + s * r_[6]))))));
  }

  double t0() const { return t0_; }
  double t1() const { return t1_; }
  const State& x0() const { return x0_; }
  const State& x1() const { return x1_; }
  double suggested_step() const { return h_; }
  long rhs_evaluations() const { return rhs_evals_; }
  long rejected_steps() const { return rejected_; }

 private:
  // Hairer's control for DOP853: no PI term (beta = 0), the factor within [1/6, 3]
  static constexpr double kSafe = 0.9, kFacc1 = 3.0, kFacc2 = 1.0 / 6.0, kExpo = 1.0 / 8.0;

  // x_s = x1 + h sum_j a_sj k_j; the sum is spelled out per stage so that each is one Eigen
  // expression (no temporaries)
  template <class System>
  void stages(System&& sys, double t, double h) {
    using namespace dop853;
    const State& x = x1_;
    const auto& k = k_;
    const double* a = kA[1];
    xs_ = x + h * (a[0] * k[0]);
    sys(t + kC[1] * h, xs_, k_[1]);
    a = kA[2];
    xs_ = x + h * (a[0] * k[0] + a[1] * k[1]);
    sys(t + kC[2] * h, xs_, k_[2]);
    a = kA[3];
    xs_ = x + h * (a[0] * k[0] + a[2] * k[2]);
    sys(t + kC[3] * h, xs_, k_[3]);
    a = kA[4];
    xs_ = x + h * (a[0] * k[0] + a[2] * k[2] + a[3] * k[3]);
    sys(t + kC[4] * h, xs_, k_[4]);
    a = kA[5];
    xs_ = x + h * (a[0] * k[0] + a[3] * k[3] + a[4] * k[4]);
    sys(t + kC[5] * h, xs_, k_[5]);
    a = kA[6];
    xs_ = x + h * (a[0] * k[0] + a[3] * k[3] + a[4] * k[4] + a[5] * k[5]);
    sys(t + kC[6] * h, xs_, k_[6]);
    a = kA[7];
    xs_ = x + h * (a[0] * k[0] + a[3] * k[3] + a[4] * k[4] + a[5] * k[5] + a[6] * k[6]);
    sys(t + kC[7] * h, xs_, k_[7]);
    a = kA[8];
    xs_ =
        x + h * (a[0] * k[0] + a[3] * k[3] + a[4] * k[4] + a[5] * k[5] + a[6] * k[6] + a[7] * k[7]);
    sys(t + kC[8] * h, xs_, k_[8]);
    a = kA[9];
    xs_ = x + h * (a[0] * k[0] + a[3] * k[3] + a[4] * k[4] + a[5] * k[5] + a[6] * k[6] +
                   a[7] * k[7] + a[8] * k[8]);
    sys(t + kC[9] * h, xs_, k_[9]);
    a = kA[10];
    xs_ = x + h * (a[0] * k[0] + a[3] * k[3] + a[4] * k[4] + a[5] * k[5] + a[6] * k[6] +
                   a[7] * k[7] + a[8] * k[8] + a[9] * k[9]);
    sys(t + kC[10] * h, xs_, k_[10]);
    a = kA[11];
    xs_ = x + h * (a[0] * k[0] + a[3] * k[3] + a[4] * k[4] + a[5] * k[5] + a[6] * k[6] +
                   a[7] * k[7] + a[8] * k[8] + a[9] * k[9] + a[10] * k[10]);
    sys(t + kC[11] * h, xs_, k_[11]);
    a = kA[12];  // the 8th-order result: b = a_13,j
    xn_ = x + h * (a[0] * k[0] + a[5] * k[5] + a[6] * k[6] + a[7] * k[7] + a[8] * k[8] +
                   a[9] * k[9] + a[10] * k[10] + a[11] * k[11]);
    sys(t + h, xn_, k_[12]);
    rhs_evals_ += 12;
  }

  // Hairer's norm: the 5th-order estimate, damped by the 3rd where that is larger
  double error_norm(double h) const {
    using namespace dop853;
    const int n = ctl_.controlled < 0 ? static_cast<int>(x1_.size()) : ctl_.controlled;
    if (n == 0) return 0.0;
    const auto& k = k_;
    double e5 = 0.0, e3 = 0.0;
    for (int i = 0; i < n; ++i) {
      const double sc = ctl_.atol + ctl_.rtol * std::max(std::abs(x1_(i)), std::abs(xn_(i)));
      double s5 = kE5[0] * k[0](i), s3 = kE3[0] * k[0](i);
      for (std::size_t j = 5; j < 12; ++j) {
        s5 += kE5[j] * k[j](i);
        s3 += kE3[j] * k[j](i);
      }
      e5 += (s5 / sc) * (s5 / sc);
      e3 += (s3 / sc) * (s3 / sc);
    }
    if (e5 == 0.0 && e3 == 0.0) return 0.0;
    return std::abs(h) * e5 / std::sqrt((e5 + 0.01 * e3) * n);
  }

  // the accepted step: the dense output's three extra stages and its coefficients
  template <class System>
  void finish(System&& sys, double t, double h, double t_end) {
    using namespace dop853;
    const auto& k = k_;
    const double* a = kA[13];
    xs_ = x1_ + h * (a[0] * k[0] + a[6] * k[6] + a[7] * k[7] + a[8] * k[8] + a[9] * k[9] +
                     a[10] * k[10] + a[11] * k[11] + a[12] * k[12]);
    sys(t + kC[13] * h, xs_, k_[13]);
    a = kA[14];
    xs_ = x1_ + h * (a[0] * k[0] + a[5] * k[5] + a[6] * k[6] + a[7] * k[7] + a[10] * k[10] +
                     a[11] * k[11] + a[12] * k[12] + a[13] * k[13]);
    sys(t + kC[14] * h, xs_, k_[14]);
    a = kA[15];
    xs_ = x1_ + h * (a[0] * k[0] + a[5] * k[5] + a[6] * k[6] + a[7] * k[7] + a[8] * k[8] +
                     a[12] * k[12] + a[13] * k[13] + a[14] * k[14]);
    sys(t + kC[15] * h, xs_, k_[15]);
    rhs_evals_ += 3;
    // x(t0 + s h) = x0 + s (r0 + (1-s) (r1 + s (r2 + (1-s) (r3 + s (r4 + (1-s) (r5 + s r6))))))
    r_[0] = xn_ - x1_;
    r_[1] = h * k[0] - r_[0];
    r_[2] = r_[0] - h * k[12] - r_[1];
    for (int row = 0; row < 4; ++row) {
      const double* d = kD[row];
      r_[static_cast<std::size_t>(3 + row)] =
          h * (d[0] * k[0] + d[5] * k[5] + d[6] * k[6] + d[7] * k[7] + d[8] * k[8] + d[9] * k[9] +
               d[10] * k[10] + d[11] * k[11] + d[12] * k[12] + d[13] * k[13] + d[14] * k[14] +
               d[15] * k[15]);
    }
    t0_ = t;
    t1_ = t_end;
    hd_ = h;
    x0_ = x1_;
    x1_ = xn_;
    k1s_ = k[0];
  }

  template <class System>
  double initial_step(System&& sys, double t, const State& x) {
    return detail::hairer_initial_step(sys, ctl_, t, x, k_[12], xs_, k_[1], 8.0, rhs_evals_);
  }

  StepControl ctl_;
  State x0_, x1_, xn_, xs_, k1s_;
  std::array<State, 16> k_;
  std::array<State, 7> r_;
  double t0_ = 0.0, t1_ = 0.0, hd_ = 0.0, h_ = 0.0, facold_ = 1e-4;
  long rhs_evals_ = 0, rejected_ = 0;
};

}  // namespace flexrock
