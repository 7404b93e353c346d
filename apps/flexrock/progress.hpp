// SPDX-License-Identifier: BSD-3-Clause
// Progress bars of the command line: on a terminal only, after the first second, drawn on stderr
// with the share done, the rate and the time left. Nothing when stderr is not a terminal or with
// --quiet / --no-progress (the caller passes `enabled`).
#pragma once

#include <fmt/core.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace flexrock::cli {

class Progress {
 public:
  /// `total`: the simulated time of a run [s] (draw_time) or the number of runs (draw_count).
  Progress(bool enabled, double total) : enabled_(enabled), total_(total) {}

  /// One run: simulated seconds reached after `elapsed` wall seconds.
  void draw_time(double elapsed, double simulated) {
    if (!enabled_ || elapsed < 1.0 || total_ <= 0.0) return;
    const double frac = std::clamp(simulated / total_, 0.0, 1.0);
    const double rate = simulated / elapsed;  // simulated seconds per second
    const double eta = rate > 0.0 ? (total_ - simulated) / rate : 0.0;
    fmt::print(stderr, "\r[{}] {:5.1f}%  t = {:.2f} of {:.2f} s  {:.3g} s/s  {:.0f} s left\033[K",
               bar(frac), 100.0 * frac, simulated, total_, rate, eta);
    std::fflush(stderr);
    drawn_ = true;
  }

  /// A study: `done` runs finished of `total` after `elapsed` wall seconds.
  void draw_count(double elapsed, double done, const std::string& note = {}) {
    if (!enabled_ || elapsed < 1.0 || total_ <= 0.0) return;
    const double frac = std::clamp(done / total_, 0.0, 1.0);
    const double rate = done / elapsed;  // runs per second
    const double eta = rate > 0.0 ? (total_ - done) / rate : 0.0;
    fmt::print(stderr,
               "\r[{}] {:5.1f}%  {:.0f} of {:.0f} runs  {:.3g} runs/s  {:.0f} s left{}\033[K",
               bar(frac), 100.0 * frac, done, total_, rate, eta, note);
    std::fflush(stderr);
    drawn_ = true;
  }

  void clear() {
    if (drawn_) fmt::print(stderr, "\r\033[K");
    drawn_ = false;
  }

 private:
  static std::string bar(double frac) {
    constexpr int kWidth = 30;
    const auto filled = static_cast<std::size_t>(frac * kWidth);
    return std::string(filled, '#') + std::string(kWidth - filled, '.');
  }

  bool enabled_;
  double total_;
  bool drawn_ = false;
};

/// Progress of a study as plain lines on stdout, for a log (a batch job's output file) where no
/// bar can be drawn: one line at the start, one each time another tenth of the runs is done or
/// `every` seconds have passed, and one at the end, each flushed as it is written.
class ProgressLines {
 public:
  ProgressLines(bool enabled, double total, double every)
      : enabled_(enabled), total_(total), every_(every) {}

  void start(const std::string& note) {
    if (!enabled_) return;
    fmt::print("progress: 0 of {:.0f} runs{}\n", total_, note);
    std::fflush(stdout);
  }

  void update(double elapsed, double done) {
    if (!enabled_ || total_ <= 0.0) return;
    const int tenth = static_cast<int>(10.0 * std::clamp(done / total_, 0.0, 1.0));
    if (tenth <= tenth_ && elapsed - last_ < every_) return;
    if (done <= done_ && elapsed - last_ < every_) return;
    tenth_ = std::max(tenth, tenth_);
    last_ = elapsed;
    done_ = done;
    const double rate = done / std::max(elapsed, 1e-9);
    const double eta = rate > 0.0 ? (total_ - done) / rate : 0.0;
    fmt::print(
        "progress: {:.0f} of {:.0f} runs ({:.0f}%) after {:.0f} s, {:.3g} runs/s, {:.0f} s "
        "left\n",
        done, total_, 100.0 * done / total_, elapsed, rate, eta);
    std::fflush(stdout);
  }

  void end(double elapsed, double done) {
    if (!enabled_) return;
    fmt::print("progress: {:.0f} of {:.0f} runs done in {:.3g} s\n", done, total_, elapsed);
    std::fflush(stdout);
  }

 private:
  bool enabled_;
  double total_, every_;
  int tenth_ = 0;
  double last_ = 0.0, done_ = 0.0;
};

}  // namespace flexrock::cli
