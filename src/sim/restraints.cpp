// SPDX-License-Identifier: BSD-3-Clause
// The restrained rigid body's event loop (docs/theory.md §26): full contact and rocking on either
// edge on the rigid floor, the ties' forces as a generalised force, their yield, unloading,
// fracture and slack as located events, impacts by the run's impact law. A loop beside the
// Simulator, as the compliant contact's: the Simulator's fast rigid paths (closed-form arcs, the
// Taylor series) have no place for a force that depends on the ties' states, so the rocking is
// integrated by DOPRI5 with its dense output, and the runs without restraints never come here.
#include "flexrock/sim/restraints.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "crossing_resolution.hpp"
#include "event_location.hpp"
#include "flexrock/contact/impact.hpp"
#include "flexrock/core/error.hpp"
#include "flexrock/core/format.hpp"
#include "flexrock/integrate/dopri5.hpp"
#include "flexrock/model/dynamics.hpp"

namespace flexrock {

const char* to_string(RestraintEventKind k) {
  switch (k) {
    case RestraintEventKind::kYield:
      return "yield";
    case RestraintEventKind::kUnload:
      return "unload";
    case RestraintEventKind::kFracture:
      return "fracture";
  }
  return "?";
}

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// the pivot's abscissa on the base (body axes): the left tipping point for edge 1
double pivot_x(const BodyParameters& p, int edge) { return edge == 1 ? -p.b1 : p.b2; }

// P(theta) - F and its first two theta-derivatives: P = P_0 + (R - I)(P_0 - pivot), written with
// R - I so that theta = 0 gives P_0 exactly
struct TiePoint {
  double dx, dy;    // P - F [m]
  double px, py;    // dP/dtheta
  double ppx, ppy;  // d2P/dtheta2
};
TiePoint tie_point(const BodyParameters& p, const Restraint& r, int edge, double s, double c) {
  const double rx = r.body_x - pivot_x(p, edge), ry = r.body_y;
  // c - 1 without the cancellation near theta = 0: -s^2 / (1 + c) (|theta| < pi/2 here)
  const double cm1 = c > 0.0 ? -s * s / (1.0 + c) : c - 1.0;
  TiePoint t;
  t.dx = r.body_x - r.floor_x + cm1 * rx - s * ry;
  t.dy = r.body_y - r.floor_y + s * rx + cm1 * ry;
  t.px = -s * rx - c * ry;
  t.py = c * rx - s * ry;
  t.ppx = -c * rx + s * ry;
  t.ppy = -s * rx - c * ry;
  return t;
}

double rest_length(const Restraint& r) {
  const double dx = r.body_x - r.floor_x, dy = r.body_y - r.floor_y;
  return std::sqrt(dx * dx + dy * dy);
}

TieGeometry geometry(const BodyParameters& p, const Restraint& r, int edge, double s, double c) {
  const TiePoint t = tie_point(p, r, edge, s, c);
  // lengths of the body's scale: no overflow for hypot to guard against
  const double len = std::sqrt(t.dx * t.dx + t.dy * t.dy);
  const double de = (t.dx * t.px + t.dy * t.py) / len;
  const double pp = t.px * t.px + t.py * t.py;
  return {len - rest_length(r), de, (t.dx * t.ppx + t.dy * t.ppy + pp - de * de) / len};
}

// the unit vector from F to P (the tie pulls P toward F with -T u)
Eigen::Vector2d tie_direction(const BodyParameters& p, const Restraint& r, int edge, double s,
                              double c) {
  const TiePoint t = tie_point(p, r, edge, s, c);
  const double len = std::hypot(t.dx, t.dy);
  return {t.dx / len, t.dy / len};
}

// the tie's law: the trial force P_0 + k (e - s - e_p) (may be negative: slack)
double trial_force(const Restraint& r, double e, double ep) {
  return r.prestress + r.stiffness * (e - r.slack - ep);
}

// the elastic energy with dU/de = max(0, trial): P_0 w + k w^2/2 while taut, -P_0^2/(2k) slack
double tie_energy(const Restraint& r, double e, double ep) {
  const double w = e - r.slack - ep;
  if (r.stiffness == 0.0) return r.prestress * w;
  const double f = r.prestress + r.stiffness * w;
  return (std::max(f, 0.0) * std::max(f, 0.0) - r.prestress * r.prestress) / (2.0 * r.stiffness);
}
// the energy left once the tie is gone (its slack value, so that U stays continuous in form)
double broken_energy(const Restraint& r) {
  return r.stiffness > 0.0 ? -r.prestress * r.prestress / (2.0 * r.stiffness) : 0.0;
}

std::string where(std::size_t i) { return "restraint " + std::to_string(i + 1) + ": "; }

enum class TieState { kElastic, kYielding, kFractured };

struct Tie {
  Restraint r;
  TieState state = TieState::kElastic;
  double ep = 0.0;            // [m] plastic elongation (while yielding: at the yield's start)
  bool taut = false;          // the trial force is positive (orients the slack guard)
  RestraintSummary sum;       // what it did
  double energy_after = 0.0;  // [J] fractured: the energy it keeps (broken_energy)
};

// the guards, in slot order: the mode's, then four per tie (yield/unload, fracture, slack)
enum Slot : int { kUpliftOrImpact = 0, kUplift2OrPeak = 1, kOverturn = 2, kLiftOff = 3, kTies = 4 };
constexpr int kPerTie = 3;  // flow (yield or unload), fracture, slack

using State = Eigen::Matrix<double, 3, 1>;  // theta, theta_dot, input work

class RestrainedSim final : public detail::GuardProbe {
 public:
  RestrainedSim(const Body& body, const std::vector<Restraint>& restraints,
                const GroundMotion& motion, const SimulationOptions& opt)
      : body_(body), p_(body.params()), dyn_(body), motion_(motion), opt_(opt) {
    for (const Restraint& r : restraints) {
      Tie t;
      t.r = r;
      ties_.push_back(t);
    }
    slots_ = kTies + kPerTie * static_cast<int>(ties_.size());
    samples_ = std::clamp(opt.event_samples, 1, detail::kMaxSamples);
    for (auto& v : smp_) v.assign(static_cast<std::size_t>(slots_), 0.0);
    zero_start_.assign(static_cast<std::size_t>(slots_), false);
    crossing_.assign(static_cast<std::size_t>(slots_), kInf);
    geo_.assign(ties_.size(), TieGeometry{});
    smp_tie_.assign(static_cast<std::size_t>(detail::kMaxSamples + 1) * 2 * ties_.size(), 0.0);
    ctl_.rtol = opt.rtol;
    ctl_.atol = opt.atol;
    ctl_.controlled = 2;
    ctl_.max_step = opt.max_step;
    rule_.law = opt.impact_law;
    rule_.restitution_factor = opt.restitution_factor;
    rule_.ratio_edge1 = opt.restitution_ratio_edge1;
    rule_.ratio_edge2 = opt.restitution_ratio_edge2;
    mg_ = p_.mass * p_.gravity;
  }

  RestrainedResult run(const InitialState& init);

  // GuardProbe: a guard on the last step's dense output
  double guard_value(int slot, double t) override {
    if (still_) return guard(slot, t, still_x_);
    integ_.dense(t, buf_);
    return guard(slot, t, buf_);
  }

  // every tie elastic and on its side of the slack kink at theta (statics)
  void settle_at(int edge, double theta) {
    const double s = std::sin(theta), c = std::cos(theta);
    for (Tie& tie : ties_)
      tie.taut = trial_force(tie.r, geometry(p_, tie.r, edge, s, c).e, 0.0) > 0.0;
  }

  // the angular acceleration rocking on `edge`, the ties in their current states
  double rocking_acceleration(int edge, double theta, double theta_dot, BaseAcceleration b) const {
    (void)theta_dot;
    return rocking_acceleration_sc(edge, std::sin(theta), std::cos(theta), b);
  }
  double rocking_acceleration_sc(int edge, double s, double c, BaseAcceleration b) const {
    const double cx = edge == 1 ? p_.b1 : -p_.b2;  // the c.g. from the pivot, body axes
    const double ax = b.x / p_.gravity, ay = 1.0 + b.y / p_.gravity;
    const double gx = ax * c + ay * s, gy = ay * c - ax * s;
    double moment = -mg_ * (cx * gy - p_.height * gx);
    for (const Tie& t : ties_) {
      if (t.state == TieState::kFractured) continue;
      const TieGeometry g = geometry(p_, t.r, edge, s, c);
      moment -= force(t, g.e) * g.de;
    }
    return moment / inertia(edge);
  }

 private:
  double inertia(int edge) const {
    const double cx = edge == 1 ? p_.b1 : p_.b2;
    return p_.mass * (p_.height * p_.height * (1.0 + p_.zeta2) + cx * cx);
  }
  double force(const Tie& t, double e) const {
    switch (t.state) {
      case TieState::kFractured:
        return 0.0;
      case TieState::kYielding:
        return t.r.yield_force;
      case TieState::kElastic:
        break;
    }
    // each side of the slack kink is continued smoothly past it (a taut tie's trial force, a
    // slack one's zero) until the slack guard locates the kink: a step across it then keeps its
    // accuracy instead of being rejected down to it
    return t.taut ? trial_force(t.r, e, t.ep) : 0.0;
  }
  // the plastic elongation now: while yielding it follows the elongation
  double plastic_now(const Tie& t, double e) const {
    if (t.state != TieState::kYielding) return t.ep;
    return std::max(t.ep, e - t.r.slack - (t.r.yield_force - t.r.prestress) / t.r.stiffness);
  }
  int edge() const { return mode_ == ContactMode::kRockingEdge1 ? 1 : 2; }
  double sigma() const { return mode_ == ContactMode::kRockingEdge1 ? 1.0 : -1.0; }
  bool rocking() const { return mode_ != ContactMode::kFullContact; }

  void rhs(double t, const State& x, State& dx) {
    dx.setZero();
    if (!rocking()) return;
    const BaseAcceleration b = motion_.at(t, cursor_);
    const double s = std::sin(x(0)), c = std::cos(x(0));
    const double thdd = rocking_acceleration_sc(edge(), s, c, b);
    dx(0) = x(1);
    dx(1) = thdd;
    // the base's power on the body relative to it: -M a_base . v_cg
    const double cx = edge() == 1 ? p_.b1 : -p_.b2;
    const double vx = x(1) * (-s * cx - c * p_.height), vy = x(1) * (c * cx - s * p_.height);
    dx(2) = -p_.mass * (b.x * vx + b.y * vy);
  }

  // the floor's reaction on the body [N], inertial axes, and the ties' pull
  Eigen::Vector2d reaction(double t, const State& x, double& thdd) {
    const BaseAcceleration b = motion_.at(t, gcursor_);
    Eigen::Vector2d f(p_.mass * b.x, p_.mass * (b.y + p_.gravity));
    thdd = 0.0;
    const int e = rocking() ? edge() : 1;
    const double s = rocking() ? std::sin(x(0)) : 0.0, c = rocking() ? std::cos(x(0)) : 1.0;
    if (rocking()) {
      thdd = rocking_acceleration(e, x(0), x(1), b);
      const double cx = e == 1 ? p_.b1 : -p_.b2, cy = p_.height;
      const double w2 = x(1) * x(1);
      f(0) += p_.mass * (thdd * (-s * cx - c * cy) - w2 * (c * cx - s * cy));
      f(1) += p_.mass * (thdd * (c * cx - s * cy) - w2 * (s * cx + c * cy));
    }
    for (const Tie& tie : ties_) {
      if (tie.state == TieState::kFractured) continue;
      const TieGeometry g = geometry(p_, tie.r, e, s, c);
      f += force(tie, g.e) * tie_direction(p_, tie.r, e, s, c);
    }
    return f;
  }

  double guard(int slot, double t, const State& x) {
    const double s = std::sin(x(0)), c = std::cos(x(0));
    if (slot < kTies) {
      if (!rocking()) {
        const BaseAcceleration b = motion_.at(t, gcursor_);
        const double gh = p_.gravity / p_.height;
        if (slot == kUpliftOrImpact) return -rocking_acceleration(1, 0.0, 0.0, b) / gh;
        if (slot == kUplift2OrPeak) return rocking_acceleration(2, 0.0, 0.0, b) / gh;
        if (slot == kLiftOff) {
          double thdd;
          return reaction(t, x, thdd)(1) / mg_;
        }
        return 1.0;
      }
      switch (slot) {
        case kUpliftOrImpact:
          return sigma() * x(0);
        case kUplift2OrPeak:
          return sigma() * x(1);
        case kOverturn:
          return overturn_angle(edge()) - sigma() * x(0);
        default: {
          double thdd;
          return reaction(t, x, thdd)(1) / mg_;
        }
      }
    }
    const int i = (slot - kTies) / kPerTie, which = (slot - kTies) % kPerTie;
    const Tie& tie = ties_[static_cast<std::size_t>(i)];
    if (tie.state == TieState::kFractured) return 1.0;
    const int e = rocking() ? edge() : 1;
    const TieGeometry g = geometry(p_, tie.r, e, rocking() ? s : 0.0, rocking() ? c : 1.0);
    const double scale = std::isfinite(tie.r.yield_force) ? std::max(tie.r.yield_force, mg_) : mg_;
    switch (which) {
      case 0:  // flow: yield while elastic, unloading while yielding
        if (tie.state == TieState::kYielding)
          return rocking() ? g.de * x(1) / std::sqrt(p_.gravity * p_.height) : 0.0;
        if (!std::isfinite(tie.r.yield_force)) return 1.0;
        return (tie.r.yield_force - trial_force(tie.r, g.e, tie.ep)) / scale;
      case 1:  // fracture
        if (!std::isfinite(tie.r.fracture_elongation)) return 1.0;
        return (tie.r.fracture_elongation - (g.e - tie.r.slack)) / p_.height;
      default: {  // slack
        if (tie.state != TieState::kElastic) return 1.0;
        const double f = trial_force(tie.r, g.e, tie.ep) / scale;
        return tie.taut ? f : -f;
      }
    }
  }

  double overturn_angle(int edge) const {
    return opt_.overturn == OverturnCriterion::kHalfPi ? 0.5 * std::numbers::pi
                                                       : body_.tipping_angle(edge);
  }

  // every guard at once: the ties' geometry and the acceleration formed once (guard() forms them
  // per slot, for the root finder's single-slot calls); the same values as guard() gives
  void sample(double t, const State& x, std::vector<double>& v) {
    const bool rock = rocking();
    const int e = rock ? edge() : 1;
    const double s = rock ? std::sin(x(0)) : 0.0, c = rock ? std::cos(x(0)) : 1.0;
    const BaseAcceleration b = motion_.at(t, gcursor_);
    const double gh = p_.gravity / p_.height;
    // the ties' forces and the floor's reaction (as reaction())
    Eigen::Vector2d f(p_.mass * b.x, p_.mass * (b.y + p_.gravity));
    double tie_moment = 0.0;
    for (std::size_t i = 0; i < ties_.size(); ++i) {
      const Tie& tie = ties_[i];
      if (tie.state == TieState::kFractured) continue;
      const TieGeometry g = geometry(p_, tie.r, e, s, c);
      geo_[i] = g;
      const double fi = force(tie, g.e);
      tie_moment += fi * g.de;
      if (fi != 0.0) f += fi * tie_direction(p_, tie.r, e, s, c);
    }
    if (!rock) {
      // uplift: the rocking accelerations about either edge at rest, from the same sums
      v[kUpliftOrImpact] = -rest_acceleration(1, b) / gh;
      v[kUplift2OrPeak] = rest_acceleration(2, b) / gh;
      v[kOverturn] = 1.0;
      v[kLiftOff] = f(1) / mg_;
    } else {
      const double cx = e == 1 ? p_.b1 : -p_.b2, cy = p_.height;
      const double ax = b.x / p_.gravity, ay = 1.0 + b.y / p_.gravity;
      const double gx = ax * c + ay * s, gy = ay * c - ax * s;
      const double thdd = (-mg_ * (cx * gy - cy * gx) - tie_moment) / inertia(e);
      const double w2 = x(1) * x(1);
      f(0) += p_.mass * (thdd * (-s * cx - c * cy) - w2 * (c * cx - s * cy));
      f(1) += p_.mass * (thdd * (c * cx - s * cy) - w2 * (s * cx + c * cy));
      v[kUpliftOrImpact] = sigma() * x(0);
      v[kUplift2OrPeak] = sigma() * x(1);
      v[kOverturn] = overturn_angle(e) - sigma() * x(0);
      v[kLiftOff] = f(1) / mg_;
    }
    last_reaction_ = f;
    for (std::size_t i = 0; i < ties_.size(); ++i) {
      const Tie& tie = ties_[i];
      double* g3 = &v[static_cast<std::size_t>(kTies) + kPerTie * i];
      if (tie.state == TieState::kFractured) {
        g3[0] = g3[1] = g3[2] = 1.0;
        continue;
      }
      const TieGeometry& g = geo_[i];
      const double scale =
          std::isfinite(tie.r.yield_force) ? std::max(tie.r.yield_force, mg_) : mg_;
      if (tie.state == TieState::kYielding) {
        g3[0] = rock ? g.de * x(1) / std::sqrt(p_.gravity * p_.height) : 0.0;
      } else {
        g3[0] = std::isfinite(tie.r.yield_force)
                    ? (tie.r.yield_force - trial_force(tie.r, g.e, tie.ep)) / scale
                    : 1.0;
      }
      g3[1] = std::isfinite(tie.r.fracture_elongation)
                  ? (tie.r.fracture_elongation - (g.e - tie.r.slack)) / p_.height
                  : 1.0;
      if (tie.state != TieState::kElastic) {
        g3[2] = 1.0;
      } else {
        const double ft = trial_force(tie.r, g.e, tie.ep) / scale;
        g3[2] = tie.taut ? ft : -ft;
      }
    }
  }
  // the rocking acceleration about `edge` at theta = 0 with the ties' forces at rest (full
  // contact: their geometry does not depend on the edge there, their levers do)
  double rest_acceleration(int e, BaseAcceleration b) const {
    return rocking_acceleration(e, 0.0, 0.0, b);
  }

  // the first crossing of `slot` (positive to non-positive) among the step's samples
  double first_crossing(int slot) {
    const auto j = static_cast<std::size_t>(slot);
    double prev = smp_[0][j], t_prev = smp_t_[0];
    bool armed = prev > 0.0 || zero_start_[j];
    for (int k = 1; k <= samples_; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      const double cur = smp_[kk][j];
      if (armed && cur <= 0.0) {
        double tl = t_prev, gl = prev;
        if (!(gl > 0.0)) {
          bool found = false;
          double span = smp_t_[kk] - t_prev;
          for (int i = 1; i <= 60 && !found; ++i) {
            span *= 0.5;
            tl = t_prev + span;
            gl = guard_value(slot, tl);
            found = gl > 0.0;
          }
          if (!found) return kInf;
        }
        return detail::locate_crossing(slot, tl, smp_t_[kk], gl, cur, *this);
      }
      if (cur > 0.0) armed = true;
      prev = cur;
      t_prev = smp_t_[kk];
    }
    return kInf;
  }

  bool advance(double& t, State& x);
  bool advance_still(double& t, State& x);
  bool fire(int slot, double t, State& x);
  void unload(int i, double t, const State& x);
  void enter_full_contact(double t, State& x);
  void uplift(int edge, double t, State& x);
  void observe(double t, const State& x);
  void observe_sample(std::size_t k);
  void emit_row(double t, const State& x);
  void emit_rows_until(double t_to);
  bool stop(double t, const std::string& why) {
    res_.result.status = Status::kStopped;
    res_.result.message = why;
    Event ev;
    ev.time = t;
    ev.kind = EventKind::kStopped;
    res_.result.events.push_back(ev);
    return false;
  }
  double stored_energy(const State& x) const {
    double u = 0.0;
    const int e = rocking() ? edge() : 1;
    const double s = rocking() ? std::sin(x(0)) : 0.0, c = rocking() ? std::cos(x(0)) : 1.0;
    for (const Tie& tie : ties_) {
      if (tie.state == TieState::kFractured) {
        u += tie.energy_after;
        continue;
      }
      const TieGeometry g = geometry(p_, tie.r, e, s, c);
      u += tie_energy(tie.r, g.e, plastic_now(tie, g.e));
    }
    return u;
  }
  double kinetic(const State& x) const {
    return rocking() ? 0.5 * inertia(edge()) * x(1) * x(1) : 0.0;
  }
  double gravity_energy(const State& x) const {
    if (!rocking()) return 0.0;
    const double cx = edge() == 1 ? p_.b1 : -p_.b2;
    return mg_ * (cx * std::sin(x(0)) + p_.height * (std::cos(x(0)) - 1.0));
  }
  double plastic_work() const {
    double w = 0.0;
    for (const Tie& t : ties_) w += t.sum.plastic_work;
    return w;
  }
  // the plastic work of ties yielding now, not yet booked
  double plastic_pending(const State& x) const {
    double w = 0.0;
    const int e = rocking() ? edge() : 1;
    const double s = rocking() ? std::sin(x(0)) : 0.0, c = rocking() ? std::cos(x(0)) : 1.0;
    for (const Tie& tie : ties_) {
      if (tie.state != TieState::kYielding) continue;
      const TieGeometry g = geometry(p_, tie.r, e, s, c);
      w += tie.r.yield_force * (plastic_now(tie, g.e) - tie.ep);
    }
    return w;
  }
  // ends a tie's yielding at the current state: e_p and the plastic work booked
  void end_yield(Tie& tie, double e) {
    const double ep = plastic_now(tie, e);
    tie.sum.plastic_work += tie.r.yield_force * (ep - tie.ep);
    tie.ep = ep;
  }
  // after a contact event: each elastic tie's side of the slack kink, from its trial force, or
  // where that is zero (a tie with no slack or prestress at rest), from the way it is about to
  // move: the elongation's rate, or at rest the side the body lifts toward
  void retaut(const State& x) {
    const int e = rocking() ? edge() : 1;
    const double s = rocking() ? std::sin(x(0)) : 0.0, c = rocking() ? std::cos(x(0)) : 1.0;
    for (Tie& tie : ties_) {
      if (tie.state != TieState::kElastic) continue;
      const TieGeometry g = geometry(p_, tie.r, e, s, c);
      const double f = trial_force(tie.r, g.e, tie.ep);
      const double tiny =
          1e-12 * std::max({std::abs(tie.r.prestress), mg_, tie.r.stiffness * p_.height});
      if (std::abs(f) > tiny) {
        tie.taut = f > 0.0;
      } else {
        const double way = rocking() ? (x(1) != 0.0 ? x(1) : sigma()) : 0.0;
        tie.taut = g.de * way > 0.0;
      }
    }
  }
  void set_taut(Tie& tie, double e, double rate) {
    const double f = trial_force(tie.r, e, tie.ep);
    tie.taut = f > 0.0 || (f == 0.0 && rate > 0.0);
  }

  const Body& body_;
  const BodyParameters& p_;
  Dynamics<0> dyn_;
  const GroundMotion& motion_;
  const SimulationOptions& opt_;
  // the right-hand side's, the guards' and outputs' (the two walk the record apart), the steps'
  GroundMotion::Cursor cursor_, gcursor_, break_cursor_;
  std::vector<Tie> ties_;
  int slots_ = 0, samples_ = 4;
  std::array<std::vector<double>, detail::kMaxSamples + 1> smp_;
  std::array<double, detail::kMaxSamples + 1> smp_t_{};
  std::array<State, detail::kMaxSamples + 1> smp_x_{};
  std::vector<bool> zero_start_;
  std::vector<double> crossing_;  // each guard's crossing in the last step (+inf: none)
  std::vector<TieGeometry> geo_;  // sample()'s scratch: each tie's geometry
  Eigen::Vector2d last_reaction_ = Eigen::Vector2d::Zero();  // sample()'s floor reaction [N]
  // each sample's floor reaction and ties' forces and elongations, for observe_sample()
  std::array<Eigen::Vector2d, detail::kMaxSamples + 1> smp_f_{};
  std::vector<double> smp_tie_;  // (kMaxSamples + 1) x ties x {force, elongation}
  bool still_ = false;           // the still path's step: guards on still_x_, not the stepper
  State still_x_ = State::Zero();
  bool still_valid_ = false;  // smp_[1] holds the guards at still_t_ (the still path's last end)
  double still_t_ = -1.0;
  StepControl ctl_;
  ImpactRule rule_;
  Dopri5<State> integ_;
  State buf_;
  ContactMode mode_ = ContactMode::kFullContact;
  double mg_ = 0.0, t_end_ = 0.0, last_impact_ = -kInf;
  double impact_loss_ = 0.0, chatter_loss_ = 0.0, fracture_work_ = 0.0, energy0_ = 0.0;
  double scale_ = 0.0;
  std::size_t next_output_ = 0;
  long steps_ = 0;
  RestrainedResult res_;
};

void RestrainedSim::emit_row(double t, const State& x) {
  History& h = res_.result.history;
  double thdd = 0.0;
  const Eigen::Vector2d f = reaction(t, x, thdd);
  const BaseAcceleration b = motion_.at(t, gcursor_);
  h.time.push_back(t);
  h.phase.push_back(static_cast<int>(mode_));
  h.theta.push_back(x(0));
  h.theta_dot.push_back(x(1));
  h.base_acc_x.push_back(b.x);
  h.base_acc_y.push_back(b.y);
  h.reaction_x.push_back(f(0));
  h.reaction_y.push_back(f(1));
  // the resultant's distance from the c.g.'s projection: on the pivot while rocking
  h.resultant.push_back(rocking() ? (edge() == 1 ? -p_.b1 : p_.b2) : 0.0);
  h.friction_demand.push_back(f(1) > 0.0 ? std::abs(f(0)) / f(1) : kInf);
  h.kinetic.push_back(kinetic(x));
  h.potential.push_back(gravity_energy(x) + stored_energy(x));
  h.input_work.push_back(x(2));
  h.damping_loss.push_back(0.0);
  h.impact_loss.push_back(impact_loss_ + chatter_loss_);
  h.offset.push_back(0.0);
  h.lift.push_back(0.0);
  const int e = rocking() ? edge() : 1;
  const double s = rocking() ? std::sin(x(0)) : 0.0, c = rocking() ? std::cos(x(0)) : 1.0;
  for (const Tie& tie : ties_) {
    const TieGeometry g = geometry(p_, tie.r, e, s, c);
    res_.force.push_back(force(tie, g.e));
    res_.elongation.push_back(g.e);
    res_.energy.push_back(tie.state == TieState::kFractured
                              ? tie.energy_after
                              : tie_energy(tie.r, g.e, plastic_now(tie, g.e)));
  }
}

void RestrainedSim::emit_rows_until(double t_to) {
  if (!(opt_.output_dt > 0.0)) return;
  for (;;) {
    const double to = static_cast<double>(next_output_) * opt_.output_dt;
    if (to > t_to || to > t_end_ + 1e-12) return;
    if (still_) {
      buf_ = still_x_;
    } else {
      integ_.dense(to, buf_);
    }
    if (!rocking()) buf_.head<2>().setZero();
    emit_row(to, buf_);
    ++next_output_;
  }
}

// extremes at a state: rotation, uplift, base shear, the ties' forces
void RestrainedSim::observe(double t, const State& x) {
  Extremes& ex = res_.result.extremes;
  if (rocking()) {
    if (x(0) > ex.max_theta_edge1) ex.max_theta_edge1 = x(0);
    if (-x(0) > ex.max_theta_edge2) ex.max_theta_edge2 = -x(0);
    ex.max_uplift = std::max(ex.max_uplift, (p_.b1 + p_.b2) * std::abs(std::sin(x(0))));
  }
  double thdd;
  const Eigen::Vector2d f = reaction(t, x, thdd);
  ex.max_base_shear = std::max(ex.max_base_shear, std::abs(f(0)));
  if (f(1) > 0.0) ex.max_friction_demand = std::max(ex.max_friction_demand, std::abs(f(0)) / f(1));
  const int e = rocking() ? edge() : 1;
  const double s = rocking() ? std::sin(x(0)) : 0.0, c = rocking() ? std::cos(x(0)) : 1.0;
  for (Tie& tie : ties_) {
    const TieGeometry g = geometry(p_, tie.r, e, s, c);
    tie.sum.max_force = std::max(tie.sum.max_force, force(tie, g.e));
    tie.sum.max_elongation = std::max(tie.sum.max_elongation, g.e);
  }
  scale_ = std::max({scale_, kinetic(x), std::abs(gravity_energy(x)), std::abs(x(2))});
}

// observe() at sample k of the step, from what sample() formed there
void RestrainedSim::observe_sample(std::size_t k) {
  Extremes& ex = res_.result.extremes;
  const State& x = smp_x_[k];
  if (rocking()) {
    if (x(0) > ex.max_theta_edge1) ex.max_theta_edge1 = x(0);
    if (-x(0) > ex.max_theta_edge2) ex.max_theta_edge2 = -x(0);
    ex.max_uplift = std::max(ex.max_uplift, (p_.b1 + p_.b2) * std::abs(std::sin(x(0))));
  }
  const Eigen::Vector2d& f = smp_f_[k];
  ex.max_base_shear = std::max(ex.max_base_shear, std::abs(f(0)));
  if (f(1) > 0.0) ex.max_friction_demand = std::max(ex.max_friction_demand, std::abs(f(0)) / f(1));
  for (std::size_t i = 0; i < ties_.size(); ++i) {
    const double* w = &smp_tie_[(k * ties_.size() + i) * 2];
    ties_[i].sum.max_force = std::max(ties_[i].sum.max_force, w[0]);
    ties_[i].sum.max_elongation = std::max(ties_[i].sum.max_elongation, w[1]);
  }
  scale_ = std::max({scale_, kinetic(x), std::abs(gravity_energy(x)), std::abs(x(2))});
}

void RestrainedSim::uplift(int e, double t, State& x) {
  mode_ = e == 1 ? ContactMode::kRockingEdge1 : ContactMode::kRockingEdge2;
  x(0) = 0.0;
  x(1) = 0.0;
  Extremes& ex = res_.result.extremes;
  if (ex.first_uplift_time < 0.0) {
    ex.first_uplift_time = t;
    ex.first_uplift_edge = e;
  }
  Event ev;
  ev.time = t;
  ev.kind = EventKind::kUplift;
  ev.edge = e;
  res_.result.events.push_back(ev);
  std::fill(zero_start_.begin(), zero_start_.end(), false);
  zero_start_[kUpliftOrImpact] = true;
  zero_start_[kUplift2OrPeak] = true;
}

void RestrainedSim::enter_full_contact(double t, State& x) {
  mode_ = ContactMode::kFullContact;
  x(0) = 0.0;
  x(1) = 0.0;
  std::fill(zero_start_.begin(), zero_start_.end(), false);
  // a base already past a threshold lifts the body again at once
  const BaseAcceleration b = motion_.at(t, gcursor_);
  if (rocking_acceleration(1, 0.0, 0.0, b) > 0.0)
    uplift(1, t, x);
  else if (rocking_acceleration(2, 0.0, 0.0, b) < 0.0)
    uplift(2, t, x);
}

// a yielding tie turns elastic, its plastic elongation kept
void RestrainedSim::unload(int i, double t, const State& x) {
  Tie& tie = ties_[static_cast<std::size_t>(i)];
  const int e = rocking() ? edge() : 1;
  const double s = rocking() ? std::sin(x(0)) : 0.0, c = rocking() ? std::cos(x(0)) : 1.0;
  const TieGeometry g = geometry(p_, tie.r, e, s, c);
  RestraintEvent ev;
  ev.time = t;
  ev.restraint = i;
  ev.kind = RestraintEventKind::kUnload;
  ev.force = force(tie, g.e);
  ev.elongation = g.e;
  end_yield(tie, g.e);
  tie.state = TieState::kElastic;
  // at the peak the rate is zero and turns negative: slack comes from above
  set_taut(tie, g.e, rocking() ? g.de * x(1) : 0.0);
  ev.plastic_elongation = tie.ep;
  res_.events.push_back(ev);
}

bool RestrainedSim::fire(int slot, double t, State& x) {
  Extremes& ex = res_.result.extremes;
  if (slot < kTies) {
    if (!rocking()) {
      if (slot == kUpliftOrImpact || slot == kUplift2OrPeak) {
        uplift(slot == kUpliftOrImpact ? 1 : 2, t, x);
        return true;
      }
      double thdd;
      const Eigen::Vector2d f = reaction(t, x, thdd);
      return stop(t, "the floor's vertical reaction reached " + format_number(f(1), 6) +
                         " N at t = " + format_number(t, 9) +
                         " s in full contact: flight is not modelled with restraints");
    }
    switch (slot) {
      case kUpliftOrImpact: {
        // an impact: the ties' forces are finite and give no impulse
        const int landing = edge() == 1 ? 2 : 1;
        const double thd_minus = x(1);
        const Eigen::Matrix<double, 0, 1> q, qd;
        const auto out = resolve_impact(dyn_, landing, q, thd_minus, qd, rule_);
        ++ex.impacts;
        const double loss = 0.5 * inertia(edge()) * thd_minus * thd_minus -
                            0.5 * inertia(landing) * out.theta_dot * out.theta_dot;
        Event ev;
        ev.time = t;
        ev.theta_dot_before = thd_minus;
        ev.impulse_x = out.impulse(0);
        ev.impulse_y = out.impulse(1);
        ex.max_impulse = std::max(ex.max_impulse, std::abs(out.impulse(1)));
        const double period = 2.0 * std::numbers::pi / body_.rocking_frequency();
        const bool chatter = t - last_impact_ < opt_.chatter_ratio * period;
        last_impact_ = t;
        if (out.both_edges || chatter) {
          ev.kind = chatter ? EventKind::kChatterCutoff : EventKind::kRockingEnded;
          ev.edge = 0;
          ev.energy_loss = 0.5 * inertia(edge()) * thd_minus * thd_minus;
          if (chatter) {
            ++ex.chatter_cutoffs;
            res_.result.chatter_cut_off = true;
            chatter_loss_ += ev.energy_loss;
          } else {
            impact_loss_ += ev.energy_loss;
          }
          ex.max_impact_energy_loss = std::max(ex.max_impact_energy_loss, ev.energy_loss);
          res_.result.events.push_back(ev);
          enter_full_contact(t, x);
          return true;
        }
        ev.kind = EventKind::kImpact;
        ev.edge = landing;
        ev.theta_dot_after = out.theta_dot;
        ev.energy_loss = loss;
        ev.force_estimate = std::numbers::pi * out.impulse.norm() / (2.0 * opt_.impact_duration);
        ex.max_impact_force = std::max(ex.max_impact_force, ev.force_estimate);
        impact_loss_ += loss;
        ex.max_impact_energy_loss = std::max(ex.max_impact_energy_loss, loss);
        if (loss < -kImpactEnergyRounding * std::max(scale_, 1.0)) {
          res_.result.impact_gained_energy = true;
        }
        res_.result.events.push_back(ev);
        mode_ = landing == 1 ? ContactMode::kRockingEdge1 : ContactMode::kRockingEdge2;
        x(0) = 0.0;
        x(1) = out.theta_dot;
        std::fill(zero_start_.begin(), zero_start_.end(), false);
        zero_start_[kUpliftOrImpact] = true;
        return true;
      }
      case kUplift2OrPeak: {
        Event ev;
        ev.time = t;
        ev.kind = EventKind::kPeak;
        ev.edge = edge();
        ev.theta = x(0);
        res_.result.events.push_back(ev);
        // the located peak: theta_dot is zero there (a rounding residue of the sign the guard
        // had before would read as a second peak at once)
        x(1) = 0.0;
        // the elongations' rates e' theta_dot change sign with theta_dot: yielding ties unload
        for (std::size_t i = 0; i < ties_.size(); ++i)
          if (ties_[i].state == TieState::kYielding) unload(static_cast<int>(i), t, x);
        // past the peak sigma theta_dot turns negative: no zero start for it
        std::fill(zero_start_.begin(), zero_start_.end(), false);
        return true;
      }
      case kOverturn: {
        res_.result.status = Status::kOverturned;
        res_.result.message = "overturned";
        ex.overturn_time = t;
        ex.overturn_edge = edge();
        Event ev;
        ev.time = t;
        ev.kind = EventKind::kOverturn;
        ev.edge = edge();
        ev.theta = x(0);
        res_.result.events.push_back(ev);
        return false;
      }
      default: {
        double thdd;
        const Eigen::Vector2d f = reaction(t, x, thdd);
        return stop(t, "the floor's vertical reaction reached " + format_number(f(1), 6) +
                           " N at t = " + format_number(t, 9) + " s while rocking on edge " +
                           std::to_string(edge()) + ": flight is not modelled with restraints");
      }
    }
  }
  const int i = (slot - kTies) / kPerTie, which = (slot - kTies) % kPerTie;
  Tie& tie = ties_[static_cast<std::size_t>(i)];
  const int e = rocking() ? edge() : 1;
  const double s = rocking() ? std::sin(x(0)) : 0.0, c = rocking() ? std::cos(x(0)) : 1.0;
  const TieGeometry g = geometry(p_, tie.r, e, s, c);
  RestraintEvent ev;
  ev.time = t;
  ev.restraint = i;
  ev.force = force(tie, g.e);
  ev.elongation = g.e;
  std::fill(zero_start_.begin(), zero_start_.end(), false);
  if (which == 0 && tie.state == TieState::kElastic) {
    tie.state = TieState::kYielding;
    ev.kind = RestraintEventKind::kYield;
    if (!tie.sum.yielded) tie.sum.yield_time = t;
    tie.sum.yielded = true;
    zero_start_[static_cast<std::size_t>(slot)] = false;
  } else if (which == 0) {
    unload(i, t, x);
    return true;
  } else if (which == 1) {
    if (tie.state == TieState::kYielding) end_yield(tie, g.e);
    const double before = tie_energy(tie.r, g.e, tie.ep);
    tie.energy_after = broken_energy(tie.r);
    tie.sum.fracture_work = before - tie.energy_after;
    fracture_work_ += tie.sum.fracture_work;
    tie.state = TieState::kFractured;
    tie.sum.fractured = true;
    tie.sum.fracture_time = t;
    ev.kind = RestraintEventKind::kFracture;
    ev.energy = tie.sum.fracture_work;
  } else {
    // slack or taut again: no event in the log, the force's kink is only located
    tie.taut = !tie.taut;
    zero_start_[static_cast<std::size_t>(slot)] = true;
    return true;
  }
  ev.plastic_elongation = tie.ep;
  res_.events.push_back(ev);
  return true;
}

// full contact under a sampled record: the body is still and every guard is linear in the base
// acceleration, itself linear between samples, so each sample interval is one step whose guards
// are known at its ends (the still path; no integration)
bool RestrainedSim::advance_still(double& t, State& x) {
  const double t_stop = std::min(motion_.next_breakpoint(t, break_cursor_), t_end_);
  if (++steps_ > opt_.max_steps)
    return stop(t, "more than max_steps = " + std::to_string(opt_.max_steps) + " steps");
  ++res_.result.steps;
  still_ = true;
  still_x_ = x;
  // the interval's start is the last one's end unless an event came between
  if (!(still_valid_ && still_t_ == t)) {
    sample(t, x, smp_[0]);
    smp_f_[0] = last_reaction_;
  } else {
    smp_[0].swap(smp_[1]);
    smp_f_[0] = smp_f_[1];
  }
  sample(t_stop, x, smp_[1]);
  smp_f_[1] = last_reaction_;
  still_valid_ = true;
  still_t_ = t_stop;
  double t_hit = kInf;
  for (int slot = 0; slot < slots_; ++slot) {
    const auto j = static_cast<std::size_t>(slot);
    const double g0 = smp_[0][j], g1 = smp_[1][j];
    double th = kInf;
    if (g0 > 0.0 && g1 <= 0.0) th = detail::locate_crossing(slot, t, t_stop, g0, g1, *this);
    crossing_[j] = th;
    t_hit = std::min(t_hit, th);
  }
  // the extremes of a still body: the base shear at the interval's ends (linear between)
  Extremes& ex = res_.result.extremes;
  for (int k = 0; k < 2; ++k) {
    const Eigen::Vector2d& f = smp_f_[static_cast<std::size_t>(k)];
    ex.max_base_shear = std::max(ex.max_base_shear, std::abs(f(0)));
    if (f(1) > 0.0)
      ex.max_friction_demand = std::max(ex.max_friction_demand, std::abs(f(0)) / f(1));
  }
  if (!std::isfinite(t_hit)) {
    emit_rows_until(t_stop);
    t = t_stop;
    still_ = false;
    if (opt_.progress) opt_.progress->store(t, std::memory_order_relaxed);
    return true;
  }
  still_valid_ = false;
  emit_rows_until(t_hit);
  still_ = false;
  t = t_hit;
  observe(t, x);
  auto sys = [this](double tt, const State& z, State& dz) { rhs(tt, z, dz); };
  for (int slot = 0; slot < slots_; ++slot) {
    const double c = crossing_[static_cast<std::size_t>(slot)];
    if (!(std::isfinite(c) && c - detail::crossing_resolution(c) <= t_hit)) continue;
    if (!fire(slot, t, x)) return false;
    if (rocking()) break;
  }
  retaut(x);
  integ_.start(sys, ctl_, t, x);
  return true;
}

bool RestrainedSim::advance(double& t, State& x) {
  if (!rocking() && motion_.is_sampled()) return advance_still(t, x);
  auto sys = [this](double tt, const State& z, State& dz) { rhs(tt, z, dz); };
  const double t_stop = std::min(motion_.next_breakpoint(t, break_cursor_), t_end_);
  if (integ_.step(sys, t_stop) != Dopri5<State>::Status::kAccepted)
    return stop(t, "the integrator's step collapsed at t = " + format_number(t, 9) + " s");
  if (++steps_ > opt_.max_steps)
    return stop(t, "more than max_steps = " + std::to_string(opt_.max_steps) + " steps");
  ++res_.result.steps;
  const double t0 = integ_.t0(), t1 = integ_.t1();
  for (int k = 0; k <= samples_; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    smp_t_[kk] = k == samples_ ? t1 : t0 + (t1 - t0) * k / samples_;
    if (k == 0) {
      smp_x_[kk] = integ_.x0();
    } else if (k == samples_) {
      smp_x_[kk] = integ_.x1();
    } else {
      integ_.dense(smp_t_[kk], smp_x_[kk]);
    }
    sample(smp_t_[kk], smp_x_[kk], smp_[kk]);
    smp_f_[kk] = last_reaction_;
    for (std::size_t i = 0; i < ties_.size(); ++i) {
      double* w = &smp_tie_[(kk * ties_.size() + i) * 2];
      w[0] = ties_[i].state == TieState::kFractured ? 0.0 : force(ties_[i], geo_[i].e);
      w[1] = geo_[i].e;
    }
  }
  double t_hit = kInf;
  int slot_hit = -1;
  for (int slot = 0; slot < slots_; ++slot) {
    const double th = first_crossing(slot);
    crossing_[static_cast<std::size_t>(slot)] = th;
    if (th < t_hit) {
      t_hit = th;
      slot_hit = slot;
    }
  }
  for (int k = 0; k <= samples_; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    if (smp_t_[kk] >= t_hit) break;
    observe_sample(kk);
  }
  if (slot_hit < 0) {
    emit_rows_until(t1);
    t = t1;
    x = integ_.x1();
    // a guard that started at zero and stayed positive is an ordinary guard again
    std::fill(zero_start_.begin(), zero_start_.end(), false);
    if (opt_.progress) opt_.progress->store(t, std::memory_order_relaxed);
    return true;
  }
  integ_.restep_to(sys, t_hit);
  emit_rows_until(t_hit);
  t = t_hit;
  x = integ_.x1();
  observe(t, x);
  // every guard whose crossing cannot be told from the first one's fires with it: the ties'
  // first (they act in the configuration the guards were evaluated in), then the contact mode's
  bool fired_tie = false;
  int mode_slot = -1;
  for (int slot = 0; slot < slots_; ++slot) {
    const double c = crossing_[static_cast<std::size_t>(slot)];
    if (!(std::isfinite(c) && c - detail::crossing_resolution(c) <= t_hit)) continue;
    if (slot >= kTies) {
      if (!fire(slot, t, x)) return false;
      fired_tie = true;
    } else if (mode_slot < 0) {
      mode_slot = slot;
    }
  }
  if (fired_tie && mode_slot >= 0) std::fill(zero_start_.begin(), zero_start_.end(), false);
  if (mode_slot >= 0 && !fire(mode_slot, t, x)) return false;
  if (mode_slot >= 0) retaut(x);
  // a tie event located a hair before the impact it coincides with (a corner's anchor goes slack
  // as the corner lands) leaves theta at zero and falling: the impact is now
  if (mode_slot < 0 && rocking() && !zero_start_[kUpliftOrImpact] && sigma() * x(0) <= 0.0 &&
      sigma() * x(1) < 0.0) {
    if (!fire(kUpliftOrImpact, t, x)) return false;
    retaut(x);
  }
  (void)slot_hit;
  observe(t, x);
  integ_.start(sys, ctl_, t, x);
  if (opt_.progress) opt_.progress->store(t, std::memory_order_relaxed);
  return true;
}

RestrainedResult RestrainedSim::run(const InitialState& init) {
  State x;
  x << init.theta, init.theta_dot, 0.0;
  if (init.theta > 0.0 || (init.theta == 0.0 && init.theta_dot > 0.0))
    mode_ = ContactMode::kRockingEdge1;
  else if (init.theta < 0.0 || (init.theta == 0.0 && init.theta_dot < 0.0))
    mode_ = ContactMode::kRockingEdge2;
  {
    const int e = rocking() ? edge() : 1;
    const double s = std::sin(x(0)), c = std::cos(x(0));
    for (std::size_t i = 0; i < ties_.size(); ++i) {
      Tie& tie = ties_[i];
      const TieGeometry g = geometry(p_, tie.r, e, s, c);
      FLEXROCK_THROW_UNLESS(trial_force(tie.r, g.e, 0.0) < tie.r.yield_force &&
                                g.e - tie.r.slack < tie.r.fracture_elongation,
                            where(i) + "the initial rotation " + format_number(x(0)) +
                                " rad already stretches it past its yield force or its "
                                "fracture elongation; start nearer rest");
      set_taut(tie, g.e, g.de * x(1));
    }
  }
  t_end_ = opt_.t_end >= 0.0 ? opt_.t_end : motion_.duration();
  const double kin0 = kinetic(x), grav0 = gravity_energy(x), stored0 = stored_energy(x);
  energy0_ = kin0 + grav0 + stored0;
  double t = 0.0;
  auto sys = [this](double tt, const State& z, State& dz) { rhs(tt, z, dz); };
  if (!rocking()) enter_full_contact(t, x);
  retaut(x);
  integ_.start(sys, ctl_, t, x);
  if (opt_.output_dt > 0.0) emit_row(t, x);
  next_output_ = 1;
  observe(t, x);
  bool running = true;
  while (running && t < t_end_) running = advance(t, x);
  // the end
  SimulationResult& r = res_.result;
  r.t_end = t;
  if (opt_.output_dt > 0.0 && (r.history.time.empty() || r.history.time.back() < t - 1e-12))
    emit_row(t, x);
  r.final_phase = mode_;
  r.final_theta = x(0);
  r.final_theta_dot = x(1);
  r.final_q = VectorX(0);
  r.final_q_dot = VectorX(0);
  r.history.modes = 0;
  res_.stored_energy_change = stored_energy(x) - stored0;
  // book the plastic work of ties still yielding
  {
    const int e = rocking() ? edge() : 1;
    const double s = rocking() ? std::sin(x(0)) : 0.0, c = rocking() ? std::cos(x(0)) : 1.0;
    for (Tie& tie : ties_) {
      const TieGeometry g = geometry(p_, tie.r, e, s, c);
      tie.sum.final_force = force(tie, g.e);
      if (tie.state == TieState::kYielding) end_yield(tie, g.e);
      tie.sum.plastic_elongation = tie.ep;
      res_.restraints.push_back(tie.sum);
    }
  }
  res_.plastic_work = plastic_work();
  res_.fracture_work = fracture_work_;
  EnergyBalance& e = r.energy;
  e.input_work = x(2);
  e.kinetic_change = kinetic(x) - kin0;
  e.potential_change = gravity_energy(x) - grav0 + res_.stored_energy_change;
  e.impact_loss = impact_loss_;
  e.chatter_loss = chatter_loss_;
  e.residual = e.input_work - (e.kinetic_change + e.potential_change + e.impact_loss +
                               e.chatter_loss + res_.plastic_work + res_.fracture_work);
  e.scale = std::max({scale_, std::abs(e.potential_change), impact_loss_ + chatter_loss_,
                      res_.plastic_work + res_.fracture_work});
  if (!(std::abs(e.residual) <= energy_residual_bound(body_, e.scale))) {
    r.energy_unbalanced = true;
    Event ev;
    ev.time = r.t_end;
    ev.kind = EventKind::kEnergyUnbalanced;
    ev.energy_loss = e.residual;
    r.events.push_back(ev);
  }
  r.rejected_steps = integ_.rejected_steps();
  r.rhs_evaluations = integ_.rhs_evaluations();
  if (r.status == Status::kCompleted) r.message = "completed";
  return std::move(res_);
}

}  // namespace

void validate_restraints(const Body& body, const std::vector<Restraint>& restraints,
                         const SimulationOptions& o) {
  FLEXROCK_THROW_UNLESS(body.modes() == 0,
                        "restraints: the body has " + std::to_string(body.modes()) +
                            " modes; restraints are modelled on a rigid body (modes = 0) only");
  FLEXROCK_THROW_UNLESS(o.contact_model == ContactModel::kImpulsive,
                        "restraints: contact_model = compliant is not modelled with restraints; "
                        "use the impulsive floor");
  FLEXROCK_THROW_UNLESS(
      std::isinf(o.friction_coefficient),
      "restraints: friction_coefficient = " + format_number(o.friction_coefficient) +
          ": sliding is not modelled with restraints; leave it infinite");
  for (std::size_t i = 0; i < restraints.size(); ++i) {
    const Restraint& r = restraints[i];
    const std::string w = where(i);
    FLEXROCK_THROW_UNLESS(std::isfinite(r.body_x) && std::isfinite(r.body_y) &&
                              std::isfinite(r.floor_x) && std::isfinite(r.floor_y),
                          w + "its points must be finite");
    FLEXROCK_THROW_UNLESS(r.body_y >= 0.0, w + "body_y = " + format_number(r.body_y) +
                                               " m: the body point must be on or above the base");
    FLEXROCK_THROW_UNLESS(r.floor_y <= 0.0,
                          w + "floor_y = " + format_number(r.floor_y) +
                              " m: the floor point must be on or below the floor");
    FLEXROCK_THROW_UNLESS(rest_length(r) > 1e-6 * body.params().height,
                          w + "the body point and the floor point coincide at rest: give the tie "
                              "a length (length > 0)");
    FLEXROCK_THROW_UNLESS(
        std::isfinite(r.stiffness) && r.stiffness >= 0.0,
        w + "stiffness must be >= 0 and finite, got " + format_number(r.stiffness));
    FLEXROCK_THROW_UNLESS(
        std::isfinite(r.prestress) && r.prestress >= 0.0,
        w + "prestress must be >= 0 and finite, got " + format_number(r.prestress));
    FLEXROCK_THROW_UNLESS(std::isfinite(r.slack) && r.slack >= 0.0,
                          w + "slack must be >= 0 and finite, got " + format_number(r.slack));
    FLEXROCK_THROW_UNLESS(r.slack == 0.0 || r.prestress == 0.0,
                          w + "a slack and a prestress exclude each other");
    FLEXROCK_THROW_UNLESS(r.yield_force > r.prestress,
                          w + "yield_force = " + format_number(r.yield_force) +
                              " N must exceed the prestress " + format_number(r.prestress) +
                              " N (inf: elastic)");
    FLEXROCK_THROW_UNLESS(std::isinf(r.yield_force) || r.stiffness > 0.0,
                          w + "a yield force needs a stiffness > 0");
    FLEXROCK_THROW_UNLESS(r.fracture_elongation > 0.0,
                          w + "fracture_elongation must be > 0 (inf: never), got " +
                              format_number(r.fracture_elongation));
  }
}

RestrainedResult simulate_restrained(const Body& body, const std::vector<Restraint>& restraints,
                                     const GroundMotion& motion, const InitialState& init,
                                     const SimulationOptions& options) {
  validate_options(body, init, options);
  validate_restraints(body, restraints, options);
  return RestrainedSim(body, restraints, motion, options).run(init);
}

TieGeometry tie_geometry(const Body& body, const Restraint& r, int edge, double theta) {
  return geometry(body.params(), r, edge, std::sin(theta), std::cos(theta));
}

double tie_force(const Restraint& r, double e) { return std::max(trial_force(r, e, 0.0), 0.0); }

double restoring_moment(const Body& body, const std::vector<Restraint>& restraints, int edge,
                        double theta) {
  const BodyParameters& p = body.params();
  const double s = std::sin(theta), c = std::cos(theta);
  const double cx = edge == 1 ? p.b1 : -p.b2;
  // gravity's moment about the pivot, and the ties', both signed so that positive restores
  const double sg = edge == 1 ? 1.0 : -1.0;
  double m = sg * p.mass * p.gravity * (cx * c - p.height * s);
  for (const Restraint& r : restraints) {
    const TieGeometry g = geometry(p, r, edge, s, c);
    m += sg * tie_force(r, g.e) * g.de;
  }
  return m;
}

double pushover_acceleration(const Body& body, const std::vector<Restraint>& restraints, int edge,
                             double theta) {
  const BodyParameters& p = body.params();
  const double s = std::sin(theta), c = std::cos(theta);
  const double cx = edge == 1 ? p.b1 : -p.b2;
  const double sg = edge == 1 ? 1.0 : -1.0;
  return restoring_moment(body, restraints, edge, theta) / (p.mass * (sg * cx * s + p.height * c));
}

double uplift_acceleration(const Body& body, const std::vector<Restraint>& restraints, int edge) {
  return pushover_acceleration(body, restraints, edge, 0.0);
}

double self_centring_stiffness(const Body& body, const std::vector<Restraint>& restraints,
                               int edge) {
  const BodyParameters& p = body.params();
  const double sg = edge == 1 ? 1.0 : -1.0;
  // dM_r/d|theta| at 0+: gravity's -M g h, each tie's k e'^2 + T_0 e'' (taut at rest)
  double k = -p.mass * p.gravity * p.height;
  for (const Restraint& r : restraints) {
    const TieGeometry g = geometry(p, r, edge, 0.0, 1.0);
    const double t0 = tie_force(r, 0.0);
    // taut on both sides of rest, or engaging at once on this side
    if (t0 > 0.0 || (r.slack == 0.0 && sg * g.de > 0.0)) k += r.stiffness * g.de * g.de;
    k += t0 * g.d2e;
  }
  return k;
}

double critical_stiffness(const Body& body, const std::vector<Restraint>& restraints, int which,
                          int edge) {
  std::vector<Restraint> others = restraints;
  others[static_cast<std::size_t>(which)].stiffness = 0.0;
  const TieGeometry g =
      geometry(body.params(), restraints[static_cast<std::size_t>(which)], edge, 0.0, 1.0);
  return -self_centring_stiffness(body, others, edge) / (g.de * g.de);
}

double restrained_rocking_acceleration(const Body& body, const std::vector<Restraint>& restraints,
                                       int edge, double theta, BaseAcceleration base) {
  const GroundMotion none = GroundMotion::none(1.0);
  const SimulationOptions opt;
  RestrainedSim sim(body, restraints, none, opt);
  sim.settle_at(edge, theta);
  return sim.rocking_acceleration(edge, theta, 0.0, base);
}

}  // namespace flexrock
