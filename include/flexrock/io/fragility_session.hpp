// SPDX-License-Identifier: BSD-3-Clause
// A fragility fit of a sweep CSV as a session, the third beside the spectrum and sweep sessions
// (io/study_session.hpp): the damage states and the intensity measure typed, the observations
// and fits of every state and body, the checks of the states' order, and the fit CSV. The
// command line (`flexrock fragility`) only reads its options into FragilityOptions and prints;
// Python gets the same session.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

#include "flexrock/core/enum_names.hpp"
#include "flexrock/io/study_files.hpp"
#include "flexrock/study/fragility.hpp"

namespace flexrock::io {

/// How the observations of a body become a fit.
enum class FragilityAnalysis {
  kRuns,        // every run an observation (study::fit_lognormal)
  kStripes,     // multiple-stripe analysis over the sweep's levels (study::fit_stripes)
  kCapacities,  // each record's capacity from its first failure (study::fit_capacity_intervals)
};
/// Their names, as --analysis takes them.
inline constexpr EnumName<FragilityAnalysis> kFragilityAnalysisNames[] = {
    {FragilityAnalysis::kRuns, "runs"},
    {FragilityAnalysis::kStripes, "msa"},
    {FragilityAnalysis::kCapacities, "ida"},
};

/// What to fit. Errors name the options as `flexrock fragility` does (--state, --level, --im).
struct FragilityOptions {
  // fragility_measures(); the library's default is SI (the command line and Python default to
  // pga_g, as their plots); kStripes: requested_level (the default there)
  std::string im = "pga";
  bool im_given = false;  // im was chosen (kStripes refuses any measure but requested_level)
  // the damage states of a family (--state), least severe first, fitted at once and written
  // with a state column; empty: the one state of `outcome` and `level`
  std::vector<DamageState> states;
  FragilityOutcome outcome = FragilityOutcome::kOverturned;  // without `states`
  double level = 0.0;  // threshold of a levelled `outcome` (> 0)
  FragilityAnalysis analysis = FragilityAnalysis::kRuns;
  std::string body;            // only this body (empty: every body)
  double confidence = 0.95;    // level of the bounds, in (0, 1)
  bool worst_azimuth = false;  // FragilityQuery::worst_azimuth: one observation per record pair
                               // and level
};

/// A note on the order of two damage states of a body (given least severe first).
struct FragilityOrderNote {
  std::size_t body = 0;        // index of the body
  std::size_t state = 0;       // the more severe state; the other is state - 1
  bool medians_cross = false;  // its median is below the less severe one's
  double crossing = 0.0;  // [IM] where the two curves cross inside the data's range; NaN: nowhere
  bool latter_likelier_above = false;  // above `crossing` the more severe state is the likelier
};

/// The fits of every damage state and body of a sweep CSV.
class FragilitySession {
 public:
  /// Checks the options and the table (check_sweep_table), then fits every state and body. A
  /// body or state that cannot be fitted (it never fails, the measure separates its outcomes
  /// perfectly, ...) is kept with the reason (fitted(), not_fitted()) and the others are fitted.
  /// Throws InputError: options as `flexrock fragility` names them, data with the file, and,
  /// naming every body and state with its reason, when nothing could be fitted.
  FragilitySession(CsvTable table, FragilityOptions options);
  /// The same for the sweep CSV at `path`.
  FragilitySession(const std::string& path, FragilityOptions options);

  const CsvTable& table() const { return table_; }
  const FragilityOptions& options() const { return options_; }
  const FragilityMeasure& measure() const { return measure_; }
  /// The unit of the measure ([scales] units of the file for requested_level).
  const std::string& unit() const { return unit_; }
  /// The states fitted: the family given, or the one of `outcome` and `level`.
  const std::vector<DamageState>& states() const { return states_; }
  /// A family of states (options.states): the fit CSV has a state column.
  bool several() const { return several_; }
  /// Bodies in the order of their first row (the same for every state).
  std::size_t bodies() const { return data_.front().size(); }
  const FragilityData& data(std::size_t state, std::size_t body) const;
  /// The fit of a state and body; throws InputError with the reason when it could not be fitted.
  const study::FragilityFit& fit(std::size_t state, std::size_t body) const;
  /// Whether a state and body could be fitted.
  bool fitted(std::size_t state, std::size_t body) const;
  /// Why a state and body could not be fitted ("<file>: body 'b', state 's': ..."); "" if fitted.
  const std::string& not_fitted(std::size_t state, std::size_t body) const;
  /// The number of states and bodies fitted (at least 1).
  std::size_t fitted_count() const;
  /// The stripes of a multiple-stripe analysis (the sweep's levels).
  std::vector<study::Stripe> stripes(std::size_t state, std::size_t body) const;
  /// The observed range of the measure over two states of a body (or one: a == b).
  std::pair<double, double> range(std::size_t body, std::size_t a, std::size_t b) const;
  /// Medians out of order and curves that cross inside the data, every body, state after state
  /// (pairs of fitted states only).
  std::vector<FragilityOrderNote> order_notes() const;

  /// The fit CSV (fragility_columns, or fragility_state_columns with several states): bodies in
  /// order, their states in order; the states and bodies not fitted have no row.
  void write_fits(std::ostream& out) const;

 private:
  CsvTable table_;
  FragilityOptions options_;
  FragilityMeasure measure_;
  std::string unit_;
  std::vector<DamageState> states_;
  bool several_ = false;
  std::vector<std::vector<FragilityData>> data_;        // [state][body]
  std::vector<std::vector<study::FragilityFit>> fits_;  // [state][body]
  std::vector<std::vector<std::string>> not_fitted_;    // [state][body]: why not; "" fitted
};

}  // namespace flexrock::io
