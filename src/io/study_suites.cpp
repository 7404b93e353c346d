// SPDX-License-Identifier: BSD-3-Clause
// Record suites: [[suite]] tables of a sweep manifest whose components are globs or lists.
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
#include "flexrock/excitation/azimuth.hpp"
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

namespace study_detail {

namespace {

// ---------------------------------------------------------------------------------------------
// record suites: [[suite]] tables whose horizontal (and vertical) components are globs or lists

// `name` matches `pattern`: '*' any run of characters, '?' any one, the rest literally
bool glob_match(std::string_view pattern, std::string_view name) {
  std::size_t p = 0, n = 0, star = std::string_view::npos, resume = 0;
  while (n < name.size()) {
    if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == name[n])) {
      ++p;
      ++n;
    } else if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      resume = n;
    } else if (star != std::string_view::npos) {
      p = star + 1;
      n = ++resume;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

// the files of one component of a suite, in the order the suite takes them
struct SuiteComponent {
  bool glob = false;               // a pattern (files sorted by name) or a list (as written)
  std::string pattern;             // the pattern as written (glob)
  std::vector<std::string> paths;  // resolved against the manifest
  std::vector<std::string> keys;   // glob with one '*': the text it matched (pairs by it)
  std::size_t line = 0;            // line of the key
};

SuiteComponent suite_component(Keys& r, const std::string& key) {
  const std::string what =
      "a glob (\"dir/*_H1.AT2\": '*' and '?' in the file name only) or an array of paths, "
      "relative to this file";
  const toml::node* n = r.node(key);
  SuiteComponent c;
  c.line = line_of(*n);
  if (const toml::array* a = n->as_array()) {
    if (a->empty()) r.expected(key, what + " (at least one file)");
    for (const toml::node& e : *a) {
      if (!e.is_string() || e.as_string()->get().empty()) r.expected(key, what);
      c.paths.push_back(detail::resolve_path(r.file(), e.as_string()->get()));
    }
    return c;
  }
  if (!n->is_string() || n->as_string()->get().empty()) r.expected(key, what);
  c.glob = true;
  c.pattern = n->as_string()->get();
  const fs::path written(c.pattern);
  const std::string dir_written = written.parent_path().string();
  const std::string name = written.filename().string();
  if (dir_written.find_first_of("*?") != std::string::npos)
    r.fail(key, "expected wildcards ('*', '?') in the file name only, got \"" + c.pattern + "\"");
  if (name.empty()) r.expected(key, what);
  const std::string dir =
      detail::resolve_path(r.file(), dir_written.empty() ? std::string(".") : dir_written);
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    r.fail(key, "expected an existing directory in \"" + c.pattern + "\", got no directory " + dir);
  std::vector<std::string> names;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string f = it->path().filename().string();
    if (!glob_match(name, f)) continue;
    // a match that is no record file is named, never skipped: a record would vanish from the
    // study without a word
    std::error_code sec;
    const fs::file_status st = fs::status(it->path(), sec);
    std::string why;
    if (sec || st.type() == fs::file_type::not_found) {
      const std::string reason = sec.message();
      why = fs::is_symlink(fs::symlink_status(it->path(), sec))
                ? "a symbolic link to nothing (dangling)"
                : "unreadable (" + reason + ")";
    } else if (st.type() == fs::file_type::directory) {
      why = "a directory";
    } else if (st.type() == fs::file_type::fifo) {
      why = "a FIFO (named pipe)";
    } else if (st.type() != fs::file_type::regular) {
      why = "not a regular file";
    }
    if (!why.empty())
      r.fail(key, "the pattern \"" + c.pattern + "\" matches " +
                      (fs::path(dir) / f).lexically_normal().string() + ", " + why +
                      "; expected only record files (move it away, or narrow the pattern)");
    names.push_back(f);
  }
  if (ec) r.fail(key, "cannot list the directory " + dir + ": " + ec.message());
  if (names.empty())
    r.fail(key, "the pattern \"" + c.pattern + "\" matches no file in " + dir +
                    "; expected at least one record file");
  std::sort(names.begin(), names.end());  // by bytes: the same order on every machine and rank
  const std::size_t star = name.find('*');
  const bool keyed = star != std::string::npos && name.find('*', star + 1) == std::string::npos &&
                     name.find('?') == std::string::npos;
  for (const std::string& f : names) {
    c.paths.push_back((fs::path(dir) / f).lexically_normal().string());
    if (keyed) c.keys.push_back(f.substr(star, f.size() - (name.size() - 1)));
  }
  return c;
}

// one record of a suite (a component file), its errors placed at the key that named it
Record read_suite_file(Keys& r, const std::string& key, std::size_t line, const std::string& path,
                       const std::optional<std::string>& format,
                       const std::optional<std::string>& units, double dt) {
  const RecordFormat* by_name = record_format_for(path);
  const std::string fmt = format.value_or(by_name != nullptr ? by_name->name : "");
  if (fmt.empty())
    r.fail_at(line, key,
              "the name of file " + path + " does not say its format; expected 'format' in this " +
                  "[[suite]] (" + record_format_names() + ")");
  const RecordFormat* rf = find_record_format(fmt);
  if (rf->needs_dt && !(dt > 0.0))
    r.fail("dt", "missing; expected 'dt' [s] (sample spacing) for the single_column files");
  if (rf->units == RecordUnits::kGiven && !units)
    r.fail("units", "missing; expected one of: " + join(detail::accel_unit_names()) +
                        " (the units of the files' values)");
  const std::optional<AccelUnit> given =
      units ? std::optional<AccelUnit>(detail::accel_unit(*units)) : std::nullopt;
  Record rec;
  try {
    rec = rf->read(path, dt, given);
  } catch (const InputError& e) {
    throw InputError(std::string(e.what()) + " (record matched by key '" + r.full(key) + "' at " +
                     r.file() + ":" + std::to_string(line) + ")");
  }
  if (given && *given != rec.units) {
    r.fail("units", "expected the units the " + std::string(rf->name) + " file " + path +
                        " states (" + std::string(unit_name(rec.units)) + "), got \"" + *units +
                        "\"");
  }
  if (rec.npts() < 2) r.fail_at(line, key, "expected a record with at least 2 samples in " + path);
  return rec;
}

}  // namespace

// the records of a [[suite]]: each horizontal file with its vertical one (if the suite has
// verticals), paired by the text of a glob's '*' or by position in lists; file bytes go into
// `hash`, file paths into `files`
std::vector<study::SweepRecord> read_suite(Keys& r, std::uint64_t& hash,
                                           std::vector<std::string>& files) {
  r.require("horizontal", "a glob or an array of horizontal record files");
  const SuiteComponent h = suite_component(r, "horizontal");
  const bool has_v = r.has("vertical"), has_h2 = r.has("horizontal2");
  SuiteComponent v, h2;
  if (has_v) v = suite_component(r, "vertical");
  if (has_h2) h2 = suite_component(r, "horizontal2");
  // a pair's azimuths [deg]: the plane of each run, from H1 toward H2 (docs/theory.md §23)
  std::vector<double> azimuths;
  if (has_h2) {
    if (r.has("azimuths_deg") && r.has("azimuth_step_deg"))
      r.fail("azimuth_step_deg", "expected 'azimuths_deg' or 'azimuth_step_deg', not both");
    if (r.has("azimuths_deg")) {
      azimuths = *grid_opt(r, "azimuths_deg", "[deg] (the body's plane, from H1 toward H2)");
      std::set<double> seen;
      for (const double a : azimuths) {
        if (!(a >= 0.0 && a < 360.0) || !seen.insert(a).second)
          r.fail("azimuths_deg", "expected distinct azimuths in [0, 360) deg, got " + num(a));
      }
    } else {
      const double step = r.positive_or("azimuth_step_deg", 5.0, "[deg] (in (0, 360))");
      if (!(step < 360.0))
        r.expected("azimuth_step_deg", "a step in (0, 360) deg, got " + num(step));
      for (std::size_t k = 0; static_cast<double>(k) * step < 360.0 - 1e-9; ++k)
        azimuths.push_back(static_cast<double>(k) * step);
    }
  } else {
    for (const char* k : {"azimuths_deg", "azimuth_step_deg"}) {
      if (r.has(k)) r.fail(k, "expected only with 'horizontal2' (a record pair)");
    }
  }
  std::optional<std::string> format;
  if (r.has("format")) {
    std::vector<std::string> names;
    for (const RecordFormat& f : record_formats()) names.emplace_back(f.name);
    format = r.choice("format", names);
  }
  std::optional<std::string> units;
  if (r.has("units")) units = r.choice("units", detail::accel_unit_names());
  const double dt = r.positive_or("dt", 0.0, "[s] (sample spacing of single_column files)");
  r.finish("for a [[suite]] (see docs/studies.md)");

  // the file of component `o` (named by `key`, e.g. "vertical") that goes with each horizontal
  // one (index into o.paths): by the text of a glob's '*', or by position in lists
  const auto pair_with = [&](const SuiteComponent& o, const std::string& key) {
    std::vector<std::size_t> pair(h.paths.size());
    if (h.glob != o.glob)
      r.fail(key, "expected 'horizontal' and '" + key + "' both globs or both arrays");
    std::set<std::string> hp(h.paths.begin(), h.paths.end());
    for (const std::string& p : o.paths) {
      if (hp.count(p))
        r.fail(key, "the file " + p + " is both a horizontal and a " + key + " component");
    }
    if (h.glob) {
      if (h.keys.empty() || o.keys.empty()) {
        r.fail(h.keys.empty() ? "horizontal" : key,
               "expected exactly one '*' (and no '?') in the file name of a glob with a " + key +
                   " pair: the text '*' matches pairs the components");
      }
      std::map<std::string, std::size_t> by_key;
      for (std::size_t j = 0; j < o.keys.size(); ++j) by_key.emplace(o.keys[j], j);
      std::set<std::size_t> used;
      for (std::size_t i = 0; i < h.paths.size(); ++i) {
        const auto it = by_key.find(h.keys[i]);
        if (it == by_key.end()) {
          r.fail(key, "the horizontal record " + h.paths[i] + " has no " + key +
                          " one: expected a file matching \"" + o.pattern + "\" with '*' = \"" +
                          h.keys[i] + "\"");
        }
        pair[i] = it->second;
        used.insert(it->second);
      }
      for (std::size_t j = 0; j < o.paths.size(); ++j) {
        if (!used.count(j)) {
          r.fail("horizontal", "the " + key + " record " + o.paths[j] +
                                   " has no horizontal one: expected a file matching \"" +
                                   h.pattern + "\" with '*' = \"" + o.keys[j] + "\"");
        }
      }
    } else {
      if (h.paths.size() != o.paths.size()) {
        r.fail(key, "expected as many " + key + " files as horizontal ones (" +
                        std::to_string(h.paths.size()) + "), got " +
                        std::to_string(o.paths.size()) + "; the lists pair by position");
      }
      for (std::size_t i = 0; i < pair.size(); ++i) pair[i] = i;
    }
    return pair;
  };
  const std::vector<std::size_t> pair =
      has_v ? pair_with(v, "vertical") : std::vector<std::size_t>{};
  const std::vector<std::size_t> pair2 =
      has_h2 ? pair_with(h2, "horizontal2") : std::vector<std::size_t>{};
  if (has_v && has_h2) {
    for (const std::string& p : v.paths) {
      if (std::find(h2.paths.begin(), h2.paths.end(), p) != h2.paths.end())
        r.fail("vertical", "the file " + p + " is both a horizontal2 and a vertical component");
    }
  }
  // the components of one station share a clock: a different one is refused, not resampled
  const auto same_grid = [&](const Record& hr, const Record& o, const SuiteComponent& oc,
                             const std::string& key, const std::string& hp, const std::string& op) {
    bool same = hr.npts() == o.npts();
    const double tol =
        1e-9 * (hr.time.back() - hr.time.front()) / static_cast<double>(hr.npts() - 1);
    for (std::size_t k = 0; same && k < hr.npts(); ++k)
      same = std::abs(hr.time[k] - o.time[k]) <= tol;
    if (!same) {
      r.fail_at(oc.line, key,
                "expected the " + key + " record " + op + " on the time grid of its horizontal " +
                    hp + " (" + std::to_string(hr.npts()) + " samples, dt " + num(hr.dt) +
                    " s), got " + std::to_string(o.npts()) + " samples, dt " + num(o.dt) +
                    " s (resample or cut one of them first)");
    }
  };

  std::vector<study::SweepRecord> out;
  for (std::size_t i = 0; i < h.paths.size(); ++i) {
    const Record hr = read_suite_file(r, "horizontal", h.line, h.paths[i], format, units, dt);
    files.push_back(h.paths[i]);
    hash = fnv1a(file_bytes(h.paths[i]), hash);
    std::string name = fs::path(h.paths[i]).stem().string();
    if (!has_v && !has_h2) {
      check_name(r, "horizontal", name);
      out.push_back({name, hr.to_motion(), nullptr});
      continue;
    }
    std::optional<Record> h2r, vr;
    if (has_h2) {
      const std::string& p2 = h2.paths[pair2[i]];
      h2r = read_suite_file(r, "horizontal2", h2.line, p2, format, units, dt);
      files.push_back(p2);
      hash = fnv1a(file_bytes(p2), hash);
      same_grid(hr, *h2r, h2, "horizontal2", h.paths[i], p2);
      name += "+" + fs::path(p2).stem().string();
    }
    if (has_v) {
      const std::string& vp = v.paths[pair[i]];
      vr = read_suite_file(r, "vertical", v.line, vp, format, units, dt);
      files.push_back(vp);
      hash = fnv1a(file_bytes(vp), hash);
      same_grid(hr, *vr, v, "vertical", h.paths[i], vp);
      name += "+" + fs::path(vp).stem().string();
    }
    if (!has_h2) {
      check_name(r, "horizontal", name);
      out.push_back({name, combine(hr, &*vr), nullptr});
      continue;
    }
    // a pair: one record per azimuth, the plane's component a = H1 cos(beta) + H2 sin(beta)
    // in m/s^2 (azimuth_motion's projection), named "<pair>@<beta>"
    auto components = std::make_shared<study::RecordPairComponents>();
    components->t = hr.time;
    components->h1 = hr.to_si();
    components->h2 = h2r->to_si();
    for (const double beta : azimuths) {
      Record a = hr;
      a.units = AccelUnit::kMetersPerSecond2;
      a.values = project_horizontal(components->h1, components->h2, beta);
      const std::string at = name + "@" + num(beta);
      check_name(r, "horizontal", at);
      out.push_back({at, has_v ? combine(a, &*vr) : a.to_motion(), components});
    }
  }
  return out;
}

}  // namespace study_detail

}  // namespace flexrock::io
