// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/io/outputs.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <numbers>
#include <ostream>
#include <stdexcept>
#include <streambuf>
#include <system_error>

#include "flexrock/core/format.hpp"
#include "flexrock/excitation/intensity.hpp"
#include "flexrock/io/files.hpp"
#include "flexrock/version.hpp"

namespace flexrock::io {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;  // keys in the documented order

namespace {

// Temporaries being written, for the interrupt handler: a fixed table (no allocation, lock-free
// atomics) so that the handler stays async-signal-safe. A slot is 0 free, 1 being filled, 2 set.
constexpr int kTempSlots = 64;
constexpr std::size_t kTempPathMax = 4096;
struct TempSlot {
  std::atomic<int> state{0};
  char path[kTempPathMax] = {};
};
TempSlot g_temp_slots[kTempSlots];

// SIGINT/SIGTERM/SIGHUP: remove every temporary being written, then die of the signal as before
extern "C" void remove_temporaries_and_reraise(int sig) {
  for (TempSlot& s : g_temp_slots) {
    if (s.state.load() == 2) ::unlink(s.path);
  }
  std::signal(sig, SIG_DFL);
  std::raise(sig);  // delivered when the handler returns: the default action (termination)
}

// installs the handler once, only where the signal still has its default action (a program or
// an interpreter with its own handler keeps it)
void install_interrupt_cleanup() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
      struct sigaction old {};
      if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler != SIG_DFL) continue;
      struct sigaction sa {};
      sa.sa_handler = remove_temporaries_and_reraise;
      sigemptyset(&sa.sa_mask);
      ::sigaction(sig, &sa, nullptr);
    }
  });
}

// registers a temporary for the handler while it exists
class TempRegistration {
 public:
  explicit TempRegistration(const std::string& tmp) {
    if (tmp.size() >= kTempPathMax) return;
    for (int i = 0; i < kTempSlots; ++i) {
      int expected = 0;
      if (g_temp_slots[i].state.compare_exchange_strong(expected, 1)) {
        std::memcpy(g_temp_slots[i].path, tmp.c_str(), tmp.size() + 1);
        g_temp_slots[i].state.store(2);
        slot_ = i;
        return;
      }
    }
  }
  ~TempRegistration() {
    if (slot_ >= 0) g_temp_slots[slot_].state.store(0);
  }
  TempRegistration(const TempRegistration&) = delete;
  TempRegistration& operator=(const TempRegistration&) = delete;

 private:
  int slot_ = -1;
};

}  // namespace

namespace {

// the bytes that follow a name in its temporary: ".tmp.", a process id (at most 10 digits), '.'
// and 16 random hex digits
constexpr std::size_t kTempRandomDigits = 16;
constexpr std::size_t kTempSuffixMax = 5 + 10 + 1 + kTempRandomDigits;

// the longest file name the directory takes (NAME_MAX: 255 on Linux file systems)
std::size_t name_max(const fs::path& dir) {
  const long n = ::pathconf(dir.empty() ? "." : dir.c_str(), _PC_NAME_MAX);
  return n > 0 ? static_cast<std::size_t>(n) : 255;
}

// "NAME.tmp.": the name a temporary of `path` starts with, before "<pid>.<random>". A name too long
// to take the suffix within NAME_MAX is cut and told apart by a hash of the whole name.
std::string temp_stem(const fs::path& path) {
  const std::string name = path.filename().string();
  const std::size_t max = name_max(path.parent_path());
  if (name.size() + kTempSuffixMax <= max) return name + ".tmp.";
  char hash[24];
  std::uint64_t h = 1469598103934665603ULL;
  for (const char c : name) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ULL;
  std::snprintf(hash, sizeof hash, ".%016llx", static_cast<unsigned long long>(h));
  const std::size_t keep = max > kTempSuffixMax + 17 + 1 ? max - kTempSuffixMax - 17 : 1;
  return name.substr(0, keep) + hash + ".tmp.";
}

// removes the temporaries of `path` that runs killed before they could clean up (SIGKILL, power
// loss) left behind: regular files "STEM<pid>.<16 hex digits>" (or "STEM<pid>", as earlier
// versions named them) where no process <pid> runs any more; anything else is left alone
void remove_stale_temporaries(const fs::path& path, const std::string& stem) {
  const fs::path dir = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  std::error_code ec;
  fs::directory_iterator it(dir, ec);
  for (; !ec && it != fs::directory_iterator(); it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (!name.starts_with(stem) || name.size() == stem.size()) continue;
    std::string digits = name.substr(stem.size());
    if (const std::size_t dot = digits.find('.'); dot != std::string::npos) {
      const std::string random = digits.substr(dot + 1);
      if (random.size() != kTempRandomDigits ||
          random.find_first_not_of("0123456789abcdef") != std::string::npos) {
        continue;
      }
      digits.resize(dot);
    }
    if (digits.empty() || digits.size() > 10 ||
        digits.find_first_not_of("0123456789") != std::string::npos) {
      continue;
    }
    const long pid = std::stol(digits);
    if (pid <= 0 || pid == static_cast<long>(::getpid())) continue;
    if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;  // still running
    struct stat st {};
    if (::lstat(it->path().c_str(), &st) != 0 || !S_ISREG(st.st_mode)) continue;
    std::error_code ignored;
    fs::remove(it->path(), ignored);
  }
}

// 16 hex digits nobody can guess: a temporary's name must not be known before it exists
std::string random_hex() {
  std::uint64_t v = 0;
  if (::getrandom(&v, sizeof v, 0) != static_cast<ssize_t>(sizeof v)) {
    // no entropy source (a very old kernel): the clock and the address space still vary
    static std::atomic<std::uint64_t> counter{0};
    v = static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count()) ^
        (reinterpret_cast<std::uintptr_t>(&v) << 16) ^
        (counter.fetch_add(1) * 0x9e3779b97f4a7c15ULL);
  }
  char buf[kTempRandomDigits + 1];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

// "PATH: reason" of the last system call
std::runtime_error os_error(const std::string& what, const std::string& path, int err) {
  return std::runtime_error("cannot " + what + " " + path + ": " + std::strerror(err));
}

// a stream buffer on a file descriptor that keeps the first write error's errno
class FdBuf : public std::streambuf {
 public:
  explicit FdBuf(int fd) : fd_(fd) { setp(buf_, buf_ + sizeof buf_); }
  int error() const { return error_; }

 protected:
  int_type overflow(int_type c) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return drain() ? 0 : -1; }

 private:
  bool drain() {
    const char* p = pbase();
    while (p < pptr() && error_ == 0) {
      const ssize_t n = ::write(fd_, p, static_cast<std::size_t>(pptr() - p));
      if (n < 0) {
        if (errno != EINTR) error_ = errno;
        continue;
      }
      p += n;
    }
    setp(buf_, buf_ + sizeof buf_);
    return error_ == 0;
  }
  int fd_;
  int error_ = 0;
  char buf_[1 << 16];
};

}  // namespace

void write_atomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
  const fs::path target(path);
  // an existing directory, device or FIFO is not replaced by a regular file
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
    throw std::runtime_error("cannot write " + path + ": it exists and is not a regular file");
  }
  const std::string stem = temp_stem(target);
  remove_stale_temporaries(target, stem);
  install_interrupt_cleanup();
  // a new file of an unpredictable name, never an existing one and never through a symbolic link
  // planted at the name: O_EXCL fails on any existing entry, links included
  std::string tmp;
  int fd = -1;
  for (int attempt = 0; fd < 0; ++attempt) {
    tmp =
        (target.parent_path() / (stem + std::to_string(::getpid()) + "." + random_hex())).string();
    fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd < 0 && (errno != EEXIST || attempt == 100)) {
      throw os_error("create the temporary file", tmp, errno);
    }
  }
  const TempRegistration registration(tmp);
  struct stat written {};
  bool open = true;
  try {
    FdBuf buf(fd);
    std::ostream out(&buf);
    write(out);
    out.flush();
    if (buf.error() != 0) throw os_error("write", tmp, buf.error());
    if (!out) throw std::runtime_error("cannot write " + tmp);
    // on the disk before the rename: a crash after it finds the new content, not an empty file
    if (::fsync(fd) != 0) throw os_error("flush to disk", tmp, errno);
    if (::fstat(fd, &written) != 0) throw os_error("inspect", tmp, errno);
    open = false;
    if (::close(fd) != 0) throw os_error("close", tmp, errno);
  } catch (...) {
    if (open) ::close(fd);
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw;
  }
  // the name must still be the file written: a directory others may write to can have had it
  // replaced (by a link to a file of theirs) meanwhile
  struct stat now {};
  if (::lstat(tmp.c_str(), &now) != 0 || !S_ISREG(now.st_mode) || now.st_dev != written.st_dev ||
      now.st_ino != written.st_ino) {
    throw std::runtime_error("cannot rename " + tmp + " to " + path +
                             ": the temporary was replaced by another process; nothing written");
  }
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    const int e = errno;
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw std::runtime_error("cannot rename " + tmp + " to " + path + ": " + std::strerror(e));
  }
  // the rename itself on the disk: the directory entry
  const std::string dir = target.parent_path().empty() ? "." : target.parent_path().string();
  const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd >= 0) {
    ::fsync(dfd);
    ::close(dfd);
  }
}

namespace {

// shortest text that reads back to the same double
void put(std::ostream& out, double v) { out << format_number(v); }

template <class T>
void put_row(std::ostream& out, const std::vector<T>& row) {
  for (std::size_t i = 0; i < row.size(); ++i) {
    if (i) out << ',';
    put(out, static_cast<double>(row[i]));
  }
  out << '\n';
}

void put_header(std::ostream& out, const std::vector<std::string>& cols) {
  for (std::size_t i = 0; i < cols.size(); ++i) out << (i ? "," : "") << cols[i];
  out << '\n';
}

// a double for JSON: null when not finite (JSON has no inf/nan)
Json jnum(double v) { return std::isfinite(v) ? Json(v) : Json(); }

// a time that is -1 when the event never happened: null then
Json jtime(double t) { return t < 0.0 ? Json() : Json(t); }

Json jvec(const VectorX& v) {
  Json a = Json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) a.push_back(jnum(v(i)));
  return a;
}

Json component_json(const ExcitationComponent& e) {
  if (e.type.empty()) return nullptr;
  Json j{{"type", e.type}};
  if (e.type == "record") {
    j["file"] = e.file;
    j["format"] = e.format;
    j["units"] = e.units;
    j["scale"] = e.scale;
  } else if (e.type != "none") {
    j["amplitude_m_per_s2"] = e.amplitude;
  }
  return j;
}

std::string resolve_out(const std::string& dir, const std::string& p) {
  if (p.empty()) return {};
  const fs::path path(p);
  if (path.is_absolute() || dir.empty()) return p;
  return (fs::path(dir) / path).lexically_normal().string();
}

}  // namespace

namespace {

// a History vector as a column: one value per output time, NaN where the engine left none
template <std::vector<double> History::*kMember>
std::vector<double> member(const SimulationResult& r, const Body&, std::size_t) {
  std::vector<double> c(r.history.*kMember);
  c.resize(r.history.size(), std::nan(""));  // a column the engine did not fill is not a number
  return c;
}

// mode i's column of a row-major History vector (q or q_dot)
template <std::vector<double> History::*kMember>
std::vector<double> modal(const SimulationResult& r, const Body&, std::size_t i) {
  const History& h = r.history;
  const auto modes = static_cast<std::size_t>(h.modes);
  std::vector<double> c(h.size());
  for (std::size_t k = 0; k < c.size(); ++k) c[k] = (h.*kMember)[k * modes + i];
  return c;
}

// one column of the time history: name (a modal column's has "{i}" for the mode number), unit,
// meaning, and its values from a run (mode i of a modal column). The CSV, the Python arrays
// and the column reference of docs/case-file.md are written from this table.
struct HistoryColumn {
  const char* name;
  const char* unit;
  const char* doc;
  bool modal;  // one column a mode
  std::vector<double> (*values)(const SimulationResult& r, const Body& body, std::size_t mode);
};

const HistoryColumn kHistoryColumns[] = {
    {"time_s", "s", "time", false,
     [](const SimulationResult& r, const Body&, std::size_t) { return r.history.time; }},
    {"phase", "-",
     "contact mode: 0 full contact, 1 rocking on edge 1, 2 rocking on edge 2, 3 flight; sliding "
     "(finite friction): 4 / 5 full contact sliding along +I / -I, 6 / 7 rocking on edge 1 and 8 / "
     "9 on edge 2 with the pivot sliding along +I / -I",
     false,
     [](const SimulationResult& r, const Body&, std::size_t) {
       return std::vector<double>(r.history.phase.begin(), r.history.phase.end());
     }},
    {"theta_rad", "rad", "tilt", false,
     [](const SimulationResult& r, const Body&, std::size_t) { return r.history.theta; }},
    {"theta_dot_rad_per_s", "rad/s", "tilt rate", false,
     [](const SimulationResult& r, const Body&, std::size_t) { return r.history.theta_dot; }},
    {"uplift_m", "m",
     "height of the higher tipping point: (b1 + b2) sin\\|theta\\| while rocking, plus `lift_m` "
     "in flight",
     false,
     [](const SimulationResult& r, const Body& body, std::size_t) {
       // the base width swung through |theta|, plus the lower edge's height in flight
       const History& h = r.history;
       const double width = body.params().b1 + body.params().b2;
       std::vector<double> uplift(h.size(), 0.0);
       for (std::size_t k = 0; k < h.size(); ++k) {
         const double lift = k < h.lift.size() ? h.lift[k] : 0.0;
         if (h.phase[k] != 0) uplift[k] = lift + width * std::sin(std::abs(h.theta[k]));
       }
       return uplift;
     }},
    {"q{i}", "-", "modal coordinates (n = body modes; none for a rigid body)", true,
     modal<&History::q>},
    {"q{i}_dot_per_s", "1/s", "their rates", true, modal<&History::q_dot>},
    {"base_acc_x_m_per_s2", "m/s^2", "ground acceleration, horizontal", false,
     member<&History::base_acc_x>},
    {"base_acc_y_m_per_s2", "m/s^2", "ground acceleration, vertical", false,
     member<&History::base_acc_y>},
    {"reaction_x_N", "N", "floor reaction on the body, horizontal", false,
     member<&History::reaction_x>},
    {"reaction_y_N", "N", "floor reaction on the body, vertical", false,
     member<&History::reaction_y>},
    {"resultant_m", "m",
     "where the reaction acts, from the c.g. projection (the pivot while rocking)", false,
     member<&History::resultant>},
    {"friction_demand", "-", "abs(reaction_x)/reaction_y (0 in flight)", false,
     member<&History::friction_demand>},
    {"kinetic_J", "J", "relative kinetic energy", false, member<&History::kinetic>},
    {"potential_J", "J", "gravity + strain energy", false, member<&History::potential>},
    {"input_work_J", "J", "work of the base motion, cumulative", false,
     member<&History::input_work>},
    {"damping_loss_J", "J", "energy lost to modal damping, cumulative", false,
     member<&History::damping_loss>},
    {"impact_loss_J", "J", "energy lost in impacts, cumulative", false,
     member<&History::impact_loss>},
    {"offset_m", "m",
     "horizontal offset of the base centre (below the undeformed c.g.) from where the body "
     "stood: changes in flight and while the base slides",
     false, member<&History::offset>},
    {"lift_m", "m", "height of the lower tipping point above the floor: > 0 only in flight", false,
     member<&History::lift>},
};

// the support's columns (a run on a [support] only), after the body's
struct SupportColumn {
  const char* name;
  const char* unit;
  const char* doc;
  std::vector<double> SupportHistory::*values;
};

const SupportColumn kSupportColumns[] = {
    {"support_u_m", "m", "with `[support]` only: the support's displacement from the ground",
     &SupportHistory::displacement},
    {"support_u_dot_m_per_s", "m/s", "with `[support]` only: its velocity relative to the ground",
     &SupportHistory::velocity},
    {"support_acc_m_per_s2", "m/s^2",
     "with `[support]` only: its absolute acceleration (the body's base)",
     &SupportHistory::acceleration},
    {"support_force_N", "N",
     "with `[support]` only: the force of its spring and dashpot, k u + c u_dot",
     &SupportHistory::force},
};

// a modal column's name for mode `i` (1-based); appended, not concatenated: GCC 12 warns
// (-Wrestrict) on "q" + std::to_string(i)
std::string column_name(const HistoryColumn& c, const std::string& i) {
  std::string name(c.name);
  const std::size_t at = name.find("{i}");
  if (at != std::string::npos) name.replace(at, 3, i);
  return name;
}

}  // namespace

std::vector<std::string> time_history_columns(int modes) {
  std::vector<std::string> c;
  for (const HistoryColumn& col : kHistoryColumns) {
    if (!col.modal) {
      c.emplace_back(col.name);
      continue;
    }
    for (int i = 1; i <= modes; ++i) c.push_back(column_name(col, std::to_string(i)));
  }
  return c;
}

std::vector<std::vector<double>> time_history_values(const SimulationResult& r, const Body& body) {
  const auto modes = static_cast<std::size_t>(r.history.modes);
  std::vector<std::vector<double>> cols;
  for (const HistoryColumn& col : kHistoryColumns) {
    for (std::size_t i = 0; i < (col.modal ? modes : 1); ++i)
      cols.push_back(col.values(r, body, i));
  }
  return cols;
}

std::string time_history_column_reference() {
  std::string s =
      "<!-- begin: written by `flexrock keys --markdown` from the table of time-history columns "
      "(src/io/outputs.cpp); edit the table, not these lines -->\n"
      "| column | unit | meaning |\n"
      "|---|---|---|\n";
  for (const HistoryColumn& c : kHistoryColumns) {
    // appended, not concatenated: GCC 12 warns falsely on "`" + std::string (PR 105651)
    std::string name("`");
    if (c.modal) {
      name.append(column_name(c, "1")).append("` ... `").append(column_name(c, "n"));
    } else {
      name.append(c.name);
    }
    name.append("`");
    s += "| " + name + " | " + c.unit + " | " + c.doc + " |\n";
  }
  for (const SupportColumn& c : kSupportColumns)
    s += std::string("| `") + c.name + "` | " + c.unit + " | " + c.doc + " |\n";
  s += "<!-- end: written by `flexrock keys --markdown` -->\n";
  return s;
}

void write_time_history(std::ostream& out, const SimulationResult& r, const Body& body,
                        const SupportRunResult* support) {
  std::vector<std::string> names = time_history_columns(r.history.modes);
  std::vector<std::vector<double>> cols = time_history_values(r, body);
  if (support) {
    for (const SupportColumn& c : kSupportColumns) {
      names.emplace_back(c.name);
      cols.push_back(support->history.*c.values);
      cols.back().resize(r.history.size(), std::nan(""));
    }
  }
  put_header(out, names);
  std::vector<double> row(cols.size());
  for (std::size_t k = 0; k < r.history.size(); ++k) {
    for (std::size_t j = 0; j < cols.size(); ++j) row[j] = cols[j][k];
    put_row(out, row);
  }
}

namespace {

// one column of the event log: name, unit, meaning and its value of an event (a number, or the
// kind's name). The CSV, the Python arrays and the column reference of docs/case-file.md are
// written from this table
struct EventColumn {
  const char* name;
  const char* unit;
  const char* doc;
  double (*value)(const Event& e);      // nullptr: a text column
  const char* (*text)(const Event& e);  // the text of a text column
};

const EventColumn kEventColumns[] = {
    {"time_s", "s", "when", [](const Event& e) { return e.time; }, nullptr},
    {"event", "-", "what happened: one of the kinds below", nullptr,
     [](const Event& e) { return to_string(e.kind); }},
    {"edge", "-",
     "1 or 2: the pivot after an uplift or impact, the overturning side; 0: both (a level "
     "landing) or none",
     [](const Event& e) { return static_cast<double>(e.edge); }, nullptr},
    {"theta_rad", "rad", "tilt (peaks)", [](const Event& e) { return e.theta; }, nullptr},
    {"theta_dot_before_rad_per_s", "rad/s", "tilt rate before (impacts)",
     [](const Event& e) { return e.theta_dot_before; }, nullptr},
    {"theta_dot_after_rad_per_s", "rad/s",
     "tilt rate after (impacts). With the compliant contact a touch lasts: this is theta_dot at "
     "the end of the touch's transfer, i.e. at the next corner event (the other corner's release, "
     "the rate at separation, or another touch) or, if theta_dot reaches zero first, at the end "
     "of the step where it did. It is not a restitution: the springs keep exchanging energy with "
     "the body after it, so the ratio to theta_dot before moves with the stiffness "
     "(docs/theory.md §22, \"Results\")",
     [](const Event& e) { return e.theta_dot_after; }, nullptr},
    {"energy_loss_J", "J",
     "energy lost (impacts, chatter cut-off); for `energy_unbalanced`, the residual",
     [](const Event& e) { return e.energy_loss; }, nullptr},
    {"impulse_x_N_s", "N s", "horizontal impulse of the floor (impacts)",
     [](const Event& e) { return e.impulse_x; }, nullptr},
    {"impulse_y_N_s", "N s",
     "vertical impulse of the floor (impacts); negative at a `tensile_landing`: the pull the "
     "sticking landing needed",
     [](const Event& e) { return e.impulse_y; }, nullptr},
    {"friction_demand", "-", "\\|F_I\\|/F_J, or \\|impulse_x\\|/impulse_y at an impact",
     [](const Event& e) { return e.friction_demand; }, nullptr},
    {"force_estimate_N", "N",
     "impacts: the peak force of a half-sine contact of the assumed `impact_duration` carrying the "
     "impulse, pi \\|impulse\\| / (2 impact_duration); with the compliant contact, the resolved "
     "peak normal force of the touching tipping point until it leaves the floor; for "
     "`pivot_tension`, the episode's most negative vertical reaction F_J (the floor's largest "
     "pull on the held pivot, < 0)",
     [](const Event& e) { return e.force_estimate; }, nullptr},
};

}  // namespace

std::vector<std::string> event_columns() {
  std::vector<std::string> v;
  for (const EventColumn& c : kEventColumns) v.emplace_back(c.name);
  return v;
}

std::vector<EventColumnValues> event_values(const SimulationResult& r) {
  std::vector<EventColumnValues> cols;
  for (const EventColumn& c : kEventColumns) {
    if (c.value) {
      std::vector<double> v;
      for (const Event& e : r.events) v.push_back(c.value(e));
      cols.emplace_back(std::move(v));
    } else {
      std::vector<std::string> v;
      for (const Event& e : r.events) v.emplace_back(c.text(e));
      cols.emplace_back(std::move(v));
    }
  }
  return cols;
}

std::string event_column_reference() {
  std::string s =
      "<!-- begin: written by `flexrock keys --markdown` from the table of event-log columns "
      "(src/io/outputs.cpp); edit the table, not these lines -->\n"
      "| column | unit | meaning |\n"
      "|---|---|---|\n";
  for (const EventColumn& c : kEventColumns) {
    s.append("| `").append(c.name).append("` | ").append(c.unit).append(" | ").append(c.doc);
    s.append(" |\n");
  }
  s += "<!-- end: written by `flexrock keys --markdown` -->\n";
  return s;
}

void write_events(std::ostream& out, const SimulationResult& r) {
  put_header(out, event_columns());
  for (const Event& e : r.events) {
    for (const EventColumn& c : kEventColumns) {
      if (&c != kEventColumns) out << ',';
      if (c.value) {
        put(out, c.value(e));
      } else {
        out << c.text(e);
      }
    }
    out << '\n';
  }
}

std::string summary_json(const Case& c, const Body& body, const SimulationResult& r,
                         const OutputPaths& paths, const SupportRunResult* support) {
  using json = Json;
  const BodyParameters& p = body.params();
  const Extremes& x = r.extremes;
  const EnergyBalance& e = r.energy;
  const auto [pga_x, pga_y] = peak_acceleration(c.motion);
  const double g = p.gravity;

  json j;
  j["schema"] = "flexrock.summary";
  j["schema_version"] = kSummarySchemaVersion;
  j["flexrock_version"] = flexrock::version();  // the program that wrote the file
  j["case"] = {{"name", c.name}, {"description", c.description}, {"file", c.source}};
  VectorX hz = body.natural_frequencies() / (2.0 * std::numbers::pi);
  j["body"] = {{"type", c.body_type},
               {"rigid", body.modes() == 0},
               {"modes", body.modes()},
               {"mass_kg", p.mass},
               {"height_m", p.height},
               {"b1_m", p.b1},
               {"b2_m", p.b2},
               {"alpha1", body.alpha1()},
               {"alpha2", body.alpha2()},
               {"uplift_acceleration_edge1_m_per_s2", g * body.alpha1()},
               {"uplift_acceleration_edge2_m_per_s2", g * body.alpha2()},
               {"tipping_angle_edge1_rad", body.tipping_angle(1)},
               {"tipping_angle_edge2_rad", body.tipping_angle(2)},
               {"rocking_frequency_rad_per_s", body.rocking_frequency()},
               {"natural_frequencies_hz", jvec(hz)},
               {"damping_ratios", jvec(body.damping_ratios())}};
  j["excitation"] = {{"horizontal", component_json(c.horizontal)},
                     {"vertical", component_json(c.vertical)},
                     {"scale", c.excitation_scale},
                     {"duration_s", c.motion.duration()},
                     {"pga_x_m_per_s2", pga_x},
                     {"pga_y_m_per_s2", pga_y},
                     {"pga_x_g", pga_x / kStandardGravity},
                     {"pga_y_g", pga_y / kStandardGravity}};
  // a record pair run at one azimuth: the second component and the azimuth (absent otherwise, so
  // that single-component summaries keep their bytes)
  if (c.pair) {
    j["excitation"]["horizontal2"] = component_json(c.horizontal2);
    j["excitation"]["azimuth_deg"] = c.azimuth ? Json(*c.azimuth) : Json();
  }
  j["outcome"] = {{"status", to_string(r.status)},
                  {"message", r.message},
                  {"t_end_s", r.t_end},
                  {"final_phase", to_string(r.final_phase)},
                  {"final_theta_rad", r.final_theta},
                  {"final_theta_dot_rad_per_s", r.final_theta_dot},
                  {"uplifted", x.first_uplift_time >= 0.0},
                  {"first_uplift_time_s", jtime(x.first_uplift_time)},
                  {"first_uplift_edge", x.first_uplift_edge},
                  {"overturned", r.status == Status::kOverturned},
                  {"overturn_time_s", jtime(x.overturn_time)},
                  {"overturn_edge", x.overturn_edge},
                  {"lift_offs", x.lift_offs},
                  {"flight_time_s", x.flight_time},
                  {"final_offset_m", r.final_offset}};
  j["peaks"] = {{"max_theta_rad", std::max(x.max_theta_edge1, x.max_theta_edge2)},
                {"max_theta_edge1_rad", x.max_theta_edge1},
                {"max_theta_edge2_rad", x.max_theta_edge2},
                {"max_uplift_m", x.max_uplift},
                {"max_abs_q", jvec(x.max_abs_q)},
                {"max_base_shear_N", x.max_base_shear},
                {"max_overturning_moment_N_m", x.max_overturning_moment},
                {"max_friction_demand", x.max_friction_demand},
                {"impacts", x.impacts},
                {"max_impulse_N_s", x.max_impulse},
                {"max_impact_force_estimate_N", x.max_impact_force},
                {"max_impact_energy_loss_J", x.max_impact_energy_loss},
                {"max_offset_m", x.max_offset},
                {"max_flight_height_m", x.max_flight_height},
                {"chatter_cutoffs", x.chatter_cutoffs}};
  j["energy"] = {{"input_work_J", e.input_work},
                 {"kinetic_change_J", e.kinetic_change},
                 {"potential_change_J", e.potential_change},
                 {"damping_loss_J", e.damping_loss},
                 {"impact_loss_J", e.impact_loss},
                 {"chatter_loss_J", e.chatter_loss},
                 {"energy_lost_J", e.damping_loss + e.impact_loss + e.chatter_loss},
                 {"residual_J", e.residual},
                 {"scale_J", e.scale},
                 {"relative_residual", e.scale > 0.0 ? e.residual / e.scale : 0.0}};
  if (std::isfinite(c.options.friction_coefficient)) {
    // only with friction, so that a run without it writes what it always did
    j["sliding"] = {{"slips", x.slips},
                    {"sliding_time_s", x.sliding_time},
                    {"max_offset_m", x.max_offset},
                    {"final_offset_m", r.final_offset},
                    {"friction_loss_J", e.friction_loss}};
    j["energy"]["friction_loss_J"] = e.friction_loss;
    j["energy"]["energy_lost_J"] =
        e.damping_loss + e.impact_loss + e.chatter_loss + e.friction_loss;
  }
  j["warnings"] = {{"friction_exceeded", r.friction_exceeded},
                   {"chatter_cut_off", r.chatter_cut_off},
                   {"impact_gained_energy", r.impact_gained_energy},
                   {"impact_law_fallbacks", x.impact_law_fallbacks},
                   {"pivot_tension", r.pivot_tension},
                   {"pivot_tension_episodes", x.tension_episodes},
                   {"max_pivot_pull_N", x.max_pivot_pull},
                   {"max_pivot_pull_over_weight", x.max_pivot_pull / (p.mass * g)},
                   {"tension_time_s", x.tension_time},
                   {"tensile_landing", x.tensile_landings > 0},
                   {"tensile_landings", x.tensile_landings},
                   {"max_tensile_impulse_N_s", x.max_tensile_impulse},
                   {"energy_unbalanced", r.energy_unbalanced}};
  const SimulationOptions& o = c.options;
  j["solver"] = {
      {"rtol", o.rtol},
      {"atol", o.atol},
      {"max_step_s", o.max_step},
      {"event_samples", o.event_samples},
      {"overturn", o.overturn == OverturnCriterion::kHalfPi ? "half_pi" : "static_instability"},
      {"chatter_ratio", o.chatter_ratio},
      {"restitution_factor", o.restitution_factor},
      {"impact_law", to_string(o.impact_law)},
      {"impact_duration_s", o.impact_duration},
      {"friction_coefficient", jnum(o.friction_coefficient)},
      {"steps", r.steps},
      {"rejected_steps", r.rejected_steps},
      {"rhs_evaluations", r.rhs_evaluations},
      {"events", r.events.size()}};
  if (takes_measured_ratio(o.impact_law)) {
    j["solver"]["restitution_ratio_edge1"] = o.restitution_ratio_edge1;
    j["solver"]["restitution_ratio_edge2"] = o.restitution_ratio_edge2;
  }
  if (std::isfinite(o.friction_coefficient))
    j["solver"]["kinetic_friction_coefficient"] =
        std::min(o.friction_coefficient, o.kinetic_friction_coefficient);
  if (o.contact_model == ContactModel::kCompliant) {
    // only with the compliant contact, so that an impulsive run writes what it always did
    j["contact"] = {
        {"model", to_string(o.contact_model)},
        {"force_law", to_string(o.contact_force_law)},
        {"stiffness", o.contact_stiffness},
        {"exponent", o.contact_exponent},
        {"damping_ratio", o.contact_damping_ratio},
        {"restitution", o.contact_restitution < 0.0 ? json() : json(o.contact_restitution)},
        {"tangential_stiffness_N_per_m",
         o.contact_tangential_stiffness > 0.0 ? json(o.contact_tangential_stiffness) : json()},
        {"max_contact_force_N", x.max_contact_force}};
  }
  if (support && c.support) {
    // only on a support, so that a run on the floor writes what it always did
    const SupportParameters& sp = *c.support;
    const SupportFrequencies f = support_frequencies(body, sp);
    const SupportExtremes& se = support->support;
    j["support"] = {{"mass_kg", sp.mass},
                    {"stiffness_N_per_m", sp.stiffness},
                    {"damping_N_s_per_m", sp.damping},
                    {"frequency_hz", f.frequency_hz},
                    {"damping_ratio", f.damping_ratio},
                    {"max_displacement_m", se.max_displacement},
                    {"max_velocity_m_per_s", se.max_velocity},
                    {"max_force_N", se.max_force},
                    {"final_displacement_m", se.final_displacement},
                    {"final_velocity_m_per_s", se.final_velocity}};
  }
  auto jpath = [](const std::string& s) { return s.empty() ? json() : json(s); };
  j["outputs"] = {{"time_history", jpath(paths.time_history)},
                  {"summary", jpath(paths.summary)},
                  {"events", jpath(paths.events)},
                  {"output_dt_s", c.options.output_dt}};
  return j.dump(2) + "\n";
}

OutputPaths output_paths(const Case& c, const std::string& output_dir) {
  return {resolve_out(output_dir, c.output.time_history), resolve_out(output_dir, c.output.summary),
          resolve_out(output_dir, c.output.events)};
}

void check_output_paths(const Case& c, const OutputPaths& paths) {
  std::vector<NamedPath> inputs;
  for (const std::string& f : c.input_files) inputs.push_back({"input", f});
  check_distinct_files(inputs, {{"time history", paths.time_history},
                                {"summary", paths.summary},
                                {"event log", paths.events}});
}

OutputPaths write_outputs(const Case& c, const Body& body, const SimulationResult& r,
                          const std::string& output_dir, const SupportRunResult* support) {
  const OutputPaths paths = output_paths(c, output_dir);
  check_output_paths(c, paths);
  // results that are not finite are no results: no file of them, not even a partial set
  if (const std::string bad = non_finite_output(r); !bad.empty()) {
    throw std::runtime_error("the results are not finite (" + bad + "); no output written");
  }
  for (const std::string* p : {&paths.time_history, &paths.summary, &paths.events}) {
    if (p->empty()) continue;
    const fs::path parent = fs::path(*p).parent_path();
    if (!parent.empty()) {
      std::error_code ec;
      fs::create_directories(parent, ec);
      if (ec)
        throw std::runtime_error("cannot create directory " + parent.string() + ": " +
                                 ec.message());
    }
  }
  // a summary on disk vouches for the files it names: the old one goes before any of them is
  // replaced, the new one comes after all of them are complete
  if (!paths.summary.empty() && ::unlink(paths.summary.c_str()) != 0 && errno != ENOENT) {
    throw std::runtime_error("cannot remove the old summary " + paths.summary + ": " +
                             std::strerror(errno));
  }
  if (!paths.time_history.empty()) {
    write_atomically(paths.time_history,
                     [&](std::ostream& out) { write_time_history(out, r, body, support); });
  }
  if (!paths.events.empty()) {
    write_atomically(paths.events, [&](std::ostream& out) { write_events(out, r); });
  }
  if (!paths.summary.empty()) {
    const std::string text = summary_json(c, body, r, paths, support);
    write_atomically(paths.summary, [&](std::ostream& out) { out << text; });
  }
  return paths;
}

}  // namespace flexrock::io
