// SPDX-License-Identifier: BSD-3-Clause
// Uncertain parameters of a study: distributions of friction, restitution, size, mass, damping
// and modal frequencies, sampled per run by a seeded counter-based generator (plain random or
// Latin hypercube), so that a run's values depend only on the seed and the sample index, never
// on threads, processes or the order runs finish in. No files here: io/study_files.hpp reads
// the [[uncertain]] and [sampling] tables of a sweep manifest.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "flexrock/core/enum_names.hpp"
#include "flexrock/model/body.hpp"
#include "flexrock/sim/simulate.hpp"

namespace flexrock::study {

/// What an uncertain parameter varies (docs/studies.md, "Uncertain parameters").
enum class UncertainKind {
  kFriction,           // the static Coulomb coefficient mu_s [-] (the kinetic one keeps its ratio)
  kRestitutionFactor,  // SimulationOptions::restitution_factor [-] (paper and rigid_body laws)
  kRestitutionRatio,   // both restitution_ratio_edge1/2 [-] (impact_law = restitution)
  kSizeScale,          // every length x s (h, b1, b2), mass and modal frequencies held [-]
  kMassScale,          // M x s, stiffness held: modal frequencies x 1/sqrt(s) [-]
  kFrequencyScale,     // every pinned-base modal frequency x s (stiffness x s^2) [-]
  kDampingRatio,       // the damping ratio of every pinned-base mode [-]
  kBaseWidthScale,     // rigid: b1, b2 x s, the mass and its distribution held [-]
  kCgHeightScale,      // rigid: h x s, the rotary inertia about the c.g. held [-]
};

/// One entry of the table of uncertain parameters: its name in a manifest, its CSV column, the
/// values it may take (the domain a distribution, after truncation, must lie in) and what it
/// does.
struct UncertainKindInfo {
  UncertainKind kind;
  const char* name;    // `parameter` in [[uncertain]]
  const char* column;  // the sweep CSV column of the sampled value
  const char* unit;
  double lowest;       // domain: lowest value
  bool lowest_open;    // true: lowest itself excluded
  double highest;      // domain: highest value (inf: none)
  bool highest_open;   // true: highest itself excluded
  const char* domain;  // the domain as errors and docs say it ("> 0", "in [0, 1]")
  const char* doc;     // one line: what a sampled value changes
};

/// Every uncertain parameter, in the order the docs list them.
const std::vector<UncertainKindInfo>& uncertain_kinds();
/// The entry of a kind, and of a name (nullptr if unknown).
const UncertainKindInfo& uncertain_kind(UncertainKind kind);
const UncertainKindInfo* find_uncertain_kind(std::string_view name);

/// A probability distribution of an uncertain parameter.
enum class Distribution {
  kUniform,    // a = minimum, b = maximum
  kNormal,     // a = mean, b = standard deviation
  kLognormal,  // a = median, b = beta, the standard deviation of ln x
};
inline constexpr EnumName<Distribution> kDistributionNames[] = {
    {Distribution::kUniform, "uniform"},
    {Distribution::kNormal, "normal"},
    {Distribution::kLognormal, "lognormal"},
};
inline const char* to_string(Distribution d) { return name_of(kDistributionNames, d, "?"); }

struct UncertainParameter {
  UncertainKind kind = UncertainKind::kFriction;
  Distribution distribution = Distribution::kUniform;
  double a = 0.0;  // minimum, mean or median (see Distribution), in the parameter's unit
  double b = 0.0;  // maximum, standard deviation or beta
  // truncation (normal and lognormal): the distribution conditioned on [lower, upper]
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
};

enum class SamplingMethod {
  kRandom,          // independent draws
  kLatinHypercube,  // per parameter, exactly one draw in each of n equiprobable strata
};

/// Which runs share a realisation.
enum class SamplingScope {
  kRun,     // each (record, level) run its own: sample index record * levels + level
  kRecord,  // one per record, the same at every level (IDA curves of one realisation)
};

struct Sampling {
  std::uint64_t seed = 0;
  SamplingMethod method = SamplingMethod::kRandom;
  SamplingScope scope = SamplingScope::kRun;
};

/// The uncertain parameters of a study and how they are sampled. Empty: no sampling at all.
struct Uncertainty {
  std::vector<UncertainParameter> parameters;
  Sampling sampling;
  bool empty() const { return parameters.empty(); }
};

/// Checks a parameter: its distribution's own numbers (minimum < maximum, standard deviation and
/// beta > 0, median > 0, lower < upper, a truncation that keeps some probability) and that
/// every value it can give lies in the parameter's domain. Throws InputError saying what is
/// wrong and what would be right (the caller adds where).
void validate(const UncertainParameter& p);
/// Checks every parameter and that no kind is given twice.
void validate(const Uncertainty& u);

/// The value of `p` at probability u in (0, 1): the inverse of its (truncated) distribution
/// function. Truncated distributions are sampled exactly: u is mapped into [F(lower), F(upper)]
/// (on the upper tail through the complement, for precision).
double quantile(const UncertainParameter& p, double u);

/// A uniform number in (0, 1) that is a pure function of (seed, index, dimension): a splitmix64
/// hash of the three, its 52 high bits centred in their interval, so in [2^-53, 1 - 2^-53]
/// (never 0 nor 1).
double counter_uniform(std::uint64_t seed, std::uint64_t index, std::uint64_t dimension);

/// The samples of a study: `samples` realisations of every parameter, each a pure function of
/// the seed and its index. Latin hypercube: for parameter d the sample i lies in stratum
/// perm_d(i) of `samples` equiprobable strata, perm_d a permutation drawn from the seed alone
/// (Fisher-Yates on counter_uniform), at a uniform position inside it.
class SampleDesign {
 public:
  SampleDesign() = default;
  SampleDesign(const Uncertainty& u, std::size_t samples);
  std::size_t samples() const { return samples_; }
  std::size_t dimensions() const { return parameters_.size(); }
  /// The uniform of sample i, parameter d, in (0, 1).
  double uniform(std::size_t i, std::size_t d) const;
  /// The values of sample i, one per parameter, in the Uncertainty's order.
  std::vector<double> values(std::size_t i) const;

 private:
  std::vector<UncertainParameter> parameters_;
  Sampling sampling_;
  std::size_t samples_ = 0;
  std::vector<std::vector<std::uint32_t>> strata_;  // Latin hypercube: per parameter, per sample
};

/// True if a kind changes the body (geometry, mass, frequencies, damping), not the solver
/// options.
bool changes_body(UncertainKind kind);

/// `body` with the values of the body-changing parameters applied. Throws InputError when a
/// parameter cannot apply to it (modal frequencies or damping of a rigid body, a damping ratio
/// for a body with Rayleigh damping, the base width or c.g. height of a body with modes).
BodyParameters apply(const Uncertainty& u, const std::vector<double>& values, BodyParameters body);
/// `o` with the values of friction and restitution applied: friction sets the static coefficient
/// and scales a finite kinetic one with it (their ratio kept); restitution_ratio sets both edges.
void apply(const Uncertainty& u, const std::vector<double>& values, SimulationOptions& o);

}  // namespace flexrock::study
