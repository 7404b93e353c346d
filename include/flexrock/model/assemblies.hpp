// SPDX-License-Identifier: BSD-3-Clause
// Bodies that stand on something (docs/theory.md §25): a rocking frame, equal free-standing
// columns capped by a freely supported rigid beam, and a rigid block standing on another. Closed
// forms derived in tools/derive/assemblies.py. No files here.
#pragma once

#include <array>

#include "flexrock/model/body.hpp"

namespace flexrock {

/// A rocking frame: `count` equal uniform rigid columns capped by a rigid beam that rests on
/// their top corners and translates with them (it does not rotate: its c.g. stands above the
/// middle of the columns). All columns rock together about the same-side base corners and the
/// beam bears on the diagonally opposite top corners.
struct RockingFrame {
  double column_width = 0.0;          // [m] full width of a column's footprint, 2 b
  double column_height = 0.0;         // [m] full height of a column, 2 h
  double column_mass = 0.0;           // [kg] m, one column
  int count = 2;                      // N >= 2 columns
  double beam_mass = 0.0;             // [kg] m_b >= 0, the cap beam
  double gravity = kStandardGravity;  // g [m/s^2]
};

/// What a frame rocks like (docs/theory.md §25): the frame is its equivalent rigid body.
struct FrameConstants {
  double gamma = 0.0;          // m_b / (N m) [-], the beam-to-columns mass ratio
  double alpha = 0.0;          // [rad] slenderness atan(b/h) of a column, the frame's
  double p = 0.0;              // [rad/s] p = sqrt((1+2 gamma)/(1+3 gamma) 3 g / (4 R))
  double r = 0.0;              // [-] impact ratio theta_dot+/theta_dot- when all columns land:
                               // (1 + 3 (1+4 gamma) cos 2 alpha) / (4 (1+3 gamma))
  double column_p = 0.0;       // [rad/s] one column alone, sqrt(3 g / (4 R))
  double column_r = 0.0;       // [-] one column alone (Housner), 1 - 3/2 sin^2 alpha
  double height_eq = 0.0;      // [m] the equivalent body's c.g. height h (1+4 gamma)/(1+2 gamma)
  double zeta2_eq = 0.0;       // [-] its I_cg/(M h^2), (1 + b^2/h^2) / (3 (1+4 gamma))
  double mass_eq = 0.0;        // [kg] its mass N m (1+2 gamma)^2/(1+4 gamma): the frame's moment
                               // of inertia about the pivots and gravity moment
  double mass_total = 0.0;     // [kg] N m + m_b
  double reaction_mass = 0.0;  // [kg] N m gamma/(1+4 gamma): the frame's floor reaction is the
                               // equivalent body's plus this mass times (a_base + g)
};

/// The frame's constants; throws InputError naming the field for a bad frame.
FrameConstants frame_constants(const RockingFrame& frame);

/// The rigid body the engine runs for a frame: slenderness alpha, frequency parameter p and
/// (under the paper's or the rigid-body impact law) impact ratio r of the frame, and the frame's
/// moment of inertia about the pivots and gravity moment, so that its rocking, impacts and
/// energies are the frame's. With beam_mass = 0 it is rigid_block(column_width, column_height,
/// count * column_mass) exactly.
BodyParameters frame_equivalent_body(const RockingFrame& frame);

/// A uniform rigid block (the top) standing centred on the top face of another (the bottom),
/// which stands on the floor. The top's footprint must fit on the bottom's top face.
struct BlockStack {
  double bottom_width = 0.0, bottom_height = 0.0, bottom_mass = 0.0;  // [m], [m], [kg]
  double top_width = 0.0, top_height = 0.0, top_mass = 0.0;           // [m], [m], [kg]
};

/// How a stack starts to move from rest under a constant horizontal acceleration.
enum class StackPattern : int {
  kRest = 0,                // both contacts hold
  kTopAlone = 1,            // the top rocks on the bottom, the bottom holds
  kAsOne = 2,               // both rock as one on the floor, the interface holds
  kSeparately = 3,          // both rock separately, each on its corner away from the acceleration
  kSeparatelyOpposite = 4,  // both rock separately, the top thrown back onto its other corner by
                            // the bottom's rotation
};

const char* to_string(StackPattern p);

/// The band of lambda = a/g over which a pattern is the consistent one: [lo, hi) (lo = hi =
/// inf: never; hi = inf: for every larger lambda).
struct StackBand {
  StackPattern pattern = StackPattern::kRest;
  double lo = 0.0, hi = 0.0;
};

/// The five patterns' bands of lambda >= 0, in the enum's order (docs/theory.md §25): the unique
/// solution of the acceleration-level contact problem at rest, in closed form. They partition
/// lambda >= 0; an empty band has lo = hi = inf. Throws InputError for a bad stack.
std::array<StackBand, 5> stack_uplift_bands(const BlockStack& stack);

/// The consistent pattern at lambda = a/g >= 0 (at a band's boundary, the band it opens).
StackPattern stack_pattern(const BlockStack& stack, double lambda);

/// The first uplift: the smallest lambda past rest and the pattern that starts there.
struct StackUplift {
  double lambda = 0.0;  // [-] a/g
  StackPattern pattern = StackPattern::kTopAlone;
};
StackUplift stack_first_uplift(const BlockStack& stack);

}  // namespace flexrock
