// SPDX-License-Identifier: BSD-3-Clause
// Overturning spectra: the outcome of a body under a family of pulses over a grid of amplitude x
// frequency (or one record x scale factors), and the minimum overturning amplitude of every
// frequency, refined by bisection between grid points. No files here: io/ and the CLI read specs
// and write the CSV.
#pragma once

#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "flexrock/core/enum_names.hpp"
#include "flexrock/excitation/ground_motion.hpp"
#include "flexrock/model/body.hpp"
#include "flexrock/sim/simulate.hpp"
#include "flexrock/study/outcome.hpp"
#include "flexrock/study/parallel.hpp"

namespace flexrock::study {

/// The narrowest relative bracket a bisection may ask for: below it the bracket is finer than the
/// simulations resolve (their rtol is >= 1e-14) and soon than doubles can split (the midpoint of
/// adjacent doubles is one of them).
inline constexpr double kMinBisectionTolerance = 1e-12;

/// The units a physical grid is given in (amplitude_units, frequency_units): the grid, the cells'
/// `amplitude` and `frequency` and the bisection stay in them, and the cell and boundary tables
/// add columns in them beside the SI ones (a_p_g, f_p_hz, min_overturning_g) where they differ, so
/// that a file and its plot keep the units asked for.
struct GridUnits {
  std::string amplitude = "m/s^2";  // "m/s^2", "g" or "cm/s^2"
  double amplitude_si = 1.0;        // [m/s^2] one amplitude unit
  std::string frequency = "rad/s";  // "rad/s" or "Hz"
  double frequency_si = 1.0;        // [rad/s] one frequency unit

  bool amplitude_differs() const { return amplitude != "m/s^2"; }
  bool frequency_differs() const { return frequency != "rad/s"; }
  bool operator==(const GridUnits&) const = default;
};

/// A pulse spectrum: pulse type x amplitude x frequency.
struct SpectrumSpec {
  std::string pulse = "one_sine";  // a pulse type with a length (excitation/pulses.hpp table)
  bool normalized = true;  // true: amplitudes a_p/(g tan alpha1) [-], frequencies omega_p/p [-];
                           // false: amplitudes and frequencies in `units` (m/s^2, rad/s unless
                           // asked otherwise)
  std::vector<double> amplitudes;   // the grid rows, strictly increasing, > 0
  std::vector<double> frequencies;  // the grid columns, > 0
  GridUnits units;                  // physical axes: the grid's units (normalised: unused)
  double free_periods = 4.0;        // [-] free motion after the pulse, in rocking periods 2 pi / p
  bool bisect = true;               // refine the minimum overturning amplitude of every column
  double bisection_tolerance = 1e-3;  // [-] relative width of the final bracket, in
                                      // [kMinBisectionTolerance, 1)
  // tolerances etc. (overturning at pi/2); t_end and output_dt are set per run
  SimulationOptions solver = study_solver_defaults();
};

/// One record x scale factors: the same outcome classes and a minimum overturning scale.
struct RecordSpectrumSpec {
  GroundMotion motion;                // [m/s^2] the record at scale 1
  std::vector<double> scales;         // [-] strictly increasing, > 0
  double free_periods = 4.0;          // [-] free motion after the record, in 2 pi / p
  bool bisect = true;                 // refine the minimum overturning scale
  double bisection_tolerance = 1e-3;  // [-] as in SpectrumSpec
  // overturning at pi/2; t_end and output_dt are set per run
  SimulationOptions solver = study_solver_defaults();
};

/// One cell of the grid.
struct SpectrumCell {
  std::size_t row = 0;        // amplitude (or scale) index
  std::size_t column = 0;     // frequency index (0 for a record)
  double amplitude = 0.0;     // in the spec's units (normalised, its GridUnits, or the factor)
  double frequency = 0.0;     // in the spec's units (normalised or its GridUnits; record: 0)
  double amplitude_si = 0.0;  // [m/s^2] a_p (record: the scaled record's PGA)
  double omega_si = 0.0;      // [rad/s] omega_p (record: 0)
  bool computed = false;      // false: another process (rank) computed this cell
  RunSummary run;
  bool resumed = false;  // known before the call (SpectrumResume): only run.outcome is set
};

/// The minimum overturning amplitude of one frequency column.
struct OverturnBoundary {
  std::size_t column = 0;
  double frequency = 0.0;  // in the spec's units
  // where the first overturning cell of the column is (from the bottom), in the spec's units:
  //   found: bracket [safe, overturning] refined by bisection to the tolerance;
  //   below_grid: the lowest amplitude of the grid already overturns (min <= amplitudes[0]);
  //   none: no cell of the column overturns.
  enum class Kind { kFound, kBelowGrid, kNone } kind = Kind::kNone;
  double safe = 0.0;         // largest amplitude known not to overturn below `overturning`
  double overturning = 0.0;  // smallest amplitude found to overturn: the estimate of the minimum
  int bisection_runs = 0;    // extra simulations the bisection took
  bool computed = false;     // false: another process (rank) computed this column
  Outcome mode = Outcome::kNoUplift;  // outcome at `overturning` (which overturning mode)
  bool resumed = false;  // known before the call (SpectrumResume): not bisected, not set here
};

/// The names of the boundary kinds, as the boundary CSV writes them.
inline constexpr EnumName<OverturnBoundary::Kind> kBoundaryKindNames[] = {
    {OverturnBoundary::Kind::kFound, "found"},
    {OverturnBoundary::Kind::kBelowGrid, "below_grid"},
    {OverturnBoundary::Kind::kNone, "none"},
};
inline const char* to_string(OverturnBoundary::Kind k) { return name_of(kBoundaryKindNames, k); }

struct SpectrumResult {
  double alpha = 0.0;               // [rad] tipping angle of edge 1 (atan(b1/h) for a rigid body)
  double tan_alpha = 0.0;           // [-] b1/h: g tan alpha is the static uplift acceleration
  double p = 0.0;                   // [rad/s] Body::rocking_frequency()
  std::vector<SpectrumCell> cells;  // row-major: cells[row * columns + column]
  std::vector<OverturnBoundary> boundary;  // one per column (empty without bisection)
  bool sliding = false;  // the spec's friction coefficient is finite: the cells carry the sliding
                         // fields (offsets, time sliding, regime)
  GridUnits units;       // the units a physical pulse grid was asked in (otherwise SI: no columns
                         // beyond the SI and normalised ones)
};

/// The motion of one cell: a_p [m/s^2], omega_p [rad/s], total duration [s], the pulse type's
/// other keys at their defaults. Throws InputError for a type that is not a spectrum family.
GroundMotion pulse_motion(const std::string& type, double a_p, double omega_p, double duration);
/// Length of the pulse [s] (where the free motion starts; Ricker: its centre + 3 sqrt(6)/omega).
double pulse_length(const std::string& type, double omega_p);

/// Simulates one cell (a pulse spectrum cell) exactly as compute_spectrum does.
RunSummary run_pulse_cell(const Body& body, const SpectrumSpec& spec, double a_p, double omega_p);
/// Simulates one record cell exactly as compute_record_spectrum does.
RunSummary run_record_cell(const Body& body, const RecordSpectrumSpec& spec, double scale);

/// What a spectrum already has (e.g. from the journal of an interrupted one) and where each
/// new result goes as it is found: how a spectrum resumes. Cell indices are row * columns +
/// column (a record spectrum: the scale index); boundary indices are columns (a record: 0).
struct SpectrumResume {
  std::map<std::size_t, Outcome> cells;  // finished cells: not run again; their outcomes
                                         // place the bisection bracket of their column
  std::set<std::size_t> boundaries;      // columns whose boundary is finished: not bisected
  std::function<void(const SpectrumCell&)> on_cell;          // every cell run, one call at a time
  std::function<void(const OverturnBoundary&)> on_boundary;  // every finished boundary, alike
};

/// The grid of a spec with nothing run: every cell's indices and amplitudes, the boundary slots
/// (column, frequency), alpha and p. It checks the spec and every run it makes (finite
/// durations, the solver options as simulate() checks them) and throws InputError otherwise.
SpectrumResult spectrum_grid(const Body& body, const SpectrumSpec& spec);
/// The same for a record spectrum (one column; boundary slot 0 when spec.bisect).
SpectrumResult record_spectrum_grid(const Body& body, const RecordSpectrumSpec& spec);

/// Every cell of the grid, then (if spec.bisect) the boundary of every column. Columns run in
/// parallel (one task a column: its cells, then its bisection), so results do not depend on the
/// thread count. With options.ranks > 1 only the columns with index % ranks == rank are
/// computed (the others keep computed = false). A stop request (options.cancel) is seen between
/// runs: cells not run keep computed = false and an unfinished bisection is dropped. With
/// `resume`, its cells and boundaries are not computed again (resumed = true). Throws
/// InputError for a bad spec, before any run.
SpectrumResult compute_spectrum(const Body& body, const SpectrumSpec& spec,
                                const RunOptions& options = {},
                                const SpectrumResume* resume = nullptr);
/// The record spectrum: one column, rows = scales (spread over threads and ranks), then the
/// boundary (the minimum overturning scale) when this process computed every row (ranks == 1).
/// Stop requests and `resume` as for compute_spectrum.
SpectrumResult compute_record_spectrum(const Body& body, const RecordSpectrumSpec& spec,
                                       const RunOptions& options = {},
                                       const SpectrumResume* resume = nullptr);
/// The boundary of a record spectrum from its complete cells (after gathering them from every
/// rank): what compute_record_spectrum adds itself with ranks == 1. A stop request (`cancel`
/// true) ends the bisection between runs and returns computed = false.
OverturnBoundary record_boundary(const Body& body, const RecordSpectrumSpec& spec,
                                 const std::vector<SpectrumCell>& cells,
                                 const std::atomic<bool>* cancel = nullptr);

/// Runs a study computes for a spec: grid cells (the bisection adds more, not known ahead).
inline std::size_t grid_runs(const SpectrumSpec& s) {
  return s.amplitudes.size() * s.frequencies.size();
}

}  // namespace flexrock::study
