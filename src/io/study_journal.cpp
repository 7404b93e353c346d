// SPDX-License-Identifier: BSD-3-Clause
// Journal lines of studies: what a journaled spectrum or sweep line may hold, and a sweep CSV
// checked as flexrock sweep writes it.
#include <toml++/toml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <ostream>
#include <set>
#include <sstream>
#include <string_view>
#include <utility>
#include <variant>

#include "flexrock/core/error.hpp"
#include "flexrock/core/types.hpp"
#include "flexrock/excitation/intensity.hpp"
#include "flexrock/excitation/pulses.hpp"
#include "flexrock/io/case_file.hpp"
#include "flexrock/io/files.hpp"
#include "flexrock/io/records.hpp"
#include "flexrock/io/study_files.hpp"
#include "study_internal.hpp"
#include "table_reader.hpp"

namespace flexrock::io {

namespace fs = std::filesystem;
using namespace study_detail;

// ---------------------------------------------------------------------------------------------
// journal lines

namespace study_detail {

std::vector<std::string_view> fields_of(std::string_view line) {
  std::vector<std::string_view> out;
  for (std::size_t start = 0;;) {
    const std::size_t c = line.find(',', start);
    out.push_back(
        line.substr(start, c == std::string_view::npos ? std::string_view::npos : c - start));
    if (c == std::string_view::npos) return out;
    start = c + 1;
  }
}

// a finite number as field() writes it ("inf" and "nan" are never written)
bool is_number(std::string_view f) {
  double v = 0.0;
  const auto r = std::from_chars(f.data(), f.data() + f.size(), v);
  return !f.empty() && r.ec == std::errc() && r.ptr == f.data() + f.size() && std::isfinite(v);
}

// a field's text read back as a value of its column's type: what format_field wrote (a real
// left empty, a value the run did not have, is NaN)
Value parse_field(std::string_view f, ColumnType type) {
  switch (type) {
    case ColumnType::kInteger: {
      long long v = 0;
      const auto r = std::from_chars(f.data(), f.data() + f.size(), v);
      if (f.empty() || r.ec != std::errc() || r.ptr != f.data() + f.size()) {
        throw InputError("\"" + std::string(f) + "\" is not an integer");
      }
      return v;
    }
    case ColumnType::kReal: {
      if (f.empty()) return std::numeric_limits<double>::quiet_NaN();
      if (!is_number(f)) throw InputError("\"" + std::string(f) + "\" is not a finite number");
      double v = 0.0;
      std::from_chars(f.data(), f.data() + f.size(), v);
      return v;
    }
    case ColumnType::kText:
      break;
  }
  return std::string(f);
}

// the first field where a line and the line written back from what was read of it differ: what
// does not follow from the others (an outcome and its overturned flag, a body's name)
std::string first_difference(const std::vector<std::string>& names, std::string_view line,
                             std::string_view again) {
  const std::vector<std::string_view> a = fields_of(line), b = fields_of(again);
  for (std::size_t k = 0; k < a.size() && k < b.size(); ++k) {
    if (a[k] != b[k]) {
      return "field " + std::to_string(k + 1) + " (" + (k < names.size() ? names[k] : "?") +
             ") is \"" + std::string(a[k]) + "\", expected \"" + std::string(b[k]) + "\"";
    }
  }
  return "its fields do not read back to the same line";
}

}  // namespace study_detail

namespace {

// the text before the n-th comma: the first n fields
std::string_view first_fields(std::string_view line, std::size_t n) {
  std::size_t pos = 0;
  for (std::size_t k = 0; k < n; ++k) {
    pos = line.find(',', pos);
    if (pos == std::string_view::npos) return line;
    ++pos;
  }
  return line.substr(0, pos == 0 ? 0 : pos - 1);
}

// a run's result figure: a finite number, or empty where the run has none (field())
bool is_figure(std::string_view f) { return f.empty() || is_number(f); }

bool is_count(std::string_view f) {
  long v = 0;
  const auto r = std::from_chars(f.data(), f.data() + f.size(), v);
  return !f.empty() && r.ec == std::errc() && r.ptr == f.data() + f.size() && v >= 0;
}

bool is_status(std::string_view name) { return status_named(name).has_value(); }

// the fields of a run's outcome: a known name and the overturned flag that goes with it
std::string check_outcome(std::string_view outcome, std::string_view flag) {
  const std::optional<study::Outcome> o = outcome_named(outcome);
  if (!o) return "unknown outcome \"" + std::string(outcome) + "\"";
  if (flag != (study::overturned(*o) ? "1" : "0")) {
    return "overturned = " + std::string(flag) + " does not go with outcome " +
           std::string(outcome);
  }
  return "";
}

// the sliding fields from position `first` on: a known regime word, numbers, a count
std::string check_sliding_fields(const std::vector<std::string_view>& f, std::size_t first) {
  if (!regime_named(f[first])) return "unknown regime \"" + std::string(f[first]) + "\"";
  for (std::size_t k = first + 1; k + 1 < f.size(); ++k) {
    if (!is_figure(f[k]))
      return "field " + std::to_string(k + 1) + " is not a finite number or empty";
  }
  if (!is_count(f.back())) return "slips is not a count";
  return "";
}

std::string check_fields(const std::vector<std::string_view>& f, std::size_t expected) {
  if (f.size() != expected) {
    return std::to_string(f.size()) + " fields, expected " + std::to_string(expected);
  }
  return "";
}

}  // namespace

JournalCheck sweep_journal_check(const study::SweepSpec& spec) {
  // the bodies and record intensities, once: every run's input fields follow from them
  auto bodies = std::make_shared<std::vector<Body>>();
  for (const study::SweepBody& b : spec.bodies) bodies->emplace_back(b.body);
  auto im = std::make_shared<std::vector<study::Intensity>>(study::record_intensities(spec));
  auto runs = std::make_shared<std::vector<study::SweepRun>>(study::sweep_runs(spec));
  auto design = std::make_shared<study::SampleDesign>(study::sample_design(spec));
  // where the fields are, by column name
  const bool sliding = study::has_friction(spec);
  const std::vector<std::string> names = sweep_columns(spec);
  auto col = [&names](const char* name) {
    return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
  };
  const std::size_t columns = names.size();
  // the sliding columns end the row
  const std::size_t first_sliding =
      names.size() - (sliding ? sweep_columns(true).size() - sweep_columns(false).size() : 0);
  const std::size_t inputs = col("duration_s") + 1;  // the fields a run's inputs decide
  const std::size_t outcome = col("outcome"), edge = col("overturn_edge");
  const std::size_t impacts = col("impacts"), status = col("status");
  return [&spec, bodies, im, runs, design, columns, inputs, outcome, edge, impacts, status, sliding,
          first_sliding](std::size_t index, const std::string& line) -> std::string {
    if (index >= runs->size()) return "no such run";
    const study::SweepRun& run = (*runs)[index];
    const std::vector<std::string_view> f = fields_of(line);
    if (std::string why = check_fields(f, columns); !why.empty()) return why;
    // index, body, record, level, scale, PGA, PGV, sampled values, duration: as the manifest
    // makes this run
    const study::SweepRow row =
        study::sweep_inputs(spec, run, (*bodies)[run.body], (*im)[run.record], *design);
    const std::string expected(first_fields(sweep_row(spec, row), inputs));
    if (first_fields(line, inputs) != expected) {
      return "its first fields are not those of run " + std::to_string(index) + " (" + expected +
             ")";
    }
    if (std::string why = check_outcome(f[outcome], f[outcome + 1]); !why.empty()) return why;
    for (std::size_t k = edge + 1; k < status; ++k) {
      if (k != impacts && !is_figure(f[k])) {
        return "field " + std::to_string(k + 1) + " is not a finite number or empty";
      }
    }
    if (f[edge] != "0" && f[edge] != "1" && f[edge] != "2") return "overturn_edge is not 0, 1 or 2";
    if (!is_count(f[impacts])) return "impacts is not a count";
    if (!is_status(f[status])) return "unknown status \"" + std::string(f[status]) + "\"";
    if (sliding) return check_sliding_fields(f, first_sliding);
    return "";
  };
}

JournalCheck spectrum_journal_check(const study::SpectrumResult& grid, bool normalized, double g) {
  auto res = std::make_shared<study::SpectrumResult>(grid);
  // where the fields are, by column name
  struct Fields {
    std::size_t count, inputs, outcome, ratio, impacts, uplift, overturn, energy, status;
  };
  struct BoundaryFields {
    std::size_t count, inputs, kind, min, safe, min_si, min_norm, mode, runs;
  };
  auto at = [](const std::vector<std::string>& names, const char* name) {
    const auto it = std::find(names.begin(), names.end(), name);
    FLEXROCK_DEMAND(it != names.end());
    return static_cast<std::size_t>(it - names.begin());
  };
  const std::vector<std::string> cn = spectrum_columns(grid.sliding, grid.units),
                                 bn = boundary_columns(grid.units);
  const std::size_t first_sliding = spectrum_columns(false, grid.units).size();
  // a cell's inputs: row, column, amplitudes, frequencies, scale: as the spec makes this cell
  const Fields c{cn.size(),
                 at(cn, "scale") + 1,
                 at(cn, "outcome"),
                 at(cn, "max_theta_over_alpha"),
                 at(cn, "impacts"),
                 at(cn, "first_uplift_time_s"),
                 at(cn, "overturn_time_s"),
                 at(cn, "energy_lost_J"),
                 at(cn, "status")};
  // a boundary's inputs: column and frequencies
  const BoundaryFields bf{bn.size(),
                          at(bn, "omega_p_over_p") + 1,
                          at(bn, "kind"),
                          at(bn, "min_overturning"),
                          at(bn, "safe_below"),
                          at(bn, "min_overturning_m_per_s2"),
                          at(bn, "min_overturning_over_g_tan_alpha"),
                          at(bn, "mode"),
                          at(bn, "bisection_runs")};
  return [res, normalized, g, c, bf, first_sliding](std::size_t index,
                                                    const std::string& line) -> std::string {
    const std::vector<std::string_view> f = fields_of(line);
    const std::size_t cells = res->cells.size();
    if (index < cells) {
      if (std::string why = check_fields(f, c.count); !why.empty()) return why;
      const std::string expected(first_fields(spectrum_row(*res, res->cells[index], g), c.inputs));
      if (first_fields(line, c.inputs) != expected) {
        return "its first fields are not those of cell " + std::to_string(index) + " (" + expected +
               ")";
      }
      if (std::string why = check_outcome(f[c.outcome], f[c.outcome + 1]); !why.empty()) return why;
      for (const std::size_t k : {c.ratio, c.uplift, c.overturn, c.energy}) {
        if (!is_figure(f[k]))
          return "field " + std::to_string(k + 1) + " is not a finite number or empty";
      }
      if (!is_count(f[c.impacts])) return "impacts is not a count";
      if (!is_status(f[c.status])) return "unknown status \"" + std::string(f[c.status]) + "\"";
      if (res->sliding) return check_sliding_fields(f, first_sliding);
      return "";
    }
    const std::size_t j = index - cells;
    if (j >= res->boundary.size()) return "no such cell or boundary";
    if (std::string why = check_fields(f, bf.count); !why.empty()) return why;
    const std::string expected(
        first_fields(boundary_row(*res, res->boundary[j], normalized, g), bf.inputs));
    if (first_fields(line, bf.inputs) != expected) {
      return "its first fields are not those of the boundary of column " + std::to_string(j) +
             " (" + expected + ")";
    }
    using Kind = study::OverturnBoundary::Kind;
    const std::optional<Kind> kind = value_named(study::kBoundaryKindNames, f[bf.kind]);
    if (!kind) return "unknown kind \"" + std::string(f[bf.kind]) + "\"";
    const bool none = *kind == Kind::kNone;
    for (const std::size_t k : {bf.min, bf.safe, bf.min_si, bf.min_norm}) {
      const bool empty_ok = none || (k == bf.safe && *kind == Kind::kBelowGrid);
      if (!(is_number(f[k]) || (empty_ok && f[k].empty()))) {
        return "field " + std::to_string(k + 1) + " is not a number";
      }
    }
    if (!none && (!outcome_named(f[bf.mode]) || !study::overturned(*outcome_named(f[bf.mode])))) {
      return "mode \"" + std::string(f[bf.mode]) + "\" is not an overturning outcome";
    }
    if (!is_count(f[bf.runs])) return "bisection_runs is not a count";
    return "";
  };
}

void check_sweep_table(const CsvTable& t) {
  const auto where = [&t](const char* name) {
    return static_cast<std::size_t>(std::find(t.columns.begin(), t.columns.end(), name) -
                                    t.columns.begin());
  };
  const std::size_t none = t.columns.size();
  const std::size_t index = where("index"), outcome = where("outcome"), flag = where("overturned"),
                    edge = where("overturn_edge"), impacts = where("impacts"),
                    status = where("status"), first_figure = where("overturn_time_s"),
                    regime = where("regime"), slips = where("slips");
  std::map<std::size_t, std::size_t> seen;  // run index -> file line
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const std::vector<std::string>& f = t.rows[r];
    auto bad = [&](const std::string& what) {
      throw InputError(t.source + ":" + std::to_string(t.lines[r]) + ": " + what +
                       "; expected a row as flexrock sweep writes it (was the file edited?)");
    };
    auto column = [&](std::size_t c, const std::string& what) {
      bad("column '" + t.columns[c] + "': expected " + what + ", got \"" + f[c] + "\"");
    };
    if (index != none) {
      if (!is_count(f[index])) column(index, "a run index (an integer >= 0)");
      const std::size_t i = std::stoul(f[index]);
      if (const auto [it, fresh] = seen.emplace(i, t.lines[r]); !fresh) {
        bad("run index " + f[index] + " twice, first at line " + std::to_string(it->second));
      }
    }
    // `contact_lost`, as outcome and as status: rows written before the engine followed flight,
    // which fragility still reads (and leaves out unless the outcome says overturned)
    const bool legacy = outcome != none && f[outcome] == "contact_lost";
    if (outcome != none && flag != none && !(legacy && f[flag] == "0")) {
      if (std::string why = check_outcome(f[outcome], f[flag]); !why.empty()) bad(why);
    }
    if (edge != none && f[edge] != "0" && f[edge] != "1" && f[edge] != "2") {
      column(edge, "0, 1 or 2");
    }
    if (impacts != none && !is_count(f[impacts])) column(impacts, "a count (an integer >= 0)");
    if (status != none && !is_status(f[status]) && f[status] != "contact_lost") {
      column(status, "a status flexrock writes");
    }
    // the run's figures: from overturn_time_s up to the status, and the sliding ones
    for (std::size_t c = first_figure; c < std::min(status, none); ++c) {
      if (c != impacts && !is_figure(f[c])) column(c, "a finite number or empty");
    }
    if (regime != none) {
      if (!regime_named(f[regime])) column(regime, "a regime flexrock writes");
      for (std::size_t c = regime + 1; c < std::min(slips, none); ++c) {
        if (!is_figure(f[c])) column(c, "a finite number or empty");
      }
    }
    if (slips != none && !is_count(f[slips])) column(slips, "a count (an integer >= 0)");
  }
}

}  // namespace flexrock::io
