// SPDX-License-Identifier: BSD-3-Clause
// A rigid body's own steppers (N = 0 only): the still path in full contact, the Taylor series of
// the rocking with its guards bounded over the step, and the closed-form free-rocking arc
// (docs/theory.md §14, §17). Part of the event loop (simulator.hpp), included at its end.
#pragma once

#include "simulator.hpp"

namespace flexrock::detail {

// A rigid body rocking on its series takes steps as long as the series' tolerance allows, with no
// guard samples: every guard of the mode is a polynomial on the step (theta's and theta_dot's, or
// the reaction's series within its truncation), so a bound over the step rules a crossing out, and
// a guard that could cross is halved in its Bernstein form until a single crossing is bracketed
// (series_guards.hpp; docs/theory.md, "Guards of the series step by bounds"). A friction limit
// makes |F_I| a guard, which is not a polynomial: such a run keeps the sampled steps, as does a
// lift-off function that does not start armed (and a step whose lift-off the bound cannot rule out
// is taken again with samples).
template <int N, int MaxN>
bool Simulator<N, MaxN>::series_bounded() const requires(N == 0) {
  if (std::isfinite(eq_.mu_s) || latch_.hold_tension) return false;
  const auto lift = static_cast<std::size_t>(guard_slot(eq_.mode, Guard::kLiftOff));
  return latch_.tension || (!latch_.zero_start[lift] && s0_.v[lift] > 0.0);
}

template <int N, int MaxN>
StepEnd Simulator<N, MaxN>::advance_series(double& t, State& x) requires(N == 0) {
  const double t_stop =
      std::min({setup_.t_end, eq_.motion.next_breakpoint(t, eq_.cursor.brk), step_stop_});
  if (!count_step(t)) return StepEnd::ended();
  auto none = [](double, const ContactState&, ContactState&) {};
  series_.integ.set_max_step(std::numeric_limits<double>::infinity());
  if (series_.integ.step(none, t_stop) != RockingSeries<ContactState>::Status::kAccepted)
    return StepEnd::ran(step_collapsed(t));
  const double t0 = series_.integ.t0(), t1 = series_.integ.t1(), h = t1 - t0;
  if (opt_.progress) opt_.progress->store(t1, std::memory_order_relaxed);
  const int e = edge();
  const double sg = edge_sign(e);
  // the guards' polynomials: s theta (impact), limit - s theta (overturn), s theta_dot (peak);
  // lift-off's, F_J, below
  const double* th = series_.integ.theta_coefficients();
  const double* dth = series_.integ.theta_rate_coefficients();  // k c[k]
  const int degree = series_.integ.order();
  series_.sp_impact.degree = series_.sp_overturn.degree = degree;
  series_.sp_peak.degree = degree - 1;
  for (int k = 0; k <= degree; ++k) {
    const auto i = static_cast<std::size_t>(k);
    series_.sp_impact.c[i] = sg * th[k];
    series_.sp_overturn.c[i] = -sg * th[k];
    if (k < degree) series_.sp_peak.c[i] = sg * dth[k + 1];
  }
  series_.sp_overturn.c[0] += eq_.overturn_limit[static_cast<std::size_t>(e - 1)];
  // where the floor's pressing cannot be shown to hold throughout (a lift-off may come), the
  // step is taken again with the guards sampled, as any step of a friction-limited run: the
  // reaction's enclosure settles most steps; its series (O(order^2)) only the rest
  bool reaction = false;  // the reaction's series formed on this step (reaction_polynomials)
  const ReactionRange range = series_.integ.reaction_range(eq_.dyn.g_over_h(), h);
  if (!latch_.tension && !(range.fj_lo > 0.0)) {
    reaction_polynomials(h);
    reaction = true;
    if (!(series_.sp_fj.c[0] - series_.sp_fj.excursion(h) > series_.sp_fj.margin) &&
        !(bernstein_piece(series_.sp_fj, 0.0, h, series_.sp_fj.c[0]).min() >
          series_.sp_fj.margin)) {
      --res_.steps;
      series_.buf = series_.integ.x0();
      series_.integ.start(none, ctl_, t0, series_.buf);
      series_.integ.set_max_step(ctl_.max_step);
      return advance_with(series_.integ, none, series_.buf, t, x);
    }
  }
  // the guards at the step's end, exactly (the next step's start)
  GuardSample& se = points_.samples[1];
  State& xe = points_.states[1];
  put(series_.integ.x1(), xe);
  eq_.evaluate(t1, xe, se);
  // how guard k stands at the step's start
  auto start_of = [&](std::size_t k) {
    return latch_.zero_start[k] ? GuardStart::kZero
           : s0_.v[k] > 0.0     ? GuardStart::kArmed
                                : GuardStart::kDisarmed;
  };
  // the first crossing of each resetting guard
  const ModeSpec& spec = mode_spec(eq_.mode);
  double t_hit = std::numeric_limits<double>::infinity();
  int slot_hit = -1, peak_slot = -1;
  for (int j = 0; j < spec.count; ++j) {
    const auto k = static_cast<std::size_t>(j);
    const Guard guard = spec.guards[k];
    const GuardStart start = start_of(k);
    CrossingBracket b;
    int found = 0;
    switch (guard) {
      case Guard::kImpact:
        found = polynomial_bracket(series_.sp_impact, 0.0, h, start, b);
        break;
      case Guard::kOverturn:
        found = polynomial_bracket(series_.sp_overturn, 0.0, h, start, b);
        break;
      case Guard::kLiftOff:
        // lift-off needs the floor to stop pressing: ruled out where the reaction's Bernstein
        // bound keeps F_J above its truncation (it is near 1 while rocking); checked beforehand
        continue;
      case Guard::kPeak:
        peak_slot = j;  // records only: after the first resetting crossing is known
        continue;
      default:
        continue;  // the friction margin is the constant 1 without a friction limit
    }
    double when = std::numeric_limits<double>::infinity();
    if (found < 0 && guard_spec(guard).fires_if_unresolved) when = t0;
    if (found > 0) when = crossing(j, t0 + b.tl, t0 + b.tr, b.gl, b.gr);
    if (when < t_hit) {
      t_hit = when;
      slot_hit = j;
    }
  }
  const double tau_end = slot_hit >= 0 ? t_hit - t0 : h;
  // every peak up to the first resetting crossing (a long step may hold more than one)
  if (peak_slot >= 0) {
    GuardStart start = start_of(static_cast<std::size_t>(peak_slot));
    double a = 0.0;
    CrossingBracket b;
    while (a < tau_end && polynomial_bracket(series_.sp_peak, a, tau_end, start, b) > 0) {
      const double tp = crossing(peak_slot, t0 + b.tl, t0 + b.tr, b.gl, b.gr);
      if (!(tp - t0 > a) || tp > t0 + tau_end) break;
      record(tp);
      a = tp - t0;
      start = GuardStart::kCrossed;
    }
  }
  series_extremes(t0, tau_end, slot_hit >= 0, range, reaction);
  if (slot_hit < 0) observe(se, xe);
  const StepEnd end = end_step(series_.integ, none, slot_hit, t_hit, se, t, x);
  // where the floor has come to rest (a record's or a pulse's end, start_arc), the rest of the arc
  // in closed form
  if (slot_hit < 0) {
    series_.buf = x.head(2 * n_ + 4);
    start_arc(t, series_.buf);
  }
  return end;
}

// The closed form takes a rigid body's rocking (docs/theory.md, "Free rocking in closed form")
// where the floor is at rest from t on, no friction limit can make it slide, and the arc stays
// within what the rocking mode assumes: below the upright energy (no overturn), the floor pressing
// with at least kPressingFraction of the weight throughout (no lift-off; F_J is a quadratic in
// cos(phi) on the arc). Elsewhere the series steps it, as it does near those limits.
template <int N, int MaxN>
bool Simulator<N, MaxN>::start_arc(double t, const ContactState& x) requires(N == 0) {
  if (n_ != 0 || !opt_.methods.closed_form_free_rocking || t < eq_.quiet_from ||
      std::isfinite(eq_.mu_s) || latch_.hold_tension)
    return false;
  const int e = edge();
  const double a = eq_.dyn.alpha(e);
  arc_.arc.set_pivot(a, eq_.dyn.inertia(a, eq_.scratch.q), eq_.dyn.g_over_h());
  if (!arc_.arc.start(t, x, edge_sign(e))) return false;
  // F_J over the whole arc, cos(phi) from cos(alpha_t) = 1/c to cos(phi_m) = cm
  if (!(arc_.arc.least_press(arc_.arc.floor_cos(), arc_.arc.energy_cosine()) >= kPressingFraction))
    return false;
  stepper_ = &arc_;
  return true;
}

// One step of the closed form: to the impact, or to the run's end. The peak inside is recorded;
// the extremes are the step's ends' and its interior critical points' (arc_extremes).
template <int N, int MaxN>
StepEnd Simulator<N, MaxN>::advance_arc(double& t, State& x) requires(N == 0) {
  const double t_stop =
      std::min({setup_.t_end, eq_.motion.next_breakpoint(t, eq_.cursor.brk), step_stop_});
  if (!count_step(t)) return StepEnd::ended();
  arc_.arc.step(t_stop);
  const double t0 = arc_.arc.t0(), t1 = arc_.arc.t1();
  if (opt_.progress) opt_.progress->store(t1, std::memory_order_relaxed);
  const double tp = arc_.arc.peak_time();
  if (tp > t0 && tp <= t1 && guard_slot(eq_.mode, Guard::kPeak) >= 0) {
    GuardSample s;
    state_at(tp, scratch_.xr);
    eq_.arc_sample(arc_.arc, tp, scratch_.xr, arc_.arc.sin_phi_m(), arc_.arc.energy_cosine(), s);
    record_sample(s, scratch_.xr);
  }
  // the step's end, before the reset where the impact ends it (a point of the motion too)
  GuardSample& se = points_.samples[1];
  State& xe = points_.states[1];
  put(arc_.arc.x1(), xe);
  const bool impact = t1 == arc_.arc.impact_time();
  if (impact)
    eq_.arc_sample(arc_.arc, t1, xe, arc_.arc.floor_sin(), arc_.arc.floor_cos(), se);
  else
    eq_.evaluate(t1, xe, se);
  observe(se, xe);
  arc_extremes(t0, t1);
  auto none = [](double, const ContactState&, ContactState&) {};
  return end_step(arc_.arc, none, impact ? guard_slot(eq_.mode, Guard::kImpact) : -1, t1, se, t, x);
}

// On the arc the reaction depends on phi = alpha_t - |theta| alone (theta_dot^2 by the energy):
// F_I = sin(phi) (3 cos(phi) - 2 cm)/kappa, F_J = 1 - (1 - 3 cos^2 + 2 cm cos)/kappa and the
// moment alpha (cos(theta) - lambda (beta sin(phi) + 2 (cm - cos(phi)))), kappa = m/c^2,
// lambda = c/m, c^2 = 1 + alpha^2 (tools/derive/derive.py, derive_free_rocking_arc). The step
// spans phi over [lo, hi] (lo = phi_m where the peak is inside); its ends are observed, and
// within it F_I's and the moment's one critical point each, where the value there could raise the
// extreme. The friction demand |F_I|/F_J is bounded by max |F_I| over min F_J and searched in phi
// only where that bound could raise it.
template <int N, int MaxN>
void Simulator<N, MaxN>::arc_extremes(double t0, double t1) requires(N == 0) {
  if (!(t1 > t0)) return;
  const Extremes& ex = res_.extremes;
  const double sg = edge_sign(edge());
  const double cm = arc_.arc.energy_cosine(), at = arc_.arc.alpha_t();
  const double ph0 = at - sg * arc_.arc.x0()(0), ph1 = at - sg * arc_.arc.x1()(0);
  const double tp = arc_.arc.peak_time();
  const bool peak = tp > t0 && tp < t1;
  const double lo = peak ? at - arc_.arc.peak_tilt() : std::min(ph0, ph1);
  const double hi = std::max(ph0, ph1);
  const double mg = eq_.dyn.mass() * eq_.dyn.g(), mgh = mg * eq_.dyn.height();
  // sin(phi) and cos(phi) at the ends: at the peak and on the floor these are known
  // (sin(phi_m) = 2 s k, cos(phi_m) = cm; beta/c and 1/c), elsewhere one sincos
  struct Trig {
    double s, c;
  };
  auto trig = [](double ph) { return Trig{std::sin(ph), std::cos(ph)}; };
  const Trig tlo = peak ? Trig{arc_.arc.sin_phi_m(), cm} : trig(lo);
  const Trig thi = hi == at ? Trig{arc_.arc.floor_sin(), arc_.arc.floor_cos()} : trig(hi);
  auto at_phi = [&](double ph) { observe_at(arc_.arc.time_of(ph)); };
  // phi within (lo, hi), by its cosine: cos falls on (0, pi/2)
  auto inside = [&](double cp) { return cp < tlo.c && cp > thi.c; };
  // F_I: d/dphi sin (3 cos - 2 cm) = 6 cos^2 - 2 cm cos - 3, one root in (0, pi/2)
  double fi_max = std::max(arc_.arc.shear(tlo.s, tlo.c), arc_.arc.shear(thi.s, thi.c));
  const double c_fi = (cm + std::sqrt(cm * cm + 18.0)) / 6.0;
  if (inside(c_fi)) {
    const double fi = arc_.arc.shear(std::sqrt(1.0 - c_fi * c_fi), c_fi);
    fi_max = std::max(fi_max, fi);
    if (mg * fi > ex.max_base_shear) at_phi(std::acos(c_fi));
  }
  // the moment: its derivative cos (beta/c - lambda beta) - sin (1/c + 2 lambda) vanishes once
  const double ph_mo = arc_.arc.phi_moment();
  if (ph_mo > lo && ph_mo < hi) {
    const Trig t = trig(ph_mo);
    if (mgh * arc_.arc.moment(t.s, t.c) > ex.max_overturning_moment) at_phi(ph_mo);
  }
  // the friction demand
  const double fj_min = arc_.arc.least_press(thi.c, tlo.c);
  const double r = ex.max_friction_demand;
  if (fj_min >= kPressingFraction && fi_max / fj_min <= r) return;
  auto demand = [&](double ph) {
    const Trig t = trig(ph);
    const double f = arc_.arc.press(t.c);
    return f >= kPressingFraction ? arc_.arc.shear(t.s, t.c) / f : 0.0;
  };
  const double ph_r = lo + polynomial_argmax([&](double d) { return demand(lo + d); }, hi - lo);
  if (demand(ph_r) > r) at_phi(ph_r);
}

// the floor reaction's and the overturning moment's series on a series step of length h
template <int N, int MaxN>
void Simulator<N, MaxN>::reaction_polynomials(double h) requires(N == 0) {
  series_.integ.reaction_series(eq_.dyn.g_over_h(), series_.sp_fi.c.data(), series_.sp_fj.c.data(),
                                series_.sp_moment.c.data());
  // the reaction's series is known to theta's power: its last two terms at h, doubled, stand for
  // the rest
  for (StepPolynomial* p : {&series_.sp_fi, &series_.sp_fj, &series_.sp_moment}) {
    p->degree = series_.integ.order();
    double hk = 1.0, tail = 0.0;
    for (int k = 0; k <= p->degree; ++k, hk *= h)
      if (k + 1 >= p->degree) tail += std::abs(p->c[static_cast<std::size_t>(k)]) * hk;
    p->margin = 2.0 * tail;
  }
}

// the extremes over [t0, t0 + tau_end] of a series step: a quantity whose bound there could
// exceed its extreme so far (the shear, the overturning moment, F_I over F_J for the friction
// demand, the input work for the energy scale) is located on its polynomial and observed from the
// exact state there; theta's are the peaks'. The end of a step without an event is observed by the
// loop; where an event ends it, the state just before the reset is one of the motion's too.
template <int N, int MaxN>
void Simulator<N, MaxN>::series_extremes(double t0, double tau_end, bool event,
                                         const ReactionRange& range,
                                         bool& reaction) requires(N == 0) {
  if (!(tau_end > 0.0)) return;
  const Extremes& ex = res_.extremes;
  const double mg = eq_.dyn.mass() * eq_.dyn.g(), mgh = mg * eq_.dyn.height();
  double seen = -1.0;  // the last point observed here: quantities largest at one point share it
  auto at = [&](double tau) {
    if (tau == tau_end && !event) return;  // the step's end: the loop observes it
    if (tau == seen) return;
    seen = tau;
    observe_at(t0 + tau);
  };
  // bounds over [0, tau_end] by the Bernstein form (within the reaction series' truncation)
  // (the coefficients' bound first: it settles most steps for less)
  auto exceeds = [&](const StepPolynomial& p, double scale, double extreme) {
    return scale * p.abs_bound(tau_end) > extreme &&
           scale * (bernstein_piece(p, 0.0, tau_end, p.c[0]).max_abs() + p.margin) > extreme;
  };
  const double r = ex.max_friction_demand;
  // the reaction's enclosure over the step first (O(order)): where it keeps the shear, the moment
  // and the friction demand within their extremes so far, as on most steps, its series is not
  // needed
  const ReactionReach reach = reaction_reach(std::max(std::abs(range.fi_lo), std::abs(range.fi_hi)),
                                             range.moment_abs, range.fj_lo, range.fj_hi);
  if (latch_.tension) {
    // the floor pulls on the held pivot: its largest pull and the time it pulls, on F_J's series
    if (!reaction) {
      reaction_polynomials(series_.integ.t1() - series_.integ.t0());
      reaction = true;
    }
    constexpr int kParts = 16;
    std::array<double, kParts + 1> ts{}, fs{};
    for (int k = 0; k <= kParts; ++k) {
      ts[static_cast<std::size_t>(k)] = tau_end * k / kParts;
      fs[static_cast<std::size_t>(k)] = series_.sp_fj.value(ts[static_cast<std::size_t>(k)]);
    }
    res_.extremes.tension_time += time_negative(
        ts.data(), fs.data(), kParts + 1, [&](double tau) { return series_.sp_fj.value(tau); });
    if (reach.pull)
      at(polynomial_argmax([&](double tau) { return -series_.sp_fj.value(tau); }, tau_end));
  }
  if (reach.shear || reach.moment || reach.demand) {
    if (!reaction) {
      reaction_polynomials(series_.integ.t1() - series_.integ.t0());
      reaction = true;
    }
    // F_I's and F_J's Bernstein forms serve the shear and the friction demand: formed once, where
    // the coefficients' bounds do not settle either
    BernsteinPiece bi, bj;
    bool formed = false;
    auto form = [&] {
      if (formed) return;
      bi = bernstein_piece(series_.sp_fi, 0.0, tau_end, series_.sp_fi.c[0]);
      bj = bernstein_piece(series_.sp_fj, 0.0, tau_end, series_.sp_fj.c[0]);
      formed = true;
    };
    if (mg * series_.sp_fi.abs_bound(tau_end) > ex.max_base_shear) {
      form();
      if (mg * (bi.max_abs() + series_.sp_fi.margin) > ex.max_base_shear)
        at(polynomial_argmax([&](double tau) { return std::abs(series_.sp_fi.value(tau)); },
                             tau_end));
    }
    if (exceeds(series_.sp_moment, mgh, ex.max_overturning_moment))
      at(polynomial_argmax([&](double tau) { return std::abs(series_.sp_moment.value(tau)); },
                           tau_end));
    // F_I over F_J within the largest demand r so far: by the coefficients' bounds, else where
    // |F_I| - r F_J <= 0 throughout by Bernstein's (linear in the coefficients)
    const double fj_swing = series_.sp_fj.excursion(tau_end) + series_.sp_fj.margin;
    const double fj_lo = series_.sp_fj.c[0] - fj_swing, fj_hi = series_.sp_fj.c[0] + fj_swing;
    bool within = fj_hi < kPressingFraction ||
                  (fj_lo >= kPressingFraction && series_.sp_fi.abs_bound(tau_end) / fj_lo <= r);
    if (!within) {
      form();
      double worst = -std::numeric_limits<double>::infinity();
      for (int i = 0; i <= bi.degree; ++i) {
        const auto k = static_cast<std::size_t>(i);
        worst = std::max(worst, std::abs(bi.b[k]) - r * bj.b[k]);
      }
      within = worst + series_.sp_fi.margin + r * series_.sp_fj.margin <= 0.0;
    }
    if (!within)
      at(polynomial_argmax(
          [&](double tau) {
            const double f = series_.sp_fj.value(tau);
            return f >= kPressingFraction ? std::abs(series_.sp_fi.value(tau)) / f : 0.0;
          },
          tau_end));
  }
  series_.sp_work.degree = series_.integ.order() - 1;
  const double* w = series_.integ.work_coefficients();
  for (int k = 0; k <= series_.sp_work.degree; ++k)
    series_.sp_work.c[static_cast<std::size_t>(k)] = w[k];
  if (exceeds(series_.sp_work, 1.0, rec_.energy_scale()))
    at(polynomial_argmax([&](double tau) { return std::abs(series_.sp_work.value(tau)); },
                         tau_end));
}

// a rigid body in full contact does not move, and its guards (uplift about either edge, lift-off,
// friction margin) depend on the base acceleration alone, linearly (docs/theory.md, "A rigid body
// in full contact"). Under a sampled record they are linear between samples, so a sign check at
// each sample finds every crossing and the state jumps from sample to sample; an analytic motion
// is checked at event_samples points per max_step.
template <int N, int MaxN>
StepEnd Simulator<N, MaxN>::advance_still(double& t, State& x) requires(N == 0) {
  // each span checked counts as a step toward max_steps
  if (!count_step(t)) return StepEnd::ended();
  double ta = t, tb = t;
  int samples = 1;
  if (eq_.motion.is_sampled()) {
    tb = scan_record(t);
  } else if (t >= eq_.quiet_from) {
    // the base acceleration is zero from here on (a pulse has ended): the body at rest stays so,
    // every guard constant and positive, so nothing can change any more
    tb = setup_.t_end;
  } else {
    tb = std::min({setup_.t_end, eq_.motion.next_breakpoint(t, eq_.cursor.brk), t + opt_.max_step});
    samples = samples_;
  }
  auto& smp = points_.samples;
  smp[0] = s0_;
  if (eq_.motion.is_sampled() && scan_.from > ta) {
    // the scan passed samples with no event on them: start from the last of them
    ta = scan_.from;
    eq_.evaluate(ta, still_.x, smp[0]);
  }
  for (int k = 1; k <= samples; ++k) {
    const double tk = k == samples ? tb : ta + (tb - ta) * k / samples;
    eq_.evaluate(tk, still_.x, smp[static_cast<std::size_t>(k)]);
  }
  still_.t1 = tb;
  if (opt_.progress) opt_.progress->store(tb, std::memory_order_relaxed);
  double t_hit = 0.0;
  int slot_hit = -1;
  const bool hit = step_guards(samples, tb, t_hit, slot_hit);
  int points = 1;
  for (int k = 1; k <= samples; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    if (smp[kk].t >= t_hit) break;
    observe(smp[kk], still_.x);
    ++points;
  }
  if (latch_.tension) {
    // the time the floor pulls on the held body, to the last sample before any event and on to it
    std::array<double, kMaxSamples + 2> ts{}, fs{};
    GuardSample s;
    auto fj_at = [&](double tt) {
      eq_.evaluate(tt, still_.x, s);
      return s.fj;
    };
    for (int p = 0; p < points; ++p) {
      ts[static_cast<std::size_t>(p)] = smp[static_cast<std::size_t>(p)].t;
      fs[static_cast<std::size_t>(p)] = smp[static_cast<std::size_t>(p)].fj;
    }
    if (hit && t_hit > ts[static_cast<std::size_t>(points - 1)]) {
      ts[static_cast<std::size_t>(points)] = t_hit;
      fs[static_cast<std::size_t>(points)] = fj_at(t_hit);
      ++points;
    }
    res_.extremes.tension_time += time_negative(ts.data(), fs.data(), points, fj_at);
  }
  if (!hit) {
    emit_rows_until(tb);
    t = tb;
    s0_ = smp[static_cast<std::size_t>(samples)];
    release_latches(s0_);
    return StepEnd::stepped();
  }
  emit_rows_until(t_hit);
  t = t_hit;
  x = still_.x;
  return StepEnd::guard(slot_hit);
}

// walks the record's samples after t while every guard stays positive there, folding their
// reactions into the extremes; returns the end of the first span that may hold a crossing (a
// sample where some guard is <= 0), or the end time. scan_.from is the span's start.
template <int N, int MaxN>
double Simulator<N, MaxN>::scan_record(double t) requires(N == 0) {
  const std::vector<double>& ts = eq_.motion.times();
  const std::vector<double>& hx = eq_.motion.horizontal();
  const std::vector<double>& vy = eq_.motion.vertical();
  const bool vertical = vy.size() == ts.size();
  const double g = eq_.dyn.g();
  const double a1 = eq_.dyn.alpha1(), a2 = eq_.dyn.alpha2();
  const double fc = eq_.mu_s;
  const bool friction = std::isfinite(fc);
  std::size_t i = scan_.index;
  while (i > 0 && ts[i - 1] > t) --i;
  while (i < ts.size() && ts[i] <= t) ++i;
  scan_.from = t;
  double shear = 0.0, demand = 0.0;
  // uplift about edge 1 / edge 2, lift-off, friction margin, over M g (rigid body)
  for (; i < ts.size() && ts[i] < setup_.t_end; ++i) {
    const double ax = hx[i] / g, ay = 1.0 + (vertical ? vy[i] / g : 0.0);
    const double u1 = a1 * ay - ax, u2 = a2 * ay + ax;
    if (!(u1 > 0.0 && u2 > 0.0 && ay > 0.0)) break;
    if (friction && !(fc * ay - std::abs(ax) > 0.0)) break;  // the base starts to slide
    shear = std::max(shear, std::abs(ax));
    if (ay >= kPressingFraction) demand = std::max(demand, std::abs(ax) / ay);
    scan_.from = ts[i];
  }
  scan_.index = i;
  Extremes& ex = res_.extremes;
  const double mg = eq_.dyn.mass() * g;
  ex.max_base_shear = std::max(ex.max_base_shear, mg * shear);
  ex.max_overturning_moment = std::max(ex.max_overturning_moment, mg * eq_.dyn.height() * shear);
  ex.max_friction_demand = std::max(ex.max_friction_demand, demand);
  return i < ts.size() ? std::min(ts[i], setup_.t_end) : setup_.t_end;
}

}  // namespace flexrock::detail
