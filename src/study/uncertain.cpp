// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/study/uncertain.hpp"

#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <set>

#include "flexrock/core/error.hpp"
#include "flexrock/core/format.hpp"
#include "flexrock/sim/option_bounds.hpp"

namespace flexrock::study {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::string num(double v) { return format_number(v); }

// the open interval (0, 1) in doubles, as far as the uniforms reach: [2^-53, 1 - 2^-53]
constexpr double kLowestU = 0x1p-53;
constexpr double kHighestU = 1.0 - 0x1p-53;

}  // namespace

const std::vector<UncertainKindInfo>& uncertain_kinds() {
  static const std::vector<UncertainKindInfo> kinds = {
      {UncertainKind::kFriction, "friction", "friction_coefficient", "-", 0.0, true, kInf, true,
       "> 0",
       "the static Coulomb coefficient mu_s at the base, in place of the body's or [solver]'s; "
       "a finite kinetic coefficient keeps its ratio to it"},
      {UncertainKind::kRestitutionFactor, "restitution_factor", "restitution_factor", "-", 0.0,
       false, kRestitutionFactorBound.hi, false, "in [0, 2]",
       "[solver] restitution_factor: the factor on theta_dot after an impact (impact laws "
       "`paper` and `rigid_body`)"},
      {UncertainKind::kRestitutionRatio, "restitution_ratio", "restitution_ratio", "-", 0.0, false,
       1.0, false, "in [0, 1]",
       "theta_dot+/theta_dot- at an impact on either edge (impact_law = \"restitution\")"},
      {UncertainKind::kSizeScale, "size_scale", "size_scale", "-", 0.0, true, kInf, true, "> 0",
       "every length of the body times s (c.g. height, base distances, mode shapes): the same "
       "shape, mass and modal frequencies; rocking frequency p / sqrt(s)"},
      {UncertainKind::kBaseWidthScale, "base_width_scale", "base_width_scale", "-", 0.0, true, kInf,
       true, "> 0",
       "the distances b1, b2 from the c.g. to the tipping points times s, the mass and its "
       "distribution held (a body on feet or a plinth of uncertain width; rigid bodies only)"},
      {UncertainKind::kCgHeightScale, "cg_height_scale", "cg_height_scale", "-", 0.0, true, kInf,
       true, "> 0",
       "the c.g. height h times s, the rotary inertia about the c.g. held (uncertain contents; "
       "rigid bodies only)"},
      {UncertainKind::kMassScale, "mass_scale", "mass_scale", "-", 0.0, true, kInf, true, "> 0",
       "the mass times s, spread as before, stiffness held: modal frequencies / sqrt(s); modal "
       "damping ratios and Rayleigh coefficients held (a rigid body: energies and impulses "
       "only)"},
      {UncertainKind::kFrequencyScale, "frequency_scale", "frequency_scale", "-", 0.0, true, kInf,
       true, "> 0",
       "every pinned-base modal frequency times s (stiffness times s^2); modal damping ratios "
       "and Rayleigh coefficients held (a body with modes only)"},
      {UncertainKind::kDampingRatio, "damping_ratio", "damping_ratio", "-", 0.0, false, 1.0, true,
       "in [0, 1)",
       "the damping ratio of every pinned-base mode (a body with modes and modal or no "
       "damping)"},
  };
  return kinds;
}

const UncertainKindInfo& uncertain_kind(UncertainKind kind) {
  for (const UncertainKindInfo& k : uncertain_kinds()) {
    if (k.kind == kind) return k;
  }
  FLEXROCK_DEMAND(false);
  return uncertain_kinds().front();
}

const UncertainKindInfo* find_uncertain_kind(std::string_view name) {
  for (const UncertainKindInfo& k : uncertain_kinds()) {
    if (name == k.name) return &k;
  }
  return nullptr;
}

namespace {

using boost::math::normal_distribution;

// the standard normal of the distribution's variable: z of x (normal) or of ln x (lognormal)
double standard_z(const UncertainParameter& p, double x) {
  if (p.distribution == Distribution::kNormal) return (x - p.a) / p.b;
  if (x <= 0.0) return -kInf;
  return std::log(x / p.a) / p.b;
}

double from_z(const UncertainParameter& p, double z) {
  return p.distribution == Distribution::kNormal ? p.a + p.b * z : p.a * std::exp(p.b * z);
}

double phi(double z) {
  if (std::isinf(z)) return z > 0.0 ? 1.0 : 0.0;
  return boost::math::cdf(normal_distribution<double>(), z);
}
double phi_c(double z) {
  if (std::isinf(z)) return z > 0.0 ? 0.0 : 1.0;
  return boost::math::cdf(boost::math::complement(normal_distribution<double>(), z));
}

// the probability a truncation keeps
double kept(const UncertainParameter& p) {
  const double zl = standard_z(p, p.lower), zu = standard_z(p, p.upper);
  // on the upper tail through the complement: 1 - F loses nothing there
  return zl > 0.0 ? phi_c(zl) - phi_c(zu) : phi(zu) - phi(zl);
}

// the lowest and highest value a parameter can give
std::pair<double, double> support(const UncertainParameter& p) {
  if (p.distribution == Distribution::kUniform) return {p.a, p.b};
  const double lo = p.distribution == Distribution::kLognormal ? std::max(0.0, p.lower) : p.lower;
  return {lo, p.upper};
}

}  // namespace

void validate(const UncertainParameter& p) {
  const UncertainKindInfo& k = uncertain_kind(p.kind);
  const std::string name = std::string("uncertain ") + k.name + ": ";
  switch (p.distribution) {
    case Distribution::kUniform:
      FLEXROCK_THROW_UNLESS(std::isfinite(p.a) && std::isfinite(p.b) && p.a < p.b,
                            name + "uniform: expected finite minimum < maximum, got " + num(p.a) +
                                " and " + num(p.b));
      FLEXROCK_THROW_UNLESS(std::isinf(p.lower) && std::isinf(p.upper),
                            name +
                                "uniform: lower and upper are for normal and lognormal; a "
                                "uniform distribution is bounded by its minimum and maximum");
      break;
    case Distribution::kNormal:
      FLEXROCK_THROW_UNLESS(std::isfinite(p.a),
                            name + "normal: expected a finite mean, got " + num(p.a));
      FLEXROCK_THROW_UNLESS(std::isfinite(p.b) && p.b > 0.0,
                            name + "normal: expected a standard deviation > 0, got " + num(p.b));
      break;
    case Distribution::kLognormal:
      FLEXROCK_THROW_UNLESS(std::isfinite(p.a) && p.a > 0.0,
                            name + "lognormal: expected a median > 0, got " + num(p.a));
      FLEXROCK_THROW_UNLESS(std::isfinite(p.b) && p.b > 0.0,
                            name +
                                "lognormal: expected beta (the standard deviation of ln x) > "
                                "0, got " +
                                num(p.b));
      break;
  }
  FLEXROCK_THROW_UNLESS(
      !std::isnan(p.lower) && !std::isnan(p.upper) && p.lower < p.upper,
      name + "expected lower < upper, got " + num(p.lower) + " and " + num(p.upper));
  if (p.distribution != Distribution::kUniform) {
    // a truncation to a far tail keeps nothing that double precision can sample
    const double mass = kept(p);
    FLEXROCK_THROW_UNLESS(mass > 1e-12, name + "the truncation [" + num(p.lower) + ", " +
                                            num(p.upper) + "] keeps a probability of " + num(mass) +
                                            " of the " + to_string(p.distribution) +
                                            " distribution; expected bounds around its bulk");
  }
  const auto [lo, hi] = support(p);
  const bool lo_ok = k.lowest_open ? lo > k.lowest : lo >= k.lowest;
  // no draw is infinite: an unbounded domain takes any upper end
  const bool hi_ok = std::isinf(k.highest) || (k.highest_open ? hi < k.highest : hi <= k.highest);
  // the lognormal's own lower end, 0, is never drawn
  const bool lo_open_ok =
      p.distribution == Distribution::kLognormal && lo == 0.0 && k.lowest == 0.0 && p.lower <= 0.0;
  if (!(lo_ok || lo_open_ok) || !hi_ok) {
    std::string hint;
    if (p.distribution == Distribution::kUniform) {
      hint = "minimum and maximum";
    } else if (!(lo_ok || lo_open_ok)) {
      hint = "a lower bound";
    } else {
      hint = "an upper bound";
    }
    throw InputError(name + "the values must be " + k.domain + ", but the " +
                     to_string(p.distribution) + " distribution can give values from " + num(lo) +
                     " to " + num(hi) + "; give " + hint + " inside that range");
  }
}

void validate(const Uncertainty& u) {
  std::set<UncertainKind> seen;
  for (const UncertainParameter& p : u.parameters) {
    validate(p);
    FLEXROCK_THROW_UNLESS(seen.insert(p.kind).second, std::string("uncertain ") +
                                                          uncertain_kind(p.kind).name +
                                                          ": given twice; expected one "
                                                          "distribution per parameter");
  }
}

double quantile(const UncertainParameter& p, double u) {
  FLEXROCK_DEMAND(u > 0.0 && u < 1.0);
  if (p.distribution == Distribution::kUniform) return p.a + u * (p.b - p.a);
  const normal_distribution<double> n;
  const double zl = standard_z(p, p.lower), zu = standard_z(p, p.upper);
  // the probability handed to the quantile stays inside (0, 1) after rounding: at 0 or 1 it is
  // infinite (and Boost throws)
  auto inside = [](double q) { return std::clamp(q, kLowestU, kHighestU); };
  double z;
  if (zl > 0.0) {
    // the upper tail: through the complement, 1 - F, which keeps its digits there
    const double ql = phi_c(zl), qu = phi_c(zu);
    z = boost::math::quantile(boost::math::complement(n, inside(ql - u * (ql - qu))));
  } else {
    const double pl = phi(zl), pu = phi(zu);
    z = boost::math::quantile(n, inside(pl + u * (pu - pl)));
  }
  // rounding may step a hair past a bound
  return std::clamp(from_z(p, z), p.lower, p.upper);
}

namespace {

// splitmix64's finaliser (Steele, Lea & Flood 2014): a bijection that mixes every bit
std::uint64_t mix(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// the stream of the Latin hypercube's permutations, apart from the draws inside the strata
constexpr std::uint64_t kPermutationStream = 0x5a3c0ffee1234567ULL;

}  // namespace

double counter_uniform(std::uint64_t seed, std::uint64_t index, std::uint64_t dimension) {
  const std::uint64_t h = mix(mix(mix(seed) ^ index) ^ dimension);
  // 52 bits: the centre of the top interval, 1 - 2^-53, is a double below 1 (with 53 it would
  // round to 1)
  return (static_cast<double>(h >> 12) + 0.5) * 0x1p-52;
}

SampleDesign::SampleDesign(const Uncertainty& u, std::size_t samples)
    : parameters_(u.parameters), sampling_(u.sampling), samples_(samples) {
  FLEXROCK_THROW_UNLESS(samples <= std::numeric_limits<std::uint32_t>::max(),
                        "sampling: too many samples");
  if (sampling_.method != SamplingMethod::kLatinHypercube) return;
  const std::uint64_t stream = mix(sampling_.seed ^ kPermutationStream);
  strata_.resize(parameters_.size());
  for (std::size_t d = 0; d < parameters_.size(); ++d) {
    std::vector<std::uint32_t>& perm = strata_[d];
    perm.resize(samples);
    for (std::size_t i = 0; i < samples; ++i) perm[i] = static_cast<std::uint32_t>(i);
    // Fisher-Yates from the top: position k swaps with one of 0..k
    for (std::size_t k = samples; k-- > 1;) {
      const auto j =
          static_cast<std::size_t>(counter_uniform(stream, k, d) * static_cast<double>(k + 1));
      std::swap(perm[k], perm[std::min(j, k)]);
    }
  }
}

double SampleDesign::uniform(std::size_t i, std::size_t d) const {
  FLEXROCK_DEMAND(i < samples_ && d < parameters_.size());
  const double v = counter_uniform(sampling_.seed, i, d);
  if (sampling_.method != SamplingMethod::kLatinHypercube) return v;
  // stratum perm_d(i) of n: (k + v) / n stays inside (k/n, (k+1)/n) and so inside (0, 1)
  const double u = (static_cast<double>(strata_[d][i]) + v) / static_cast<double>(samples_);
  return std::clamp(u, kLowestU, kHighestU);
}

std::vector<double> SampleDesign::values(std::size_t i) const {
  std::vector<double> out;
  out.reserve(parameters_.size());
  for (std::size_t d = 0; d < parameters_.size(); ++d) {
    out.push_back(quantile(parameters_[d], uniform(i, d)));
  }
  return out;
}

bool changes_body(UncertainKind kind) {
  return kind == UncertainKind::kSizeScale || kind == UncertainKind::kMassScale ||
         kind == UncertainKind::kFrequencyScale || kind == UncertainKind::kDampingRatio ||
         kind == UncertainKind::kBaseWidthScale || kind == UncertainKind::kCgHeightScale;
}

BodyParameters apply(const Uncertainty& u, const std::vector<double>& values, BodyParameters b) {
  FLEXROCK_DEMAND(values.size() == u.parameters.size());
  const auto modes = b.kappa.rows();
  for (std::size_t d = 0; d < values.size(); ++d) {
    const double s = values[d];
    const std::string name = uncertain_kind(u.parameters[d].kind).name;
    switch (u.parameters[d].kind) {
      case UncertainKind::kSizeScale:
        // q_i and every integral are lengths over h: unchanged; K = (g/h) kappa held
        b.height *= s;
        b.b1 *= s;
        b.b2 *= s;
        b.kappa *= s;
        break;
      case UncertainKind::kMassScale:
        // kappa = k / (M g h) with k held
        b.mass *= s;
        b.kappa /= s;
        break;
      case UncertainKind::kFrequencyScale:
        FLEXROCK_THROW_UNLESS(modes > 0, "uncertain " + name +
                                             ": the body is rigid (no modes); expected a body "
                                             "with modes");
        b.kappa *= s * s;
        break;
      case UncertainKind::kDampingRatio:
        FLEXROCK_THROW_UNLESS(modes > 0, "uncertain " + name +
                                             ": the body is rigid (no modes); expected a body "
                                             "with modes");
        FLEXROCK_THROW_UNLESS(
            b.damping.kind != DampingKind::kRayleigh,
            "uncertain " + name +
                ": the body has Rayleigh damping; expected a body with modal or no damping");
        b.damping.kind = DampingKind::kModal;
        b.damping.modal_ratios = VectorX::Constant(modes, s);
        break;
      case UncertainKind::kBaseWidthScale:
        // pinned-base modes vanish at the tipping points: moving them changes the modes
        FLEXROCK_THROW_UNLESS(modes == 0, "uncertain " + name + ": the body has modes (" +
                                              std::to_string(modes) +
                                              "), whose pinned-base shapes are tied to its "
                                              "tipping points; expected a rigid body");
        b.b1 *= s;
        b.b2 *= s;
        break;
      case UncertainKind::kCgHeightScale:
        // every modal integral is over h: a body with modes would need its shapes again
        FLEXROCK_THROW_UNLESS(modes == 0, "uncertain " + name + ": the body has modes (" +
                                              std::to_string(modes) +
                                              "), whose integrals are taken about its c.g.; "
                                              "expected a rigid body");
        // zeta2 = I_cg / (M h^2) with I_cg held
        b.height *= s;
        b.zeta2 /= s * s;
        break;
      default:
        break;
    }
  }
  return b;
}

void apply(const Uncertainty& u, const std::vector<double>& values, SimulationOptions& o) {
  FLEXROCK_DEMAND(values.size() == u.parameters.size());
  for (std::size_t d = 0; d < values.size(); ++d) {
    const double s = values[d];
    switch (u.parameters[d].kind) {
      case UncertainKind::kFriction:
        // mu_k <= mu_s holds after rounding too
        if (std::isfinite(o.friction_coefficient) && std::isfinite(o.kinetic_friction_coefficient))
          o.kinetic_friction_coefficient =
              std::min(s, s * (o.kinetic_friction_coefficient / o.friction_coefficient));
        else
          o.kinetic_friction_coefficient = kInf;
        o.friction_coefficient = s;
        break;
      case UncertainKind::kRestitutionFactor:
        o.restitution_factor = s;
        break;
      case UncertainKind::kRestitutionRatio:
        o.restitution_ratio_edge1 = o.restitution_ratio_edge2 = s;
        break;
      default:
        break;
    }
  }
}

}  // namespace flexrock::study
