// SPDX-License-Identifier: BSD-3-Clause
// Base accelerations Xddot(t), Yddot(t): sampled records (piecewise linear) or analytic functions.
#pragma once

#include <cstddef>
#include <functional>
#include <limits>
#include <vector>

#include "flexrock/core/types.hpp"

namespace flexrock {

/// Horizontal and vertical base accelerations [m/s^2] (Xddot along I, from edge 1 to edge 2;
/// Yddot along J, up). Outside the record both are zero.
struct BaseAcceleration {
  double x = 0.0;  // Xddot [m/s^2]
  double y = 0.0;  // Yddot [m/s^2]
};

/// One sinusoidal piece of an analytic motion: amplitude sin(omega t + phase) [m/s^2] for
/// begin <= t < end along one component, zero elsewhere (omega = 0: the constant amplitude
/// sin(phase)). The pulses made of such pieces carry them, so that a rigid body's rocking is
/// stepped by its Taylor series with the motion expanded in closed form (docs/theory.md, "Rocking
/// of a rigid body by its Taylor series").
struct SinusoidPiece {
  double begin = 0.0, end = 0.0;  // [s]
  double amplitude = 0.0;         // [m/s^2]
  double omega = 0.0;             // [rad/s]
  double phase = 0.0;             // [rad]
  bool vertical = false;          // Yddot, else Xddot
};

/// A ground motion, in memory. Sampled records are linear between samples; their sample times
/// are breakpoints where the simulation ends a step, so kinks cost no accuracy.
class GroundMotion {
 public:
  using Function = std::function<BaseAcceleration(double t)>;

  /// Samples at strictly increasing times [s]; vertical is empty (zero) or of the same length.
  static GroundMotion sampled(std::vector<double> time, std::vector<double> horizontal,
                              std::vector<double> vertical = {});
  /// Samples every dt [s] from `start` [s].
  static GroundMotion uniform(double dt, std::vector<double> horizontal,
                              std::vector<double> vertical = {}, double start = 0.0);
  /// An analytic motion on [0, duration]; `breakpoints` are times of kinks or jumps (the ends of
  /// a pulse), where steps end. Zero outside [0, duration].
  static GroundMotion analytic(Function f, double duration, std::vector<double> breakpoints = {});
  /// No motion at all (free rocking), lasting `duration` [s].
  static GroundMotion none(double duration);

  /// This analytic motion described also as the sum of `pieces`, which must be what its function
  /// gives (the pulses' tests check it); their ends become breakpoints. Throws on a sampled motion
  /// or a piece that is not finite, ends before it begins or lies outside [0, duration].
  GroundMotion with_sinusoids(std::vector<SinusoidPiece> pieces) const;

  /// Walks forward through the samples so that a sequence of calls at increasing times costs O(1);
  /// any other call costs a binary search. One cursor per thread.
  struct Cursor {
    std::size_t index = 0;
    // the sample interval [t0, t1] of the last lookup and the record on it: Xddot = x0 + (t -
    // t0) sx inside, x1 at its end (Yddot alike). An integration step lies in one interval, so
    // its dozen calls cost two comparisons and two products each, not a search and two
    // divisions. At a sample the value is the sample's, whichever side the cursor saw last, so a
    // value depends on t alone.
    double t0 = std::numeric_limits<double>::infinity();
    double t1 = -std::numeric_limits<double>::infinity();
    double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0, sx = 0.0, sy = 0.0;
  };

  // inlined into every right-hand side and guard (the event loop's files are large enough that
  // GCC's unit-growth limit left it out of line: 2 % of a flexible body's run)
  [[gnu::always_inline]] BaseAcceleration at(double t, Cursor& cursor) const {
    if (cursor.t0 <= t && t <= cursor.t1) {
      if (t == cursor.t1) return {cursor.x1, cursor.y1};
      return {cursor.x0 + (t - cursor.t0) * cursor.sx, cursor.y0 + (t - cursor.t0) * cursor.sy};
    }
    return look_up(t, cursor);
  }
  BaseAcceleration at(double t) const {
    Cursor c;
    return at(t, c);
  }
  /// First breakpoint strictly after t, or +infinity.
  double next_breakpoint(double t, Cursor& cursor) const;
  /// End of the record (last sample, or the analytic duration) [s].
  double duration() const { return duration_; }
  /// The time after which the base acceleration is zero for good [s]: 0 for none(), the end of the
  /// last piece of a motion made of sinusoids (its function is their sum), else duration().
  double quiet_from() const;
  /// Sample count (0 for analytic motions).
  std::size_t samples() const { return time_.size(); }
  bool is_sampled() const { return !time_.empty(); }
  bool has_vertical() const { return has_vertical_; }
  /// Made by none(): zero throughout.
  bool is_none() const { return none_; }
  /// The sinusoidal pieces of an analytic motion that has them (scaled as the motion); empty
  /// otherwise.
  const std::vector<SinusoidPiece>& sinusoids() const { return sinusoids_; }
  bool is_sinusoidal() const { return !sinusoids_.empty(); }
  const std::vector<double>& times() const { return time_; }
  const std::vector<double>& horizontal() const { return ax_; }
  const std::vector<double>& vertical() const { return ay_; }

  /// The same motion with both components multiplied by `factor`.
  GroundMotion scaled(double factor) const;

 private:
  // at() outside the cursor's interval: finds t's interval (and keeps it in the cursor)
  BaseAcceleration look_up(double t, Cursor& cursor) const;

  std::vector<double> time_, ax_, ay_;    // sampled record
  Function f_;                            // analytic motion
  std::vector<double> breaks_;            // analytic breakpoints, sorted
  std::vector<SinusoidPiece> sinusoids_;  // the analytic motion as sinusoids, when it is so made
  double duration_ = 0.0;
  double scale_ = 1.0;  // analytic motions only; sampled ones are scaled in place
  bool has_vertical_ = false;
  bool uniform_ = false;
  double dt_ = 0.0, t0_ = 0.0;
  bool none_ = false;
};

}  // namespace flexrock
