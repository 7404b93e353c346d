// SPDX-License-Identifier: BSD-3-Clause
// A flexible body's full contact under a record (N > 0 only): the exact propagation walked from
// sample to sample where no guard can cross, with the excursion bounds that rule a crossing out
// and the search for the extremes inside a piece (docs/theory.md §14, §17). Part of the event loop
// (simulator.hpp), included at its end.
#pragma once

#include "simulator.hpp"

namespace flexrock::detail {

// a flexible body in full contact under a sampled record, walked piece by piece from a record
// sample (docs/theory.md, "Exact propagation in full contact"): true when the walk can start at t
template <int N, int MaxN>
bool Simulator<N, MaxN>::can_walk(double t) const requires(N != 0) {
  if (!std::holds_alternative<Exact*>(stepper_) || !opt_.methods.full_contact_walk ||
      !eq_.motion.is_sampled())
    return false;
  if (t < exact_.fine_until - 1e-12 * std::max(1.0, t)) return false;
  if (latch_.tension || latch_.hold_tension) return false;
  const ModeSpec& spec = mode_spec(eq_.mode);
  for (int j = 0; j < spec.count; ++j) {
    const auto k = static_cast<std::size_t>(j);
    if (latch_.zero_start[k] || !(s0_.v[k] > 0.0)) return false;
  }
  const std::vector<double>& ts = eq_.motion.times();
  return t >= ts.front() && t < ts.back();
}

// The walk: one exact update per piece (a record interval, or an equal part of it within
// ContactPropagator::kWalkPhase of the fastest mode), with the guards at its ends from
// evaluate(). The guards are quadratic in the modal state and linear in the base acceleration,
// and the piece bounds their excursion E from the chord between its ends
// (ContactPropagator::walk_excursion), so f >= min(f(0), f(h)) - E throughout. Where that stays
// positive for every guard no crossing lies in the piece; else the piece is halved until the
// bound clears or a guard is found <= 0, and the stepped propagation locates the crossing there.
// The extremes are located the same way: a piece whose bound could raise one is searched
// (locate_extremes). A quiet piece (walk_quiet: bounds on the values themselves clear every guard
// and extreme) is not evaluated at its end at all.
template <int N, int MaxN>
bool Simulator<N, MaxN>::advance_walk(double& t, State& x) requires(N != 0) {
  const std::vector<double>& ts = eq_.motion.times();
  const std::vector<double>& hx = eq_.motion.horizontal();
  const std::vector<double>& vy = eq_.motion.vertical();
  const bool vertical = vy.size() == ts.size();
  const double g = eq_.dyn.g();
  std::size_t i = scan_.index;
  if (i >= ts.size()) i = ts.size() - 1;
  while (i > 0 && ts[i] > t) --i;
  while (i + 1 < ts.size() && ts[i + 1] <= t) ++i;
  exact_.prop.walk_start(x);
  exact_.xw = x;
  GuardSample& sa = points_.samples[0];
  GuardSample& sb = points_.samples[1];
  sa = s0_;
  bool sa_due = false;  // sa is not yet evaluated at the piece's start (after a quiet piece)
  const double cap = exact_.prop.walk_cap();
  for (; i + 1 < ts.size() && ts[i + 1] <= setup_.t_end; ++i) {
    if (!count_step(t)) {
      x = exact_.xw;
      return false;
    }
    const double tb = ts[i + 1], span = ts[i + 1] - ts[i];
    const BaseAcceleration slope{(hx[i + 1] - hx[i]) / span,
                                 vertical ? (vy[i + 1] - vy[i]) / span : 0.0};
    // most intervals are one piece: std::ceil is a libm call without SSE4.1 (above one span,
    // spans - 1e-9 > 0, so the ceiling is at least 1)
    const double spans = (tb - t) / cap;
    const double pieces = spans <= 1.0 ? 1.0 : std::ceil(spans - 1e-9);
    const double hp = (tb - t) / pieces;
    const double ti = t;
    for (int k = 0; k < static_cast<int>(pieces); ++k) {
      const double tp0 = t, tp1 = k + 1 == static_cast<int>(pieces) ? tb : ti + hp * (k + 1);
      const double h = tp1 - tp0;
      const BaseAcceleration a0{hx[i] + slope.x * (tp0 - ts[i]),
                                vertical ? vy[i] + slope.y * (tp0 - ts[i]) : 0.0};
      exact_.prop.walk_piece(h, a0, slope);
      exact_.xe = exact_.xw;
      exact_.prop.walk_state(exact_.xe);
      // the forcing over the piece (over g; a_y = 1 + Y''/g): max |a_x|, a_y at its ends
      const double ax = std::max(std::abs(a0.x), std::abs(a0.x + slope.x * h)) / g;
      const double ay0 = 1.0 + a0.y / g, ay1 = 1.0 + (a0.y + slope.y * h) / g;
      if (walk_quiet(ax, ay0, ay1)) {
        // no guard near zero and no extreme within reach anywhere in the piece: its end is not
        // evaluated (the energies' scale still follows the ends)
        rec_.observe_energy(exact_.xe(iw()), exact_.xe(id()));
        emit_walk_rows(tp0, tp1);
        exact_.xw = exact_.xe;
        sa_due = true;
        t = tp1;
        if (opt_.progress) opt_.progress->store(t, std::memory_order_relaxed);
        continue;
      }
      if (sa_due) {
        eq_.evaluate(tp0, exact_.xw, sa);
        sa_due = false;
      }
      eq_.evaluate(tp1, exact_.xe, sb);
      // the guards' excursion between the piece's ends
      exact_.forcing = {ax, std::max(std::abs(ay0), std::abs(ay1)), std::abs(slope.x) / g,
                        std::abs(slope.y) / g};
      const Excursion c = walk_excursion(h);
      if (!guards_clear(sa, sb, c)) {
        // a crossing may lie in this piece: halve it until the bound clears every part or a
        // guard is found <= 0 at a part's end
        double ba = 0.0, bb = h;
        const int found = walk_search(tp0, 0.0, h, sa, sb, 40, ba, bb);
        if (found != 0) {
          scan_.index = i;
          exact_.fine_until = tb;
          if (found == 1 && ba > 0.0) {
            // the stepped propagation from the bracket's start, its first step ending at the
            // bracket's end (where a guard is <= 0): it locates the crossing there
            exact_.prop.walk_start(exact_.xw);
            exact_.prop.walk_piece(ba, a0, slope, false);
            x = exact_.xw;
            exact_.prop.walk_state(x);
            t = tp0 + ba;
            eq_.evaluate(t, x, s0_);
            // the extremes before the bracket, located as in a whole piece
            exact_.xe = x;
            locate_extremes(tp0, ba, sa, s0_, walk_excursion(ba));
          } else {
            x = exact_.xw;
            s0_ = sa;
          }
          if (found == 1) step_stop_ = tp0 + bb;
          exact_.prop.start(t, x);
          return true;
        }
      }
      locate_extremes(tp0, h, sa, sb, c);
      emit_walk_rows(tp0, tp1);
      observe(sb, exact_.xe);
      exact_.xw = exact_.xe;
      sa = sb;
      t = tp1;
      if (opt_.progress) opt_.progress->store(t, std::memory_order_relaxed);
    }
  }
  scan_.index = i;
  x = exact_.xw;
  if (sa_due) eq_.evaluate(t, exact_.xw, sa);
  s0_ = sa;
  release_latches(s0_);
  exact_.prop.start(t, x);
  // the rest (past the record's last sample within t_end) goes to the stepped propagation
  exact_.fine_until = setup_.t_end;
  return true;
}

// the excursion bounds over any part of length w of the walk's piece, under its forcing
template <int N, int MaxN>
typename Simulator<N, MaxN>::Excursion Simulator<N, MaxN>::walk_excursion(double w) const
    requires(N != 0) {
  const auto& f = exact_.forcing;
  return exact_.prop.walk_excursion(w, f[0], f[1], f[2], f[3]);
}

// the full-contact guards over a part of the walk's piece with values sa, sb at its ends cannot
// cross there: each stays above min(f(a), f(b)) - E > 0 (E: its excursion bound on that part)
template <int N, int MaxN>
bool Simulator<N, MaxN>::guards_clear(const GuardSample& sa, const GuardSample& sb,
                                      const Excursion& e) const requires(N != 0) {
  constexpr ContactMode m = ContactMode::kFullContact;
  const double mu = eq_.mu_s;
  auto clear = [&](std::size_t j, double excursion) {
    const double lo = std::min(sa.v[j], sb.v[j]) - excursion;
    return lo > 1e-12 * (1.0 + std::abs(sa.v[j]) + std::abs(sb.v[j]));
  };
  return clear(kSlot<m, Guard::kUpliftEdge1>, e.u1) && clear(kSlot<m, Guard::kUpliftEdge2>, e.u2) &&
         clear(kSlot<m, Guard::kLiftOff>, e.fj) &&
         (!std::isfinite(mu) || clear(kSlot<m, Guard::kFrictionLimit>, mu * e.fj + e.fi));
}

// the walk's last piece (max |a_x| = ax, a_y from ay0 to ay1, over g) can neither cross a
// full-contact guard nor raise an extreme anywhere: the bounds on the values themselves over the
// piece (ContactPropagator::walk_reach) keep every guard above zero (U_1 = R(0) + alpha_1 F_J and
// U_2 = alpha_2 F_J - R(0) are >= alpha_k min F_J - max|R(0)|), and every reported quantity
// within its extreme so far
template <int N, int MaxN>
bool Simulator<N, MaxN>::walk_quiet(double ax, double ay0, double ay1) const requires(N != 0) {
  const auto r = exact_.prop.walk_reach(ax, std::min(ay0, ay1), std::max(ay0, ay1));
  const double margin = 1e-12 * (1.0 + r.fj_hi + r.moment);
  if (!(r.fj_lo > margin && eq_.dyn.alpha1() * r.fj_lo - r.moment > margin &&
        eq_.dyn.alpha2() * r.fj_lo - r.moment > margin))
    return false;
  const double mu = eq_.mu_s;
  if (std::isfinite(mu) && !(mu * r.fj_lo - r.fi > margin)) return false;
  const ReactionReach reach = reaction_reach(r.fi, r.moment, r.fj_lo, r.fj_hi);
  if (reach.shear || reach.moment || reach.demand || reach.pull) return false;
  const Extremes& ex = res_.extremes;
  for (int j = 0; j < n_; ++j)
    if (exact_.prop.walk_q_reach(j) > ex.max_abs_q(j)) return false;
  return true;
}

// which reported reaction quantities (the shear, the overturning moment, the friction demand as
// Recorder::observe forms it) could exceed their extremes so far, for values within |F_I| <=
// fi_top, |R(0)| <= moment_top and fj_lo <= F_J <= fj_hi (evaluate()'s units)
template <int N, int MaxN>
typename Simulator<N, MaxN>::ReactionReach Simulator<N, MaxN>::reaction_reach(double fi_top,
                                                                              double moment_top,
                                                                              double fj_lo,
                                                                              double fj_hi) const {
  const Extremes& ex = res_.extremes;
  const double mg = eq_.dyn.mass() * eq_.dyn.g();
  return {mg * fi_top > ex.max_base_shear,
          mg * eq_.dyn.height() * moment_top > ex.max_overturning_moment,
          fj_hi >= kPressingFraction &&
              !(fj_lo >= kPressingFraction && fi_top / fj_lo <= ex.max_friction_demand),
          latch_.tension && -mg * fj_lo > ex.max_pivot_pull};
}

// [a, b] of the walk's piece from tp0 (guards sa, sb at its ends, every one > 0 at a), halved
// until the bound clears each part (0), a guard is <= 0 at a part's end b_out with all > 0 at
// its start a_out (1), or `depth` halvings leave a part unresolved (2, a grazing guard)
template <int N, int MaxN>
int Simulator<N, MaxN>::walk_search(double tp0, double a, double b, const GuardSample& sa,
                                    const GuardSample& sb, int depth, double& a_out,
                                    double& b_out) requires(N != 0) {
  if (guards_clear(sa, sb, walk_excursion(b - a))) return 0;
  const ModeSpec& spec = mode_spec(eq_.mode);
  for (int j = 0; j < spec.count; ++j) {
    if (!(sb.v[static_cast<std::size_t>(j)] > 0.0)) {
      a_out = a;
      b_out = b;
      return 1;
    }
  }
  if (depth == 0) {
    a_out = a;
    b_out = b;
    return 2;
  }
  const double mid = 0.5 * (a + b);
  GuardSample sm;
  scratch_.xr = exact_.xw;
  exact_.prop.walk_dense(mid, scratch_.xr);
  eq_.evaluate(tp0 + mid, scratch_.xr, sm);
  const int left = walk_search(tp0, a, mid, sa, sm, depth - 1, a_out, b_out);
  if (left != 0) return left;
  return walk_search(tp0, mid, b, sm, sb, depth - 1, a_out, b_out);
}

// the rows due in the walk's piece [tp0, tp1] (state exact_.xw at tp0, exact_.xe at tp1): one at
// the piece's end from its state, others from the propagator's exact steps over the piece
template <int N, int MaxN>
void Simulator<N, MaxN>::emit_walk_rows(double tp0, double tp1) requires(N != 0) {
  if (opt_.output_dt <= 0.0) return;
  const double to = static_cast<double>(ledger_.next_output) * opt_.output_dt;
  if (to > tp1 || to > setup_.t_end * (1.0 + 1e-14)) return;
  if (to >= tp1 - 1e-12 * std::max(1.0, tp1)) {
    emit_row(to, exact_.xe);
    ++ledger_.next_output;
    return;
  }
  exact_.prop.start(tp0, exact_.xw);
  auto none = [](double, const State&, State&) {};
  while (exact_.prop.t1() < tp1) {
    exact_.prop.step(none, tp1);
    emit_rows_until(exact_.prop.t1());
  }
}

// the extremes the piece [tp0, tp0 + h] could raise between its ends (by the excursion bounds
// `e`), located: the exact solution at the piece's kept points, then Brent's search about the
// largest of each such quantity; every point searched is observed (by a deformation's search,
// its own value), so the extremes stay values the motion reaches
template <int N, int MaxN>
void Simulator<N, MaxN>::locate_extremes(double tp0, double h, const GuardSample& sa,
                                         const GuardSample& sb,
                                         const Excursion& e) requires(N != 0) {
  const Extremes& ex = res_.extremes;
  // which quantities might exceed their extreme within the piece: -1 none, j < n: q_j,
  // n: shear, n + 1: moment, n + 2: friction demand, n + 3: the floor's pull on a held pivot
  std::vector<int>& wanted = exact_.wanted;
  int count = 0;
  // u_j could exceed its extreme within the excursion bound over a length w of a value `top`
  auto deformation_reach = [&](int j, double top, double w) {
    return top + exact_.prop.walk_q_excursion(j, w) > ex.max_abs_q(j);
  };
  // the reaction's range over the points seen: the piece's ends, then its kept points too
  double fi_top = std::max(std::abs(sa.fi), std::abs(sb.fi));
  double moment_top = std::max(std::abs(sa.moment), std::abs(sb.moment));
  double fj_lo = std::min(sa.fj, sb.fj), fj_hi = std::max(sa.fj, sb.fj);
  // which reaction quantities could exceed their extremes within excursion bounds r of that range
  auto range_reach = [&](const Excursion& r) {
    return reaction_reach(fi_top + r.fi, moment_top + r.moment, fj_lo - r.fj, fj_hi + r.fj);
  };
  exact_.ua.noalias() = Dyn::mv(eq_.to_user, exact_.xw.segment(iq(), n_));
  exact_.ub.noalias() = Dyn::mv(eq_.to_user, exact_.xe.segment(iq(), n_));
  for (int j = 0; j < n_; ++j)
    if (deformation_reach(j, std::max(std::abs(exact_.ua(j)), std::abs(exact_.ub(j))), h))
      wanted[static_cast<std::size_t>(count++)] = j;
  const ReactionReach reach = range_reach(e);
  if (reach.shear) wanted[static_cast<std::size_t>(count++)] = n_;
  if (reach.moment) wanted[static_cast<std::size_t>(count++)] = n_ + 1;
  if (reach.demand) wanted[static_cast<std::size_t>(count++)] = n_ + 2;
  if (reach.pull) wanted[static_cast<std::size_t>(count++)] = n_ + 3;
  if (count == 0) return;
  // the state at tau in the piece, and the guards where a reaction's extreme is sought (they
  // come after the deformations in `wanted`), observed on the way
  const bool guards = wanted[static_cast<std::size_t>(count - 1)] >= n_;
  GuardSample s;
  auto visit = [&](double tau) {
    exact_.prop.walk_dense(tau, scratch_.xr);
    if (!guards) return;
    eq_.evaluate(tp0 + tau, scratch_.xr, s);
    observe(s, scratch_.xr);
  };
  // the quantity `k` of the point visited last
  auto quantity = [&](int k) { return point_quantity(k, s, scratch_.xr); };
  scratch_.xr = exact_.xw;
  constexpr int kPoints = ContactPropagator<N, MaxN, State>::kPoints;
  std::vector<double>& best = exact_.best;
  std::vector<double>& at = exact_.best_at;
  std::fill(best.begin(), best.end(), -1.0);
  for (int p = 1; p < kPoints; ++p) {
    const double tau = h * p / kPoints;
    visit(tau);
    if (guards) {
      fi_top = std::max(fi_top, std::abs(s.fi));
      moment_top = std::max(moment_top, std::abs(s.moment));
      fj_lo = std::min(fj_lo, s.fj);
      fj_hi = std::max(fj_hi, s.fj);
    }
    for (int q = 0; q < count; ++q) {
      const double v = quantity(wanted[static_cast<std::size_t>(q)]);
      if (v > best[static_cast<std::size_t>(q)]) {
        best[static_cast<std::size_t>(q)] = v;
        at[static_cast<std::size_t>(q)] = tau;
      }
    }
  }
  // a quantity is searched further only where a part between two neighbouring points (the ends
  // and the kept points, all observed) could still raise its extreme: the largest value at the
  // points plus the excursion bound over a part of length h / kPoints, whose curvature term
  // (w^2/8 max|f''|) is 64 times smaller than the one over the whole piece that asked for it
  const double part = h / kPoints;
  ReactionReach part_reach;
  if (guards) part_reach = range_reach(walk_excursion(part));
  // the largest value of each about its best kept point, from its jet: a deformation u_j from its
  // own (ContactPropagator::walk_q_jet), each point observed; a reaction from q's derivatives
  // (guard_jet), the point found then observed through evaluate() as every other sample
  for (int q = 0; q < count; ++q) {
    const int k = wanted[static_cast<std::size_t>(q)];
    const double tau = at[static_cast<std::size_t>(q)];
    const double lo = std::max(0.0, tau - h / kPoints), hi = std::min(h, tau + h / kPoints);
    if (k < n_) {
      rec_.observe_deformation(k, best[static_cast<std::size_t>(q)]);
      if (!deformation_reach(k,
                             std::max({best[static_cast<std::size_t>(q)], std::abs(exact_.ua(k)),
                                       std::abs(exact_.ub(k))}),
                             part))
        continue;
      auto jet = [&](double t) {
        const std::array<double, 3> u = exact_.prop.walk_q_jet(t, k);
        rec_.observe_deformation(k, std::abs(u[0]));
        return u;
      };
      largest_near(jet, tau, lo, hi);
    } else if (k == n_       ? part_reach.shear
               : k == n_ + 1 ? part_reach.moment
               : k == n_ + 2 ? part_reach.demand
                             : part_reach.pull) {
      visit(largest_near([&](double t) { return guard_jet(k, t); }, tau, lo, hi));
    }
  }
}

// The largest |f| in [lo, hi] about tau, the kept point of the walk's piece where |f| is largest
// of the kept points, from f's jet (f, f', f'') at any point of the piece: a root of s f'
// (s = sign f(tau)) from + to -, bracketed by tau and the end of [lo, hi] that s f'(tau) points
// to, found by Newton's method safeguarded by bisection. Where s f' keeps its sign to that end,
// |f| rises to it where it is larger there (a piece's end); else it rose and fell back in
// between, where Brent's search finds that maximum. Newton's method stops when a step is within
// 16 bits of [lo, hi], Brent's tolerance, so |f| there is within |f''| (2^-16 (hi - lo))^2 / 2 of
// the maximum: about three jets where Brent's search took a dozen values. Returns where it
// ended: the maximum found, or the end |f| rises to.
template <int N, int MaxN>
template <class Jet>
double Simulator<N, MaxN>::largest_near(Jet&& jet, double tau, double lo, double hi) {
  std::array<double, 3> f = jet(tau);
  const double s = f[0] < 0.0 ? -1.0 : 1.0;
  if (s * f[1] == 0.0) return tau;                      // stationary at the kept point
  const bool rising = s * f[1] > 0.0;                   // the maximum lies toward hi
  double a = rising ? tau : lo, b = rising ? hi : tau;  // s f' > 0 at a, < 0 at b
  const double end_at = rising ? hi : lo;
  const std::array<double, 3> end = jet(end_at);
  if (rising ? !(s * end[1] < 0.0) : !(s * end[1] > 0.0)) {
    if (s * end[0] >= s * f[0]) return end_at;
    std::uintmax_t iterations = 40;
    return boost::math::tools::brent_find_minima([&](double t) { return -std::abs(jet(t)[0]); }, lo,
                                                 hi, 16, iterations)
        .first;
  }
  const double tol = std::ldexp(hi - lo, -16);
  for (int it = 0; it < 64; ++it) {
    const double newton = tau - f[1] / f[2];
    const bool inside = s * f[2] < 0.0 && newton > a && newton < b;
    const double next = inside ? newton : 0.5 * (a + b);
    if (std::abs(next - tau) <= tol) break;
    tau = next;
    f = jet(tau);
    if (s * f[1] > 0.0) {
      a = tau;
    } else {
      b = tau;
    }
  }
  return tau;
}

// The reaction quantity k of locate_extremes (n: F_I, n + 1: the moment R(0) about the c.g.
// projection, n + 2: F_I/F_J) and its first two time derivatives at tau within the walk's piece,
// in evaluate()'s units: Dynamics::full_contact_reaction_rates along q's exact derivatives
// (ContactPropagator::walk_q_derivatives), the base acceleration linear in the piece, and F_I/F_J
// by the quotient rule.
template <int N, int MaxN>
std::array<double, 3> Simulator<N, MaxN>::guard_jet(int k, double tau) requires(N != 0) {
  exact_.prop.walk_q_derivatives(tau, exact_.qjet);
  const auto r = eq_.dyn.full_contact_reaction_rates(exact_.qjet, exact_.prop.walk_base(tau),
                                                     exact_.prop.walk_slope());
  if (k == n_) return r.fi;
  if (k == n_ + 1) return r.moment;
  if (k == n_ + 3) return {-r.fj[0], -r.fj[1], -r.fj[2]};
  const std::array<double, 3>&fi = r.fi, &fj = r.fj;
  const double d = fi[0] / fj[0], d1 = (fi[1] - d * fj[1]) / fj[0];
  return {d, d1, (fi[2] - d * fj[2] - 2.0 * d1 * fj[1]) / fj[0]};
}

}  // namespace flexrock::detail
