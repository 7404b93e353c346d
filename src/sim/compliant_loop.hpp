// SPDX-License-Identifier: BSD-3-Clause
// The compliant contact's loop: the initial state at rest, the steps with their guards and
// extremes, the end of a run; and the entry points that each size file compiles. Internal header.
#pragma once

#include "compliant_events.hpp"

namespace flexrock::detail {

// the body at rest on both springs: theta, y_c and (unless given) q from the statics, by Newton's
// method on the accelerations (a tilt appears when the c.g. is off the base's centre)
template <int MaxN>
void CompliantSim<MaxN>::place_at_rest(const InitialState& init, State& x) {
  const bool solve_q = init.q.size() == 0;
  const int m = 2 + (solve_q ? n_ : 0);
  auto residual = [&](const State& z, Eigen::VectorXd& r) {
    // the corners' anchors where they stand, so that no horizontal spring is stretched
    unpack(z);
    const double s = std::sin(z(2)), c = std::cos(z(2));
    for (int e = 1; e <= 2; ++e)
      corner_[static_cast<std::size_t>(e - 1)].anchor = dyn_.corner_x(e, s, c, q_, z(0));
    State dz(size());
    rhs(0.0, z, dz);
    r.resize(m);
    r(0) = dz(iv() + 1) / g_;
    r(1) = dz(iv() + 2) * h_ / g_;
    if (solve_q) r.tail(n_) = dz.segment(iv() + 3, n_) * h_ / g_;
  };
  auto unknown = [&](State& z, int i) -> double& {
    return i == 0 ? z(1) : i == 1 ? z(2) : z(i + 1);
  };
  Eigen::VectorXd r, r1;
  for (int it = 0; it < 30; ++it) {
    residual(x, r);
    if (r.cwiseAbs().maxCoeff() < 1e-14) break;
    Eigen::MatrixXd jac(m, m);
    for (int i = 0; i < m; ++i) {
      State z = x;
      const double step = i == 0 ? 1e-7 * h_ : 1e-7;
      unknown(z, i) += step;
      residual(z, r1);
      jac.col(i) = (r1 - r) / step;
    }
    const Eigen::VectorXd d = jac.fullPivLu().solve(r);
    for (int i = 0; i < m; ++i) unknown(x, i) -= d(i);
  }
  residual(x, r);  // leaves the anchors at the final place
}

// the initial state: on both corners' springs at rest (pivot 0) or on the pivot's, pressed by the
// whole weight; the corners' states and anchors set accordingly
template <int MaxN>
typename CompliantSim<MaxN>::State CompliantSim<MaxN>::initial_state(const InitialState& init,
                                                                     int pivot) {
  State x(size());
  x.setZero();
  const VectorX q0 = init.q.size() == n_ ? init.q : VectorX(body_.static_deformation());
  x.segment(3, n_) = q0;
  if (init.q_dot.size() == n_) x.segment(iv() + 3, n_) = init.q_dot;
  x(2) = init.theta;
  x(iv() + 2) = init.theta_dot;
  unpack(x);
  if (pivot == 0) {
    // both corners on their springs, at the static penetration
    const double delta = static_penetration(cc_.k, cc_.p, 0.5 * mg_);
    x(0) = h_ * dyn_.psi_x().dot(q_);
    x(1) = h_ * (1.0 + dyn_.psi_y().dot(q_)) - delta;
    x(iv()) = h_ * dyn_.psi_x().dot(qd_);
    x(iv() + 1) = h_ * dyn_.psi_y().dot(qd_);
    corner_[0].state = corner_[1].state = CornerState::kStick;
    place_at_rest(init, x);
  } else {
    // rocking on the pivot's spring, pressed by the whole weight
    const double delta = static_penetration(cc_.k, cc_.p, mg_);
    Eigen::Vector2d r, v;
    const double s = std::sin(x(2)), c = std::cos(x(2));
    dyn_.cg_from_pivot(pivot, s, c, q_, x(iv() + 2), qd_, r, v);
    x(0) = h_ * dyn_.alpha(pivot) + r(0);
    x(1) = -delta + r(1);
    x(iv()) = v(0);
    x(iv() + 1) = v(1);
    Corner& k = corner_[static_cast<std::size_t>(pivot - 1)];
    k.state = CornerState::kStick;
    unpack(x);
    k.anchor = dyn_.corner_x(pivot, s, c, q_, x(0));
  }
  return x;
}

// the eigenvalues of the equations of motion linearized by central differences at rest, on both
// corners (pivot 0) or on one, its corners sticking, without base motion: the coordinates and
// their rates, not the accumulators. The steps are a thousandth of the static penetration (and
// of the corresponding rates), where the linear law is exact and the clips are far
template <int MaxN>
Eigen::VectorXcd CompliantSim<MaxN>::rest_eigenvalues(int pivot, const InitialState& at) {
  const State x0 = initial_state(at, pivot);
  const int dim = 2 * (3 + n_);
  const double delta = static_penetration(cc_.k, cc_.p, 0.5 * mg_);
  const double omega_v = std::sqrt(2.0 * cc_.k_secant / m_);
  Eigen::MatrixXd jac(dim, dim);
  State xp(size()), xm(size()), fp(size()), fm(size());
  for (int j = 0; j < dim; ++j) {
    const int coord = j % (3 + n_);
    double eps = 1e-3 * delta * (coord < 2 ? 1.0 : 1.0 / h_);
    if (j >= 3 + n_) eps *= omega_v;
    xp = x0;
    xm = x0;
    xp(j) += eps;
    xm(j) -= eps;
    rhs(0.0, xp, fp);
    rhs(0.0, xm, fm);
    jac.col(j) = (fp.head(dim) - fm.head(dim)) / (2.0 * eps);
  }
  const Eigen::EigenSolver<Eigen::MatrixXd> es(jac, false);
  return es.eigenvalues();
}

template <int MaxN>
SimulationResult CompliantSim<MaxN>::run(const InitialState& init) {
  int pivot = 0;
  if (init.theta > 0.0 || (init.theta == 0.0 && init.theta_dot > 0.0)) pivot = 1;
  if (init.theta < 0.0 || (init.theta == 0.0 && init.theta_dot < 0.0)) pivot = 2;
  State x = initial_state(init, pivot);
  t_end_ = opt_.t_end >= 0.0 ? opt_.t_end : motion_.duration();
  kinetic0_ = kinetic_energy(x);
  potential0_ = potential_energy(x);
  contact0_ = contact_energy(x);
  mode_before_ = mode();
  if (mode_before_ == ContactMode::kFlight) flight_start_ = 0.0;
  double t = 0.0;
  integ_.start([this](double tt, const State& z, State& dz) { rhs(tt, z, dz); }, ctl_, t, x);
  if (opt_.output_dt > 0.0) emit_row(t, x);
  next_output_ = 1;
  bool running = true;
  while (running && t < t_end_) running = advance(t, x);
  finish(t, x);
  return std::move(res_);
}

template <int MaxN>
bool CompliantSim<MaxN>::advance(double& t, State& x) {
  auto sys = [this](double tt, const State& z, State& dz) { rhs(tt, z, dz); };
  const double t_stop = std::min(motion_.next_breakpoint(t, break_cursor_), t_end_);
  if (integ_.step(sys, t_stop) != StiffSwitching<State>::Status::kAccepted)
    return stop(t, "the integrator's step collapsed at t = " + format_number(t, 9) +
                       " s (a contact stiffer than rtol/atol can follow)");
  if (++steps_ > opt_.max_steps)
    return stop(t, "more than max_steps = " + std::to_string(opt_.max_steps) + " steps");
  ++res_.steps;
  const double t0 = integ_.t0(), t1 = integ_.t1();
  // the guards at the samples of the step
  for (int k = 0; k <= samples_; ++k) {
    const double tk = k == samples_ ? t1 : t0 + (t1 - t0) * k / samples_;
    State& xk = states_[static_cast<std::size_t>(k)];
    if (k == 0) {
      xk = integ_.x0();
    } else if (k == samples_) {
      xk = integ_.x1();
    } else {
      integ_.dense(tk, xk);
    }
    evaluate(tk, xk, smp_[static_cast<std::size_t>(k)]);
    fn_at_[static_cast<std::size_t>(k)] = fn_;
    law_at_[static_cast<std::size_t>(k)] = law_;
  }
  double t_hit = std::numeric_limits<double>::infinity();
  int slot_hit = -1;
  std::array<double, kMaxGuards> crossing{};
  for (int slot = 0; slot < kMaxGuards; ++slot) {
    const double th = first_crossing(slot, smp_.data(), samples_,
                                     zero_start_[static_cast<std::size_t>(slot)], false, *this);
    crossing[static_cast<std::size_t>(slot)] = th;
    if (th < t_hit) {
      t_hit = th;
      slot_hit = slot;
    }
  }
  // the extremes at the samples before the crossing (the normal forces at them included) and at
  // the state just before it, then located between them
  int points = 0;
  for (int k = 0; k <= samples_; ++k) {
    const std::size_t i = static_cast<std::size_t>(k);
    if (smp_[i].t >= t_hit) break;
    keep_point(points++, observe(smp_[i], states_[i], fn_at_[i]), fn_at_[i], law_at_[i]);
  }
  if (slot_hit >= 0 && points > 0 && t_hit > point_t_[static_cast<std::size_t>(points - 1)]) {
    integ_.dense(t_hit, buf_);
    GuardSample before;
    evaluate(t_hit, buf_, before);
    keep_point(points++, observe(before, buf_, fn_), fn_, law_);
  }
  observe_switches(points);
  locate_step_extremes(points);
  zero_start_.fill(false);
  if (slot_hit < 0) {
    emit_rows_until(t1);
    t = t1;
    x = integ_.x1();
    if (transfer_.event >= 0 && !(x(iv() + 2) * transfer_.theta_dot > 0.0)) close_transfer(x);
    if (opt_.progress) opt_.progress->store(t, std::memory_order_relaxed);
    return true;
  }
  integ_.restep_to(sys, t_hit);
  emit_rows_until(t_hit);
  t = t_hit;
  x = integ_.x1();
  GuardSample gs;
  evaluate(t, x, gs);
  observe(gs, x, fn_);
  // Zeno: more than 64 changes within 1e-9 s end the run
  if (burst_time_ >= 0.0 && t - burst_time_ <= 1e-9) {
    if (++burst_ > 64)
      return stop(t, "more than 64 contact changes within 1e-9 s at t = " + format_number(t, 9) +
                         " s (Zeno behaviour)");
  } else {
    burst_time_ = t;
    burst_ = 0;
  }
  // every guard whose crossing cannot be told from the first one's fires with it, at t_hit: a
  // crossing's bracket ends where it was returned and is crossing_resolution wide, and two
  // brackets that overlap are one instant (both corners of a level body lifting off or landing;
  // alone, the second corner's guard would start the next step already crossed, and be missed)
  std::array<bool, kMaxGuards> fires{};
  for (std::size_t i = 0; i < fires.size(); ++i)
    fires[i] =
        std::isfinite(crossing[i]) && crossing[i] - crossing_resolution(crossing[i]) <= t_hit;
  if (!fire(fires, t, x)) return false;
  integ_.start(sys, ctl_, t, x, integ_.suggested_step());
  if (opt_.progress) opt_.progress->store(t, std::memory_order_relaxed);
  return true;
}

template <int MaxN>
void CompliantSim<MaxN>::finish(double t, const State& x) {
  res_.t_end = t;
  if (opt_.progress) opt_.progress->store(t, std::memory_order_relaxed);
  if (opt_.output_dt > 0.0 && (res_.history.time.empty() || res_.history.time.back() < t - 1e-12))
    emit_row(t, x);
  close_transfer(x);
  for (std::size_t j = 0; j < 2; ++j) close_contact(j);
  const ContactMode now = mode();
  if (now == ContactMode::kFlight && res_.status != Status::kOverturned)
    res_.extremes.flight_time += t - flight_start_;
  if (mode_spec(now).slip != 0 && res_.status != Status::kOverturned)
    res_.extremes.sliding_time += t - slide_start_;
  res_.final_phase = now;
  res_.final_theta = x(2);
  res_.final_theta_dot = x(iv() + 2);
  res_.final_q = x.segment(3, n_);
  res_.final_q_dot = x.segment(iv() + 3, n_);
  GuardSample gs;
  State xf = x;
  evaluate(t, xf, gs);
  res_.final_offset = observation(gs, xf).offset;
  EnergyBalance& e = res_.energy;
  const double kin = kinetic_energy(xf), pot = potential_energy(xf);
  e.input_work = x(iw());
  e.damping_loss = x(iw() + 1);
  e.impact_loss = contact_loss(xf);
  e.friction_loss = x(iw() + 3);
  e.kinetic_change = kin - kinetic0_;
  e.potential_change = pot - potential0_;
  e.residual = e.input_work - (e.kinetic_change + e.potential_change + e.damping_loss +
                               e.impact_loss + e.friction_loss);
  e.scale = std::max({rec_.energy_scale(), std::abs(pot - potential0_), std::abs(kin), kinetic0_,
                      std::abs(e.impact_loss) + e.friction_loss, x(iw() + 2)});
  if (audit_) {
    audit_->dashpot_work = x(iw() + 6);
    audit_->released_at_slip = released_;
  }
  res_.rejected_steps = integ_.rejected_steps();
  res_.rhs_evaluations = integ_.rhs_evaluations();
  if (res_.status == Status::kCompleted) res_.message = "completed";
}

/// One run with the compliant contact for bodies of at most MaxN modes (simulate_compliant).
template <int MaxN>
SimulationResult run_compliant(const Body& body, const GroundMotion& motion,
                               const InitialState& init, const SimulationOptions& opt,
                               CompliantAudit* audit) {
  return CompliantSim<MaxN>(body, motion, opt, audit).run(init);
}

/// The linearized eigenvalues at rest for bodies of at most MaxN modes
/// (compliant_rest_eigenvalues).
template <int MaxN>
Eigen::VectorXcd run_compliant_rest_eigenvalues(const Body& body, const GroundMotion& still,
                                                const SimulationOptions& opt, int pivot,
                                                const InitialState& at) {
  return CompliantSim<MaxN>(body, still, opt, nullptr).rest_eigenvalues(pivot, at);
}

// compiled in compliant.cpp (MaxN = 16) and compliant_dynamic.cpp (heap), in parallel
extern template SimulationResult run_compliant<16>(const Body&, const GroundMotion&,
                                                   const InitialState&, const SimulationOptions&,
                                                   CompliantAudit*);
extern template SimulationResult run_compliant<Eigen::Dynamic>(const Body&, const GroundMotion&,
                                                               const InitialState&,
                                                               const SimulationOptions&,
                                                               CompliantAudit*);
extern template Eigen::VectorXcd run_compliant_rest_eigenvalues<16>(const Body&,
                                                                    const GroundMotion&,
                                                                    const SimulationOptions&, int,
                                                                    const InitialState&);
extern template Eigen::VectorXcd run_compliant_rest_eigenvalues<Eigen::Dynamic>(
    const Body&, const GroundMotion&, const SimulationOptions&, int, const InitialState&);

}  // namespace flexrock::detail
