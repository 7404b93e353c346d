// SPDX-License-Identifier: BSD-3-Clause
// The event loop of a rigid body of revolution in three dimensions (docs/theory.md §27). Its own
// automaton (modes, guards, resets as tables, in the style of automaton.hpp), DOPRI5 over the
// rolling mode, the guards located on the dense output by the planar engine's event location.
#include "flexrock/sim/axisymmetric.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "event_location.hpp"
#include "flexrock/contact/rim_landing.hpp"
#include "flexrock/core/error.hpp"
#include "flexrock/core/format.hpp"
#include "flexrock/excitation/azimuth.hpp"
#include "flexrock/integrate/dopri5.hpp"

namespace flexrock {

const char* to_string(RimStatus s) {
  switch (s) {
    case RimStatus::kCompleted:
      return "completed";
    case RimStatus::kOverturned:
      return "overturned";
    case RimStatus::kUnmodelled:
      return "unmodelled";
    case RimStatus::kStopped:
      return "stopped";
  }
  return "?";
}

const char* to_string(RimEventKind k) {
  switch (k) {
    case RimEventKind::kUplift:
      return "uplift";
    case RimEventKind::kLanding:
      return "landing";
    case RimEventKind::kRest:
      return "rest";
    case RimEventKind::kOverturn:
      return "overturn";
    case RimEventKind::kLiftOff:
      return "lift_off";
    case RimEventKind::kRimSlip:
      return "rim_slip";
    case RimEventKind::kFullSliding:
      return "full_sliding";
    case RimEventKind::kStopped:
      return "stopped";
  }
  return "?";
}

const char* to_string(RimMode m) {
  switch (m) {
    case RimMode::kFullContact:
      return "full_contact";
    case RimMode::kRolling:
      return "rolling";
    case RimMode::kPivoting:
      return "pivoting";
  }
  return "?";
}

namespace {

// ---------------------------------------------------------------------------------------------
// the automaton as data (docs/theory.md §27, "Modes and transitions")

/// Guards: positive while nothing happens; each fires when it reaches zero from above.
enum class RimGuard : int {
  kUplift,        // ((g + a_z) R - |a_h| h) / (g h): the moment about the rim point toward -a_h
  kFloorLoad,     // (g + a_z) / g: the floor presses the base (full contact)
  kBaseFriction,  // (mu (g + a_z) - |a_h|) / g: friction holds the base (full contact)
  kNearUpright,   // (|k_h| - kPivotZone) / kPivotZone: rolling comes within the pivot zone
  kLeaveUpright,  // (kPivotZone - |k_h|) / kPivotZone: pivoting leaves the pivot zone
  kUpright,       // k_h . c / kPivotZone: pivoting, the tilt passes through upright
  kOverturn,      // theta_c - theta
  kNormalForce,   // F_z / M g: the floor presses the rim point
  kRimFriction,   // (mu F_z - |F_h|) / M g: friction holds the rim point
};

enum class RimReset : int {
  kUplift,      // full contact -> pivoting on the rim point toward -a_h, no impulse
  kPivot,       // rolling -> pivoting on the current contact point, no impulse
  kRoll,        // pivoting -> rolling, no impulse
  kLanding,     // the landing map (rim_landing) -> rolling on the opposite point, or rest
  kOverturn,    // the run ends overturned
  kUnmodelled,  // the run ends: a mode not modelled began (named by the guard)
};

struct RimGuardSpec {
  RimGuard guard;
  const char* name;
  RimReset reset;
  RimEventKind event;
};

constexpr std::array<RimGuardSpec, 9> kRimGuards = {{
    {RimGuard::kUplift, "uplift", RimReset::kUplift, RimEventKind::kUplift},
    {RimGuard::kFloorLoad, "floor_load", RimReset::kUnmodelled, RimEventKind::kLiftOff},
    {RimGuard::kBaseFriction, "base_friction", RimReset::kUnmodelled, RimEventKind::kFullSliding},
    {RimGuard::kNearUpright, "near_upright", RimReset::kPivot, RimEventKind::kUplift},
    {RimGuard::kLeaveUpright, "leave_upright", RimReset::kRoll, RimEventKind::kUplift},
    {RimGuard::kUpright, "upright", RimReset::kLanding, RimEventKind::kLanding},
    {RimGuard::kOverturn, "overturn", RimReset::kOverturn, RimEventKind::kOverturn},
    {RimGuard::kNormalForce, "normal_force", RimReset::kUnmodelled, RimEventKind::kLiftOff},
    {RimGuard::kRimFriction, "rim_friction", RimReset::kUnmodelled, RimEventKind::kRimSlip},
}};

struct RimModeSpec {
  RimMode mode;
  int count;
  std::array<RimGuard, 5> guards;  // slot order
};

constexpr std::array<RimModeSpec, 3> kRimModes = {{
    // ties go to the earlier slot: leaving the floor before tipping on it
    {RimMode::kFullContact, 3, {RimGuard::kFloorLoad, RimGuard::kBaseFriction, RimGuard::kUplift}},
    // rolling also watches the tilt vector crossing the line through upright normal to the step's
    // contact direction: a pass through the zone between two samples (the V of |k_h| there is
    // not seen by the zone's guard) lands; a crossing outside the zone only renews the direction
    {RimMode::kRolling,
     5,
     {RimGuard::kNearUpright, RimGuard::kUpright, RimGuard::kOverturn, RimGuard::kNormalForce,
      RimGuard::kRimFriction}},
    {RimMode::kPivoting,
     4,
     {RimGuard::kUpright, RimGuard::kLeaveUpright, RimGuard::kNormalForce, RimGuard::kRimFriction}},
}};

const RimGuardSpec& spec(RimGuard g) { return kRimGuards[static_cast<std::size_t>(g)]; }
const RimModeSpec& spec(RimMode m) { return kRimModes[static_cast<std::size_t>(m)]; }

// state: quaternion (w, x, y, z), omega (world), c.g. offset on the floor (x, y), input work
using State = Eigen::Matrix<double, 10, 1>;

RimState rim_state(const State& x) {
  return {Eigen::Quaterniond(x(0), x(1), x(2), x(3)), Vector3(x(4), x(5), x(6))};
}

// the orientation with its tilt removed, kept its heading: the axis exactly vertical
Eigen::Quaterniond upright(const Eigen::Quaterniond& q) {
  const double yaw = 2.0 * std::atan2(q.z(), q.w());
  return Eigen::Quaterniond(std::cos(0.5 * yaw), 0.0, 0.0, std::sin(0.5 * yaw));
}

class Loop final : public detail::GuardProbe {
 public:
  Loop(const AxisymmetricBody& b, const FloorMotion& m, const RimOptions& o)
      : b_(b), m_(m), o_(o), mg_(b.mass * b.gravity) {
    t_end_ = o.t_end >= 0.0 ? o.t_end : std::max(m.h1->duration(), m.h2 ? m.h2->duration() : 0.0);
    theta_c_ = o.overturn == OverturnCriterion::kHalfPi ? 0.5 * std::numbers::pi
                                                        : std::atan2(b.radius, b.height);
    chatter_dt_ = o.chatter_ratio * 2.0 * std::numbers::pi / rocking_frequency(b);
    ctl_.rtol = o.rtol;
    ctl_.atol = o.atol;
    ctl_.max_step = o.max_step;
    ctl_.controlled = 9;  // not the input work
  }

  RimResult run(const RimInitialState& init);

  // GuardProbe: guard values within the last step (rolling) or at any time (full contact)
  double guard_value(int slot, double t) override {
    const RimGuard g = spec(mode_).guards[static_cast<std::size_t>(slot)];
    if (mode_ == RimMode::kFullContact) return full_guard(g, floor(t));
    State x;
    stepper_.dense(t, x);
    return rolling_guard(g, x, rates(t, x));
  }

 private:
  Vector3 floor(double t) {
    const BaseAcceleration a1 = m_.h1->at(t, cur1_);
    const double ay = m_.h2 ? m_.h2->at(t, cur2_).x : 0.0;
    return {a1.x, ay, a1.y};
  }
  double next_break(double t) {
    double n = m_.h1->next_breakpoint(t, cur1_);
    if (m_.h2) n = std::min(n, m_.h2->next_breakpoint(t, cur2_));
    return n;
  }
  double full_guard(RimGuard g, const Vector3& a) const {
    const double gz = b_.gravity + a.z(), ah = std::hypot(a.x(), a.y());
    switch (g) {
      case RimGuard::kUplift:
        return (gz * b_.radius - ah * b_.height) / (b_.gravity * b_.height);
      case RimGuard::kFloorLoad:
        return gz / b_.gravity;
      case RimGuard::kBaseFriction:
        return std::isinf(o_.friction_coefficient)
                   ? 1.0
                   : (o_.friction_coefficient * gz - ah) / b_.gravity;
      default:
        return 1.0;
    }
  }
  // the rates of the integrated mode (rolling or pivoting) at a state
  RimRates rates(double t, const State& x) {
    return mode_ == RimMode::kPivoting ? pivot_rates(b_, rim_state(x), floor(t), pivot_body_)
                                       : rim_rates(b_, rim_state(x), floor(t), c_step_);
  }
  double rolling_guard(RimGuard g, const State& x, const RimRates& r) const {
    switch (g) {
      case RimGuard::kUpright: {
        const Vector3 k = r.axis;
        return (k.x() * c_step_.x() + k.y() * c_step_.y()) / o_.pivot_zone;
      }
      case RimGuard::kNearUpright:
        return (r.sin_tilt - o_.pivot_zone) / o_.pivot_zone;
      case RimGuard::kLeaveUpright:
        return (o_.pivot_zone - r.sin_tilt) / o_.pivot_zone;
      case RimGuard::kOverturn:
        return theta_c_ - r.tilt;
      case RimGuard::kNormalForce:
        return r.force.z() / mg_;
      case RimGuard::kRimFriction:
        return std::isinf(o_.friction_coefficient) ? 1.0
                                                   : (o_.friction_coefficient * r.force.z() -
                                                      std::hypot(r.force.x(), r.force.y())) /
                                                         mg_;
      default:
        (void)x;
        return 1.0;
    }
  }
  void rhs(double t, const State& x, State& dx) {
    const RimState s = rim_state(x);
    const Vector3 a = floor(t);
    const RimRates r = rates(t, x);
    const Eigen::Quaterniond& q = s.orientation;
    // q_dot = (0, omega) q / 2, omega in world components
    const Eigen::Quaterniond wq(0.0, s.omega.x(), s.omega.y(), s.omega.z());
    const Eigen::Quaterniond qd = wq * q;
    dx(0) = 0.5 * qd.w();
    dx(1) = 0.5 * qd.x();
    dx(2) = 0.5 * qd.y();
    dx(3) = 0.5 * qd.z();
    dx.segment<3>(4) = r.omega_dot;
    dx(7) = r.v_cg.x();
    dx(8) = r.v_cg.y();
    // the pseudo-force's power: -M a_f . v_G
    dx(9) = -b_.mass * a.dot(r.v_cg);
  }
  // kinetic and potential energy of a state in contact
  void energies(const State& x, const RimRates& r, double& kin, double& pot) const {
    const Vector3 w(x(4), x(5), x(6));
    const Matrix3 iw = b_.inertia_diameter * Matrix3::Identity() +
                       (b_.inertia_axis - b_.inertia_diameter) * r.axis * r.axis.transpose();
    kin = 0.5 * (b_.mass * r.v_cg.squaredNorm() + w.dot(iw * w));
    pot = mg_ * (b_.height * r.axis.z() + b_.radius * r.sin_tilt);
  }
  void observe(double t, const State& x);  // extremes and history at a state
  void record(double t, const State& x, const RimRates& r, int mode);
  void outputs_until(double t_to, bool inclusive);
  RimResult finish(RimStatus s, std::string msg);
  void event(RimEventKind k, double t, double value, double e_loss = 0.0) {
    RimEvent ev;
    ev.time = t;
    ev.kind = k;
    ev.tilt = tilt_;
    ev.azimuth = std::atan2(c_step_.y(), c_step_.x());
    ev.value = value;
    ev.energy_loss = e_loss;
    res_.events.push_back(ev);
  }
  bool run_full_contact();  // false: the run ended
  // ends the run in a mode the engine does not model (lift-off or rim slip) at the state `r`
  RimResult end_unmodelled(RimEventKind kind, const RimRates& r);
  bool run_rolling();  // false: the run ended
  void refine_peaks(const detail::GuardSample* smp, const double* tl, int ns);
  void enter_rolling(double t, const Vector3& c);

  const AxisymmetricBody& b_;
  FloorMotion m_;
  const RimOptions& o_;
  double mg_, t_end_ = 0.0, theta_c_ = 0.0, chatter_dt_ = 0.0;
  StepControl ctl_;
  Dopri5<State> stepper_;
  GroundMotion::Cursor cur1_, cur2_;
  RimMode mode_ = RimMode::kFullContact;
  Vector3 pivot_body_ = Vector3::UnitX();  // pivoting: the rim point, body frame
  State x_ = State::Zero();
  double t_ = 0.0, tilt_ = 0.0;
  Vector3 c_step_ = Vector3::UnitX();
  RimResult res_;
  double kin0_ = 0.0, pot0_ = 0.0, impact_loss_ = 0.0, last_landing_ = -1e300;
  double next_out_ = 0.0;
  // the last two sampled tilts (for the closest pass by upright)
  double tilt_prev_ = 0.0, tilt_prev2_ = 0.0;
  double contact_angle_ = 0.0, azimuth_ = 0.0;  // unwrapped
  bool have_angles_ = false;
  std::array<double, 4> slot_scale_{};
};

void Loop::record(double t, const State& x, const RimRates& r, int mode) {
  RimHistory& h = res_.history;
  h.time.push_back(t);
  h.mode.push_back(mode);
  h.tilt.push_back(mode == 0 ? 0.0 : r.tilt);
  // unwrap the azimuth of the contact and its angle on the base circle (body frame)
  const Eigen::Quaterniond q = rim_state(x).orientation.normalized();
  const Vector3 u(r.axis.z() * r.contact_dir.x(), r.axis.z() * r.contact_dir.y(), -r.sin_tilt);
  const Vector3 ub = q.conjugate() * u;
  const double az = std::atan2(r.contact_dir.y(), r.contact_dir.x());
  const double ca = std::atan2(ub.y(), ub.x());
  if (!have_angles_) {
    azimuth_ = az, contact_angle_ = ca, have_angles_ = true;
  } else {
    azimuth_ += std::remainder(az - azimuth_, 2.0 * std::numbers::pi);
    contact_angle_ += std::remainder(ca - contact_angle_, 2.0 * std::numbers::pi);
  }
  h.azimuth.push_back(azimuth_);
  h.contact_angle.push_back(contact_angle_);
  // base centre = c.g. - h k
  h.x.push_back(x(7) - b_.height * r.axis.x());
  h.y.push_back(x(8) - b_.height * r.axis.y());
  h.reaction_x.push_back(r.force.x());
  h.reaction_y.push_back(r.force.y());
  h.reaction_z.push_back(r.force.z());
  h.friction_demand.push_back(std::hypot(r.force.x(), r.force.y()) / r.force.z());
  double kin = 0.0, pot = 0.0;
  energies(x, r, kin, pot);
  h.kinetic.push_back(kin);
  h.potential.push_back(pot);
  h.input_work.push_back(x(9));
  h.impact_loss.push_back(impact_loss_);
}

RimResult Loop::run(const RimInitialState& init) {
  const bool moving =
      init.tilt != 0.0 || init.tilt_rate != 0.0 || init.precession != 0.0 || init.spin != 0.0;
  // the tilt about the horizontal e2 = (-sin phi, cos phi, 0), no heading: Euler angles
  // Rz(phi) Ry(theta) Rz(-phi); the circle's symmetries exact (a tilt toward -x stays in the
  // x-z plane to the last bit)
  double cphi = 1.0, sphi = 0.0;
  direction_cosines(init.azimuth_deg, cphi, sphi);
  const Vector3 e2(-sphi, cphi, 0.0);
  const Eigen::Quaterniond q(Eigen::AngleAxisd(init.tilt, e2));
  x_.setZero();
  x_(0) = q.w(), x_(1) = q.x(), x_(2) = q.y(), x_(3) = q.z();
  const Vector3 k = q * Vector3::UnitZ();
  const Vector3 w = init.precession * Vector3::UnitZ() + init.tilt_rate * e2 + init.spin * k;
  x_.segment<3>(4) = w;
  c_step_ = Vector3(cphi, sphi, 0.0);
  const RimRates r0 = rim_rates(b_, rim_state(x_), floor(0.0), c_step_);
  // the c.g. stands at the floor origin's vertical at the start (base centre at -h k_h)
  x_(7) = b_.height * k.x();
  x_(8) = b_.height * k.y();
  tilt_ = init.tilt;
  energies(x_, r0, kin0_, pot0_);
  if (!moving) {
    mode_ = RimMode::kFullContact;
    kin0_ = 0.0;
    pot0_ = mg_ * b_.height;
  } else {
    FLEXROCK_THROW_UNLESS(init.tilt >= 0.0 && init.tilt < theta_c_,
                          "initial tilt: expected 0 <= theta < the overturning angle " +
                              format_number(theta_c_) + " rad, got " + format_number(init.tilt));
    mode_ = RimMode::kRolling;
    if (std::sin(init.tilt) < o_.pivot_zone) {
      mode_ = RimMode::kPivoting;
      pivot_body_ = q.conjugate() *
                    Vector3(k.z() * c_step_.x(), k.z() * c_step_.y(), -std::hypot(k.x(), k.y()));
    }
  }
  next_out_ = 0.0;
  for (;;) {
    const bool go_on = mode_ == RimMode::kFullContact ? run_full_contact() : run_rolling();
    if (go_on && mode_ != RimMode::kFullContact && t_ < t_end_) continue;
    if (!go_on) return res_;
    if (t_ >= t_end_) return finish(RimStatus::kCompleted, "");
  }
}

void Loop::outputs_until(double t_to, bool inclusive) {
  if (!(o_.output_dt > 0.0)) return;
  while (next_out_ < t_to || (inclusive && next_out_ <= t_to)) {
    if (next_out_ > t_end_) return;
    State x = x_;
    if (mode_ != RimMode::kFullContact) stepper_.dense(next_out_, x);
    const RimRates r = rates(next_out_, x);
    if (mode_ == RimMode::kFullContact) {
      RimRates rf = r;
      rf.force = b_.mass * (Vector3(0.0, 0.0, b_.gravity) + floor(next_out_));
      rf.v_cg.setZero();
      rf.tilt = 0.0;
      State xs = x;
      xs.segment<3>(4).setZero();
      record(next_out_, xs, rf, 0);
    } else {
      record(next_out_, x, r, static_cast<int>(mode_));
    }
    const double n = static_cast<double>(res_.history.size());
    next_out_ = n * o_.output_dt;
  }
}

bool Loop::run_full_contact() {
  // at rest on the floor: only the guards move, with the floor's acceleration
  const RimModeSpec& ms = spec(mode_);
  std::array<detail::GuardSample, detail::kMaxSamples + 1> smp{};
  // twice the rolling samples, within the samples' array (event_samples may exceed its size)
  const int ns = std::clamp(2 * o_.event_samples, 2, detail::kMaxSamples);
  for (;;) {
    if (t_ >= t_end_) return true;
    const double t1 = std::min({next_break(t_), t_ + o_.max_step, t_end_});
    for (int i = 0; i <= ns; ++i) {
      const double ti = i == ns ? t1 : t_ + (t1 - t_) * i / ns;
      smp[static_cast<std::size_t>(i)].t = ti;
      const Vector3 a = floor(ti);
      for (int s = 0; s < ms.count; ++s)
        smp[static_cast<std::size_t>(i)].v[static_cast<std::size_t>(s)] =
            full_guard(ms.guards[static_cast<std::size_t>(s)], a);
    }
    double t_ev = std::numeric_limits<double>::infinity();
    int slot_ev = -1;
    for (int s = 0; s < ms.count; ++s) {
      const double te = detail::first_crossing(s, smp.data(), ns, false, true, *this);
      if (te < t_ev) t_ev = te, slot_ev = s;
    }
    if (slot_ev < 0) {
      outputs_until(t1, t1 >= t_end_);
      t_ = t1;
      continue;
    }
    outputs_until(t_ev, false);
    t_ = t_ev;
    const RimGuardSpec& gs = spec(ms.guards[static_cast<std::size_t>(slot_ev)]);
    const Vector3 a = floor(t_);
    const double gz = b_.gravity + a.z(), ah = std::hypot(a.x(), a.y());
    if (gs.reset == RimReset::kUnmodelled) {
      const bool flight = gs.event == RimEventKind::kLiftOff;
      event(gs.event, t_, flight ? gz / b_.gravity : ah / gz);
      return finish(RimStatus::kUnmodelled,
                    flight ? "the floor's downward acceleration reached g (a_z = " +
                                 format_number(a.z()) +
                                 " m/s^2): the body leaves the floor; flight is not modelled by "
                                 "the 3D engine"
                           : "full sliding: the friction demand |a_h|/(g + a_z) = " +
                                 format_number(ah / gz) +
                                 " reached mu = " + format_number(o_.friction_coefficient) +
                                 "; sliding is not modelled by the 3D engine"),
             false;
    }
    // uplift: tilt toward -a_h
    const Vector3 c = ah > 0.0 ? Vector3(-a.x() / ah, -a.y() / ah, 0.0) : c_step_;
    enter_rolling(t_, c);
    ++res_.uplifts;
    event(RimEventKind::kUplift, t_, ah / gz);
    return true;
  }
}

void Loop::enter_rolling(double t, const Vector3& c) {
  const Eigen::Quaterniond q = upright(rim_state(x_).orientation.normalized());
  x_(0) = q.w(), x_(1) = q.x(), x_(2) = q.y(), x_(3) = q.z();
  c_step_ = c;
  pivot_body_ = q.conjugate() * c;
  mode_ = RimMode::kPivoting;
  tilt_ = 0.0;
  (void)t;
}

RimResult Loop::end_unmodelled(RimEventKind kind, const RimRates& r) {
  const bool flight = kind == RimEventKind::kLiftOff;
  const double fh = std::hypot(r.force.x(), r.force.y());
  event(kind, t_, flight ? r.force.z() / mg_ : fh / r.force.z());
  return finish(
      RimStatus::kUnmodelled,
      flight
          ? "the normal force on the rim point reached zero (F_z/Mg = " +
                format_number(r.force.z() / mg_) + " at tilt " + format_number(r.tilt) +
                " rad): flight is not modelled by the 3D engine"
          : "rim slip: the friction demand |F_h|/F_z = " + format_number(fh / r.force.z()) +
                " reached mu = " + format_number(o_.friction_coefficient) + " at tilt " +
                format_number(r.tilt) + " rad; slip on the rim is not modelled by the 3D engine");
}

// The largest tilt of the step, located: a golden-section search on the dense output about each
// sampled local maximum up to where the step ends (an event's time). The largest sample lags the
// peak by O(h^2) (5e-5 relative at max_step 0.01 s) and would make max_tilt depend on the step.
void Loop::refine_peaks(const detail::GuardSample* smp, const double* tl, int ns) {
  const double t_hi = stepper_.t1();
  constexpr double kInvPhi = 0.6180339887498949;  // (sqrt(5) - 1) / 2
  for (int k = 0; k <= ns; ++k) {
    const bool peak = (k == 0 || tl[k] > tl[k - 1]) && (k == ns || tl[k] >= tl[k + 1]);
    double a = smp[std::max(k - 1, 0)].t, b = std::min(smp[std::min(k + 1, ns)].t, t_hi);
    if (!peak || a >= b) continue;
    // a smooth peak exceeds its largest sample by at most a quarter of the tilt's fall to the
    // samples two either side (a parabola through them): skip those that cannot reach max_tilt
    double fall = 0.0;
    for (int j = std::max(k - 2, 0); j <= std::min(k + 2, ns); ++j)
      fall = std::max(fall, tl[k] - tl[j]);
    if (tl[k] + fall < res_.max_tilt) continue;
    State x;
    auto tilt_at = [&](double t) {
      stepper_.dense(t, x);
      return rates(t, x).tilt;
    };
    double c = b - kInvPhi * (b - a), d = a + kInvPhi * (b - a);
    double fc = tilt_at(c), fd = tilt_at(d);
    for (int it = 0; it < 60 && d - c > 1e-15 * std::max(1.0, std::abs(d)); ++it) {
      if (fc >= fd) {
        b = d, d = c, fd = fc;
        c = b - kInvPhi * (b - a), fc = tilt_at(c);
      } else {
        a = c, c = d, fc = fd;
        d = a + kInvPhi * (b - a), fd = tilt_at(d);
      }
    }
    const double tm = fc >= fd ? c : d;
    stepper_.dense(tm, x);
    const RimRates r = rates(tm, x);
    if (r.tilt > res_.max_tilt) {
      res_.max_tilt = r.tilt;
      res_.max_tilt_azimuth = std::atan2(r.contact_dir.y(), r.contact_dir.x());
    }
  }
}

bool Loop::run_rolling() {
  std::array<detail::GuardSample, detail::kMaxSamples + 1> smp{};
  std::array<double, detail::kMaxSamples + 1> tl{};  // the tilt at the samples
  auto sys = [this](double t, const State& x, State& dx) { rhs(t, x, dx); };
  // a mode the engine does not model may be needed at once (the floor pulling, friction short)
  {
    const RimRates r0 = rates(t_, x_);
    if (rolling_guard(RimGuard::kNormalForce, x_, r0) <= 0.0)
      return end_unmodelled(RimEventKind::kLiftOff, r0), false;
    if (rolling_guard(RimGuard::kRimFriction, x_, r0) <= 0.0)
      return end_unmodelled(RimEventKind::kRimSlip, r0), false;
  }
  stepper_.start(sys, ctl_, t_, x_);
  bool upright_start = tilt_ == 0.0;
  for (;;) {
    const RimModeSpec& ms = spec(mode_);
    if (t_ >= t_end_) return true;
    if (res_.steps >= o_.max_steps) {
      event(RimEventKind::kStopped, t_, 0.0);
      return finish(RimStatus::kStopped,
                    "step limit (" + std::to_string(o_.max_steps) + ") reached"),
             false;
    }
    const double t_stop = std::min(next_break(t_), t_end_);
    if (stepper_.step(sys, t_stop) != Dopri5<State>::Status::kAccepted) {
      event(RimEventKind::kStopped, t_, 0.0);
      return finish(RimStatus::kStopped, "the step size collapsed at t = " + format_number(t_) +
                                             " s (tilt " + format_number(tilt_) + " rad)"),
             false;
    }
    ++res_.steps;
    const double t0 = stepper_.t0(), t1 = stepper_.t1();
    const int ns = std::clamp(o_.event_samples, 1, detail::kMaxSamples);
    for (int i = 0; i <= ns; ++i) {
      const double ti = i == ns ? t1 : t0 + (t1 - t0) * i / ns;
      State xi;
      if (i == 0) {
        xi = stepper_.x0();
      } else if (i == ns) {
        xi = stepper_.x1();
      } else {
        stepper_.dense(ti, xi);
      }
      const RimRates r = rates(ti, xi);
      detail::GuardSample& g = smp[static_cast<std::size_t>(i)];
      g.t = ti;
      for (int s = 0; s < ms.count; ++s)
        g.v[static_cast<std::size_t>(s)] =
            rolling_guard(ms.guards[static_cast<std::size_t>(s)], xi, r);
      // a local minimum of the tilt on the samples: a pass by upright (rolled round it); the
      // departure from upright (uplift, landing) starts afresh
      if (i == 0 && upright_start) tilt_prev_ = tilt_prev2_ = 0.0;
      if (i > 0) {  // sample 0 is the last step's last
        if (tilt_prev_ < tilt_prev2_ && r.tilt >= tilt_prev_)
          res_.closest_pass = std::min(res_.closest_pass, tilt_prev_);
        tilt_prev2_ = tilt_prev_;
        tilt_prev_ = r.tilt;
      }
      tl[static_cast<std::size_t>(i)] = r.tilt;
      if (r.tilt > res_.max_tilt) {
        res_.max_tilt = r.tilt;
        res_.max_tilt_azimuth = std::atan2(r.contact_dir.y(), r.contact_dir.x());
      }
      res_.min_normal_force = std::min(res_.min_normal_force, r.force.z());
      if (r.force.z() > 0.0)
        res_.max_friction_demand =
            std::max(res_.max_friction_demand, std::hypot(r.force.x(), r.force.y()) / r.force.z());
      const double bx = xi(7) - b_.height * r.axis.x(), by = xi(8) - b_.height * r.axis.y();
      res_.max_offset = std::max(res_.max_offset, std::hypot(bx, by));
    }
    double t_ev = std::numeric_limits<double>::infinity();
    int slot_ev = -1;
    for (int s = 0; s < ms.count; ++s) {
      const bool zero_start = s == 0 && upright_start;
      const double te = detail::first_crossing(s, smp.data(), ns, zero_start, s != 0, *this);
      if (te < t_ev) t_ev = te, slot_ev = s;
    }
    upright_start = false;
    if (slot_ev >= 0 && t_ev < t1) stepper_.restep_to(sys, t_ev);
    refine_peaks(smp.data(), tl.data(), ns);
    outputs_until(stepper_.t1(), stepper_.t1() >= t_end_ && slot_ev < 0);
    t_ = stepper_.t1();
    x_ = stepper_.x1();
    const RimRates r = rates(t_, x_);
    tilt_ = r.tilt;
    if (slot_ev < 0 && mode_ == RimMode::kRolling && r.sin_tilt <= o_.pivot_zone) {
      // a step that ends within the zone (no guard saw it: the step ended on the V of |k_h|)
      // enters it now, or lands if the tilt vector has passed through upright
      const bool passed = r.axis.x() * c_step_.x() + r.axis.y() * c_step_.y() <= 0.0;
      slot_ev = passed ? 1 : 0;  // kUpright, kNearUpright (the rolling mode's slots)
    }
    if (slot_ev < 0) {
      if (mode_ == RimMode::kRolling && r.sin_tilt > 0.0) c_step_ = r.contact_dir;
      continue;
    }
    const RimGuardSpec& gs = spec(ms.guards[static_cast<std::size_t>(slot_ev)]);
    switch (gs.reset) {
      case RimReset::kOverturn:
        event(RimEventKind::kOverturn, t_, r.tilt);
        return finish(RimStatus::kOverturned, ""), false;
      case RimReset::kUnmodelled:
        return end_unmodelled(gs.event, r), false;
      case RimReset::kUplift:
        break;
      case RimReset::kPivot: {
        // pivot on the material rim point now in contact
        const Eigen::Quaterniond q = rim_state(x_).orientation.normalized();
        const Vector3 u(r.axis.z() * r.contact_dir.x(), r.axis.z() * r.contact_dir.y(),
                        -r.sin_tilt);
        pivot_body_ = q.conjugate() * u;
        c_step_ = r.contact_dir;
        mode_ = RimMode::kPivoting;
        stepper_.start(sys, ctl_, t_, x_, stepper_.suggested_step());
        continue;
      }
      case RimReset::kRoll:
        c_step_ = r.contact_dir;
        mode_ = RimMode::kRolling;
        stepper_.start(sys, ctl_, t_, x_, stepper_.suggested_step());
        continue;
      case RimReset::kLanding: {
        if (r.sin_tilt > o_.pivot_zone) {
          // rolling: the tilt vector went round upright, outside the zone; a new direction
          res_.closest_pass = std::min(res_.closest_pass, r.tilt);
          c_step_ = r.contact_dir;
          stepper_.start(sys, ctl_, t_, x_, stepper_.suggested_step());
          continue;
        }
        const RimState s = rim_state(x_);
        const RimLanding land = rim_landing(b_, r.axis, c_step_, s.omega);
        double kin = 0.0, pot = 0.0;
        energies(x_, r, kin, pot);
        const bool chatter = t_ - last_landing_ < chatter_dt_;
        last_landing_ = t_;
        ++res_.landings;
        const Eigen::Quaterniond q = upright(s.orientation.normalized());
        x_(0) = q.w(), x_(1) = q.x(), x_(2) = q.y(), x_(3) = q.z();
        if (!land.lifts || chatter) {
          impact_loss_ += kin;
          x_.segment<3>(4).setZero();
          event(RimEventKind::kRest, t_, chatter ? 1.0 : 0.0, kin);
          res_.events.back().rate_before = s.omega.norm();
          mode_ = RimMode::kFullContact;
          tilt_ = 0.0;
          return true;
        }
        impact_loss_ += land.energy_loss;
        x_.segment<3>(4) = land.omega_after;
        c_step_ = -c_step_;
        pivot_body_ = q.conjugate() * c_step_;
        tilt_ = 0.0;
        event(RimEventKind::kLanding, t_, land.omega_after.norm() / s.omega.norm(),
              land.energy_loss);
        res_.events.back().rate_before = s.omega.norm();
        res_.events.back().rate_after = land.omega_after.norm();
        stepper_.start(sys, ctl_, t_, x_, stepper_.suggested_step());
        upright_start = true;
        continue;
      }
    }
  }
}

RimResult Loop::finish(RimStatus s, std::string msg) {
  res_.status = s;
  res_.message = std::move(msg);
  res_.t_end = t_;
  res_.final_mode = mode_;
  res_.final_tilt = tilt_;
  const RimRates r = rates(t_, x_);
  double kin = 0.0, pot = 0.0;
  energies(x_, r, kin, pot);
  if (mode_ == RimMode::kFullContact) kin = 0.0, pot = mg_ * b_.height;
  EnergyBalance& e = res_.energy;
  e.input_work = x_(9);
  e.kinetic_change = kin - kin0_;
  e.potential_change = pot - pot0_;
  e.impact_loss = impact_loss_;
  e.residual = e.input_work - (e.kinetic_change + e.potential_change + e.impact_loss);
  e.scale = std::max({std::abs(e.input_work), kin0_ + pot0_, kin + pot, impact_loss_});
  res_.rhs_evaluations = stepper_.rhs_evaluations();
  return res_;
}

}  // namespace

RimOptions rim_options(const SimulationOptions& options) {
  RimOptions o;
  o.t_end = options.t_end;
  o.rtol = options.rtol;
  o.atol = options.atol;
  o.max_step = options.max_step;
  o.event_samples = options.event_samples;
  o.output_dt = options.output_dt;
  o.overturn = options.overturn;
  o.chatter_ratio = options.chatter_ratio;
  o.friction_coefficient = options.friction_coefficient;
  o.max_steps = options.max_steps;
  return o;
}

RimResult simulate_axisymmetric(const AxisymmetricBody& body, const FloorMotion& motion,
                                const RimInitialState& initial, const RimOptions& options) {
  validate(body);
  FLEXROCK_THROW_UNLESS(motion.h1 != nullptr, "3D run: the floor motion needs its H1 component");
  FLEXROCK_THROW_UNLESS(options.rtol > 0.0 && options.atol > 0.0 && options.max_step > 0.0,
                        "3D run: rtol, atol and max_step must be > 0");
  FLEXROCK_THROW_UNLESS(options.event_samples >= 1 && options.event_samples <= detail::kMaxSamples,
                        "3D run: event_samples must be an integer in [1, " +
                            std::to_string(detail::kMaxSamples) +
                            "] (points a step where the guards are checked), got " +
                            std::to_string(options.event_samples));
  FLEXROCK_THROW_UNLESS(
      options.pivot_zone > 0.0 && options.pivot_zone < 1e-2,
      "3D run: pivot_zone must be in (0, 0.01) rad, got " + format_number(options.pivot_zone));
  FLEXROCK_THROW_UNLESS(options.friction_coefficient > 0.0,
                        "3D run: the friction coefficient must be > 0, got " +
                            format_number(options.friction_coefficient));
  Loop loop(body, motion, options);
  return loop.run(initial);
}

}  // namespace flexrock
