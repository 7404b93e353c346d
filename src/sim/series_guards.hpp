// SPDX-License-Identifier: BSD-3-Clause
// Guards and extremes over a whole step of the rocking series by bounds on their polynomials
// (docs/theory.md, "Guards of the series step by bounds"): no samples, so the step may be as long
// as the series' tolerance allows and no crossing between samples can be missed. Ordinary code,
// the same for every body size. Internal header.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace flexrock::detail {

/// c[0..degree] of p(tau) become those of p(a + sigma) in sigma: Taylor's shift, Horner's scheme
/// repeated (O(degree^2))
inline void taylor_shift(double* c, int degree, double a) {
  for (int i = 0; i < degree; ++i)
    for (int j = degree - 1; j >= i; --j) c[j] += a * c[j + 1];
}

/// A guard (or an observed quantity) on a step [0, h] known by its Taylor coefficients c[0..degree]
/// in tau: the guard itself when `margin` is 0 (theta and theta_dot are the step's polynomials),
/// else within `margin` of it (the reaction's series, truncated where the step's series is).
struct StepPolynomial {
  static constexpr int kMaxDegree = 32;  // the rocking series' theta: 31
  // left uninitialized: a step's polynomials are built in place, and zeroing 33 doubles for each
  // temporary is a good part of a short step's guard checks
  std::array<double, kMaxDegree + 1> c;
  int degree = 0;
  double margin = 0.0;

  double value(double tau) const {
    double v = c[static_cast<std::size_t>(degree)];
    for (int k = degree - 1; k >= 0; --k) v = v * tau + c[static_cast<std::size_t>(k)];
    return v;
  }
  /// sum_k>=1 |c_k| b^k: the most the polynomial moves from c_0 on [0, b]
  double excursion(double b) const {
    double v = 0.0;
    for (int k = degree; k >= 1; --k) v = (v + std::abs(c[static_cast<std::size_t>(k)])) * b;
    return v;
  }
  /// |g| <= this on [0, b]
  double abs_bound(double b) const { return std::abs(c[0]) + excursion(b) + margin; }
  /// the same polynomial with its first m coefficients dropped: g / tau^m where they vanish
  StepPolynomial over_power(int m) const {
    StepPolynomial r;
    r.degree = degree - m;
    r.margin = margin;
    for (int k = 0; k <= r.degree; ++k)
      r.c[static_cast<std::size_t>(k)] = c[static_cast<std::size_t>(k + m)];
    return r;
  }
  /// the same polynomial about a: q(sigma) = g(a + sigma)
  StepPolynomial about(double a) const {
    StepPolynomial q = *this;
    taylor_shift(q.c.data(), degree, a);
    return q;
  }
};

/// A bracket of one crossing from > 0 to <= 0: g(tl) = gl > 0 >= gr = g(tr) [tau].
struct CrossingBracket {
  double tl = 0.0, tr = 0.0, gl = 0.0, gr = 0.0;
};

inline constexpr int kBracketDepth = 48;  // halvings: 2^-48 of a step is below a step's rounding

/// How the guard stands at the step's start, for polynomial_bracket.
enum class GuardStart {
  kArmed,     // positive: its next crossing to <= 0 counts
  kDisarmed,  // <= 0 and not known to turn positive: it counts once it has been positive
  kZero,      // exactly zero, known to turn positive (the impact and peak functions at uplift)
  kCrossed,   // it has just crossed to <= 0 here (a peak found earlier in the step)
};

/// A polynomial on [lo, hi] in Bernstein form, p = sum_i b_i C(d, i) s^i (1 - s)^(d - i) with
/// s = (tau - lo) / (hi - lo): min b_i <= p <= max b_i there (the convex hull property), b_0 and
/// b_d are its values at the ends, and it has at most as many roots there as the b_i change sign
/// (Descartes' rule of signs in this basis).
struct BernsteinPiece {
  std::array<double, StepPolynomial::kMaxDegree + 1> b;  // uninitialized, as StepPolynomial's
  int degree = 0;
  double lo = 0.0, hi = 0.0;

  double min() const { return *std::min_element(b.begin(), b.begin() + degree + 1); }
  double max() const { return *std::max_element(b.begin(), b.begin() + degree + 1); }
  double max_abs() const {
    double m = 0.0;
    for (int i = 0; i <= degree; ++i) m = std::max(m, std::abs(b[static_cast<std::size_t>(i)]));
    return m;
  }
  /// changes of sign along b_0..b_d, a zero counted with the non-positive
  int sign_changes() const {
    int n = 0;
    for (int i = 1; i <= degree; ++i)
      n += (b[static_cast<std::size_t>(i)] > 0.0) != (b[static_cast<std::size_t>(i - 1)] > 0.0);
    return n;
  }
  /// the two halves, by de Casteljau's algorithm at s = 1/2
  void split(BernsteinPiece& left, BernsteinPiece& right) const {
    std::array<double, StepPolynomial::kMaxDegree + 1> w = b;
    const auto d = static_cast<std::size_t>(degree);
    left = right = *this;
    const double mid = 0.5 * (lo + hi);
    left.hi = right.lo = mid;
    for (std::size_t r = 1; r <= d; ++r) {
      for (std::size_t i = 0; i + r <= d; ++i) w[i] = 0.5 * (w[i] + w[i + 1]);
      left.b[r] = w[0];
      right.b[d - r] = w[d - r];
    }
  }
};

/// 1 / C(d, k) for d, k <= StepPolynomial::kMaxDegree (the power basis into Bernstein's)
inline const std::array<std::array<double, StepPolynomial::kMaxDegree + 1>,
                        StepPolynomial::kMaxDegree + 1>&
inverse_binomials() {
  static const auto table = [] {
    std::array<std::array<double, StepPolynomial::kMaxDegree + 1>, StepPolynomial::kMaxDegree + 1>
        t{};
    for (int d = 0; d <= StepPolynomial::kMaxDegree; ++d) {
      double inv = 1.0;
      for (int k = 0; k <= d; ++k) {
        if (k > 0) inv *= static_cast<double>(k) / (d - k + 1);
        t[static_cast<std::size_t>(d)][static_cast<std::size_t>(k)] = inv;
      }
    }
    return t;
  }();
  return table;
}

/// The Bernstein form of p on [lo, hi] (0 <= lo < hi): p about lo by Taylor's shift, then the
/// power basis in s turned into Bernstein's, b_i = sum_k<=i C(i, k) / C(d, k) a_k (hi - lo)^k, by
/// the binomial transform's running sums (O(d^2) either way). `at_lo` is p(lo) as the caller
/// evaluated it, the piece's first coefficient.
inline BernsteinPiece bernstein_piece(const StepPolynomial& p, double lo, double hi, double at_lo) {
  BernsteinPiece out;
  const int d = p.degree;
  out.degree = d;
  out.lo = lo;
  out.hi = hi;
  auto& c = out.b;
  for (int k = 0; k <= d; ++k) c[static_cast<std::size_t>(k)] = p.c[static_cast<std::size_t>(k)];
  if (lo != 0.0) taylor_shift(c.data(), d, lo);
  const double w = hi - lo;
  const auto& inv_binom = inverse_binomials()[static_cast<std::size_t>(d)];
  double wk = 1.0;  // w^k
  for (int k = 1; k <= d; ++k) {
    wk *= w;
    c[static_cast<std::size_t>(k)] *= wk * inv_binom[static_cast<std::size_t>(k)];
  }
  for (int j = 1; j <= d; ++j)
    for (int i = d; i >= j; --i)
      c[static_cast<std::size_t>(i)] += c[static_cast<std::size_t>(i - 1)];
  c[0] = at_lo;
  return out;
}

/// The first crossing from > 0 to <= 0 in a piece whose value at lo is > 0: false when none (every
/// b_i > 0, or the piece ends positive with its last half cleared), else true with a bracket
/// holding exactly one root (one sign change), or the first unresolved one after `depth` halvings.
inline bool bernstein_bracket(const BernsteinPiece& piece, int depth, CrossingBracket& out) {
  if (piece.min() > 0.0) return false;
  const double last = piece.b[static_cast<std::size_t>(piece.degree)];
  if (last <= 0.0 && (depth == 0 || piece.sign_changes() == 1)) {
    out = {piece.lo, piece.hi, piece.b[0], last};
    return true;
  }
  if (depth == 0) return false;  // a dip below resolution
  BernsteinPiece left, right;
  piece.split(left, right);
  if (bernstein_bracket(left, depth - 1, out)) return true;
  return bernstein_bracket(right, depth - 1, out);
}

/// The first crossing from > 0 to <= 0 of a guard that is its polynomial exactly (margin 0) in
/// (a, b], 0 <= a < b, as a bracket with the guard's values at its ends; start says how it stands
/// at a. Returns 1 with the bracket, 0 for none, -1 when a guard starting at zero does not turn
/// positive (unresolved, as first_crossing in event_location.hpp has it: the caller fires it at
/// the start if the guard says so).
inline int polynomial_bracket(const StepPolynomial& g, double a, double b, GuardStart start,
                              CrossingBracket& out) {
  // q(sigma) = g(a + sigma) on [0, b - a]; where g crossed at a, q(0) is that root
  StepPolynomial q;
  const StepPolynomial* p = &g;
  if (a != 0.0) {
    q = g.about(a);
    if (start == GuardStart::kCrossed) q.c[0] = 0.0;
    p = &q;
  }
  const double w = b - a;
  // the first crossing in (lo, w] of f, f(lo) = f_lo > 0, whose roots for sigma > 0 are g's
  auto search = [&](const StepPolynomial& f, double lo, double f_lo, CrossingBracket& o) {
    return bernstein_bracket(bernstein_piece(f, lo, w, f_lo), kBracketDepth, o);
  };
  // the bracket on q's axis back on g's, with g's values at its ends
  auto on_g = [&](CrossingBracket& o) {
    o.tl += a;
    o.tr += a;
    o.gl = g.value(o.tl);
    o.gr = g.value(o.tr);
  };
  const double q0 = p->c[0];
  // most steps: the guard keeps its sign by the coefficients' bound, |g(a)| > sum |c_k| w^k
  if (std::abs(q0) > p->excursion(w)) return q0 > 0.0 || start != GuardStart::kZero ? 0 : -1;
  if (q0 > 0.0) {
    if (!search(*p, 0.0, q0, out)) return 0;
    on_g(out);
    return 1;
  }
  StepPolynomial r;  // q, or q / sigma^m where it starts at exactly zero
  const StepPolynomial* f = p;
  if (q0 == 0.0) {
    int m = 1;
    while (m <= p->degree && p->c[static_cast<std::size_t>(m)] == 0.0) ++m;
    if (m > p->degree) return start == GuardStart::kZero ? -1 : 0;  // identically zero
    r = p->over_power(m);
    f = &r;
    // r keeps the sign it starts with, by the coefficients' bound: no crossing, or none resolved
    if (std::abs(r.c[0]) > r.excursion(w))
      return r.c[0] > 0.0 && start != GuardStart::kCrossed ? 0
             : start == GuardStart::kZero                  ? -1
                                                           : 0;
    if (r.c[0] > 0.0 && start != GuardStart::kCrossed) {
      // positive right after the start: armed
      if (!search(r, 0.0, r.c[0], out)) return 0;
      // q vanishes at the start: halve toward the crossing for a point inside where it is > 0
      for (int i = 0; i < 64 && !(out.tl > 0.0 && p->value(out.tl) > 0.0); ++i) {
        const double mid = 0.5 * (out.tl + out.tr);
        (r.value(mid) > 0.0 ? out.tl : out.tr) = mid;
      }
      on_g(out);
      return out.gl > 0.0 && out.gr <= 0.0 ? 1 : -1;
    }
  }
  // negative at the start, or right after it: armed once it has turned positive
  StepPolynomial nf = *f;
  for (int k = 0; k <= nf.degree; ++k)
    nf.c[static_cast<std::size_t>(k)] = -nf.c[static_cast<std::size_t>(k)];
  CrossingBracket up;
  if (!(nf.c[0] > 0.0) || !search(nf, 0.0, nf.c[0], up)) return start == GuardStart::kZero ? -1 : 0;
  if (start == GuardStart::kZero) {
    // a guard known to turn positive from zero may start with a leading term at rounding of the
    // wrong sign (theta'' at the instant of an uplift, where the uplift function vanishes): a dip
    // below zero that deep counts as none; a real dip is unresolved (it fires at the start)
    const int m = p->degree - f->degree;
    for (int i = 0; i < 200 && up.tr - up.tl > 1e-15 * up.tr; ++i) {
      const double mid = 0.5 * (up.tl + up.tr);  // where it turns positive, closely
      (nf.value(mid) > 0.0 ? up.tl : up.tr) = mid;
    }
    const double depth = std::pow(up.tr, m) * f->abs_bound(up.tr);
    if (depth > 1e-14 * p->abs_bound(w)) return -1;
  }
  const double qu = p->value(up.tr);
  if (!(qu > 0.0) || up.tr >= w) return 0;
  if (!search(*p, up.tr, qu, out)) return 0;
  on_g(out);
  return 1;
}

/// Where |g| (or the ratio |num| / den where den >= floor) is largest on [0, b] by the polynomials:
/// 9 points, then Brent-like golden refinement about the best; returns tau. Only where the bound
/// says the extreme so far could be exceeded: the value there is then taken from the exact state.
template <class F>
double polynomial_argmax(F&& f, double b) {
  constexpr int kPoints = 8;
  int best = 0;
  double fb = -std::numeric_limits<double>::infinity();
  for (int k = 0; k <= kPoints; ++k) {
    const double v = f(b * k / kPoints);
    if (v > fb) {
      fb = v;
      best = k;
    }
  }
  // largest at an end and falling away from it: that end (already a point of the motion)
  if (best == 0 && f(1e-6 * b) <= fb) return 0.0;
  if (best == kPoints && f(b * (1.0 - 1e-6)) <= fb) return b;
  double lo = b * std::max(0, best - 1) / kPoints, hi = b * std::min(kPoints, best + 1) / kPoints;
  // golden-section search of the bracket to 1e-6 of the step: at a smooth maximum the value is then
  // within its curvature times 1e-12 of the step squared
  constexpr double kR = 0.6180339887498949;
  double x1 = hi - kR * (hi - lo), x2 = lo + kR * (hi - lo);
  double f1 = f(x1), f2 = f(x2);
  while (hi - lo > 1e-6 * b) {
    if (f1 < f2) {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + kR * (hi - lo);
      f2 = f(x2);
    } else {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - kR * (hi - lo);
      f1 = f(x1);
    }
  }
  const double t = f1 > f2 ? x1 : x2;
  return std::max(f1, f2) >= fb ? t : b * best / kPoints;
}

}  // namespace flexrock::detail
