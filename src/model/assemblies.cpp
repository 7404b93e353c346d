// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/model/assemblies.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "flexrock/core/error.hpp"
#include "flexrock/core/format.hpp"

namespace flexrock {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

void require(bool ok, const char* where, const char* name, double v, const char* rule) {
  FLEXROCK_THROW_UNLESS(
      ok, std::string(where) + ": " + name + " must be " + rule + ", got " + format_number(v, 6));
}

void check_frame(const RockingFrame& f) {
  constexpr const char* kWhere = "rocking_frame";
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  require(positive(f.column_width), kWhere, "column_width [m]", f.column_width, "> 0 and finite");
  require(positive(f.column_height), kWhere, "column_height [m]", f.column_height,
          "> 0 and finite");
  require(positive(f.column_mass), kWhere, "column_mass [kg]", f.column_mass, "> 0 and finite");
  require(f.count >= 2, kWhere, "count", f.count,
          "an integer >= 2 (one column under a beam is not a frame; use rigid_block)");
  require(std::isfinite(f.beam_mass) && f.beam_mass >= 0.0, kWhere, "beam_mass [kg]", f.beam_mass,
          ">= 0 and finite");
  require(positive(f.gravity), kWhere, "gravity [m/s^2]", f.gravity, "> 0 and finite");
}

}  // namespace

FrameConstants frame_constants(const RockingFrame& f) {
  check_frame(f);
  FrameConstants c;
  const double b = 0.5 * f.column_width, h = 0.5 * f.column_height;
  const double n_m = f.count * f.column_mass;
  const double gam = f.beam_mass / n_m;
  const double R = std::hypot(b, h);
  const double cos2a = (h - b) * (h + b) / (R * R);
  c.gamma = gam;
  c.alpha = std::atan2(b, h);
  c.column_p = std::sqrt(0.75 * f.gravity / R);
  c.p = c.column_p * std::sqrt((1.0 + 2.0 * gam) / (1.0 + 3.0 * gam));
  c.column_r = (1.0 + 3.0 * cos2a) / 4.0;
  c.r = (1.0 + 3.0 * (1.0 + 4.0 * gam) * cos2a) / (4.0 * (1.0 + 3.0 * gam));
  // the equivalent body (docs/theory.md §25): written so that gamma = 0 gives rigid_block's
  // numbers bit for bit
  const double stretch = (1.0 + 4.0 * gam) / (1.0 + 2.0 * gam);
  c.height_eq = h * stretch;
  c.zeta2_eq = (f.column_width * f.column_width + f.column_height * f.column_height) /
               (12.0 * h * h) / (1.0 + 4.0 * gam);
  c.mass_eq = n_m * ((1.0 + 2.0 * gam) / stretch);
  c.mass_total = n_m + f.beam_mass;
  c.reaction_mass = n_m * gam / (1.0 + 4.0 * gam);
  return c;
}

BodyParameters frame_equivalent_body(const RockingFrame& f) {
  const FrameConstants c = frame_constants(f);
  const double b_eq = 0.5 * f.column_width * ((1.0 + 4.0 * c.gamma) / (1.0 + 2.0 * c.gamma));
  BodyParameters p = BodyParameters::rigid(c.mass_eq, c.height_eq, b_eq, b_eq, c.zeta2_eq);
  p.gravity = f.gravity;
  return p;
}

const char* to_string(StackPattern p) {
  switch (p) {
    case StackPattern::kRest:
      return "rest";
    case StackPattern::kTopAlone:
      return "top_alone";
    case StackPattern::kAsOne:
      return "as_one";
    case StackPattern::kSeparately:
      return "separately";
    case StackPattern::kSeparatelyOpposite:
      return "separately_opposite";
  }
  return "?";
}

std::array<StackBand, 5> stack_uplift_bands(const BlockStack& s) {
  constexpr const char* kWhere = "block stack";
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  require(positive(s.bottom_width), kWhere, "bottom width [m]", s.bottom_width, "> 0");
  require(positive(s.bottom_height), kWhere, "bottom height [m]", s.bottom_height, "> 0");
  require(positive(s.bottom_mass), kWhere, "bottom mass [kg]", s.bottom_mass, "> 0");
  require(positive(s.top_width) && s.top_width <= s.bottom_width, kWhere, "top width [m]",
          s.top_width, "> 0 and at most the bottom's width (the top stands on the bottom)");
  require(positive(s.top_height), kWhere, "top height [m]", s.top_height, "> 0");
  require(positive(s.top_mass), kWhere, "top mass [kg]", s.top_mass, "> 0");
  const double b1 = 0.5 * s.bottom_width, h1 = 0.5 * s.bottom_height, m1 = s.bottom_mass;
  const double b2 = 0.5 * s.top_width, h2 = 0.5 * s.top_height, m2 = s.top_mass;
  // the bottom rocking on its corner away from the acceleration (theta_1), the top on its own
  // such corner (theta_2) or on the other one (theta_2', opening the other way): the mass
  // matrices at rest and the gradients of the potential (gravity and the uniform inertial load
  // lambda g) over g, grad V = c - lambda d; the bottom's row is the same for both
  const double m11 = 4.0 * m1 * (b1 * b1 + h1 * h1) / 3.0 +
                     m2 * (b1 * b1 + (2.0 * h1 + h2) * (2.0 * h1 + h2)) +
                     m2 * (b2 * b2 + h2 * h2) / 3.0;
  const double m22 = 4.0 * m2 * (b2 * b2 + h2 * h2) / 3.0;
  const double m12 = m2 * (3.0 * b1 * b2 + b2 * b2 + 6.0 * h1 * h2 + 4.0 * h2 * h2) / 3.0;
  const double m12r = m2 * (3.0 * b1 * b2 - b2 * b2 - 6.0 * h1 * h2 - 4.0 * h2 * h2) / 3.0;
  const double c1 = b1 * (m1 + m2), c2 = b2 * m2;
  const double d1 = h1 * m1 + 2.0 * h1 * m2 + h2 * m2, d2 = h2 * m2, d2r = -h2 * m2;
  // linear functions of lambda, a0 + a1 lambda: f1, f2 the multipliers at rest of the floor and
  // of the interface; F1 = m22 f1 - m12 f2 (m22 times the floor's multiplier while the top alone
  // rocks, and minus det M times the bottom's acceleration when both rock separately);
  // F2 = m11 f2 - m12 f1 likewise for the interface; G1, G2 the same with the top on its other
  // corner (f2' = c2 - lambda d2r)
  struct Lin {
    double a0, a1;
  };
  const Lin f1{c1, -d1}, f2{c2, -d2};
  const Lin F1{m22 * c1 - m12 * c2, -(m22 * d1 - m12 * d2)};
  const Lin F2{m11 * c2 - m12 * c1, -(m11 * d2 - m12 * d1)};
  const Lin G1{m22 * c1 - m12r * c2, -(m22 * d1 - m12r * d2r)};
  const Lin G2{m11 * c2 - m12r * c1, -(m11 * d2r - m12r * d1)};
  struct Iv {
    double lo, hi;
  };
  // where l >= 0 (nonneg) or l < 0
  auto where = [](const Lin& l, bool nonneg) -> Iv {
    if (l.a1 == 0.0) return (l.a0 >= 0.0) == nonneg ? Iv{-kInf, kInf} : Iv{kInf, kInf};
    const double root = -l.a0 / l.a1;
    return (l.a1 < 0.0) == nonneg ? Iv{-kInf, root} : Iv{root, kInf};
  };
  auto meet = [](Iv a, Iv b) -> Iv {
    const double lo = std::max({a.lo, b.lo, 0.0}), hi = std::min(a.hi, b.hi);
    return lo < hi ? Iv{lo, hi} : Iv{kInf, kInf};
  };
  // rest: both multipliers >= 0; the top alone: it opens, the floor holds; as one: the bottom
  // opens, both corners of the interface press; separately: both open (on either top corner)
  const Iv rest = meet(where(f1, true), where(f2, true));
  const Iv top = meet(where(f2, false), where(F1, true));
  const Iv one = meet(meet(where(f1, false), where(F2, true)), where(G2, true));
  const Iv both = meet(where(F1, false), where(F2, false));
  const Iv opposite = meet(where(G1, false), where(G2, false));
  return {StackBand{StackPattern::kRest, rest.lo, rest.hi},
          StackBand{StackPattern::kTopAlone, top.lo, top.hi},
          StackBand{StackPattern::kAsOne, one.lo, one.hi},
          StackBand{StackPattern::kSeparately, both.lo, both.hi},
          StackBand{StackPattern::kSeparatelyOpposite, opposite.lo, opposite.hi}};
}

StackPattern stack_pattern(const BlockStack& stack, double lambda) {
  FLEXROCK_THROW_UNLESS(
      std::isfinite(lambda) && lambda >= 0.0,
      "stack_pattern: lambda = a/g must be >= 0 and finite, got " + format_number(lambda, 6));
  for (const StackBand& b : stack_uplift_bands(stack)) {
    if (b.lo <= lambda && lambda < b.hi) return b.pattern;
  }
  return StackPattern::kRest;  // not reached: the bands partition lambda >= 0
}

StackUplift stack_first_uplift(const BlockStack& stack) {
  const std::array<StackBand, 5> bands = stack_uplift_bands(stack);
  StackUplift u;
  u.lambda = bands[0].hi;
  u.pattern = stack_pattern(stack, u.lambda);
  return u;
}

}  // namespace flexrock
