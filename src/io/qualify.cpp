// SPDX-License-Identifier: BSD-3-Clause
// Qualification files, the qualification session (a sweep session at the design level and one
// record spectrum session per case and record for the IDA) and the report's numbers.
#include "flexrock/io/qualify.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>
#include <sstream>
#include <stdexcept>

#include "flexrock/contact/compliant.hpp"
#include "flexrock/contact/impact.hpp"
#include "flexrock/core/error.hpp"
#include "flexrock/core/format.hpp"
#include "flexrock/excitation/intensity.hpp"
#include "flexrock/io/case_file.hpp"
#include "flexrock/io/files.hpp"
#include "flexrock/sim/solver_keys.hpp"
#include "flexrock/study/fragility.hpp"
#include "flexrock/study/hand_estimates.hpp"
#include "flexrock/study/spectrum.hpp"
#include "flexrock/study/uncertain.hpp"
#include "flexrock/version.hpp"
#include "study_internal.hpp"
#include "table_reader.hpp"

namespace flexrock::io {

namespace fs = std::filesystem;
using namespace study_detail;
using Json = nlohmann::ordered_json;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

const std::vector<QualifyKey> kKeys = {
    {"", "name", "", "the file stem", "shown in the report"},
    {"", "description", "", "\"\"", "one line, shown in the report"},
    {"", "body", "", "required",
     "a case or body file with a [body] table (relative to this file), or a [body] table here "
     "(keys of docs/case-file.md)"},
    {"ranges", "friction", "-", "[solver] friction_coefficient (inf: the floor holds)",
     "static Coulomb coefficients to bound, each > 0 (inf: no sliding): every one is a case"},
    {"ranges", "kinetic_ratio", "-", "1", "mu_k / mu_s of every friction bound, in (0, 1]"},
    {"ranges", "mass_tolerance", "-", "0",
     "relative mass tolerance t in [0, 1): cases at (1 - t) M and (1 + t) M (stiffness held)"},
    {"ranges", "cg_height_tolerance", "-", "0",
     "relative c.g. height tolerance t in [0, 1): cases at (1 - t) h and (1 + t) h (rigid "
     "bodies)"},
    {"ranges", "cg_offset_tolerance", "m", "0",
     "horizontal c.g. tolerance d >= 0, below b1 and b2: cases with the c.g. d toward edge 1 "
     "and d toward edge 2 (rigid bodies)"},
    {"ranges", "damping_ratio", "-", "the body's",
     "[low, high] damping ratio of every mode (bodies with modes): a case at each"},
    {"record", "(keys)", "", "",
     "[[record]] tables as in a sweep manifest: file, format, units, dt, name"},
    {"suite", "(keys)", "", "",
     "[[suite]] tables as in a sweep manifest: horizontal, vertical, format, units, dt"},
    {"design", "pga", "units", "one of pga, factor",
     "the design level: every record scaled to this PGA (> 0)"},
    {"design", "units", "", "g", "of pga: g, m/s^2 or cm/s^2"},
    {"design", "factor", "-", "one of pga, factor",
     "the design level as a factor on every record (> 0)"},
    {"design", "both_polarities", "", "false",
     "each record also with its horizontal component reversed (the azimuth turned by 180 "
     "degrees), named <name>-rev"},
    {"design", "free_periods", "-", "2",
     "free motion after each record, in rocking periods 2 pi/p (>= 0)"},
    {"criteria", "tilt_fraction", "-", "not checked",
     "allowed largest tilt as a fraction of the overturning angle, in (0, 1]"},
    {"criteria", "sliding_clearance", "m", "not checked",
     "allowed peak sliding offset (the clearance to neighbours), > 0"},
    {"criteria", "impact_force", "N", "not checked",
     "allowed impact force estimate pi I_y / (2 impact_duration), > 0 (impulsive contact)"},
    {"criteria", "uplift", "m", "not checked", "allowed uplift of a tipping point, > 0"},
    {"ida", "enabled", "", "true", "run the incremental dynamic analysis (margin to overturning)"},
    {"ida", "factors", "-", "[0.5, 1, 1.5, 2, 3, 4, 6, 8]",
     "the IDA grid: multiples of the design level, strictly increasing, > 0"},
    {"ida", "tolerance", "-", "0.01",
     "relative width of the bisection's final bracket, in [1e-6, 0.5]"},
    {"report", "history_dt", "s", "0.01", "spacing of the governing time history, > 0"},
    {"report", "contact_stiffness", "N/m", "none",
     "with it, the impact force's governing run is run again on the compliant contact (a "
     "spring-dashpot of this stiffness at each tipping point, critically damped) for the "
     "resolved contact force"},
    {"report", "fragility", "", "false",
     "fit a lognormal fragility of overturning per case to the IDA's capacities (needs the IDA)"},
    {"solver", "(keys)", "", "",
     "every key of a study's [solver] table (docs/studies.md); overturning at pi/2 by default"},
};

// the criteria: name, what the demand is, its unit, the pelicun demand type and its unit, the
// limit in QualifyCriteria, the demand of a run and its pelicun value
struct Criterion {
  const char* name;
  const char* what;
  const char* unit;
  const char* pelicun;
  const char* pelicun_unit;
  std::optional<double> QualifyCriteria::*limit;
  double (*demand)(const study::RunSummary& r, double impact_duration);
  double (*pelicun_value)(const study::RunSummary& r, double impact_duration);
};

double impact_force(const study::RunSummary& r, double tau) {
  return std::numbers::pi * r.max_impulse / (2.0 * tau);
}

const Criterion kCriteria[] = {
    {"tilt", "largest tilt / overturning angle", "-", "ROT", "rad", &QualifyCriteria::tilt_fraction,
     [](const study::RunSummary& r, double) {
       return study::overturned(r.outcome) ? std::max(1.0, r.max_theta_over_alpha)
                                           : r.max_theta_over_alpha;
     },
     [](const study::RunSummary& r, double) { return r.max_theta; }},
    {"sliding", "peak sliding offset", "m", "SLD", "m", &QualifyCriteria::sliding_clearance,
     [](const study::RunSummary& r, double) { return r.max_offset; },
     [](const study::RunSummary& r, double) { return r.max_offset; }},
    {"impact_force", "impact force estimate", "N", "IMF", "N", &QualifyCriteria::impact_force,
     impact_force, impact_force},
    {"uplift", "largest uplift of a tipping point", "m", "UPL", "m", &QualifyCriteria::uplift,
     [](const study::RunSummary& r, double) { return r.max_uplift; },
     [](const study::RunSummary& r, double) { return r.max_uplift; }},
};

// the checks of docs/validation.md a qualification cites, by the features they cover; the
// agreement is quoted from that page (a test checks each quote is there)
struct Citation {
  const char* feature;  // "rigid", "flexible", "friction", "record", "any", "compliant"
  const char* section;
  const char* check;
  const char* agreement;
  const char* test;
};
const Citation kCitations[] = {
    {"rigid", "1.1 Restitution over slenderness", "Housner's restitution over 18 slendernesses",
     "Largest difference over 18 slendernesses 0.02..0.7: 1.1e-16",
     "tests/validation/rigid_block_test.cpp"},
    {"rigid", "1.3 Minimum overturning acceleration: rectangular and half-sine pulses",
     "smallest overturning amplitude of rectangular and half-sine pulses against Housner's "
     "linearized closed forms",
     "For the slender block (alpha = 0.05) it is about 0.1% or less",
     "tests/validation/housner_closed_form_test.cpp"},
    {"record", "6. Real records: El Centro 1940 and Kobe 1995",
     "first overturning scale of a rigid and a flexible body under El Centro and Kobe at rtol "
     "1e-8 and 1e-10",
     "The overturning outcome agreed at both tolerances for every scale of the sweep",
     "tools/validation/validate.cpp"},
    {"flexible", "4.1 Uplift amplitude under steady harmonic shaking",
     "uplift amplitude of an oscillator on a slab against the linear prediction",
     "asserts the engine's threshold to 1e-6 of the linear prediction",
     "tests/validation/flexible_uplift_test.cpp"},
    {"flexible", "4.2 Static uplift criterion (Chopra & Yim 1985)",
     "ramp uplift against the exact P-delta form", "1e-9 against the exact form",
     "tests/validation/flexible_uplift_test.cpp"},
    {"friction", "8. Sliding: Coulomb friction at the base",
     "rigid block under a rectangular pulse against the closed form slip distance",
     "4e-15 relative (asserted 1e-12)", "tests/unit/sliding_test.cpp"},
    {"friction", "8. Sliding: Coulomb friction at the base",
     "rigid block under sampled records against an event-exact sliding block",
     "final and peak offset 1e-9 m, the same number of slips", "tests/unit/sliding_test.cpp"},
    {"friction", "8.1 El Centro 1940: a squat rigid block and the flexible tank",
     "peak and residual offsets with rtol and atol 10 times finer",
     "Largest change of a peak or residual offset when rtol and atol are made 10 times finer: "
     "2.2e-10 m",
     "tools/validation/sliding_records.py"},
    {"compliant", "10. The impulsive laws against the compliant contact",
     "the impulsive impact laws against the compliant (spring-dashpot) contact", "",
     "tools/validation/compliant.py"},
};

// the standards' simplified estimates, and why each is or is not in the report
struct StandardNote {
  const char* name;
  const char* why;
};
const StandardNote kStandards[] = {
    {"ASCE 4-16 (seismic analysis of safety-related nuclear structures), sliding and rocking of "
     "unanchored bodies",
     "not included: its simplified energy-balance formulas are not available from a public "
     "source that could be checked here; the Housner energy estimate above is the classical "
     "form such methods derive from"},
    {"ASCE 43-19 / US NRC NUREG reports on free-standing casks",
     "not included: the acceptance formulas could not be taken from a public source and checked "
     "against their closed forms"},
    {"Eurocode 8 (EN 1998-1) and FEMA P-58 (unanchored components)",
     "not included: EN 1998 is not public; FEMA P-58's component fragilities are empirical "
     "curves, not closed-form rocking or sliding estimates"},
};

double finite_or_nan(double v) { return std::isfinite(v) ? v : std::nan(""); }

Json number(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

// the name of a case from its corner
std::string case_name(const QualifyFile& f, const QualifyCase& c) {
  std::string s = "mu=" + (std::isfinite(c.friction) ? format_number(c.friction) : "inf");
  if (f.mass_tolerance > 0.0) s += c.mass_factor < 1.0 ? " M-" : " M+";
  if (f.cg_height_tolerance > 0.0) s += c.cg_height_factor < 1.0 ? " h-" : " h+";
  if (f.cg_offset_tolerance > 0.0) s += c.cg_offset < 0.0 ? " cg->1" : " cg->2";
  if (c.damping) s += " zeta=" + format_number(*c.damping);
  return s;
}

// a body with one body-changing parameter applied (study::apply: the uncertain parameters' rules)
BodyParameters apply_one(study::UncertainKind kind, double value, const BodyParameters& body) {
  study::Uncertainty u;
  u.parameters.push_back({kind, study::Distribution::kUniform, value, value});
  return study::apply(u, {value}, body);
}

bool rigid(const BodyParameters& b) { return b.mu.size() == 0; }

// the compliant contact of stiffness k [N/m] in place of the impulsive floor: the impact law's
// own keys back at their defaults (the springs resolve each impact)
SimulationOptions compliant_options(SimulationOptions o, double k) {
  const SimulationOptions d;
  o.contact_model = ContactModel::kCompliant;
  o.contact_force_law = ContactForceLaw::kLinear;
  o.contact_stiffness = k;
  o.contact_exponent = 1.0;
  o.impact_law = d.impact_law;
  o.restitution_factor = d.restitution_factor;
  o.impact_duration = d.impact_duration;
  return o;
}

}  // namespace

const std::vector<QualifyKey>& qualify_keys() { return kKeys; }

const QualifyKey& qualify_key(std::string_view table, std::string_view key) {
  for (const QualifyKey& k : kKeys)
    if (table == k.table && key == k.key) return k;
  throw std::logic_error("qualify_key: no key " + std::string(table) + "." + std::string(key));
}

std::string qualify_key_reference() {
  std::string s =
      "<!-- begin: written by `flexrock keys --markdown` from the table of qualification keys "
      "(src/io/qualify.cpp); edit the table, not these lines -->\n"
      "| table | key | unit | default | meaning |\n|---|---|---|---|---|\n";
  for (const QualifyKey& k : kKeys) {
    const std::string table = *k.table ? std::string("[") + k.table + "]" : "top level";
    const bool arr = std::string(k.table) == "record" || std::string(k.table) == "suite";
    s += "| " + (arr ? "[[" + std::string(k.table) + "]]" : table) + " | `" + k.key + "` | " +
         k.unit + " | " + k.default_value + " | " + k.doc + " |\n";
  }
  return s + "<!-- end: written by `flexrock keys --markdown` -->\n";
}

// ---------------------------------------------------------------------------------------------
// SHA-256 (FIPS 180-4)

std::string sha256_hex(std::string_view bytes) {
  static constexpr std::array<std::uint32_t, 64> k = {
      0x428a2f98, 0x71374491, 0xb5c0fbcf, 0xe9b5dba5, 0x3956c25b, 0x59f111f1, 0x923f82a4,
      0xab1c5ed5, 0xd807aa98, 0x12835b01, 0x243185be, 0x550c7dc3, 0x72be5d74, 0x80deb1fe,
      0x9bdc06a7, 0xc19bf174, 0xe49b69c1, 0xefbe4786, 0x0fc19dc6, 0x240ca1cc, 0x2de92c6f,
      0x4a7484aa, 0x5cb0a9dc, 0x76f988da, 0x983e5152, 0xa831c66d, 0xb00327c8, 0xbf597fc7,
      0xc6e00bf3, 0xd5a79147, 0x06ca6351, 0x14292967, 0x27b70a85, 0x2e1b2138, 0x4d2c6dfc,
      0x53380d13, 0x650a7354, 0x766a0abb, 0x81c2c92e, 0x92722c85, 0xa2bfe8a1, 0xa81a664b,
      0xc24b8b70, 0xc76c51a3, 0xd192e819, 0xd6990624, 0xf40e3585, 0x106aa070, 0x19a4c116,
      0x1e376c08, 0x2748774c, 0x34b0bcb5, 0x391c0cb3, 0x4ed8aa4a, 0x5b9cca4f, 0x682e6ff3,
      0x748f82ee, 0x78a5636f, 0x84c87814, 0x8cc70208, 0x90befffa, 0xa4506ceb, 0xbef9a3f7,
      0xc67178f2};
  std::array<std::uint32_t, 8> h = {0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a,
                                    0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19};
  auto rotr = [](std::uint32_t x, int n) { return (x >> n) | (x << (32 - n)); };
  // the message padded: 0x80, zeros, the length in bits (big-endian)
  std::string m(bytes);
  const std::uint64_t bits = static_cast<std::uint64_t>(bytes.size()) * 8;
  m.push_back(static_cast<char>(0x80));
  while (m.size() % 64 != 56) m.push_back('\0');
  for (int i = 7; i >= 0; --i) m.push_back(static_cast<char>((bits >> (8 * i)) & 0xff));
  for (std::size_t chunk = 0; chunk < m.size(); chunk += 64) {
    std::array<std::uint32_t, 64> w{};
    for (int i = 0; i < 16; ++i) {
      w[i] = 0;
      for (int j = 0; j < 4; ++j)
        w[i] = (w[i] << 8) | static_cast<unsigned char>(m[chunk + 4 * i + j]);
    }
    for (int i = 16; i < 64; ++i) {
      const std::uint32_t s0 = rotr(w[i - 15], 7) ^ rotr(w[i - 15], 18) ^ (w[i - 15] >> 3);
      const std::uint32_t s1 = rotr(w[i - 2], 17) ^ rotr(w[i - 2], 19) ^ (w[i - 2] >> 10);
      w[i] = w[i - 16] + s0 + w[i - 7] + s1;
    }
    std::array<std::uint32_t, 8> v = h;
    for (int i = 0; i < 64; ++i) {
      const std::uint32_t S1 = rotr(v[4], 6) ^ rotr(v[4], 11) ^ rotr(v[4], 25);
      const std::uint32_t ch = (v[4] & v[5]) ^ (~v[4] & v[6]);
      const std::uint32_t t1 = v[7] + S1 + ch + k[i] + w[i];
      const std::uint32_t S0 = rotr(v[0], 2) ^ rotr(v[0], 13) ^ rotr(v[0], 22);
      const std::uint32_t maj = (v[0] & v[1]) ^ (v[0] & v[2]) ^ (v[1] & v[2]);
      const std::uint32_t t2 = S0 + maj;
      v = {t1 + t2, v[0], v[1], v[2], v[3] + t1, v[4], v[5], v[6]};
    }
    for (int i = 0; i < 8; ++i) h[i] += v[i];
  }
  static const char* hex = "0123456789abcdef";
  std::string out;
  for (std::uint32_t x : h)
    for (int i = 7; i >= 0; --i) out.push_back(hex[(x >> (4 * i)) & 0xf]);
  return out;
}

// ---------------------------------------------------------------------------------------------
// the qualification file

namespace {

// a key's expectation, from the table: "<doc> [unit]"
std::string what(const char* table, const char* key) {
  const QualifyKey& k = qualify_key(table, key);
  return std::string(k.doc) + (*k.unit ? std::string(" [") + k.unit + "]" : std::string());
}

}  // namespace

QualifyFile load_qualify_file(const std::string& path) {
  const toml::table doc = detail::parse_toml(path, "qualification");
  Keys top(path, doc, "");
  // a misspelt table is named before any table found missing
  for (const QualifyKey& k : kKeys) top.has(*k.table ? k.table : k.key);
  top.finish("at the top level (see docs/qualify.md)");
  QualifyFile f;
  f.source = path;
  f.name = top.string_opt("name", "a string").value_or(fs::path(path).stem().string());
  f.description = top.string_opt("description", "a string").value_or("");
  f.input_files.push_back(path);
  f.input_roles.emplace_back("qualification");
  std::uint64_t h = fnv1a(file_bytes(path));
  const bool inline_body = top.has("body") && doc.get("body")->is_table();
  if (inline_body) {
    f.body_source = path;
  } else {
    f.body_source = detail::resolve_path(path, top.string("body", what("", "body")));
    h = fnv1a(file_bytes(f.body_source), h);
  }
  {
    std::vector<std::string> files;
    refuse_restraints(f.body_source, "a qualification");
    f.body = load_body(f.body_source, &f.body_type, &files);
    FLEXROCK_THROW_UNLESS(f.body_type != "rocking_frame",
                          f.body_source +
                              ": [body] type 'rocking_frame': qualify does not run rocking frames "
                              "yet; run it as a case (flexrock run), which checks the frame's "
                              "contacts");
    for (const std::string& b : files) {
      if (b == path) continue;
      f.input_files.push_back(b);
      f.input_roles.emplace_back("body");
    }
  }
  study::SweepSpec& spec = f.spec;
  if (auto s = top.table_opt("solver")) read_solver(*s, spec.solver, f.body);

  // parameter ranges: the corners of the box are the bounding cases
  f.friction = {spec.solver.friction_coefficient};
  const bool friction_given = [&] {
    auto r = top.table_opt("ranges");
    if (!r) return false;
    bool given = false;
    if (auto mus = r->node("friction")) {
      const toml::array* a = mus->as_array();
      if (!a || a->empty())
        r->expected("friction", "a non-empty array: " + what("ranges", "friction"));
      f.friction.clear();
      for (const toml::node& e : *a) {
        const double mu = r->to_number(e, "friction", what("ranges", "friction"), true);
        if (!(mu > 0.0))
          r->fail_at(line_of(e), "friction",
                     "expected values > 0: " + what("ranges", "friction") + ", got " + num(mu));
        if (std::find(f.friction.begin(), f.friction.end(), mu) != f.friction.end())
          r->fail_at(line_of(e), "friction", "expected distinct values, got " + num(mu) + " twice");
        f.friction.push_back(mu);
      }
      given = true;
      // the bounds replace [solver]'s coefficient: both given, one would be ignored
      if (std::isfinite(spec.solver.friction_coefficient) ||
          std::isfinite(spec.solver.kinetic_friction_coefficient))
        r->fail("friction",
                "expected no [solver] friction_coefficient or kinetic_friction_coefficient with "
                "[ranges] friction (the bounds replace them; give the ratio as kinetic_ratio)");
    }
    f.kinetic_ratio = r->number_or("kinetic_ratio", 1.0, what("ranges", "kinetic_ratio"));
    if (!(f.kinetic_ratio > 0.0 && f.kinetic_ratio <= 1.0))
      r->expected("kinetic_ratio", what("ranges", "kinetic_ratio"));
    auto tolerance = [&](const char* key, double& out) {
      out = r->number_or(key, 0.0, what("ranges", key));
      if (!(out >= 0.0 && out < 1.0)) r->expected(key, what("ranges", key));
    };
    tolerance("mass_tolerance", f.mass_tolerance);
    tolerance("cg_height_tolerance", f.cg_height_tolerance);
    f.cg_offset_tolerance =
        r->nonnegative_or("cg_offset_tolerance", 0.0, what("ranges", "cg_offset_tolerance"));
    if (f.cg_offset_tolerance > 0.0 && !(f.cg_offset_tolerance < std::min(f.body.b1, f.body.b2)))
      r->expected("cg_offset_tolerance", "a number below b1 = " + num(f.body.b1) +
                                             " m and b2 = " + num(f.body.b2) +
                                             " m (the c.g. must stay between the tipping points)");
    if ((f.cg_height_tolerance > 0.0 || f.cg_offset_tolerance > 0.0) && !rigid(f.body)) {
      r->fail(f.cg_height_tolerance > 0.0 ? "cg_height_tolerance" : "cg_offset_tolerance",
              "expected a rigid body: the c.g. of a body with modes follows from its mass "
              "distribution (give the tolerance of the masses in the body file instead)");
    }
    if (auto d = r->vector_opt("damping_ratio", what("ranges", "damping_ratio"))) {
      if (d->size() != 2 || !((*d)[0] >= 0.0 && (*d)[0] <= (*d)[1] && (*d)[1] < 1.0))
        r->expected("damping_ratio", "[low, high] with 0 <= low <= high < 1");
      if (rigid(f.body))
        r->fail("damping_ratio", "expected a body with modes: a rigid body has no modal damping");
      f.damping_ratio = *d;
    }
    r->finish("in [ranges] (see docs/qualify.md)");
    return given;
  }();

  // the input set: [[record]] and [[suite]] tables, as in a sweep manifest
  std::set<std::string> names;
  std::vector<Keys> record_tables;
  if (top.has("record") || !top.has("suite")) {
    record_tables = top.tables("record",
                               "a record: { file, format, units, dt, name } (or a [[suite]] of "
                               "records: { horizontal, vertical })");
  }
  for (Keys& r : record_tables) {
    study::SweepRecord sr;
    const Record rec = read_record(r, sr.name, &h, f.input_files);
    f.input_roles.resize(f.input_files.size(), "record");
    check_name(r, "name", sr.name);
    if (!names.insert(sr.name).second)
      r.fail("name", "expected a unique record name, got \"" + sr.name + "\" twice");
    sr.motion = rec.to_motion();
    spec.records.push_back(std::move(sr));
  }
  if (top.has("suite")) {
    for (Keys& r :
         top.tables("suite", "a record suite: { horizontal, vertical, format, units, dt }")) {
      for (study::SweepRecord& sr : read_suite(r, h, f.input_files)) {
        if (!names.insert(sr.name).second)
          r.fail("horizontal", "expected unique record names, got \"" + sr.name + "\" twice");
        spec.records.push_back(std::move(sr));
      }
      f.input_roles.resize(f.input_files.size(), "record");
    }
  }

  // the design level
  {
    auto d = top.table_opt("design");
    if (!d)
      throw InputError(path +
                       ": table [design]: missing; expected a [design] table with 'pga' "
                       "or 'factor' (see docs/qualify.md)");
    const bool pga = d->has("pga"), factor = d->has("factor");
    if (pga == factor)
      d->fail(pga ? "factor" : "pga", "expected exactly one of 'pga' (with 'units') or 'factor'");
    f.design_pga = pga;
    if (pga) {
      f.design_units = d->choice("units", detail::accel_unit_names(), "g");
      f.design_level = d->positive("pga", "(" + f.design_units + ")");
      spec.scale_kind = study::ScaleKind::kTargetPga;
      spec.scales = {f.design_level * to_si_factor(detail::accel_unit(f.design_units))};
      spec.level_units = f.design_units;
    } else {
      if (d->has("units")) d->fail("units", "only with 'pga'");
      f.design_level = d->positive("factor", "[-]");
      f.design_units = "-";
      spec.scale_kind = study::ScaleKind::kFactor;
      spec.scales = {f.design_level};
    }
    spec.levels = {f.design_level};
    spec.free_periods = d->nonnegative_or("free_periods", 2.0, what("design", "free_periods"));
    if (d->boolean_or("both_polarities", false)) {
      const std::size_t n = spec.records.size();
      for (std::size_t i = 0; i < n; ++i) {
        study::SweepRecord rev;
        rev.name = spec.records[i].name + "-rev";
        if (!names.insert(rev.name).second)
          d->fail("both_polarities", "expected record names free for the reversed records, got \"" +
                                         rev.name + "\" already");
        const GroundMotion& m = spec.records[i].motion;
        std::vector<double> ax = m.horizontal();
        for (double& v : ax) v = -v;
        rev.motion = GroundMotion::sampled(m.times(), std::move(ax),
                                           m.has_vertical() ? m.vertical() : std::vector<double>{});
        spec.records.push_back(std::move(rev));
      }
      h = fnv1a("both_polarities", h);
    }
    d->finish("in [design] (see docs/qualify.md)");
  }

  // the acceptance criteria
  {
    auto c = top.table_opt("criteria");
    if (!c)
      throw InputError(path +
                       ": table [criteria]: missing; expected a [criteria] table with at "
                       "least one of tilt_fraction, sliding_clearance, impact_force, "
                       "uplift (see docs/qualify.md)");
    for (const Criterion& k : kCriteria) {
      const char* key = k.name == std::string("tilt")           ? "tilt_fraction"
                        : k.name == std::string("sliding")      ? "sliding_clearance"
                        : k.name == std::string("impact_force") ? "impact_force"
                                                                : "uplift";
      if (const auto v = c->number_opt(key, what("criteria", key))) {
        if (!(*v > 0.0) || (k.name == std::string("tilt") && *v > 1.0))
          c->expected(key, what("criteria", key));
        f.criteria.*(k.limit) = *v;
      }
    }
    if (f.criteria.impact_force && spec.solver.contact_model == ContactModel::kCompliant)
      c->fail(
          "impact_force",
          "expected the impulsive contact: with contact_model = \"compliant\" the runs keep no "
          "impulse to estimate the force from (the resolved contact force is in `flexrock run`'s "
          "summary)");
    c->finish("in [criteria] (see docs/qualify.md)");
    if (!f.criteria.tilt_fraction && !f.criteria.sliding_clearance && !f.criteria.impact_force &&
        !f.criteria.uplift)
      c->fail_at(c->line(), "tilt_fraction",
                 "missing; expected at least one criterion: tilt_fraction, sliding_clearance, "
                 "impact_force, uplift");
  }

  // the IDA
  f.ida_factors = {0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 6.0, 8.0};
  if (auto a = top.table_opt("ida")) {
    f.ida = a->boolean_or("enabled", true);
    if (auto g = grid_opt(*a, "factors", "[-]")) {
      for (std::size_t i = 0; i < g->size(); ++i) {
        if (!((*g)[i] > 0.0) || (i > 0 && !((*g)[i] > (*g)[i - 1])))
          a->expected("factors", what("ida", "factors"));
      }
      f.ida_factors = *g;
    }
    f.ida_tolerance = a->number_or("tolerance", 0.01, what("ida", "tolerance"));
    if (!(f.ida_tolerance >= 1e-6 && f.ida_tolerance <= 0.5))
      a->expected("tolerance", what("ida", "tolerance"));
    a->finish("in [ida] (see docs/qualify.md)");
  }
  if (auto r = top.table_opt("report")) {
    f.history_dt = r->positive_or("history_dt", 0.01, "[s]");
    if (r->has("contact_stiffness")) {
      SimulationOptions c =
          compliant_options(spec.solver, r->positive("contact_stiffness", "[N/m]"));
      try {
        validate_options(Body(f.body), {}, c);
      } catch (const InputError& e) {
        r->fail("contact_stiffness", std::string("expected a stiffness the compliant contact "
                                                 "takes: ") +
                                         e.what());
      }
      f.contact_stiffness = c.contact_stiffness;
    }
    f.fragility = r->boolean_or("fragility", false);
    if (f.fragility && !f.ida)
      r->fail("fragility",
              "expected [ida] enabled = true: the fragility is fitted to the IDA's "
              "capacities");
    r->finish("in [report] (see docs/qualify.md)");
  }
  top.finish("at the top level (see docs/qualify.md)");

  // the bounding cases: every corner of the ranges, friction-major
  std::vector<double> masses = {1.0}, heights = {1.0}, offsets = {0.0};
  std::vector<std::optional<double>> dampings = {std::nullopt};
  if (f.mass_tolerance > 0.0) masses = {1.0 - f.mass_tolerance, 1.0 + f.mass_tolerance};
  if (f.cg_height_tolerance > 0.0)
    heights = {1.0 - f.cg_height_tolerance, 1.0 + f.cg_height_tolerance};
  if (f.cg_offset_tolerance > 0.0) offsets = {-f.cg_offset_tolerance, f.cg_offset_tolerance};
  if (!f.damping_ratio.empty()) dampings = {f.damping_ratio[0], f.damping_ratio[1]};
  std::string canonical;
  for (double mu : f.friction)
    for (double m : masses)
      for (double hf : heights)
        for (double e : offsets)
          for (const auto& z : dampings) {
            QualifyCase c;
            c.friction = mu;
            c.kinetic_friction = std::isfinite(mu) ? mu * f.kinetic_ratio : kInf;
            c.mass_factor = m;
            c.cg_height_factor = hf;
            c.cg_offset = e;
            c.damping = z;
            BodyParameters b = f.body;
            if (m != 1.0) b = apply_one(study::UncertainKind::kMassScale, m, b);
            if (hf != 1.0) b = apply_one(study::UncertainKind::kCgHeightScale, hf, b);
            if (z) b = apply_one(study::UncertainKind::kDampingRatio, *z, b);
            b.b1 += e;  // the c.g. moved toward edge 2 (e > 0) is farther from edge 1
            b.b2 -= e;
            c.body = b;
            c.name = case_name(f, c);
            canonical += c.name + ";";
            study::SweepBody sb;
            sb.name = c.name;
            sb.body = b;
            if (friction_given) {
              sb.friction_coefficient = mu;
              if (std::isfinite(mu)) sb.kinetic_friction_coefficient = c.kinetic_friction;
            } else {
              c.friction = spec.solver.friction_coefficient;
              c.kinetic_friction = std::isfinite(spec.solver.kinetic_friction_coefficient)
                                       ? spec.solver.kinetic_friction_coefficient
                                       : c.friction;
            }
            spec.bodies.push_back(std::move(sb));
            f.cases.push_back(std::move(c));
          }
  if (spec.bodies.size() * spec.records.size() > kMaxStudyRuns)
    throw InputError(path + ": expected at most " + std::to_string(kMaxStudyRuns) + " runs, got " +
                     std::to_string(spec.bodies.size()) + " cases x " +
                     std::to_string(spec.records.size()) + " records");
  try {
    study::validate(spec);
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
  // the cases and the IDA settings are inputs of the journals too
  canonical += "ida:" + std::to_string(f.ida) + ":" + format_number(f.ida_tolerance);
  for (double v : f.ida_factors) canonical += "," + format_number(v);
  f.hash = fnv1a(canonical, h);
  return f;
}

// ---------------------------------------------------------------------------------------------
// the session

namespace {

double design_scale(const study::SweepSpec& spec, std::size_t record) {
  const study::Intensity im = study::record_intensity(spec, spec.records[record]);
  return spec.scale_kind == study::ScaleKind::kTargetPga ? spec.scales[0] / im.pga : spec.scales[0];
}

SimulationOptions case_solver(const QualifyFile& f, const QualifyCase& c) {
  SimulationOptions o = f.spec.solver;
  o.friction_coefficient = c.friction;
  o.kinetic_friction_coefficient = c.kinetic_friction;
  return o;
}

std::string work_path(const std::string& dir, const std::string& name) {
  return (fs::path(dir) / name).string();
}

}  // namespace

QualifySession::QualifySession(QualifyFile file, std::string work_dir)
    : file_(std::move(file)), work_dir_(std::move(work_dir)) {
  std::error_code ec;
  fs::create_directories(work_dir_, ec);
  if (ec)
    throw InputError(work_dir_ + ": " + ec.message() +
                     "; expected a directory for the qualification's runs");
  SweepManifest m;
  m.source = file_.source;
  m.spec = file_.spec;
  m.hash = file_.hash;
  m.input_files = file_.input_files;
  design_ = std::make_unique<SweepSession>(std::move(m), work_path(work_dir_, "design.csv"));
  if (!file_.ida) return;
  const study::SweepSpec& spec = file_.spec;
  for (std::size_t c = 0; c < file_.cases.size(); ++c) {
    for (std::size_t r = 0; r < spec.records.size(); ++r) {
      SpectrumFile sf;
      sf.source = file_.source;
      sf.name = file_.name;
      sf.body_source = file_.body_source;
      sf.body = file_.cases[c].body;
      sf.is_record = true;
      sf.record.motion = spec.records[r].motion;
      const double s = design_scale(spec, r);
      for (double k : file_.ida_factors) sf.record.scales.push_back(k * s);
      sf.record.free_periods = spec.free_periods;
      sf.record.bisect = true;
      sf.record.bisection_tolerance = file_.ida_tolerance;
      sf.record.solver = case_solver(file_, file_.cases[c]);
      sf.record_name = spec.records[r].name;
      sf.input_files = file_.input_files;
      sf.hash = fnv1a("ida case " + std::to_string(c) + " record " + std::to_string(r), file_.hash);
      const std::string stem = "ida_c" + std::to_string(c) + "_r" + std::to_string(r);
      ida_.push_back(
          std::make_unique<SpectrumSession>(std::move(sf), work_path(work_dir_, stem + ".csv"),
                                            work_path(work_dir_, stem + ".boundary.csv")));
    }
  }
}

QualifySession::~QualifySession() = default;

std::size_t QualifySession::design_runs() const { return design_->runs(); }

std::size_t QualifySession::resumed() const {
  std::size_t n = design_->resumed();
  for (const auto& s : ida_) n += s->resumed();
  return n;
}

void QualifySession::run(const study::RunOptions& options) {
  design_->run(options);
  if (options.cancel && options.cancel->load()) return;
  // the IDA sessions side by side, one thread each (each bisection is sequential)
  study::RunOptions one = options;
  one.threads = 1;
  study::parallel_for(
      ida_.size(), options.threads, [&](std::size_t i) { ida_[i]->run(one); }, options.cancel);
}

namespace {

// the report's numbers, from the rows and spectra

Json body_json(const BodyParameters& p) {
  const Body body(p);
  Json j;
  j["mass_kg"] = p.mass;
  j["height_m"] = p.height;
  j["b1_m"] = p.b1;
  j["b2_m"] = p.b2;
  j["zeta2"] = p.zeta2;
  j["modes"] = body.modes();
  j["alpha1"] = body.alpha1();
  j["alpha2"] = body.alpha2();
  j["uplift_acceleration_edge1_m_per_s2"] = study::uplift_threshold(p, 1);
  j["uplift_acceleration_edge2_m_per_s2"] = study::uplift_threshold(p, 2);
  j["tipping_angle_edge1_rad"] = body.tipping_angle(1);
  j["tipping_angle_edge2_rad"] = body.tipping_angle(2);
  j["rocking_frequency_rad_per_s"] = body.rocking_frequency();
  Json fr = Json::array(), zr = Json::array();
  for (Eigen::Index i = 0; i < body.natural_frequencies().size(); ++i) {
    fr.push_back(body.natural_frequencies()(i) / (2.0 * std::numbers::pi));
    zr.push_back(body.damping_ratios()(i));
  }
  j["natural_frequencies_hz"] = fr;
  j["damping_ratios"] = zr;
  return j;
}

double demand(const Criterion& k, const study::RunSummary& r, double tau) {
  return finite_or_nan(k.demand(r, tau));
}

study::RunSummary rerun(const QualifyFile& f, std::size_t c, const study::SweepRow& row,
                        SimulationOptions o, SimulationResult* out = nullptr) {
  const Body body(f.cases[c].body);
  const GroundMotion motion = f.spec.records[row.record].motion.scaled(row.scale);
  o.t_end = row.duration;
  SimulationResult res = simulate(body, motion, {}, o);
  study::RunSummary s = study::summarize(body, res);
  if (out) *out = std::move(res);
  return s;
}

}  // namespace

QualifyReport QualifySession::finish() {
  const QualifyFile& f = file_;
  const study::SweepSpec& spec = f.spec;
  const std::vector<study::SweepRow> rows = design_->finish();
  std::vector<study::SpectrumResult> ida;
  for (auto& s : ida_) ida.push_back(s->finish());
  const std::size_t nr = spec.records.size();
  const double tau = spec.solver.impact_duration;
  const double g = f.body.gravity;

  Json j;
  j["schema"] = "flexrock.qualification";
  j["schema_version"] = 1;
  j["flexrock_version"] = version();
  j["build"] = {{"compiler", __VERSION__},
#ifdef NDEBUG
                {"assertions", false}
#else
                {"assertions", true}
#endif
  };
  j["qualification"] = {{"name", f.name}, {"description", f.description}, {"file", f.source}};
  Json inputs = Json::array();
  for (std::size_t i = 0; i < f.input_files.size(); ++i) {
    const std::string bytes = read_input_file(f.input_files[i], "input");
    inputs.push_back({{"role", i < f.input_roles.size() ? f.input_roles[i] : "input"},
                      {"path", f.input_files[i]},
                      {"bytes", bytes.size()},
                      {"sha256", sha256_hex(bytes)}});
  }
  j["inputs"] = inputs;
  Json body = body_json(f.body);
  body["type"] = f.body_type;
  body["source"] = f.body_source;
  j["body"] = body;
  Json ranges;
  Json mus = Json::array();
  for (double mu : f.friction) mus.push_back(number(mu));
  ranges["friction"] = mus;
  ranges["kinetic_ratio"] = f.kinetic_ratio;
  ranges["mass_tolerance"] = f.mass_tolerance;
  ranges["cg_height_tolerance"] = f.cg_height_tolerance;
  ranges["cg_offset_tolerance_m"] = f.cg_offset_tolerance;
  ranges["damping_ratio"] = f.damping_ratio;
  j["ranges"] = ranges;
  j["design"] = {{"kind", f.design_pga ? "pga" : "factor"},
                 {"level", f.design_level},
                 {"units", f.design_units},
                 {"free_periods", spec.free_periods}};
  const SimulationOptions& o = spec.solver;
  j["method"] = {
      {"overturn", solver_choice_name(o.overturn)},
      {"impact_law", to_string(o.impact_law)},
      {"contact_model", to_string(o.contact_model)},
      {"restitution_factor", o.restitution_factor},
      {"impact_duration_s", o.impact_duration},
      {"rtol", o.rtol},
      {"atol", o.atol},
      {"impact_force",
       "pi I_y / (2 impact_duration): the peak of a half-sine contact of the assumed duration "
       "carrying the largest vertical impulse I_y"}};

  // records at the design level
  Json recs = Json::array();
  for (std::size_t r = 0; r < nr; ++r) {
    const study::Intensity im = study::record_intensity(spec, spec.records[r]);
    const double s = rows[r].scale;  // case 0's row of this record
    recs.push_back({{"name", spec.records[r].name},
                    {"pga_m_per_s2", im.pga},
                    {"pgv_m_per_s", im.pgv},
                    {"duration_s", spec.records[r].motion.duration()},
                    {"design_scale", s},
                    {"design_pga_m_per_s2", rows[r].pga},
                    {"design_pgv_m_per_s", rows[r].pgv}});
  }
  j["records"] = recs;

  // the cases
  Json cases = Json::array();
  for (std::size_t c = 0; c < f.cases.size(); ++c) {
    const QualifyCase& k = f.cases[c];
    Json cj = {{"index", c},
               {"name", k.name},
               {"friction", number(k.friction)},
               {"kinetic_friction", number(k.kinetic_friction)},
               {"mass_factor", k.mass_factor},
               {"cg_height_factor", k.cg_height_factor},
               {"cg_offset_m", k.cg_offset},
               {"damping_ratio", k.damping ? Json(*k.damping) : Json(nullptr)}};
    cj["body"] = body_json(k.body);
    cases.push_back(cj);
  }
  j["cases"] = cases;

  // every run at the design level (the design CSV's rows)
  Json runs = Json::array();
  std::vector<std::string> warnings;
  std::size_t stopped = 0, over = 0, tension = 0;
  double max_pull = 0.0;
  for (const study::SweepRow& r : rows) {
    const study::RunSummary& s = r.run;
    runs.push_back({{"index", r.index},
                    {"case", r.body},
                    {"record", r.record},
                    {"scale", r.scale},
                    {"pga_m_per_s2", r.pga},
                    {"pgv_m_per_s", r.pgv},
                    {"outcome", study::to_string(s.outcome)},
                    {"status", to_string(s.status)},
                    {"max_theta_rad", number(s.max_theta)},
                    {"max_theta_over_alpha", number(s.max_theta_over_alpha)},
                    {"max_uplift_m", number(s.max_uplift)},
                    {"max_offset_m", number(s.max_offset)},
                    {"final_offset_m", number(s.final_offset)},
                    {"max_impulse_N_s", number(s.max_impulse)},
                    {"impact_force_N", number(impact_force(s, tau))},
                    {"impacts", s.impacts},
                    {"slips", s.slips},
                    {"message", r.message}});
    stopped += s.outcome == study::Outcome::kStopped ? 1 : 0;
    over += study::overturned(s.outcome) ? 1 : 0;
    if (s.tension_episodes > 0) ++tension;
    max_pull = std::max(max_pull, s.max_pivot_pull);
  }
  j["runs"] = runs;
  if (stopped)
    warnings.push_back(std::to_string(stopped) +
                       " run(s) stopped before the end (see their message): their demands are "
                       "not results");
  if (over) warnings.push_back(std::to_string(over) + " run(s) overturned at the design level");
  if (tension)
    warnings.push_back(std::to_string(tension) +
                       " run(s) without a friction limit had the floor pull on a held pivot "
                       "(the sticking-contact assumption broke; largest pull " +
                       format_number(max_pull, 4) + " N): give friction bounds");

  // the criteria: demand per case (largest over the records), the governing case, the ratio
  std::vector<std::string> summary;
  Json crits = Json::array();
  bool pass = stopped == 0 && over == 0;
  std::map<std::string, std::size_t> governing_row;
  for (const Criterion& k : kCriteria) {
    const std::optional<double> limit = f.criteria.*(k.limit);
    if (!limit) continue;
    Json per = Json::array();
    std::size_t gov = 0;
    double gov_v = -kInf;
    for (std::size_t c = 0; c < f.cases.size(); ++c) {
      double mx = -kInf, sum = 0.0;
      std::size_t at = c * nr;
      for (std::size_t r = 0; r < nr; ++r) {
        const double v = demand(k, rows[c * nr + r].run, tau);
        sum += std::isfinite(v) ? v : 0.0;
        if (v > mx) {
          mx = v;
          at = c * nr + r;
        }
      }
      per.push_back({{"case", c},
                     {"max", number(mx)},
                     {"mean", sum / static_cast<double>(nr)},
                     {"record_of_max", rows[at].record},
                     {"ratio", number(mx / *limit)}});
      if (mx > gov_v) {
        gov_v = mx;
        gov = at;
      }
    }
    const double ratio = gov_v / *limit;
    const bool ok = ratio <= 1.0;
    summary.push_back(std::string(k.name) + ": " + format_number(gov_v, 4) + " " + k.unit + " of " +
                      format_number(*limit, 4) + " (ratio " + format_number(ratio, 3) +
                      (ok ? ", ok" : ", EXCEEDED") + "), governed by " +
                      f.cases[rows[gov].body].name + " under " +
                      spec.records[rows[gov].record].name);
    pass = pass && ok;
    governing_row[k.name] = gov;
    crits.push_back(
        {{"name", k.name},
         {"demand", k.what},
         {"unit", k.unit},
         {"limit", *limit},
         {"per_case", per},
         {"governing",
          {{"case", rows[gov].body}, {"record", rows[gov].record}, {"demand", number(gov_v)}}},
         {"ratio", number(ratio)},
         {"pass", ok}});
  }
  j["criteria"] = crits;

  // the IDA: per case and record, the smallest overturning multiple of the design level
  Json idaj;
  idaj["enabled"] = f.ida;
  idaj["factors"] = f.ida_factors;
  idaj["tolerance"] = f.ida_tolerance;
  idaj["method"] =
      "per case and record: the grid of multiples of the design level scanned upward to the "
      "first overturning one, then bisection between it and the grid point below to the "
      "stated relative width; the margin is the upper end of the bracket (shown to overturn)";
  Json per = Json::array();
  double min_margin = kInf;
  std::size_t min_at = 0;
  std::vector<double> margins;
  for (std::size_t i = 0; i < ida.size(); ++i) {
    const std::size_t c = i / nr, r = i % nr;
    const study::SpectrumResult& res = ida[i];
    const double s = rows[c * nr + r].scale;
    Json curve = Json::array();
    for (const study::SpectrumCell& cell : res.cells) {
      curve.push_back({{"factor", cell.amplitude / s},
                       {"max_theta_over_alpha", number(cell.run.max_theta_over_alpha)},
                       {"overturned", study::overturned(cell.run.outcome)},
                       {"outcome", study::to_string(cell.run.outcome)}});
    }
    const study::OverturnBoundary& b = res.boundary.at(0);
    Json bj = {{"case", c},
               {"record", spec.records[r].name},
               {"design_scale", s},
               {"kind", to_string(b.kind)},
               {"bisection_runs", b.bisection_runs},
               {"curve", curve}};
    if (b.kind == study::OverturnBoundary::Kind::kNone) {
      bj["margin"] = nullptr;
      bj["safe_margin"] = f.ida_factors.back();
      bj["note"] = "no overturning up to the largest factor: the margin is above it";
      margins.push_back(kInf);
    } else {
      const double m = b.overturning / s;
      bj["margin"] = m;
      bj["safe_margin"] =
          b.kind == study::OverturnBoundary::Kind::kFound ? Json(b.safe / s) : Json(nullptr);
      bj["mode"] = study::to_string(b.mode);
      margins.push_back(m);
      if (m < min_margin) {
        min_margin = m;
        min_at = i;
      }
    }
    per.push_back(bj);
  }
  idaj["per"] = per;
  if (std::isfinite(min_margin)) {
    idaj["min_margin"] = {{"margin", min_margin},
                          {"case", f.cases[min_at / nr].name},
                          {"record", spec.records[min_at % nr].name}};
  } else {
    idaj["min_margin"] = nullptr;
  }
  // the median over every case and record, those that never overturned counted above the grid
  // (null: the median lies above the largest factor)
  std::sort(margins.begin(), margins.end());
  idaj["overturning_curves"] =
      std::count_if(margins.begin(), margins.end(), [](double v) { return std::isfinite(v); });
  const double median = margins.empty() ? kInf
                        : margins.size() % 2
                            ? margins[margins.size() / 2]
                            : 0.5 * (margins[margins.size() / 2 - 1] + margins[margins.size() / 2]);
  idaj["median_margin"] = number(median);
  // the smallest margin again with the bisection and the integration 10 times finer: the margin
  // is a result only if it stays put
  if (std::isfinite(min_margin)) {
    const std::size_t c = min_at / nr, r = min_at % nr;
    study::RecordSpectrumSpec rs;
    rs.motion = spec.records[r].motion;
    const double s = rows[c * nr + r].scale;
    for (double k : f.ida_factors) rs.scales.push_back(k * s);
    rs.free_periods = spec.free_periods;
    rs.bisection_tolerance = f.ida_tolerance / 10.0;
    rs.solver = case_solver(f, f.cases[c]);
    rs.solver.rtol /= 10.0;
    rs.solver.atol /= 10.0;
    study::RunOptions one;
    one.threads = 1;
    const study::SpectrumResult fine =
        study::compute_record_spectrum(Body(f.cases[c].body), rs, one);
    const study::OverturnBoundary& b = fine.boundary.at(0);
    const double m = b.kind == study::OverturnBoundary::Kind::kNone ? kInf : b.overturning / s;
    const Json& coarse = idaj["per"][min_at];
    const double safe =
        coarse["safe_margin"].is_number() ? coarse["safe_margin"].get<double>() : 0.0;
    idaj["refined"] = {{"case", f.cases[c].name},
                       {"record", spec.records[r].name},
                       {"tolerance", rs.bisection_tolerance},
                       {"rtol", rs.solver.rtol},
                       {"atol", rs.solver.atol},
                       {"margin", number(m)},
                       {"relative_change", number((m - min_margin) / min_margin)},
                       {"within_coarse_bracket", m >= safe && m <= min_margin}};
  }
  if (f.ida) {
    summary.push_back(std::isfinite(min_margin)
                          ? "margin to overturning: " + format_number(min_margin, 4) +
                                " x the design level (" + f.cases[min_at / nr].name + " under " +
                                spec.records[min_at % nr].name + ")"
                          : "margin to overturning: no overturning up to " +
                                format_number(f.ida_factors.back(), 4) + " x the design level");
  }
  j["ida"] = idaj;
  // a lognormal fragility of overturning per case, fitted to the IDA's capacity intervals in
  // multiples of the design level (Baker 2015, truncated IDA)
  if (f.fragility) {
    Json fr = Json::array();
    for (std::size_t c = 0; c < f.cases.size(); ++c) {
      std::vector<study::CapacityInterval> caps;
      for (std::size_t r = 0; r < nr; ++r) {
        const Json& p = idaj["per"][c * nr + r];
        const std::string kind = p["kind"].get<std::string>();
        if (kind == "found") {
          caps.push_back({p["safe_margin"].get<double>(), p["margin"].get<double>()});
        } else if (kind == "below_grid") {
          caps.push_back({0.0, p["margin"].get<double>()});
        } else {
          caps.push_back({f.ida_factors.back(), kInf});
        }
      }
      Json e = {{"case", c}};
      try {
        const study::FragilityFit fit = study::fit_capacity_intervals(caps);
        e["theta"] = fit.theta;
        e["beta"] = fit.beta;
        e["theta_lower"] = fit.theta_lower;
        e["theta_upper"] = fit.theta_upper;
        e["beta_lower"] = fit.beta_lower;
        e["beta_upper"] = fit.beta_upper;
        e["confidence"] = fit.confidence;
        e["records"] = fit.samples;
        e["probability_at_design"] =
            0.5 * std::erfc(-std::log(1.0 / fit.theta) / (fit.beta * std::numbers::sqrt2));
      } catch (const InputError& err) {
        e["error"] = err.what();  // no finite estimate: said, not guessed
      }
      fr.push_back(e);
    }
    j["fragility"] = {{"im", "multiple of the design level"},
                      {"method",
                       "lognormal by maximum likelihood over the capacity intervals (safe, "
                       "overturning] of the records (Baker 2015, truncated IDA)"},
                      {"per_case", fr}};
  }

  // hand estimates, per case (the rigid constants of its body) and record
  Json hand = Json::array();
  for (std::size_t c = 0; c < f.cases.size(); ++c) {
    const QualifyCase& k = f.cases[c];
    const study::RockingConstants c1 = study::rocking_constants(k.body, 1);
    const study::RockingConstants c2 = study::rocking_constants(k.body, 2);
    const double up = std::min(study::uplift_threshold(k.body, 1),
                               study::uplift_threshold(k.body, 2));  // the lower edge's
    const double vcrit =
        std::min(study::housner_critical_velocity(c1, k.body.mass, k.body.height, g),
                 study::housner_critical_velocity(c2, k.body.mass, k.body.height, g));
    const double slide = std::isfinite(k.friction) ? study::sliding_threshold(k.friction, g) : kInf;
    Json recs_h = Json::array();
    for (std::size_t r = 0; r < nr; ++r) {
      const study::SweepRow& row = rows[c * nr + r];
      const study::RunSummary& s = row.run;
      // each direction against its edge: a > 0 lifts onto edge 1, a < 0 onto edge 2
      const GroundMotion& motion = spec.records[row.record].motion;
      double a_pos = 0.0, a_neg = 0.0;
      for (double v : motion.horizontal()) {
        a_pos = std::max(a_pos, v * row.scale);
        a_neg = std::max(a_neg, -v * row.scale);
      }
      const double uplift_ratio = std::max(a_pos / study::uplift_threshold(k.body, 1),
                                           a_neg / study::uplift_threshold(k.body, 2));
      Json e = {{"record", row.record},
                {"pga_over_uplift_threshold", uplift_ratio},
                {"engine_uplifted", s.first_uplift_time >= 0.0},
                {"pga_over_sliding_threshold", number(row.pga / slide)},
                {"engine_slid", s.slips > 0},
                {"pgv_over_housner_velocity", row.pgv / vcrit},
                {"engine_overturned", study::overturned(s.outcome)},
                {"housner_pulse_duration_s",
                 // each direction's peak against its edge, as for the uplift
                 number(std::min(study::housner_rectangular_min_duration(c1, g, a_pos),
                                 study::housner_rectangular_min_duration(c2, g, a_neg)))}};
      if (std::isfinite(k.friction)) {
        const GroundMotion& m = spec.records[row.record].motion;
        std::vector<double> a = m.horizontal();
        for (double& v : a) v *= row.scale;
        const study::NewmarkResult n =
            study::newmark_sliding(m.times(), a, k.friction, k.kinetic_friction, g);
        e["newmark_max_offset_m"] = n.max_offset;
        e["newmark_final_offset_m"] = n.final_offset;
        e["engine_max_offset_m"] = number(s.max_offset);
        e["newmark_valid"] = s.first_uplift_time < 0.0 && !m.has_vertical();
      }
      recs_h.push_back(e);
    }
    hand.push_back({{"case", c},
                    {"uplift_threshold_edge1_m_per_s2", study::uplift_threshold(k.body, 1)},
                    {"uplift_threshold_edge2_m_per_s2", study::uplift_threshold(k.body, 2)},
                    {"sliding_threshold_m_per_s2", number(slide)},
                    {"sliding_before_uplift", slide < up},
                    {"housner_critical_velocity_m_per_s", vcrit},
                    {"alpha1", c1.alpha},
                    {"alpha2", c2.alpha},
                    {"p1_rad_per_s", c1.p},
                    {"p2_rad_per_s", c2.p},
                    {"records", recs_h}});
  }
  j["hand_estimates"] = {
      {"estimates",
       Json::array(
           {{{"name", "quasi-static uplift threshold"},
             {"formula",
              "a > g b1/h lifts onto edge 1, a < -g b2/h onto edge 2; the ratio shown is the "
              "larger of max(a)/(g b1/h) and max(-a)/(g b2/h) of the design motion"},
             {"source", "statics of a rigid body on a rigid floor; Housner (1963)"},
             {"validity",
              "rigid body, steady acceleration; a flexible body's dynamic threshold is lower "
              "near resonance (docs/validation.md 4.1)"}},
            {{"name", "quasi-static sliding threshold"},
             {"formula", "a_s = mu_s g"},
             {"source", "Coulomb friction of a rigid body in full contact"},
             {"validity",
              "rigid body in full contact; sliding comes before uplift when mu_s < b/h"}},
            {{"name", "Housner energy (velocity-pulse) overturning estimate"},
             {"formula",
              "V_crit = sqrt(2 g R (1 - cos alpha) I_O / M) / h: a base velocity change V > V_crit "
              "delivered as an impulse overturns the body; the ratio PGV / V_crit is shown"},
             {"source", "Housner (1963), BSSA 53(2): energy of an impulsively started block"},
             {"validity",
              "rigid body, one pulse much shorter than 1/p (exact as the pulse length -> 0, "
              "tests/unit/hand_estimates_test.cpp); a longer single pulse needs more, repeated "
              "pulses in phase can need less"}},
            {{"name", "Housner rectangular-pulse overturning duration"},
             {"formula",
              "t_min = -ln(1 - g alpha / a) / p: the shortest rectangular pulse of the design "
              "motion's peak a that overturns the body (linearized; each direction's peak "
              "against its edge, the shorter shown)"},
             {"source", "Housner (1963), rectangular pulse; docs/validation.md 1.3"},
             {"validity",
              "rigid slender body (error O(alpha^2), tested), a rectangular pulse; a record's "
              "pulses are shorter than its duration at the PGA"}},
            {{"name", "Newmark rigid sliding block"},
             {"formula",
              "d'' = -a - mu_k g sgn(d') while sliding, sticking when d' = 0 and |a| <= mu_s g, "
              "integrated exactly for the piecewise-linear record at the design scale, both "
              "ways"},
             {"source", "Newmark (1965), Geotechnique 15(2)"},
             {"validity",
              "a body that does not uplift (newmark_valid: the engine's run did not uplift and "
              "the record has no vertical component); exact then (tested against the engine to "
              "1e-9 m)"}}})},
      {"per_case", hand},
      {"standards", [] {
         Json a = Json::array();
         for (const StandardNote& s : kStandards) a.push_back({{"name", s.name}, {"why", s.why}});
         return a;
       }()}};

  // the governing time history: the tilt criterion's governing run (else the first criterion's)
  if (!governing_row.empty()) {
    const std::string crit = governing_row.count("tilt") ? "tilt" : governing_row.begin()->first;
    const study::SweepRow& row = rows[governing_row[crit]];
    SimulationOptions opt = study::run_options(spec, row);
    opt.output_dt = f.history_dt;
    SimulationResult res;
    rerun(f, row.body, row, opt, &res);
    const History& hs = res.history;
    j["governing_history"] = {
        {"criterion", crit},
        {"case", f.cases[row.body].name},
        {"record", row.record},
        {"record_name", spec.records[row.record].name},
        {"scale", row.scale},
        {"dt_s", f.history_dt},
        {"time_s", hs.time},
        {"theta_rad", hs.theta},
        {"offset_m", hs.offset},
        {"base_acc_x_m_per_s2", hs.base_acc_x},
        {"tipping_angle_edge1_rad", Body(f.cases[row.body].body).tipping_angle(1)},
        {"tipping_angle_edge2_rad", Body(f.cases[row.body].body).tipping_angle(2)}};
  }

  // convergence: each criterion's governing run again with rtol and atol 10 times finer
  Json conv = Json::array();
  for (const Criterion& k : kCriteria) {
    if (!governing_row.count(k.name)) continue;
    const study::SweepRow& row = rows[governing_row[k.name]];
    SimulationOptions opt = study::run_options(spec, row);
    opt.rtol /= 10.0;
    opt.atol /= 10.0;
    const double before = demand(k, row.run, tau);
    const double after = demand(k, rerun(f, row.body, row, opt), tau);
    conv.push_back(
        {{"criterion", k.name},
         {"case", f.cases[row.body].name},
         {"record", spec.records[row.record].name},
         {"demand", number(before)},
         {"demand_rtol_over_10", number(after)},
         {"relative_change", number(before != 0.0 ? (after - before) / before : after - before)}});
  }
  j["convergence"] = conv;

  // the impact force's sensitivity to the impact law and the assumed contact duration
  if (governing_row.count("impact_force")) {
    const study::SweepRow& row = rows[governing_row["impact_force"]];
    Json var = Json::array();
    auto variant = [&](const std::string& label, SimulationOptions opt) {
      const study::RunSummary s = rerun(f, row.body, row, opt);
      var.push_back(
          {{"variant", label}, {"impact_force_N", number(impact_force(s, opt.impact_duration))}});
    };
    const SimulationOptions base = study::run_options(spec, row);
    variant("as qualified (" + std::string(to_string(base.impact_law)) + ")", base);
    if (!takes_measured_ratio(base.impact_law)) {
      SimulationOptions o2 = base;
      o2.impact_law =
          base.impact_law == ImpactLaw::kPaper ? ImpactLaw::kRigidBody : ImpactLaw::kPaper;
      variant("impact_law = " + std::string(to_string(o2.impact_law)), o2);
      SimulationOptions o3 = base;
      o3.restitution_factor = 0.9 * base.restitution_factor;
      variant("restitution_factor x 0.9", o3);
    }
    SimulationOptions o4 = base;
    o4.impact_duration = 0.5 * base.impact_duration;
    variant("impact_duration x 0.5", o4);
    SimulationOptions o5 = base;
    o5.impact_duration = 2.0 * base.impact_duration;
    variant("impact_duration x 2", o5);
    if (f.contact_stiffness > 0.0) {
      // the resolved peak normal force of a tipping point on the springs
      SimulationOptions oc = compliant_options(base, f.contact_stiffness);
      SimulationResult res;
      rerun(f, row.body, row, oc, &res);
      var.push_back({{"variant", "compliant contact, k = " + format_number(f.contact_stiffness, 4) +
                                     " N/m (resolved)"},
                     {"impact_force_N", number(res.extremes.max_contact_force)}});
    }
    j["impact_sensitivity"] = {{"case", f.cases[row.body].name},
                               {"record", spec.records[row.record].name},
                               {"contact_model", to_string(base.contact_model)},
                               {"variants", var},
                               {"note",
                                "the force estimate is the impulse over the assumed contact "
                                "duration: it scales as 1/impact_duration, which is an "
                                "assumption, not a result; measure or bound it for the floor "
                                "and the body"}};
  }

  // the validation checks behind the features this qualification uses
  bool any_flexible = false, any_friction = false;
  for (const QualifyCase& c : f.cases) {
    any_flexible = any_flexible || !rigid(c.body);
    any_friction = any_friction || std::isfinite(c.friction);
  }
  Json val = Json::array();
  for (const Citation& c : kCitations) {
    const std::string feat = c.feature;
    const bool uses = feat == "record" || (feat == "rigid") ||
                      (feat == "flexible" && any_flexible) ||
                      (feat == "friction" && any_friction) ||
                      (feat == "compliant" && o.contact_model == ContactModel::kCompliant);
    if (!uses || !*c.agreement) continue;
    val.push_back({{"feature", c.feature},
                   {"section", std::string("docs/validation.md, ") + c.section},
                   {"check", c.check},
                   {"agreement", c.agreement},
                   {"test", c.test}});
  }
  j["validation"] = val;
  j["warnings"] = warnings;
  j["acceptance"] = {{"pass", pass}};

  // the demands as a pelicun demand sample: one realization a run (case x record)
  std::ostringstream csv;
  std::vector<const Criterion*> cols;
  for (const Criterion& k : kCriteria) cols.push_back(&k);
  csv << "";
  for (const Criterion* k : cols) csv << ",1-" << k->pelicun << "-0-1";
  csv << "\nUnits";
  for (const Criterion* k : cols) csv << "," << k->pelicun_unit;
  csv << "\n";
  for (const study::SweepRow& r : rows) {
    csv << r.index;
    for (const Criterion* k : cols) csv << "," << field(k->pelicun_value(r.run, tau));
    csv << "\n";
  }
  QualifyReport rep;
  rep.json = j.dump(1) + "\n";
  rep.demands_csv = csv.str();
  rep.pass = pass;
  for (const std::string& w : warnings) summary.push_back("warning: " + w);
  rep.summary = std::move(summary);
  return rep;
}

}  // namespace flexrock::io
