// SPDX-License-Identifier: BSD-3-Clause
// A rocking frame's run (docs/theory.md §25): its equivalent rigid body on the engine, within
// the frame's model. No files here.
#pragma once

#include "flexrock/model/assemblies.hpp"
#include "flexrock/sim/simulate.hpp"

namespace flexrock {

/// [s] where a run asks for no time history, the spacing at which simulate_frame checks the
/// frame's contact forces (the history is dropped afterwards)
inline constexpr double kFrameCheckDt = 0.005;

/// Throws InputError for options the frame's model does not cover: a finite friction coefficient
/// (sliding of a frame, its columns on the floor or its beam on the columns, is not modelled) and
/// the compliant contact (its springs would act on the equivalent body's corners, not the
/// columns'). The message names the option and what would be right.
void validate_frame_options(const SimulationOptions& options);

/// Simulates `frame` as its equivalent rigid body (frame_equivalent_body): the tilt, the impacts
/// and the energies are the frame's. Flight is not modelled: the run ends, stopped, with the time
/// and the force in its message, where the equivalent body lifts off or lands pulling, or where
/// the frame's own floor reaction or the beam's contact force on the columns turns negative while
/// rocking: seen at the time-history samples (output_dt, else kFrameCheckDt) and located between
/// them by bisection. The reactions reported
/// (reaction_x/y, base shear, friction demand, pivot tension) are the equivalent body's; the
/// frame's are larger by reaction_mass (a_base + g), FrameConstants::reaction_mass.
SimulationResult simulate_frame(const RockingFrame& frame, const GroundMotion& motion,
                                const InitialState& initial = {},
                                const SimulationOptions& options = {});

}  // namespace flexrock
