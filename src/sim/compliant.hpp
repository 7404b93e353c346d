// SPDX-License-Identifier: BSD-3-Clause
// The compliant contact's event loop (docs/theory.md, "Compliant contact"). Internal header.
//
// The body moves freely in the plane (flight's coordinates: the deformed c.g., theta, q) and the
// floor acts through a no-tension spring-dashpot at each tipping point. Each tipping point is a
// small automaton of its own:
//
// | corner state | guard (function down to 0)        | reset                     | next      |
// |--------------|-----------------------------------|---------------------------|-----------|
// | free         | y_e / h (height over the floor)   | anchor xi_e = x_e         | stick *   |
// | stick        | -y_e / h (penetration)            | none                      | free      |
// |              | (mu_s F_n - |F_t|) / M g          | none                      | slip s    |
// | slip s       | -y_e / h                          | none                      | free      |
// |              | s x_e' / sqrt(g h)                | anchor xi_e = x_e         | stick     |
//
// (* slip at once when the sticking force already needs more than mu_s F_n.) Guards that cross at
// one instant (within the locator's resolution: a level body's two corners) fire together.
// Overturning, as in the impulsive model, is |theta| reaching the chosen angle. The body's contact
// mode in the outputs (full contact, rocking on an edge, flight, their sliding variants) is read
// from which corners press and which slip.
#pragma once

#include <Eigen/Core>

#include "flexrock/sim/simulate.hpp"

namespace flexrock::detail {

/// What the compliant contact's loss is made of, integrated apart from the energy balance (tests).
struct CompliantAudit {
  double dashpot_work = 0.0;      // [J] the dashpots' work (the floor's force less the contact
                                  // potential's gradient), normal and tangential
  double released_at_slip = 0.0;  // [J] tangential springs' energy let go where corners began to
                                  // slip (booked in friction_loss with the slips' work)
};

/// One run with the compliant contact; the options are already checked. `audit`, if given,
/// receives the dashpots' work.
SimulationResult simulate_compliant(const Body& body, const GroundMotion& motion,
                                    const InitialState& init, const SimulationOptions& opt,
                                    CompliantAudit* audit = nullptr);

/// The eigenvalues of the compliant contact's equations of motion (coordinates and rates: 2 (3 + n)
/// of them) linearized by differences at rest on both corners (`pivot` 0) or on one (1, 2), the
/// corners sticking, without base motion (docs/theory.md, "Compliant contact").
Eigen::VectorXcd compliant_rest_eigenvalues(const Body& body, const SimulationOptions& opt,
                                            int pivot, const InitialState& at = {});

/// The spring-dashpot constants of each tipping point for `body` under `opt`.
CornerContact corner_contact(const Body& body, const SimulationOptions& opt);

}  // namespace flexrock::detail
