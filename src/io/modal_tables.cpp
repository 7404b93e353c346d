// SPDX-License-Identifier: BSD-3-Clause
#include "modal_tables.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string_view>
#include <utility>

#include "flexrock/core/error.hpp"
#include "flexrock/io/case_file.hpp"
#include "flexrock/io/files.hpp"

namespace flexrock::io::detail {

namespace {

namespace fs = std::filesystem;

struct Line {
  std::size_t number;
  std::string text;
};

[[noreturn]] void fail(const std::string& path, std::size_t line, const std::string& msg) {
  throw InputError(path + ":" + std::to_string(line) + ": " + msg);
}

std::vector<Line> read_lines(const std::string& path, const std::string& what) {
  // a regular file only: a FIFO would block, a device (/dev/zero) would never end
  std::istringstream in(read_input_file(path, what));
  std::vector<Line> lines;
  std::string text;
  while (std::getline(in, text)) {
    if (!text.empty() && text.back() == '\r') text.pop_back();
    if (lines.empty() && text.starts_with("\xEF\xBB\xBF")) text.erase(0, 3);
    lines.push_back({lines.size() + 1, std::move(text)});
  }
  return lines;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

// fields: on commas (CSV) or semicolons when the line has them, else on whitespace
std::vector<std::string> fields(std::string_view s) {
  std::vector<std::string> out;
  const char sep = s.find(',') != std::string_view::npos   ? ','
                   : s.find(';') != std::string_view::npos ? ';'
                                                           : '\0';
  if (sep) {
    std::size_t start = 0;
    while (true) {
      const std::size_t at = s.find(sep, start);
      out.emplace_back(trim(s.substr(start, at == std::string_view::npos ? at : at - start)));
      if (at == std::string_view::npos) break;
      start = at + 1;
    }
    if (out.size() > 1 && out.back().empty()) out.pop_back();  // a trailing separator
    return out;
  }
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    const std::size_t start = i;
    while (i < s.size() && !std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    if (i > start) out.emplace_back(s.substr(start, i - start));
  }
  return out;
}

// a number in plain or E notation ("0.", "-1.2345E-03", ".5"); nullopt if the text is not one
std::optional<double> number(const std::string& t) {
  if (t.empty()) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(t.c_str(), &end);
  if (end == t.c_str() || *end != '\0') return std::nullopt;
  // strtod also reads "nan", "inf" and hex: only decimal numbers are values here
  for (char c : t) {
    if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+' ||
          c == 'e' || c == 'E'))
      return std::nullopt;
  }
  return v;
}

// a column name for matching: lower case, units "[m]" or "(kg)" dropped, ' ' '_' '.' '-' dropped
std::string key_of(std::string_view name) {
  std::string k;
  int depth = 0;
  for (char c : name) {
    if (c == '[' || c == '(') ++depth;
    if (depth == 0 && std::isalnum(static_cast<unsigned char>(c)))
      k.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
    if ((c == ']' || c == ')') && depth > 0) --depth;
  }
  return k;
}

bool one_of(const std::string& k, std::initializer_list<const char*> names) {
  return std::any_of(names.begin(), names.end(), [&](const char* n) { return k == n; });
}

bool is_node_column(const std::string& k) {
  return one_of(
      k, {"node", "nodes", "nodelabel", "nodeid", "nodenumber", "nodeno", "id", "label", "joint"});
}

// a node label as text: "12" and "12.0" are the same node
std::string label_of(const std::string& field) {
  const auto v = number(field);
  if (v && *v == std::floor(*v) && std::abs(*v) < 1e15)
    return std::to_string(static_cast<long long>(*v));
  return field;
}

// a row of the file split into fields, and whether every field is a number
struct Row {
  const Line* line;
  std::vector<std::string> f;
  bool numeric = false;
  bool any_number = false;
};

std::vector<Row> rows_of(const std::vector<Line>& lines) {
  std::vector<Row> rows;
  for (const Line& l : lines) {
    const std::string_view t = trim(l.text);
    if (t.empty() || t.front() == '#') continue;
    Row r{&l, fields(t)};
    r.numeric = !r.f.empty();
    for (const std::string& x : r.f) {
      const bool n = number(x).has_value();
      r.numeric = r.numeric && n;
      r.any_number = r.any_number || n;
    }
    rows.push_back(std::move(r));
  }
  return rows;
}

// the values of one numeric row, checked finite
std::vector<double> values_of(const std::string& path, const Row& r) {
  std::vector<double> v;
  for (const std::string& x : r.f) {
    const double d = *number(x);
    if (!std::isfinite(d)) fail(path, r.line->number, "expected finite numbers, got \"" + x + "\"");
    v.push_back(d);
  }
  return v;
}

std::string quoted_names(const std::vector<std::string>& f) {
  std::string s;
  for (std::size_t i = 0; i < f.size(); ++i) s += (i ? ", " : "") + f[i];
  return s;
}

}  // namespace

NodeTable read_node_table(const std::string& path) {
  const std::string what = "nodes";
  const std::vector<Line> lines = read_lines(path, what);
  const std::vector<Row> rows = rows_of(lines);
  if (rows.empty()) throw InputError(path + ": no rows of nodes found");
  NodeTable t;

  // columns by name from the header row, or x, y, mass by position
  int c_id = -1, c_x = -1, c_y = -1, c_m = -1, c_j = -1;
  std::size_t first = 0, width = 3;
  const Row& head = rows.front();
  if (!head.numeric) {
    if (head.any_number) {
      fail(path, head.line->number,
           "expected a header row naming the columns (node, x, y, mass, rotary_inertia) or a row "
           "of numbers x, y, mass, got \"" +
               head.line->text + "\"");
    }
    const std::vector<std::string> known = {"node", "x", "y", "mass", "rotary_inertia"};
    for (std::size_t i = 0; i < head.f.size(); ++i) {
      const std::string k = key_of(head.f[i]);
      int* slot = is_node_column(k)                                   ? &c_id
                  : one_of(k, {"x", "coordx", "coor1", "coordcoor1"}) ? &c_x
                  : one_of(k, {"y", "coordy", "coor2", "coordcoor2"}) ? &c_y
                  : one_of(k, {"mass", "m"})                          ? &c_m
                  : one_of(k, {"rotaryinertia", "j", "inertia"})      ? &c_j
                                                                      : nullptr;
      if (!slot) {
        std::string hint = closest_key(head.f[i], known);
        fail(path, head.line->number,
             "unknown column \"" + head.f[i] + "\"" +
                 (hint.empty() ? "" : " (did you mean \"" + hint + "\"?)") +
                 "; expected the columns node (optional), x [m], y [m], mass [kg], "
                 "rotary_inertia [kg m^2] (optional)");
      }
      if (*slot >= 0) {
        fail(path, head.line->number,
             "column \"" + head.f[i] + "\" names the same quantity as column \"" +
                 head.f[static_cast<std::size_t>(*slot)] + "\"");
      }
      *slot = static_cast<int>(i);
    }
    if (c_x < 0 || c_y < 0 || c_m < 0) {
      fail(
          path, head.line->number,
          "expected columns x, y and mass in the header row, got \"" + quoted_names(head.f) + "\"");
    }
    first = 1;
    width = head.f.size();
  } else {
    if (head.f.size() != 3) {
      fail(path, head.line->number,
           "expected 3 columns x, y, mass without a header row, got " +
               std::to_string(head.f.size()) +
               "; name the columns in a header row (node, x, y, mass, rotary_inertia) so that a "
               "node-id or rotary-inertia column is not taken for a coordinate");
    }
    c_x = 0;
    c_y = 1;
    c_m = 2;
  }
  std::map<std::string, std::size_t> seen;
  for (std::size_t i = first; i < rows.size(); ++i) {
    const Row& r = rows[i];
    if (!r.numeric && c_id < 0) {
      fail(path, r.line->number,
           "expected " + std::to_string(width) + " numbers (nodes), got \"" + r.line->text + "\"");
    }
    if (r.f.size() != width) {
      fail(path, r.line->number,
           "expected " + std::to_string(width) + " values (nodes), got " +
               std::to_string(r.f.size()));
    }
    auto at = [&](int c) {
      const std::string& x = r.f[static_cast<std::size_t>(c)];
      const auto v = number(x);
      if (!v || !std::isfinite(*v)) {
        fail(path, r.line->number,
             "expected a finite number in column " + std::to_string(c + 1) + ", got \"" + x + "\"");
      }
      return *v;
    };
    LumpedNode n{at(c_x), at(c_y), at(c_m), c_j >= 0 ? at(c_j) : 0.0};
    if (!(n.mass >= 0.0) || !(n.rotary_inertia >= 0.0)) {
      fail(path, r.line->number,
           "expected a node mass and rotary inertia >= 0, got mass " +
               r.f[static_cast<std::size_t>(c_m)] +
               (c_j >= 0 ? ", rotary inertia " + r.f[static_cast<std::size_t>(c_j)] : ""));
    }
    if (c_id >= 0) {
      const std::string id = label_of(r.f[static_cast<std::size_t>(c_id)]);
      const auto [it, fresh] = seen.emplace(id, r.line->number);
      if (!fresh) {
        fail(path, r.line->number,
             "node " + id + " is listed twice (also on line " + std::to_string(it->second) + ")");
      }
      t.ids.push_back(id);
    }
    t.nodes.push_back(n);
    t.lines.push_back(r.line->number);
  }
  if (t.nodes.empty()) throw InputError(path + ": no rows of nodes found (only a header)");
  return t;
}

ShapeTable read_shape_table(const std::string& path, Eigen::Index modes) {
  const std::string what = "mode shapes";
  const std::vector<Line> lines = read_lines(path, what);
  const std::vector<Row> rows = rows_of(lines);
  if (rows.empty()) throw InputError(path + ": no rows of mode shapes found");
  const auto n = static_cast<std::size_t>(modes);

  // one mode's (or, wide, every mode's) rows while they are read
  struct Block {
    std::vector<std::string> ids;
    std::vector<std::size_t> lines;
    std::vector<std::vector<double>> x, y;  // rows, each one value a mode of this block
    std::map<std::string, std::size_t> seen;
  };
  std::vector<Block> blocks;
  ShapeTable t;

  // a header row: names an x and a y component (per mode) or phi_x_k/phi_y_k (all modes)
  struct Header {
    int id = -1;
    std::vector<int> x, y;  // column of each mode's component (wide: n of each; else 1)
    std::size_t width = 0;
    bool wide = false;
  };
  auto header_of = [&](const Row& r) -> std::optional<Header> {
    if (r.any_number) return std::nullopt;
    Header h;
    h.width = r.f.size();
    std::map<std::size_t, int> wx, wy;
    int px = -1, py = -1;
    for (std::size_t i = 0; i < r.f.size(); ++i) {
      const std::string k = key_of(r.f[i]);
      const int c = static_cast<int>(i);
      if (is_node_column(k)) {
        h.id = c;
      } else if (one_of(k, {"ux", "uu1", "u1", "phix", "dx"})) {
        px = c;
      } else if (one_of(k, {"uy", "uu2", "u2", "phiy", "dy"})) {
        py = c;
      } else if ((k.starts_with("phix") || k.starts_with("phiy")) && k.size() > 4 &&
                 std::all_of(k.begin() + 4, k.end(), [](char ch) {
                   return std::isdigit(static_cast<unsigned char>(ch));
                 })) {
        const auto mode = static_cast<std::size_t>(std::stoul(k.substr(4, 6)));
        auto& slot = k[3] == 'x' ? wx : wy;
        if (mode == 0 || slot.count(mode)) {
          fail(path, r.line->number,
               "column \"" + r.f[i] + "\": expected mode numbers 1, 2, ... each once");
        }
        slot[mode] = c;
      }
    }
    if (!wx.empty() || !wy.empty()) {
      for (std::size_t k = 1; k <= n; ++k) {
        if (!wx.count(k) || !wy.count(k)) {
          fail(path, r.line->number,
               "expected columns phi_x_" + std::to_string(k) + " and phi_y_" + std::to_string(k) +
                   " (one pair a mode, " + std::to_string(n) + " modes), got \"" +
                   quoted_names(r.f) + "\"");
        }
        h.x.push_back(wx[k]);
        h.y.push_back(wy[k]);
      }
      if (wx.size() != n || wy.size() != n) {
        fail(path, r.line->number,
             "expected " + std::to_string(n) +
                 " modes (as many as frequencies or stiffness), "
                 "got phi columns for " +
                 std::to_string(std::max(wx.size(), wy.size())));
      }
      h.wide = true;
      return h;
    }
    if (px >= 0 && py >= 0) {
      h.x = {px};
      h.y = {py};
      return h;
    }
    return std::nullopt;
  };

  std::optional<Header> cur;
  bool in_data = false;  // data rows of the current table have begun
  bool wide = false, any_header = false, text_seen = false;
  for (const Row& r : rows) {
    if (auto h = header_of(r)) {
      if (any_header && h->wide != wide) {
        fail(path, r.line->number, "a table of another kind than the first one in this file");
      }
      if (h->wide && any_header) {
        fail(path, r.line->number,
             "a second phi_x_1, phi_y_1, ... table; expected one table holding every mode");
      }
      wide = h->wide;
      any_header = true;
      cur = h;
      in_data = false;
      continue;
    }
    if (!r.numeric) {
      text_seen = true;
      // banners, units rows under a header, separators and summaries ("MAXIMUM ABSOLUTE
      // VALUES", "Minimum"): text, never values
      if (in_data) cur.reset();
      continue;
    }
    if (!cur && !any_header && text_seen) {
      fail(path, r.line->number,
           "a row of numbers with no header row above it naming its columns (node and UX, UY; "
           "U.U1, U.U2; phi_x, phi_y; or phi_x_1, phi_y_1, ...)");
    }
    if (!cur && !any_header) {
      // no header at all: phi_x_1, phi_y_1, ... by position
      Header h;
      h.width = 2 * n;
      for (std::size_t k = 0; k < n; ++k) {
        h.x.push_back(static_cast<int>(2 * k));
        h.y.push_back(static_cast<int>(2 * k + 1));
      }
      h.wide = wide = true;
      any_header = true;
      cur = h;
      if (r.f.size() != h.width) {
        fail(path, r.line->number,
             "expected " + std::to_string(h.width) + " values (phi_x_1, phi_y_1, ... for " +
                 std::to_string(n) + " modes) without a header row, got " +
                 std::to_string(r.f.size()) +
                 "; name the columns in a header row (node, phi_x_1, phi_y_1, ...)");
      }
    }
    if (!cur) {
      fail(path, r.line->number,
           "a row of numbers after the end of a table (no header row above it naming its "
           "columns), got \"" +
               r.line->text + "\"");
    }
    if (r.f.size() != cur->width) {
      fail(path, r.line->number,
           "expected " + std::to_string(cur->width) +
               " values (as many as the header row's "
               "columns), got " +
               std::to_string(r.f.size()));
    }
    const std::vector<double> v = values_of(path, r);
    const std::string id =
        cur->id >= 0 ? label_of(r.f[static_cast<std::size_t>(cur->id)]) : std::string();
    // a new mode: a new table that does not continue the last one's node labels
    if (!in_data) {
      const bool continues = !blocks.empty() && !wide && cur->id >= 0 &&
                             !blocks.back().ids.empty() && !blocks.back().seen.count(id);
      if (!continues && !(wide && !blocks.empty())) blocks.emplace_back();
      in_data = true;
    }
    Block& b = blocks.back();
    if (cur->id >= 0) {
      const auto [it, fresh] = b.seen.emplace(id, r.line->number);
      if (!fresh) {
        fail(path, r.line->number,
             "node " + id + " is listed twice in one mode (also on line " +
                 std::to_string(it->second) + ")");
      }
      b.ids.push_back(id);
    }
    b.lines.push_back(r.line->number);
    std::vector<double> x, y;
    for (std::size_t k = 0; k < cur->x.size(); ++k) {
      x.push_back(v[static_cast<std::size_t>(cur->x[k])]);
      y.push_back(v[static_cast<std::size_t>(cur->y[k])]);
    }
    b.x.push_back(std::move(x));
    b.y.push_back(std::move(y));
  }
  if (blocks.empty()) {
    throw InputError(path +
                     ": no table of mode shapes found; expected a header row naming a node "
                     "column and the components (UX and UY, U.U1 and U.U2, phi_x and phi_y, or "
                     "phi_x_1, phi_y_1, ...) above the rows");
  }
  if (!wide && blocks.size() != n) {
    throw InputError(path + ": expected " + std::to_string(n) +
                     " mode tables (one a mode, as many as frequencies or stiffness), found " +
                     std::to_string(blocks.size()));
  }

  // every mode over the first mode's rows, matched by label when there are labels
  const Block& b0 = blocks.front();
  const auto rows_n = static_cast<Eigen::Index>(b0.x.size());
  t.ids = b0.ids;
  t.lines = b0.lines;
  t.phi_x.resize(rows_n, modes);
  t.phi_y.resize(rows_n, modes);
  if (wide) {
    for (Eigen::Index i = 0; i < rows_n; ++i) {
      for (Eigen::Index k = 0; k < modes; ++k) {
        t.phi_x(i, k) = b0.x[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)];
        t.phi_y(i, k) = b0.y[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)];
      }
    }
    return t;
  }
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    const Block& b = blocks[k];
    for (Eigen::Index i = 0; i < rows_n; ++i) {
      std::size_t row = static_cast<std::size_t>(i);
      if (!b0.ids.empty() && !b.ids.empty()) {
        const auto it = b.seen.find(b0.ids[row]);
        if (it == b.seen.end()) {
          throw InputError(path + ": mode " + std::to_string(k + 1) + " has no row for node " +
                           b0.ids[row] + " (listed in mode 1 on line " +
                           std::to_string(b0.lines[row]) + ")");
        }
        row = static_cast<std::size_t>(std::find(b.ids.begin(), b.ids.end(), b0.ids[row]) -
                                       b.ids.begin());
      } else if (b.x.size() != b0.x.size()) {
        throw InputError(path + ": mode " + std::to_string(k + 1) + " has " +
                         std::to_string(b.x.size()) + " rows, mode 1 has " +
                         std::to_string(b0.x.size()) + "; expected one row a node in each");
      }
      t.phi_x(i, static_cast<Eigen::Index>(k)) = b.x[row][0];
      t.phi_y(i, static_cast<Eigen::Index>(k)) = b.y[row][0];
    }
  }
  return t;
}

void match_shapes(const NodeTable& nodes, const std::string& nodes_path, const ShapeTable& shapes,
                  const std::string& shapes_path, MatrixX& phi_x, MatrixX& phi_y) {
  const auto nn = static_cast<Eigen::Index>(nodes.nodes.size());
  const Eigen::Index n = shapes.phi_x.cols();
  phi_x.resize(nn, n);
  phi_y.resize(nn, n);
  if (!nodes.ids.empty() && !shapes.ids.empty()) {
    std::map<std::string, Eigen::Index> row;
    for (std::size_t i = 0; i < shapes.ids.size(); ++i)
      row[shapes.ids[i]] = static_cast<Eigen::Index>(i);
    for (Eigen::Index k = 0; k < nn; ++k) {
      const std::string& id = nodes.ids[static_cast<std::size_t>(k)];
      const auto it = row.find(id);
      if (it == row.end()) {
        throw InputError(nodes_path + ":" +
                         std::to_string(nodes.lines[static_cast<std::size_t>(k)]) + ": node " + id +
                         " has no row in the mode shapes " + shapes_path +
                         "; expected a shape for every node of the nodes table");
      }
      phi_x.row(k) = shapes.phi_x.row(it->second);
      phi_y.row(k) = shapes.phi_y.row(it->second);
    }
    return;
  }
  if (shapes.phi_x.rows() != nn) {
    throw InputError(shapes_path + ": expected " + std::to_string(nn) + " rows (one a node of " +
                     nodes_path + "), got " + std::to_string(shapes.phi_x.rows()) +
                     (nodes.ids.empty() || shapes.ids.empty()
                          ? "; with a node column in both files the rows are matched by node"
                          : ""));
  }
  phi_x = shapes.phi_x;
  phi_y = shapes.phi_y;
}

}  // namespace flexrock::io::detail
