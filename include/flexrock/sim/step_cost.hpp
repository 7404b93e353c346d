// SPDX-License-Identifier: BSD-3-Clause
// What the explicit integrator will cost a body, known before any run: the stiffest motion while
// rocking against the explicit method's (DOP853's, or Dopri5's) stability bound and error
// constant. A slender body with a stiff
// mode rocks with a coupled frequency far above its pinned-base ones, and an explicit method
// must resolve it on every step (docs/theory.md, "Stiff rocking").
#pragma once

#include <string>

#include "flexrock/integrate/stiff_switching.hpp"  // ExplicitMethod
#include "flexrock/model/body.hpp"
#include "flexrock/sim/simulate.hpp"

namespace flexrock {

/// |h omega| up to which Dopri5 is stable on an undamped oscillation (its stability region meets
/// the imaginary axis at 0.997; on the negative real axis it reaches 3.3).
inline constexpr double kDopri5ImaginaryStability = 0.997;
/// Dopri5's error estimate on y' = i omega y is |97/120000 (h omega)^5| |y| to leading order
/// (the difference of its 5th- and 4th-order stability polynomials): the step control keeps it
/// near rtol |y|, so h omega ~ (rtol / kDopri5ErrorConstant)^(1/5) (0.066 at rtol = 1e-9).
inline constexpr double kDopri5ErrorConstant = 97.0 / 120000.0;
/// |h omega| up to which DOP853 is stable on an undamped oscillation (dop853_stable_step({0, 1})).
inline constexpr double kDop853ImaginaryStability = 5.96;
/// DOP853's error norm on y' = i omega y: its 5th-order estimate is a (h omega)^6 and its 3rd-order
/// one b (h omega)^4 to leading order (a = -1.350e-5, b = 4.202e-3 from its table), and Hairer's
/// norm e5^2 / sqrt(e5^2 + 0.01 e3^2) is then 10 a^2 / b (h omega)^8: h omega ~ (rtol /
/// kDop853ErrorConstant)^(1/8) (0.47 at rtol = 1e-9). tests/unit/step_cost_test.cpp forms a and b
/// from the table.
inline constexpr double kDop853ErrorConstant = 4.337e-7;

/// Estimated step cost of the explicit integrator for a body.
struct StepCost {
  // the rocking's explicit method (SimulationMethods::high_order_rocking)
  ExplicitMethod method = ExplicitMethod::kDop853;
  double rocking_time_scale = 0.0;  // [s] 1/p, p the rocking frequency
  // [rad/s] largest |eigenvalue| of the rocking equations linearized at theta = 0 (at rest, the
  // static deformation), over both edges: the stiffest motion while rocking
  double rocking_omega = 0.0;
  double full_contact_omega = 0.0;  // [rad/s] largest pinned-base omega (0: rigid body)
  double h_omega = 0.0;             // [-] h omega the step control settles at (rtol)
  // steps per simulated second while rocking: at least (stability), about (accuracy at rtol,
  // and no fewer than 1/max_step)
  double rocking_min_steps_per_second = 0.0;
  double rocking_steps_per_second = 0.0;
  // the compliant contact (contact_model = compliant, integrated by DOPRI5 or switching; zero
  // otherwise): the equations of the body on its corners' springs and dashpots, linearized at rest
  // on both corners and on one (docs/theory.md, "Compliant contact: step cost")
  double contact_omega = 0.0;  // [rad/s] their largest |eigenvalue|
  // [rad/s] the largest |eigenvalue| of a motion damped below 1/sqrt(2), which a base motion
  // drives to resonance (0: none)
  double contact_resonant_omega = 0.0;
  double contact_h_omega = 0.0;  // [-] DOPRI5's h omega at rtol
  // steps per simulated second: DOPRI5's stability on every eigenvalue; at least (the larger of
  // that, accuracy on the resonant motions and 1/max_step)
  double contact_stable_steps_per_second = 0.0;
  double contact_steps_per_second = 0.0;
};

/// The step cost of `body` at `options` (rtol, max_step, methods.high_order_rocking; for the
/// compliant contact its constants and integrator); cheap: one eigenproblem per edge (and two for
/// the compliant contact).
StepCost estimate_step_cost(const Body& body, const SimulationOptions& options = {});

/// The explicit method's stability bound [s] while `body` rocks on `edge` (1 or 2): the longest
/// step with h lambda in its stability region for every eigenvalue lambda of the rocking equations
/// linearized at theta = 0 (at rest, the static deformation, no base motion); dopri5_stable_step
/// (or dop853_stable_step) of each. The structure's stiffness and damping set the fast eigenvalues,
/// and the tilt and the deformation change them only through gravity and geometry, by O(g/h) and
/// O(q): the bound holds along the motion (docs/theory.md, "Stiff rocking").
double rocking_stable_step(const Body& body, int edge,
                           ExplicitMethod method = ExplicitMethod::kDopri5);

/// Steps per simulated second above which a run is called very slow (seconds of computing per
/// simulated second at ~1-10 us a step).
inline constexpr double kSlowStepsPerSecond = 1e6;

/// A warning, in words with figures, when a run of `duration` seconds that rocks throughout is
/// expected to exceed `max_steps` or to be very slow (kSlowStepsPerSecond); empty otherwise. For
/// the compliant contact the rate is its own (contact_steps_per_second), a floor: a run needs at
/// least that many steps, at rest or rocking.
std::string step_cost_warning(const StepCost& cost, double duration, long max_steps);

}  // namespace flexrock
