// SPDX-License-Identifier: BSD-3-Clause
// The accepted ranges of the solver options that have no natural upper (or lower) limit, one
// table for the case and study readers (io), the engine's own check of the options (Python, the
// sampled values of an uncertainty study) and docs/case-file.md. Each range is wide enough for
// every contact a free-standing body of the lab or the field has, and narrow enough that the
// run's arithmetic stays far from overflow (a value past it used to end in a misattributed
// "overflow" of the results).
#pragma once

#include <cmath>
#include <string>
#include <string_view>

#include "flexrock/core/format.hpp"
#include "flexrock/excitation/pulses.hpp"

namespace flexrock {

struct OptionBound {
  const char* key;   // the [solver] key, as Python's keyword
  double lo, hi;     // accepted closed range [lo, hi]
  const char* unit;  // of lo and hi
  const char* why;   // what the ends stand for
};

// restitution_factor: above 1 an impact adds energy (reported as impact_gained_energy); 2 would
// quadruple the rocking energy at every impact, which no calibration of a contact asks for
inline constexpr OptionBound kRestitutionFactorBound{
    "restitution_factor", 0.0, 2.0, "-",
    "above 1 an impact adds energy; 2 quadruples it at every impact"};
// contact_stiffness, as the force of one tipping point pressed 1 mm into the floor, k (1 mm)^p:
// 1 N (a soft foam under a small specimen) to 1e12 N (far stiffer than steel on steel, about
// 1e8 N for a metre-wide Hertzian contact). For p = 1: k in [1e3, 1e15] N/m
inline constexpr OptionBound kContactForceAt1mmBound{
    "contact_stiffness", 1.0, 1e12, "N",
    "the force of a tipping point pressed 1 mm into the floor, from a soft foam to far stiffer "
    "than steel on steel"};
// contact_damping_ratio: about 4 already makes a landing corner plastic (the limit of the
// impulsive laws); 100 is 25 times that
inline constexpr OptionBound kContactDampingRatioBound{
    "contact_damping_ratio", 0.0, 100.0, "-",
    "about 4 already makes a landing corner plastic; 100 is 25 times that"};
// impact_duration: contacts of bodies of this scale last from tens of microseconds (steel on
// steel) to tenths of a second (rubber pads)
inline constexpr OptionBound kImpactDurationBound{
    "impact_duration", 1e-6, 1.0, "s",
    "contacts last from tens of microseconds (steel on steel) to tenths of a second (rubber)"};
// event_samples: the engine's buffers hold 32 points a step (a step is refined by location,
// never by more samples, so more would buy nothing)
inline constexpr OptionBound kEventSamplesBound{"event_samples", 1.0, 32.0, "-",
                                                "points a step where the guards are checked"};
// a synthetic pulse's period (or 1/frequency_hz): no ground or shake-table motion is faster than
// 10 kHz, and one slower than 1e-4 Hz (a period of 2.8 hours) is a static tilt
inline constexpr OptionBound kPulsePeriodBound{
    "period", kMinPulsePeriod, kMaxPulsePeriod, "s",
    "no ground or shake-table motion is faster than 10 kHz; a period of hours is a static tilt"};

/// "[lo, hi] unit"
inline std::string range_text(const OptionBound& b) {
  // appended, not "[" + ...: GCC 12 warns (-Wrestrict) on a literal plus a temporary string
  std::string s(1, '[');
  s.append(format_number(b.lo, 6)).append(", ").append(format_number(b.hi, 6));
  s.append("]");
  return b.unit == std::string_view("-") ? s : s.append(" ").append(b.unit);
}

/// True when v lies in the range (NaN never does).
inline bool in_range(const OptionBound& b, double v) { return v >= b.lo && v <= b.hi; }

/// k (1 mm)^p: the force that kContactForceAt1mmBound bounds.
inline double contact_force_at_1mm(double stiffness, double exponent) {
  return stiffness * std::pow(1e-3, exponent);
}

/// The stiffness range for exponent p, with what it stands for: "[lo, hi] N/m^p (...)".
inline std::string stiffness_range_text(double exponent) {
  const OptionBound& b = kContactForceAt1mmBound;
  const double scale = std::pow(1e-3, exponent);
  std::string s(1, '[');
  s.append(format_number(b.lo / scale, 6)).append(", ").append(format_number(b.hi / scale, 6));
  s.append(exponent == 1.0 ? "] N/m" : "] N/m^")
      .append(exponent == 1.0 ? "" : format_number(exponent));
  s.append(" (k (1 mm)^p, the force of a tipping point pressed 1 mm into the floor, in [");
  return s.append(format_number(b.lo, 6))
      .append(", ")
      .append(format_number(b.hi, 6))
      .append("] N)");
}

}  // namespace flexrock
