// SPDX-License-Identifier: BSD-3-Clause
// Sweeps: bodies x records x scale factors (incremental dynamic analysis), one summary row per
// run. No files here: io/study_files.hpp reads manifests and journals the rows.
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "flexrock/excitation/ground_motion.hpp"
#include "flexrock/model/body.hpp"
#include "flexrock/sim/simulate.hpp"
#include "flexrock/study/outcome.hpp"
#include "flexrock/study/parallel.hpp"
#include "flexrock/study/uncertain.hpp"

namespace flexrock::study {

/// An intensity measure a sweep writes besides PGA and PGV: a name of the table
/// flexrock::intensity_measures() (excitation/intensity.hpp), with its period and damping ratio
/// for "sa".
struct MeasureRequest {
  std::string name;     // e.g. "pgd", "arias", "sa"
  double period = 0.0;  // [s] sa only, > 0
  double zeta = 0.05;   // [-] sa only, in [0, 1)
  // sa only: the unit of its column, as asked: "" or "m/s^2" (SI), "g", "cm/s^2"; the column's
  // name ends with it (sa_T1_z0.05_g) and its values are in it
  std::string unit;
};

/// A measure as the command line and manifests name it: a name of the table, or "sa:T" /
/// "sa:T:zeta" (period T [s] > 0, damping ratio zeta in [0, 1), 0.05 by default). Throws
/// InputError saying what is wrong (the caller adds where).
MeasureRequest measure_request(const std::string& text);

/// The sweep CSV column of a requested measure (its table column, or spectral_column for sa,
/// with the suffix of its unit).
std::string measure_column(const MeasureRequest& m);

/// The unit of a requested measure's values: its `unit`, or the table's (SI).
std::string measure_unit(const MeasureRequest& m);

/// Intensity measures of a ground motion's horizontal component.
struct Intensity {
  double pga = 0.0;  // [m/s^2] peak |Xddot| (over the samples, or a fine sampling of a function)
  double pgv = 0.0;  // [m/s] peak |Xdot|, Xdot the trapezoidal integral of Xddot from 0 (no
                     // baseline correction: a record's own processing is trusted)
  std::vector<double> measures;  // [SI] the requested measures at scale 1, in request order
  double target = 0.0;  // [SI] the measure scaled to (ScaleKind::kTargetMeasure) at scale 1
};

/// PGA and PGV of `motion`, and the `measures` asked for. Sampled motions: over the samples.
/// Analytic motions: on a uniform grid of `analytic_dt` [s] plus the breakpoints. Throws
/// InputError for an unknown measure name or a bad period or damping ratio.
Intensity intensity(const GroundMotion& motion, double analytic_dt = 1e-3);
Intensity intensity(const GroundMotion& motion, const std::vector<MeasureRequest>& measures,
                    double analytic_dt = 1e-3);

struct SweepBody {
  std::string name;     // as the CSV shows it
  BodyParameters body;  // validated by Body when the sweep runs
  // Coulomb friction at this body's base, in place of the solver's pair (empty:
  // SweepSpec::solver's): static and kinetic coefficients as SimulationOptions has them (inf: none;
  // kinetic empty or inf: equal to the static one; the kinetic one is used only with a static one)
  std::optional<double> friction_coefficient = std::nullopt;
  std::optional<double> kinetic_friction_coefficient = std::nullopt;
};

/// The two horizontal components of a record pair [m/s^2] at their common sample times [s], shared
/// by the pair's azimuth records.
struct RecordPairComponents {
  std::vector<double> t, h1, h2;
};

struct SweepRecord {
  std::string name;     // as the CSV shows it
  GroundMotion motion;  // [m/s^2] at scale 1
  // one azimuth of a record pair (a [[suite]] with horizontal2), else null. A target (target_pga,
  // target_im of sa) scales every azimuth of the pair alike, by the pair's RotD50 of the
  // target measure, so that the pair meets the target whatever the body's orientation
  std::shared_ptr<const RecordPairComponents> pair = nullptr;
};

/// How the scale factors are given.
enum class ScaleKind {
  kFactor,     // `scales` are factors on every record
  kTargetPga,  // `scales` are target PGAs [m/s^2]: the factor is target / the record's PGA
  // `scales` are targets of SweepSpec::target [SI]: the factor s makes the scaled record's
  // measure s^power x the record's equal to the target (stripes of a multiple-stripe analysis)
  kTargetMeasure,
};

struct SweepSpec {
  std::vector<SweepBody> bodies;
  std::vector<SweepRecord> records;
  ScaleKind scale_kind = ScaleKind::kFactor;
  std::vector<double> scales;  // [-] factors, or [m/s^2] target PGAs (see scale_kind), > 0
  double free_periods = 2.0;   // [-] free motion after the record, in rocking periods 2 pi / p
  // tolerances etc. (overturning at pi/2); t_end and output_dt are set per run
  SimulationOptions solver = study_solver_defaults();
  // the scales as requested, for the CSV's level column (exact where a unit change of scales
  // is not): factors [-] or target PGAs in level_units; empty: scales, in their own units
  std::vector<double> levels;
  std::string level_units;  // "g", "m/s^2" or "cm/s^2" for target PGAs; empty: m/s^2
  // intensity measures every row gets besides PGA and PGV, as columns after pgv_m_per_s (empty:
  // the columns of a sweep before the measures existed, byte for byte)
  std::vector<MeasureRequest> measures;
  // the measure that kTargetMeasure scales to (one with scale power 1 or 2)
  MeasureRequest target;
  // parameters each run samples (empty: none, the columns of a sweep before them byte for byte);
  // the sample of a run is sample_index(spec, run): every body sees the same realisations
  Uncertainty uncertainty;
};

/// The intensity of a spec's record: intensity(motion, spec.measures), with the target measure
/// of a kTargetMeasure spec.
Intensity record_intensity(const SweepSpec& spec, const GroundMotion& motion);
/// The same for a record of the spec; an azimuth of a pair (SweepRecord::pair) under a target
/// gets the pair's RotD50 of the target measure as its `target` (what its factor divides). Throws
/// InputError for a pair under a target measure without a RotD (other than sa).
Intensity record_intensity(const SweepSpec& spec, const SweepRecord& record);
/// record_intensity of every record of the spec, a pair's RotD50 computed once.
std::vector<Intensity> record_intensities(const SweepSpec& spec);

/// One run of a sweep. Run indices are body-major: index = (body * records + record) * scales
/// + scale_index.
struct SweepRun {
  std::size_t index = 0;
  std::size_t body = 0, record = 0, scale_index = 0;
};

/// True if any run of the spec has a finite friction coefficient (the solver's or a body's): its
/// rows then carry the sliding fields (peak and residual offset, time sliding, regime).
bool has_friction(const SweepSpec& spec);

/// The runs of a spec in index order.
std::vector<SweepRun> sweep_runs(const SweepSpec& spec);

struct SweepRow {
  std::size_t index = 0;  // run index (see SweepRun)
  std::size_t body = 0, record = 0, scale_index = 0;
  double scale = 0.0;            // [-] factor applied to the record
  double pga = 0.0;              // [m/s^2] of the scaled record
  double pgv = 0.0;              // [m/s] of the scaled record
  std::vector<double> measures;  // [SI] spec.measures of the scaled record
  double duration = 0.0;         // [s] simulated span (record + free motion)
  std::string message;           // why a stopped run stopped (else empty)
  RunSummary run;
  std::vector<double> sampled;  // the run's values of spec.uncertainty, in its order
};

/// The sample a run draws from spec.uncertainty: record * scales + scale_index (SamplingScope
/// kRun) or record (kRecord); the body does not count, so every body meets the same values.
std::size_t sample_index(const SweepSpec& spec, const SweepRun& run);
/// The samples of a spec's uncertainty: one per (record, scale) or per record.
SampleDesign sample_design(const SweepSpec& spec);
/// The body of a run: its spec body with `sample` (the run's values) applied.
BodyParameters run_body(const SweepSpec& spec, const SweepRun& run,
                        const std::vector<double>& sample);

/// Simulates one run of the sweep (what run_sweep does for that index).
SweepRow run_sweep_one(const SweepSpec& spec, const SweepRun& run);

/// Runs the given indices (all of sweep_runs(spec) if `indices` is empty; with options.ranks
/// > 1 only those with index % ranks == rank) on options.threads workers. `on_row` (may be
/// empty) is called, one call at a time, as each run finishes, in completion order, e.g. to
/// journal it. Returns the rows computed here in index order. Throws InputError for a bad spec
/// (checked before any run).
std::vector<SweepRow> run_sweep(const SweepSpec& spec, const std::vector<std::size_t>& indices,
                                const RunOptions& options = {},
                                const std::function<void(const SweepRow&)>& on_row = {});

/// Checks a spec (non-empty lists, valid bodies, positive scales) and every run it makes
/// (finite scaled records and durations, the solver options as simulate() checks them), so that
/// no run can fail on its input once the sweep started; throws InputError naming the body,
/// record and scale, and the option.
void validate(const SweepSpec& spec);

/// A run's row before it runs: indices, scale factor, PGA, PGV, sampled values and duration
/// (what run_sweep writes in those fields); `body` and `im` are the run's body (run_body: with
/// its sample applied) and its record's intensity, `sample` the run's values.
SweepRow sweep_inputs(const SweepSpec& spec, const SweepRun& run, const Body& body,
                      const Intensity& im, const std::vector<double>& sample = {});
/// The same from the spec's body (`spec_body`, Body of spec.bodies[run.body]) and the spec's
/// design: the run's sample drawn and, if it changes the body, applied.
SweepRow sweep_inputs(const SweepSpec& spec, const SweepRun& run, const Body& spec_body,
                      const Intensity& im, const SampleDesign& design);
/// The simulation options of a run (spec.solver with the body's friction coefficients if it has
/// its own, then the run's sampled friction and restitution, its duration as t_end, no time
/// history).
SimulationOptions run_options(const SweepSpec& spec, const SweepRow& row);

}  // namespace flexrock::study
