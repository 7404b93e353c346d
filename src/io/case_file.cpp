// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/io/case_file.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <numbers>
#include <optional>
#include <set>
#include <sstream>
#include <utility>

#include "decimal_comma.hpp"
#include "flexrock/core/error.hpp"
#include "flexrock/excitation/azimuth.hpp"
#include "flexrock/excitation/intensity.hpp"
#include "flexrock/excitation/pulses.hpp"
#include "flexrock/io/files.hpp"
#include "flexrock/io/records.hpp"
#include "flexrock/model/builders.hpp"
#include "flexrock/sim/rocking_frame.hpp"
#include "modal_tables.hpp"
#include "restraint_reader.hpp"
#include "table_reader.hpp"

namespace flexrock::io {

namespace fs = std::filesystem;

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      const std::size_t sub = diag + (a[i - 1] == b[j - 1] ? 0 : 1);
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, sub});
      diag = up;
    }
  }
  return row[b.size()];
}

std::string closest_key(std::string_view key, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_d = std::string::npos;
  for (const std::string& c : candidates) {
    const std::size_t d = edit_distance(key, c);
    // a likely typo: a few edits for the length, or one name containing the other
    const std::size_t allowed = std::max<std::size_t>(2, (c.size() + 2) / 3);
    const bool contains = key.size() >= 3 && (c.find(key) != std::string::npos ||
                                              key.find(c) != std::string_view::npos);
    if ((d <= allowed || contains) && d < best_d) {
      best = c;
      best_d = d;
    }
  }
  return best;
}

namespace {

using detail::describe;
using detail::join;
using detail::line_of;
using detail::num;
using Reader = detail::TableReader;

// ---------------------------------------------------------------------------------------------
// small CSV files of numbers (nodes, mode shapes): src/io/modal_tables.cpp

// ---------------------------------------------------------------------------------------------
// body

// [body] damping of the modes: damping_ratios, or rayleigh_mass/rayleigh_stiffness
Damping read_damping(Reader& r) {
  Damping d;
  const auto ratios = r.vector_opt("damping_ratios", "an array of damping ratios [-], one a mode");
  const auto a = r.number_opt("rayleigh_mass", "a number >= 0 [1/s]");
  const auto b = r.number_opt("rayleigh_stiffness", "a number >= 0 [s]");
  if (ratios && (a || b)) {
    r.fail("damping_ratios", "give either damping_ratios or rayleigh_mass/rayleigh_stiffness");
  }
  if (ratios) {
    for (double z : *ratios) {
      if (z < 0.0) r.expected("damping_ratios", "damping ratios >= 0");
    }
    d.kind = DampingKind::kModal;
    d.modal_ratios =
        Eigen::Map<const VectorX>(ratios->data(), static_cast<Eigen::Index>(ratios->size()));
  } else if (a || b) {
    if (a && *a < 0.0) r.expected("rayleigh_mass", "a number >= 0 [1/s]");
    if (b && *b < 0.0) r.expected("rayleigh_stiffness", "a number >= 0 [s]");
    d.kind = DampingKind::kRayleigh;
    d.rayleigh_mass = a.value_or(0.0);
    d.rayleigh_stiffness = b.value_or(0.0);
  }
  return d;
}

VectorX to_vector(const std::vector<double>& v) {
  return Eigen::Map<const VectorX>(v.data(), static_cast<Eigen::Index>(v.size()));
}

BodyParameters read_paper_body(Reader& r) {
  BodyParameters p;
  p.mass = r.positive("mass", "[kg]");
  p.height = r.positive("height", "[m]");
  p.b1 = r.positive("b1", "[m]");
  p.b2 = r.positive("b2", "[m]");
  p.zeta2 = r.positive("zeta2", "[-]");
  p.gravity = r.positive_or("gravity", kStandardGravity, "[m/s^2]");
  const auto kappa = r.matrix_opt("kappa", "an n x n array of numbers [-]");
  const Eigen::Index n = kappa ? kappa->rows() : 0;
  auto square = [&](const char* key, const std::optional<MatrixX>& m) {
    if (m && (m->rows() != n || m->cols() != n)) {
      r.fail(key, "expected an " + std::to_string(n) + " x " + std::to_string(n) +
                      " matrix (n from kappa), got " + std::to_string(m->rows()) + " x " +
                      std::to_string(m->cols()));
    }
  };
  square("kappa", kappa);
  const auto mu = r.matrix_opt("mu", "an n x n array of numbers [-]");
  const auto gamma = r.matrix_opt("gamma", "an n x n array of numbers [-]");
  square("mu", mu);
  square("gamma", gamma);
  if (n > 0 && !mu) r.fail_at(r.line(), "mu", "missing; expected an n x n array (kappa is given)");
  p.kappa = kappa.value_or(MatrixX(0, 0));
  p.mu = mu.value_or(MatrixX(0, 0));
  p.gamma = gamma.value_or(MatrixX::Zero(n, n));
  auto vec = [&](const char* key) {
    const auto v = r.vector_opt(key, "an array of n numbers [-]");
    if (!v) return VectorX(VectorX::Zero(n));
    if (static_cast<Eigen::Index>(v->size()) != n) {
      r.fail(key, "expected " + std::to_string(n) + " values (one a mode), got " +
                      std::to_string(v->size()));
    }
    return to_vector(*v);
  };
  p.psi_x = vec("psi_x");
  p.psi_y = vec("psi_y");
  p.delta = vec("delta");
  p.beta = vec("beta");
  p.damping = read_damping(r);
  return p;
}

BodyParameters read_lumped_body(Reader& r, std::vector<std::string>& notes) {
  LumpedModel m;
  m.tip1_x = r.number("tip1_x", "a number [m] (x of tipping point 1, the left edge)");
  m.tip2_x = r.number("tip2_x", "a number [m] (x of tipping point 2, the right edge)");
  if (!(m.tip2_x > m.tip1_x)) r.expected("tip2_x", "a number > tip1_x = " + num(m.tip1_x) + " [m]");
  m.gravity = r.positive_or("gravity", kStandardGravity, "[m/s^2]");

  // nodes: inline rows [x, y, mass(, rotary_inertia)] or a table file with named columns
  std::vector<std::vector<double>> rows;
  detail::NodeTable node_table;
  std::string nodes_path;
  const bool inline_nodes = r.has("nodes");
  const auto nodes_file = r.string_opt(
      "nodes_file", "a path (CSV with a header row: node, x, y, mass[, rotary_inertia])");
  if (inline_nodes == nodes_file.has_value()) {
    r.fail_at(r.line(), "nodes", "expected exactly one of 'nodes' (inline) or 'nodes_file'");
  }
  if (inline_nodes) {
    const toml::node* n = r.node("nodes");
    const toml::array* a = n->as_array();
    if (!a || a->empty())
      r.expected("nodes", "an array of [x, y, mass] or [x, y, mass, rotary_inertia]");
    for (const toml::node& e : *a) {
      const toml::array* row = e.as_array();
      if (!row || row->size() < 3 || row->size() > 4) {
        r.fail_at(line_of(e), "nodes",
                  "expected [x, y, mass] or [x, y, mass, rotary_inertia], got " + describe(e) +
                      (row ? " with " + std::to_string(row->size()) + " values" : ""));
      }
      std::vector<double> v;
      for (const toml::node& x : *row) {
        const auto* i = x.as_integer();
        const auto* f = x.as_floating_point();
        const double d = i ? static_cast<double>(i->get()) : f ? f->get() : std::nan("");
        if (!std::isfinite(d))
          r.fail_at(line_of(x), "nodes", "expected finite numbers, got " + describe(x));
        v.push_back(d);
      }
      rows.push_back(std::move(v));
    }
  } else {
    nodes_path = detail::resolve_path(r.file(), *nodes_file);
    node_table = detail::read_node_table(nodes_path);
    for (const LumpedNode& nd : node_table.nodes)
      rows.push_back({nd.x, nd.y, nd.mass, nd.rotary_inertia});
  }
  for (std::size_t i = 0; i < rows.size(); ++i) {
    LumpedNode node{rows[i][0], rows[i][1], rows[i][2], rows[i].size() > 3 ? rows[i][3] : 0.0};
    if (!(node.mass >= 0.0) || !(node.rotary_inertia >= 0.0)) {
      r.fail(inline_nodes ? "nodes" : "nodes_file",
             "expected node masses and rotary inertias >= 0, got node " + std::to_string(i + 1) +
                 " with mass " + num(node.mass) + " kg, rotary inertia " +
                 num(node.rotary_inertia) + " kg m^2");
    }
    m.nodes.push_back(node);
  }
  const auto nn = static_cast<Eigen::Index>(m.nodes.size());

  // modes: frequencies_hz or stiffness, and the shapes inline or from a CSV file
  const auto freqs = r.vector_opt("frequencies_hz", "an array of natural frequencies > 0 [Hz]");
  const auto stiff = r.matrix_opt("stiffness", "an n x n modal stiffness matrix [N m]");
  if (freqs.has_value() == stiff.has_value()) {
    r.fail_at(r.line(), "frequencies_hz",
              "expected exactly one of 'frequencies_hz' or 'stiffness'");
  }
  const auto n = static_cast<Eigen::Index>(freqs ? freqs->size() : stiff->rows());
  if (n == 0) r.expected(freqs ? "frequencies_hz" : "stiffness", "at least one mode");
  if (freqs) {
    m.frequencies.resize(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const double f = (*freqs)[static_cast<std::size_t>(i)];
      if (!(f > 0.0)) r.expected("frequencies_hz", "natural frequencies > 0 [Hz]");
      m.frequencies(i) = 2.0 * std::numbers::pi * f;
    }
  } else {
    if (stiff->cols() != n) r.expected("stiffness", "a square matrix [N m]");
    m.stiffness = *stiff;
  }
  const bool inline_shapes = r.has("phi_x") || r.has("phi_y");
  const auto shapes_file =
      r.string_opt("shapes_file",
                   "a path (a table with named columns: node, phi_x_1, phi_y_1, ...; or one "
                   "table a mode with node, UX, UY columns)");
  if (inline_shapes == shapes_file.has_value()) {
    r.fail_at(r.line(), "phi_x",
              "expected exactly one of 'phi_x' and 'phi_y' (inline) or 'shapes_file'");
  }
  if (inline_shapes) {
    auto shape = [&](const char* key) {
      const auto s = r.matrix_opt(key, "an array of rows, one a node, of one value a mode [m]");
      if (!s)
        r.fail_at(r.line(), key, "missing; expected rows of one value a mode, one row a node");
      if (s->rows() != nn || s->cols() != n) {
        r.fail(key, "expected " + std::to_string(nn) + " rows (one a node) of " +
                        std::to_string(n) + " values (one a mode), got " +
                        std::to_string(s->rows()) + " x " + std::to_string(s->cols()));
      }
      return *s;
    };
    m.phi_x = shape("phi_x");
    m.phi_y = shape("phi_y");
  } else {
    const std::string path = detail::resolve_path(r.file(), *shapes_file);
    const detail::ShapeTable shapes = detail::read_shape_table(path, n);
    if (inline_nodes) {
      node_table.nodes = m.nodes;
      node_table.lines.assign(m.nodes.size(), r.line());
    }
    detail::match_shapes(node_table, inline_nodes ? r.file() : nodes_path, shapes, path, m.phi_x,
                         m.phi_y);
  }
  m.damping = read_damping(r);
  return from_lumped_model(m, notes);
}

// a number key of a body type (model/builders.hpp), checked by its rule; the default when not given
double read_body_number(Reader& r, const BodyKey& k) {
  const std::string unit = std::string("[") + k.unit + "]";
  if (k.value == BodyKeyValue::kInteger) {
    return static_cast<double>(r.integer_or(k.name, static_cast<long>(k.fixed), 1,
                                            std::string("an integer >= 1 (") + k.doc + ")"));
  }
  if (k.required) {
    switch (k.rule) {
      case BodyKeyRule::kPositive:
        return r.positive(k.name, unit);
      case BodyKeyRule::kNonnegative: {
        const double v = r.number(k.name, "a number >= 0 " + unit);
        if (!(v >= 0.0)) r.expected(k.name, "a number >= 0 " + unit);
        return v;
      }
      case BodyKeyRule::kFinite:
        return r.number(k.name, "a number " + unit);
    }
  }
  switch (k.rule) {
    case BodyKeyRule::kPositive:
      return r.positive_or(k.name, k.fixed, unit);
    case BodyKeyRule::kNonnegative:
      return r.nonnegative_or(k.name, k.fixed, unit);
    case BodyKeyRule::kFinite:
      return r.number_or(k.name, k.fixed, "a number " + unit);
  }
  return k.fixed;
}

// a body type whose keys are all numbers: each key by the table's rule, then its builder
BodyParameters read_table_body(Reader& r, const BodyKind& kind, BodyArgs* read = nullptr) {
  BodyArgs args;
  for (const BodyKey& k : kind.keys) args.keys.emplace(k.name, read_body_number(r, k));
  if (read) *read = args;
  return make_body(kind, std::move(args));
}

BodyParameters read_paper(Reader& r, std::vector<std::string>&) { return read_paper_body(r); }

// the readers of the body types whose keys are not all numbers (arrays, files): the table of
// body types lists their keys, these functions read them
struct BodyReader {
  const char* name;
  BodyParameters (*read)(Reader&, std::vector<std::string>& notes);
};
const BodyReader kBodyReaders[] = {
    {"paper", read_paper},
    {"lumped", read_lumped_body},
};

BodyParameters read_body_of_kind(Reader& r, const BodyKind& kind, std::vector<std::string>& notes,
                                 BodyArgs* args = nullptr) {
  if (kind.make) return read_table_body(r, kind, args);
  for (const BodyReader& b : kBodyReaders) {
    if (std::string_view(kind.name) == b.name) return b.read(r, notes);
  }
  FLEXROCK_DEMAND(false);  // a body type with neither a builder nor a reader
  return {};
}

// what was read of a [body], key by key, for `flexrock check`: numbers with their units (a
// default marked so), arrays by their size, paths as given
std::vector<BodyKeyRead> body_keys_read(Reader& r, const BodyKind& kind) {
  std::vector<BodyKeyRead> out;
  for (const BodyKey& k : kind.keys) {
    const toml::node* n = r.node(k.name);
    std::string text;
    bool given = n != nullptr;
    if (!n) {
      if (k.value != BodyKeyValue::kNumber && k.value != BodyKeyValue::kInteger) continue;
      if (k.required || !std::isfinite(k.fixed)) continue;
      text = num(k.fixed);
    } else if (const toml::array* a = n->as_array()) {
      const toml::array* row = a->empty() ? nullptr : (*a)[0].as_array();
      text = "[" +
             (row ? std::to_string(a->size()) + " x " + std::to_string(row->size())
                  : std::to_string(a->size()) + (a->size() == 1 ? " value" : " values")) +
             "]";
    } else if (const auto* str = n->as_string()) {
      text = str->get();
    } else {
      text = describe(*n);
    }
    out.push_back({k.name, text, k.unit, given});
  }
  return out;
}

// [body] of any type; `rigid` receives body.rigid, `notes` what a builder changed in the data,
// `read` (when given) what was read key by key
BodyParameters read_body(Reader& r, std::string& type, bool& rigid, std::vector<std::string>& notes,
                         std::vector<BodyKeyRead>* read = nullptr,
                         std::optional<AxisymmetricBody>* body3d = nullptr) {
  type = r.choice("type", body_kind_names());
  const BodyKind& kind = body_kind(type);
  rigid = r.boolean_or("rigid", false);
  BodyParameters p;
  try {
    BodyArgs args;
    p = read_body_of_kind(r, kind, notes, &args);
    // a body of revolution also as itself, for the 3D engine
    if (body3d && kind.make) *body3d = axisymmetric_body(type, args);
  } catch (const InputError& e) {
    // errors placed in this file pass through; builder errors get the table's place
    if (e.file() == r.file()) throw;
    throw InputError(r.file(), r.line(), "", "[body] type '" + type + "': " + e.what());
  }
  r.finish("for body type '" + type + "'");
  if (read) *read = body_keys_read(r, kind);
  if (rigid) p = taken_rigid(p);
  // validate once here, so that the error names the case file
  try {
    Body body(p);
  } catch (const InputError& e) {
    throw InputError(r.file(), r.line(), "", "[body] type '" + type + "': " + e.what());
  }
  return p;
}

// ---------------------------------------------------------------------------------------------
// excitation

// an extra key of a pulse type (excitation/pulses.hpp), checked by its rule; nullopt: not given
std::optional<double> read_pulse_key(Reader& r, const PulseKey& k) {
  const std::string unit = std::string("[") + k.unit + "]";
  const toml::node* n = r.node(k.name);
  if (!n) {
    if (k.required) r.fail_at(r.line(), k.name, "missing; expected a number " + unit);
    return std::nullopt;
  }
  switch (k.rule) {
    case PulseKeyRule::kFinite:
      return r.number(k.name, "a number " + unit);
    case PulseKeyRule::kPositive:
      return r.positive(k.name, unit);
    case PulseKeyRule::kNonnegative:
      return r.nonnegative_or(k.name, 0.0, unit);
    case PulseKeyRule::kCount:
      return static_cast<double>(r.integer_or(k.name, 1, 1, "an integer >= 1"));
  }
  return std::nullopt;
}

// every excitation type: a record, the synthetic ones, none
std::vector<std::string> motion_types() {
  std::vector<std::string> v{"record"};
  for (const PulseKind& k : pulse_kinds()) v.emplace_back(k.name);
  v.emplace_back("none");
  return v;
}

// one component: a record (kept for combine()) or a synthetic motion along its own direction
struct Built {
  std::optional<Record> record;
  GroundMotion motion;
};

Built read_component(Reader& r, bool vertical, ExcitationComponent& out) {
  out.type = r.choice("type", motion_types());
  Built b;
  const Component dir = vertical ? Component::kVertical : Component::kHorizontal;
  if (out.type == "record") {
    const detail::RecordKeys k =
        detail::read_record_keys(r, "a path to the record, relative to the case file");
    out.file = k.path;
    out.format = k.format->name;
    out.scale = r.number_or("scale", 1.0, "a number [-] (factor on this component)");
    b.record = detail::read_record_file(r, k);
    out.units = std::string(unit_name(b.record->units));
    // the file's intensity, before any scale factor
    const std::vector<double> si = b.record->to_si();
    out.pga = peak_ground_acceleration(si);
    out.pgv = peak_ground_velocity(b.record->time, si);
    out.duration = b.record->duration() - b.record->time.front();
    out.dt = b.record->dt;
    if (out.scale != 1.0) {
      for (double& v : b.record->values) v *= out.scale;
    }
    r.finish("for a record");
    return b;
  }

  const double duration = r.positive("duration", "[s] (length of the motion)");
  if (out.type == "none") {
    if (vertical) r.fail("type", "expected a motion for the vertical component, got \"none\"");
    r.finish("for type 'none'");
    b.motion = GroundMotion::none(duration);
    return b;
  }
  out.units = r.choice("units", detail::accel_unit_names());
  const double a = r.number("amplitude", "a number (peak acceleration, in `units`)");
  out.amplitude = a * to_si_factor(detail::accel_unit(out.units));
  const double ap = out.amplitude;
  const PulseKind& kind = pulse_kind(out.type);
  double omega = 0.0;
  if (kind.frequency) {
    const bool f = r.has("frequency_hz");
    const bool t = r.has("period");
    if (f == t) {
      r.fail_at(r.line(), "frequency_hz",
                "expected exactly one of 'frequency_hz' [Hz] or 'period' [s]");
    }
    // the period's range (option_bounds.hpp): a frequency as its inverse
    const OptionBound& pb = kPulsePeriodBound;
    const std::string range =
        f ? "[" + format_number(1.0 / pb.hi, 6) + ", " + format_number(1.0 / pb.lo, 6) + "] Hz"
          : range_text(pb);
    const std::string what = "a number in " + range + " (" + pb.why + ")";
    const char* key = f ? "frequency_hz" : "period";
    const double v = r.number(key, what);
    if (!in_range(pb, f ? 1.0 / v : v)) r.expected(key, what);
    omega = f ? 2.0 * std::numbers::pi * v : 2.0 * std::numbers::pi / v;
  }
  PulseArgs args{ap, omega, duration, dir, {}};
  for (const PulseKey& k : kind.keys) {
    if (const std::optional<double> v = read_pulse_key(r, k)) args.keys.emplace(k.name, *v);
  }
  try {
    b.motion = make_pulse(kind, std::move(args));
  } catch (const InputError& e) {
    if (e.file() == r.file()) throw;
    throw InputError(
        r.file(), r.line(), "",
        "[" + r.full("").substr(0, r.full("").size() - 1) + "] " + out.type + ": " + e.what());
  }
  r.finish("for type '" + out.type + "'");
  return b;
}

// the breakpoints of a motion: its samples, or the analytic ones
std::vector<double> breakpoints_of(const GroundMotion& m) {
  if (m.is_sampled()) return m.times();
  std::vector<double> b{0.0};
  GroundMotion::Cursor c;
  for (double t = m.next_breakpoint(-1.0, c); std::isfinite(t); t = m.next_breakpoint(t, c)) {
    b.push_back(t);
  }
  return b;
}

// a horizontal and a vertical motion of any kinds as one analytic motion
GroundMotion combine_any(GroundMotion h, GroundMotion v) {
  std::vector<double> breaks = breakpoints_of(h);
  const std::vector<double> bv = breakpoints_of(v);
  breaks.insert(breaks.end(), bv.begin(), bv.end());
  const double duration = std::max(h.duration(), v.duration());
  // two pulses made of sinusoids stay so described: h's horizontal pieces and v's vertical ones
  std::vector<SinusoidPiece> pieces;
  if (h.is_sinusoidal() && v.is_sinusoidal()) {
    for (const SinusoidPiece& p : h.sinusoids())
      if (!p.vertical) pieces.push_back(p);
    for (const SinusoidPiece& p : v.sinusoids())
      if (p.vertical) pieces.push_back(p);
  }
  // stateless, so copies of the motion may run on several threads (at() searches the samples)
  auto f = [h = std::move(h), v = std::move(v)](double t) {
    return BaseAcceleration{h.at(t).x, v.at(t).y};
  };
  GroundMotion m = GroundMotion::analytic(std::move(f), duration, std::move(breaks));
  return pieces.empty() ? m : m.with_sinusoids(std::move(pieces));
}

GroundMotion record_motion(const Record& rec, bool vertical) {
  std::vector<double> v = rec.to_si();
  if (!vertical) return rec.to_motion();
  return GroundMotion::sampled(rec.time, std::vector<double>(v.size(), 0.0), std::move(v));
}

// [excitation] target_pga, target_pgv or target_sa: the factor on both components that gives the
// horizontal record that intensity; 0 when no target is given
double target_scale(Reader& r, const Built& h, Case& c) {
  const auto pga = r.number_opt("target_pga", "a number > 0 [g] (PGA of the scaled record)");
  const auto pgv = r.number_opt("target_pgv", "a number > 0 [m/s] (PGV of the scaled record)");
  const auto sa = r.number_opt("target_sa", "a number > 0 [g] (Sa of the scaled record)");
  const auto period = r.number_opt(
      "sa_period", "a number >= " + num(kMinSpectralPeriod) + " [s] (period of target_sa)");
  const auto zeta = r.number_opt("sa_damping_ratio", "a number in [0, 1) (of target_sa)");
  const int given = int(pga.has_value()) + int(pgv.has_value()) + int(sa.has_value());
  if (!sa && (period || zeta)) {
    r.fail(period ? "sa_period" : "sa_damping_ratio", "expected only with target_sa");
  }
  if (given == 0) return 0.0;
  const char* key = pga ? "target_pga" : pgv ? "target_pgv" : "target_sa";
  if (given > 1) r.fail(key, "expected one of target_pga, target_pgv, target_sa, got several");
  if (r.has("scale")) r.fail("scale", "expected either scale or " + std::string(key));
  const double target = *(pga ? pga : pgv ? pgv : sa);
  if (!(target > 0.0)) r.expected(key, "a number > 0");
  if (!h.record) {
    r.fail(key, "expected a horizontal component of type \"record\" to scale, got \"" +
                    c.horizontal.type + "\"");
  }
  // the horizontal component as it is run, its own scale included
  const std::vector<double> a = h.record->to_si();
  const double g = kStandardGravity;
  double measure = 0.0, want = 0.0;
  std::string what;
  if (pga) {
    measure = peak_ground_acceleration(a);
    want = target * g;
    what = "PGA " + num(target) + " g";
  } else if (pgv) {
    measure = peak_ground_velocity(h.record->time, a);
    want = target;
    what = "PGV " + num(target) + " m/s";
  } else {
    if (!period)
      r.fail_at(r.line(), "sa_period",
                "missing; expected a period >= " + num(kMinSpectralPeriod) + " [s] with target_sa");
    if (!(std::isfinite(*period) && *period >= kMinSpectralPeriod)) {
      r.expected("sa_period", "a period >= " + num(kMinSpectralPeriod) +
                                  " [s] (below it Sa is the PGA: use target_pga)");
    }
    const double z = zeta.value_or(0.05);
    if (!(z >= 0.0 && z < 1.0)) r.expected("sa_damping_ratio", "a number in [0, 1)");
    measure = spectral_acceleration(h.record->time, a, *period, z);
    want = target * g;
    what = "Sa(" + num(*period) + " s, " + num(100.0 * z) + " %) " + num(target) + " g";
  }
  if (!(measure > 0.0)) r.fail(key, "the horizontal record is zero: it cannot be scaled");
  // Sa at a very long period tends to 0 as 1/T: no finite factor reaches a target from there
  if (!std::isfinite(want / measure)) {
    r.fail(key, "the horizontal record's measure is " + num(measure) +
                    " (SI units): no finite factor scales it to " + what);
  }
  c.scaled_to = what;
  return want / measure;
}

// the two horizontal records of a pair on their common samples: the same time step (or the same
// times), cut to the shorter; anything else is refused naming both files
RecordPair make_pair(Reader& h2r, Record h1, Record h2, Case& c) {
  const std::string both = "H1 '" + h1.source + "' and H2 '" + h2.source + "'";
  const double tol = 1e-9 * std::max(std::abs(h1.dt), std::abs(h2.dt));
  if ((h1.dt > 0.0) != (h2.dt > 0.0) || std::abs(h1.dt - h2.dt) > tol) {
    h2r.fail("file", "expected the same time step in " + both + ", got " +
                         (h1.dt > 0.0 ? num(h1.dt) + " s" : std::string("uneven times")) + " and " +
                         (h2.dt > 0.0 ? num(h2.dt) + " s" : std::string("uneven times")) +
                         " (resample one of them)");
  }
  const std::size_t n = std::min(h1.npts(), h2.npts());
  for (std::size_t i = 0; i < n; ++i) {
    const double dt = i + 1 < n ? h1.time[i + 1] - h1.time[i] : h1.time[i] - h1.time[i - 1];
    if (std::abs(h1.time[i] - h2.time[i]) > 1e-9 * std::abs(dt)) {
      h2r.fail("file", "expected the same sample times in " + both + ", got " + num(h1.time[i]) +
                           " s and " + num(h2.time[i]) + " s at sample " + std::to_string(i + 1));
    }
  }
  if (n < 2) h2r.fail("file", "expected at least 2 common samples in " + both);
  if (h1.npts() != h2.npts()) {
    c.notes.push_back("excitation: " + both + " have " + std::to_string(h1.npts()) + " and " +
                      std::to_string(h2.npts()) + " samples: the pair is cut to the shorter (" +
                      num(h1.time[n - 1]) + " s)");
    for (Record* rec : {&h1, &h2}) {
      rec->time.resize(n);
      rec->values.resize(n);
    }
  }
  RecordPair p;
  p.h1 = std::move(h1);
  p.h2 = std::move(h2);
  return p;
}

// a key of kPairKeys as the reader takes it: "[excitation.horizontal2]" is the table
// "horizontal2" of [excitation]
std::string pair_key(std::size_t i) {
  std::string_view n = kPairKeys[i].name;
  constexpr std::string_view kTable = "[excitation.";
  if (n.starts_with(kTable)) n = n.substr(kTable.size(), n.size() - kTable.size() - 1);
  return std::string(n);
}

// excitation.azimuth_deg and azimuth_step_deg (kPairKeys), only with a pair
void read_azimuths(Reader& r, Case& c) {
  const std::string az_key = pair_key(1), step_key = pair_key(2);
  const auto az = r.number_opt(az_key, "a number [deg] (the azimuth from H1 toward H2)");
  const auto step = r.number_opt(step_key, "a number in (0, 360] [deg] dividing 360");
  if (!c.pair) {
    if (az || step) {
      r.fail(az ? az_key : step_key,
             "expected only with a record pair ([excitation." + pair_key(0) + "])");
    }
    return;
  }
  if (az) c.azimuth = *az;
  const double st = step.value_or(std::stod(kPairKeys[2].default_text));
  const double count = 360.0 / st;
  if (!(st > 0.0 && st <= 360.0) || std::abs(count - std::round(count)) > 1e-9 * count) {
    r.expected(step_key, "a step in (0, 360] [deg] that divides 360 (e.g. 5, 7.5, 10)");
  }
  c.azimuth_step = st;
}

void read_excitation(Reader& r, Case& c) {
  c.excitation_scale = r.number_or("scale", 1.0, "a number [-] (factor on both components)");
  Reader hr = r.table("horizontal");
  Built h = read_component(hr, false, c.horizontal);
  std::optional<Built> h2;
  std::optional<Reader> h2r = r.table_opt(pair_key(0));
  if (h2r) {
    h2 = read_component(*h2r, false, c.horizontal2);
    if (!h2->record) {
      h2r->fail("type", "expected \"record\" for the second horizontal component, got \"" +
                            c.horizontal2.type + "\"");
    }
    if (!h.record) {
      hr.fail("type",
              "expected \"record\" for the first horizontal component of a pair "
              "([excitation.horizontal2] is given), got \"" +
                  c.horizontal.type + "\"");
    }
  }
  std::optional<Built> v;
  if (auto vr = r.table_opt("vertical")) v = read_component(*vr, true, c.vertical);
  if (h2) {
    for (const char* key : {"target_pga", "target_pgv", "target_sa"}) {
      if (r.has(key)) {
        r.fail(key,
               "expected no target with a record pair (the target of a pair is not defined "
               "by one component): use scale");
      }
    }
    auto pair = std::make_shared<RecordPair>(make_pair(*h2r, *h.record, *h2->record, c));
    if (v && v->record) pair->vertical_record = v->record;
    if (v && !v->record) pair->vertical_motion = v->motion;
    c.pair = std::move(pair);
  }
  read_azimuths(r, c);
  if (const double f = target_scale(r, h, c); f > 0.0) c.excitation_scale = f;
  for (const ExcitationComponent* e : {&c.horizontal, &c.horizontal2, &c.vertical}) {
    if (!e->file.empty()) c.input_files.push_back(e->file);
  }
  r.finish();
  const double s = c.excitation_scale;
  try {
    if (c.pair) {
      // the motion at the azimuth asked for; without one, H1 alone (beta = 0) stands for the pair
      // where a single motion is needed (`flexrock check`, the history-row bound)
      c.motion = azimuth_motion(c, c.azimuth.value_or(0.0));
    } else if (!v) {
      c.motion = h.record ? h.record->to_motion(s) : h.motion.scaled(s);
    } else if (h.record && v->record) {
      c.motion = combine(*h.record, &*v->record, s);
    } else {
      GroundMotion hm = h.record ? record_motion(*h.record, false) : h.motion;
      GroundMotion vm = v->record ? record_motion(*v->record, true) : v->motion;
      c.motion = combine_any(std::move(hm), std::move(vm)).scaled(s);
    }
  } catch (const InputError& e) {
    throw InputError(r.file(), r.line(), "", std::string("[excitation]: ") + e.what());
  }
}

// ---------------------------------------------------------------------------------------------
// initial state, solver, output

void read_initial(Reader& r, Case& c, const Body& body) {
  c.initial.theta = r.number_or("theta", 0.0, "a number [rad]");
  c.initial.theta_dot = r.number_or("theta_dot", 0.0, "a number [rad/s]");
  const auto n = static_cast<std::size_t>(body.modes());
  auto modal = [&](const char* key, VectorX& out) {
    const auto v = r.vector_opt(key, "an array of one value a mode");
    if (!v) return;
    if (v->size() != n) {
      r.fail(key, "expected " + std::to_string(n) + " values (one a mode of the body), got " +
                      std::to_string(v->size()));
    }
    out = to_vector(*v);
  };
  modal("q", c.initial.q);
  modal("q_dot", c.initial.q_dot);
  r.finish();
  const int edge = c.initial.theta >= 0.0 ? 1 : 2;
  const double limit = c.options.overturn == OverturnCriterion::kHalfPi ? std::numbers::pi / 2.0
                                                                        : body.tipping_angle(edge);
  if (!(std::abs(c.initial.theta) < limit)) {
    r.fail("theta", "expected |theta| below the overturning angle " + num(limit) + " rad, got " +
                        num(c.initial.theta));
  }
}

// [support]: the mass, the spring as a stiffness or a frequency, the dashpot as a coefficient or
// a damping ratio (both with the body as a rigid mass on the support), the start
SupportParameters read_support(Reader& r, const BodyParameters& body) {
  SupportParameters s;
  s.mass = r.nonnegative_or("mass", -1.0, "[kg]");
  if (s.mass < 0.0) r.fail_at(r.line(), "mass", "missing; expected a number >= 0 [kg]");
  const double mt = s.mass + body.mass;
  const bool by_f = r.has("frequency_hz"), by_k = r.has("stiffness");
  if (by_f == by_k) {
    r.fail_at(r.line(), by_f ? "stiffness" : "frequency_hz",
              by_f ? "give either frequency_hz or stiffness, not both"
                   : "missing; expected frequency_hz [Hz] or stiffness [N/m], > 0");
  }
  if (by_f) {
    const double w = 2.0 * std::numbers::pi * r.positive("frequency_hz", "[Hz]");
    s.stiffness = mt * w * w;
  } else {
    s.stiffness = r.positive("stiffness", "[N/m]");
  }
  if (r.has("damping_ratio") && r.has("damping"))
    r.fail("damping", "give either damping_ratio or damping, not both");
  if (r.has("damping")) {
    s.damping = r.nonnegative_or("damping", 0.0, "[N s/m]");
  } else {
    s.damping = 2.0 * r.nonnegative_or("damping_ratio", 0.0, "[-]") * std::sqrt(s.stiffness * mt);
  }
  s.displacement = r.number_or("displacement", 0.0, "a number [m]");
  s.velocity = r.number_or("velocity", 0.0, "a number [m/s]");
  r.finish();
  return s;
}

void read_solver(Reader& r, SimulationOptions& o) {
  detail::read_solver_keys(r, o, /*case_file=*/true);
  r.finish();
}

void read_output(Reader& r, OutputSettings& out) {
  out.dt = r.nonnegative_or("dt", out.dt, "[s] (0: no time history)");
  const std::string what = "a path (\"\": none)";
  out.time_history = r.string_opt("time_history", what).value_or(out.time_history);
  out.summary = r.string_opt("summary", what).value_or(out.summary);
  out.events = r.string_opt("events", what).value_or(out.events);
  r.finish();
  if (out.dt == 0.0) out.time_history.clear();
}

// the time history's rows against kMaxHistoryRows: [output] dt = 1e-300, or a record whose last
// time is 1e9 s, would otherwise fill the memory row by row
void check_history_rows(Reader& top, const Case& c) {
  if (c.options.output_dt <= 0.0) return;
  const double end = c.options.t_end >= 0.0 ? c.options.t_end : c.motion.duration();
  const double rows = std::floor(end / c.options.output_dt) + 1.0;
  if (rows <= static_cast<double>(kMaxHistoryRows)) return;
  const toml::node* out = top.node("output");
  const toml::node* dt = out && out->is_table() ? out->as_table()->get("dt") : nullptr;
  top.fail_at(dt ? line_of(*dt) : 1, "output.dt",
              "expected at most " + std::to_string(kMaxHistoryRows) + " time-history rows, got " +
                  num(rows) + " (" + num(end) + " s every " + num(c.options.output_dt) +
                  " s); choose a larger output.dt, output.dt = 0 (no time history) or a shorter " +
                  (c.options.t_end >= 0.0 ? "solver.t_end" : "excitation (or solver.t_end)"));
}

// a rocking frame: the frame's numbers from [body] (read again: the table's builder gave its
// equivalent body), and the options its model does not cover refused where they are written
RockingFrame frame_of(Reader& top) {
  Reader br = top.table("body");
  const BodyKind& kind = body_kind("rocking_frame");
  BodyArgs args;
  for (const BodyKey& k : kind.keys) args.keys.emplace(k.name, read_body_number(br, k));
  RockingFrame f;
  f.column_width = args.at("column_width");
  f.column_height = args.at("column_height");
  f.column_mass = args.at("column_mass");
  f.count = static_cast<int>(args.at("count"));
  f.beam_mass = args.at("beam_mass");
  return f;
}

void read_frame(Reader& top, Case& c) {
  const RockingFrame f = frame_of(top);
  c.frame = f;
  try {
    validate_frame_options(c.options);
  } catch (const InputError& e) {
    const toml::node* sv = top.node("solver");
    const char* key =
        std::isfinite(c.options.friction_coefficient) ? "friction_coefficient" : "contact_model";
    const toml::node* n = sv && sv->is_table() ? sv->as_table()->get(key) : nullptr;
    top.fail_at(n ? line_of(*n) : 1, std::string("solver.") + key, e.what());
  }
  const FrameConstants fc = frame_constants(f);
  c.notes.push_back(
      "rocking_frame: run as its equivalent rigid body (docs/theory.md §25): p = " + num(fc.p) +
      " rad/s, alpha = " + num(fc.alpha) + " rad, impact ratio r = " + num(fc.r) +
      (fc.reaction_mass > 0.0
           ? "; the floor reactions, base shear and friction demand reported are the equivalent "
             "body's: the frame's are larger by " +
                 num(fc.reaction_mass) + " kg x (base acceleration + g), " +
                 num(100.0 * fc.reaction_mass / fc.mass_total) + " % of the frame's weight at rest"
           : "; without a beam mass the equivalent body is the columns side by side, its "
             "reactions the frame's"));
}

toml::table parse(const std::string& path) { return detail::parse_toml(path, "case"); }

}  // namespace

std::vector<double> projected_record(const RecordPair& pair, double beta_deg) {
  return project_horizontal(pair.h1.to_si(), pair.h2.to_si(), beta_deg);
}

GroundMotion azimuth_motion(const Case& c, double beta_deg) {
  if (!c.pair) throw std::logic_error("azimuth_motion: the case has no record pair");
  const RecordPair& p = *c.pair;
  Record h;
  h.source = p.h1.source;
  h.units = AccelUnit::kMetersPerSecond2;
  h.dt = p.h1.dt;
  h.time = p.h1.time;
  h.values = projected_record(p, beta_deg);
  const double s = c.excitation_scale;
  if (p.vertical_record) return combine(h, &*p.vertical_record, s);
  if (p.vertical_motion) {
    return combine_any(record_motion(h, false), *p.vertical_motion).scaled(s);
  }
  return h.to_motion(s);
}

std::string pair_key_reference() {
  std::string s =
      "<!-- begin: written by `flexrock keys --markdown` from the table of record-pair keys "
      "(include/flexrock/io/case_file.hpp); edit the table, not these lines -->\n"
      "| key | unit | default | meaning |\n"
      "|---|---|---|---|\n";
  for (const PairKey& k : kPairKeys) {
    s.append("| `").append(k.name).append("` | ").append(k.unit).append(" | ");
    s.append(k.default_text).append(" | ").append(k.doc).append(" |\n");
  }
  s += "<!-- end: written by `flexrock keys --markdown` -->\n";
  return s;
}

Case load_case(const std::string& path) {
  const toml::table doc = parse(path);
  Reader top(path, doc, "", 1);
  Case c;
  c.source = path;
  c.stem = fs::path(path).stem().string();
  c.name = top.string_opt("name", "a string").value_or(c.stem);
  c.description = top.string_opt("description", "a string").value_or("");
  c.output.time_history = c.stem + ".csv";
  c.output.summary = c.stem + ".summary.json";

  Reader br = top.table("body");
  c.input_files.push_back(path);
  c.body = read_body(br, c.body_type, c.rigid, c.notes, &c.body_keys, &c.body3d);
  const Body body(c.body);
  Reader er = top.table("excitation");
  read_excitation(er, c);
  if (auto sr = top.table_opt("solver")) read_solver(*sr, c.options);
  if (auto orr = top.table_opt("output")) read_output(*orr, c.output);
  c.options.output_dt = c.output.time_history.empty() ? 0.0 : c.output.dt;
  check_history_rows(top, c);
  if (auto ir = top.table_opt("initial")) read_initial(*ir, c, body);
  c.restraints = detail::read_restraints(top, c.body, c.options);
  if (auto spr = top.table_opt("support")) {
    c.support = read_support(*spr, c.body);
    // what the support's engine does not model is refused here, naming the table
    try {
      validate_support(body, *c.support, c.initial, c.options);
    } catch (const InputError& e) {
      std::string why = e.what();
      if (why.rfind("support: ", 0) == 0) why.erase(0, 9);  // the key names the table
      top.fail_at(spr->line(), "support", why);
    }
    // each has its own engine: the two together are not built
    if (!c.restraints.empty()) {
      top.fail_at(spr->line(), "support",
                  "a body on a support with [[restraint]] tables is not modelled yet (each runs "
                  "on its own engine); give one or the other");
    }
  }
  top.finish("at the top level");
  // a body of revolution under a pair runs on the 3D engine: a support or restraints under it
  // are not built there
  if (c.body3d && c.pair && (c.support || !c.restraints.empty())) {
    const char* key = c.support ? "support" : "restraint";
    top.fail_at(line_of(*doc.get(key)), key,
                std::string("a body of revolution under a record pair runs in 3D, where ") +
                    (c.support ? "a [support] is" : "[[restraint]] tables are") +
                    " not modelled yet; give one horizontal component (the planar engine, on the "
                    "body's section) or leave it out");
  }
  if (c.body_type == "rocking_frame") {
    // the frame runs on its own engine: a support or restraints under it are not built
    if (c.support) {
      top.fail_at(line_of(*doc.get("support")), "support",
                  "a rocking_frame on a support is not modelled yet; give the frame without "
                  "[support]");
    }
    if (!c.restraints.empty()) {
      top.fail_at(line_of(*doc.get("restraint")), "restraint",
                  "a rocking_frame with [[restraint]] tables is not modelled yet; give the frame "
                  "without them");
    }
    read_frame(top, c);
  }
  return c;
}

void refuse_restraints(const std::string& path, const std::string& what) {
  const toml::table doc = parse(path);
  if (const toml::node* n = doc.get("restraint")) {
    throw InputError(path, n->source().begin.line, "restraint",
                     "[[restraint]] tables are not modelled in " + what +
                         " yet (they would be dropped); run the case with `flexrock run`");
  }
}

std::optional<SupportParameters> load_support(const std::string& path, const BodyParameters& body) {
  const toml::table doc = parse(path);
  Reader top(path, doc, "", 1);
  auto spr = top.table_opt("support");
  if (!spr) return std::nullopt;
  return read_support(*spr, body);
}

bool has_excitation(const std::string& path) { return parse(path).contains("excitation"); }

BodyParameters load_body(const std::string& path, std::string* type,
                         std::vector<std::string>* files, std::optional<RockingFrame>* frame,
                         bool support_ok) {
  const toml::table doc = parse(path);
  std::vector<std::string> read{path};
  Reader top(path, doc, "", 1);
  if (!support_ok && doc.contains("support")) {
    top.fail_at(line_of(*doc.get("support")), "support",
                "a body on a support runs with `flexrock run` only: spectra, sweeps, fragility and "
                "qualification on a support are not built; give the body without [support]");
  }
  Reader br = top.table("body");
  std::string t;
  bool rigid = false;
  std::vector<std::string> notes;
  BodyParameters p = read_body(br, t, rigid, notes);
  if (type) *type = t;
  if (frame) {
    frame->reset();
    if (t == "rocking_frame") *frame = frame_of(top);
  }
  if (files) files->insert(files->end(), read.begin(), read.end());
  return p;
}

std::string body_key_reference() {
  std::string types;
  for (const BodyKind& k : body_kinds())
    types += (types.empty() ? "`" : ", `") + std::string(k.name) + "`";
  std::string s =
      "<!-- begin: written by `flexrock keys --markdown` from the table of body types "
      "(src/model/builders.cpp); edit the table, not these lines -->\n"
      "Common keys:\n\n"
      "| key | unit | default | meaning |\n"
      "|---|---|---|---|\n"
      "| `type` | | required | " +
      types +
      " |\n"
      "| `rigid` | | `false` | take the body as rigid: keep M, h, b1, b2 and zeta^2, drop every "
      "deformation mode |\n";
  for (const BodyKind& k : body_kinds()) {
    s.append("\n`type = \"").append(k.name).append("\"`: ").append(k.doc);
    if (*k.function) s.append(" (Python: `flexrock.").append(k.function).append("`)");
    s.append(".\n\n| key | unit | default | meaning |\n|---|---|---|---|\n");
    for (const BodyKey& key : k.keys) {
      s.append("| `").append(key.name).append("` | ").append(key.unit).append(" | ");
      s.append(default_text(key)).append(" | ").append(key.doc).append(" |\n");
    }
  }
  s += "<!-- end: written by `flexrock keys --markdown` -->\n";
  return s;
}

std::string pulse_key_reference() {
  auto rule_text = [](const PulseKey& k) -> std::string {
    switch (k.rule) {
      case PulseKeyRule::kFinite:
        return "";
      case PulseKeyRule::kPositive:
        return ", > 0";
      case PulseKeyRule::kNonnegative:
        return ", >= 0";
      case PulseKeyRule::kCount:
        return ", integer >= 1";
    }
    return "";
  };
  std::string s =
      "<!-- begin: written by `flexrock keys --markdown` from the table of pulse types "
      "(src/excitation/pulses.cpp); edit the table, not these lines -->\n"
      "| type | `frequency_hz` or `period` | extra keys (unit, default): meaning | spectra: pulse "
      "length | acceleration |\n"
      "|---|---|---|---|---|\n";
  for (const PulseKind& k : pulse_kinds()) {
    std::string keys;
    for (const PulseKey& key : k.keys) {
      keys += (keys.empty() ? "" : "; ") + std::string("`") + key.name + "` (" + key.unit + ", " +
              key.default_text + rule_text(key) + "): " + key.doc;
    }
    s += std::string("| `") + k.name + "` | " + (k.frequency ? "required" : "no") + " | " +
         (keys.empty() ? "none" : keys) + " | " +
         (k.length ? std::string("yes: ") + k.length_text : std::string("no")) + " | " + k.doc +
         " |\n";
  }
  s += "| `none` | no | (no amplitude, units, frequency) | no | no motion: free rocking; "
       "horizontal only |\n"
       "<!-- end: written by `flexrock keys --markdown` -->\n";
  return s;
}

std::string support_key_reference() {
  std::string s =
      "<!-- begin: written by `flexrock keys --markdown` from the table of support keys "
      "(include/flexrock/io/case_file.hpp); edit the table, not these lines -->\n"
      "| key | unit | default | meaning |\n"
      "|---|---|---|---|\n";
  for (const SupportKey& k : kSupportKeys) {
    s.append("| `").append(k.name).append("` | ").append(k.unit).append(" | ");
    s.append(k.default_text).append(" | ").append(k.doc).append(" |\n");
  }
  s += "<!-- end: written by `flexrock keys --markdown` -->\n";
  return s;
}

std::string solver_key_reference() {
  std::string s =
      "<!-- begin: written by `flexrock keys --markdown` from the table of solver keys "
      "(include/flexrock/sim/solver_keys.hpp); edit the table, not these lines -->\n"
      "| key | unit | default | meaning |\n"
      "|---|---|---|---|\n";
  for (const SolverKey& k : kSolverKeys) {
    s.append("| `").append(k.name).append("` | ").append(k.unit);
    s.append(*k.unit ? " | " : "| ").append(k.default_text).append(" | ");
    // a bar in the meaning would end the cell
    for (const char c : solver_key_doc(k)) s.append(c == '|' ? "\\|" : std::string(1, c));
    s.append(" |\n");
  }
  s += "<!-- end: written by `flexrock keys --markdown` -->\n";
  return s;
}

}  // namespace flexrock::io
