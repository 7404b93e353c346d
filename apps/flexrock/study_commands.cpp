// SPDX-License-Identifier: BSD-3-Clause
// flexrock spectrum | sweep | fragility: studies over many runs, on every core and (when built
// with MPI and started by mpirun) over several processes. Outputs are byte-identical whatever
// the thread and process counts: runs are distributed by index and written in index order.
#include "study_commands.hpp"

#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <future>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

#include "flexrock/core/error.hpp"
#include "flexrock/core/format.hpp"
#include "flexrock/excitation/intensity.hpp"
#include "flexrock/io/files.hpp"
#include "flexrock/io/fragility_session.hpp"
#include "flexrock/io/journal.hpp"
#include "flexrock/io/outputs.hpp"
#include "flexrock/io/study_files.hpp"
#include "flexrock/io/study_session.hpp"
#include "flexrock/io/study_shards.hpp"
#include "flexrock/study/fragility.hpp"
#include "flexrock/study/spectrum.hpp"
#include "flexrock/study/sweep.hpp"
#include "progress.hpp"

#ifdef FLEXROCK_HAVE_MPI
#include <mpi.h>
#endif

namespace flexrock::cli {

namespace {

namespace fs = std::filesystem;

constexpr int kExitOk = 0;
constexpr int kExitRunFailed = 1;
constexpr int kExitBadInput = 2;

// the most points of `fragility --curve`: a curve of 10000 points is smooth at any print size,
// and its CSV stays under 2 MB a body and state
constexpr int kMaxCurvePoints = 10000;

// ---------------------------------------------------------------------------------------------
// interruption: the first SIGINT/SIGTERM asks the workers to stop taking runs (finished ones are
// kept); a second one ends the process the default way

std::atomic<bool> g_cancel{false};

extern "C" void on_signal(int sig) {
  g_cancel.store(true);
  std::signal(sig, SIG_DFL);
}

struct SignalGuard {
  SignalGuard() {
    g_cancel.store(false);
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
  }
  ~SignalGuard() {
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
  }
};

// ---------------------------------------------------------------------------------------------
// processes: MPI when built with it and started by a launcher, else one process

#ifdef FLEXROCK_HAVE_MPI
bool launched_by_mpirun() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"}) {
    if (std::getenv(v)) return true;
  }
  return false;
}
#endif

class Processes final : public io::StudyTransport {
 public:
  Processes() {
#ifdef FLEXROCK_HAVE_MPI
    if (launched_by_mpirun()) {
      int provided = 0;
      MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
      MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
      MPI_Comm_size(MPI_COMM_WORLD, &size_);
      mpi_ = true;
    }
#endif
  }
  ~Processes() {
#ifdef FLEXROCK_HAVE_MPI
    if (mpi_) MPI_Finalize();
#endif
  }
  Processes(const Processes&) = delete;
  Processes& operator=(const Processes&) = delete;

  int rank() const override { return rank_; }
  int size() const override { return size_; }

  // threads a process uses by default: the cores shared among the processes on this machine
  int default_threads() const {
    int local = 1;
    if (const char* s = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE"))
      local = std::max(1, std::atoi(s));
    if (size_ == 1) local = 1;
    return std::max(1, study::resolve_threads(0) / local);
  }

  // every process's text, concatenated in rank order, on rank 0 (others get "")
  std::string gather(const std::string& mine) const override {
#ifdef FLEXROCK_HAVE_MPI
    if (mpi_ && size_ > 1) {
      const int n = static_cast<int>(mine.size());
      std::vector<int> counts(static_cast<std::size_t>(size_)), displs(counts.size());
      MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
      std::string all;
      if (rank_ == 0) {
        int total = 0;
        for (std::size_t i = 0; i < counts.size(); ++i) {
          displs[i] = total;
          total += counts[i];
        }
        all.resize(static_cast<std::size_t>(total));
      }
      MPI_Gatherv(mine.data(), n, MPI_CHAR, all.data(), counts.data(), displs.data(), MPI_CHAR, 0,
                  MPI_COMM_WORLD);
      return all;
    }
#endif
    return mine;
  }

  // rank 0's text on every process
  std::string broadcast(const std::string& text) const override {
#ifdef FLEXROCK_HAVE_MPI
    if (mpi_ && size_ > 1) {
      unsigned long n = text.size();
      MPI_Bcast(&n, 1, MPI_UNSIGNED_LONG, 0, MPI_COMM_WORLD);
      std::string out = rank_ == 0 ? text : std::string(n, '\0');
      MPI_Bcast(out.data(), static_cast<int>(n), MPI_CHAR, 0, MPI_COMM_WORLD);
      return out;
    }
#endif
    return text;
  }

  // true on every process if it is true on any
  bool any(bool v) const override {
#ifdef FLEXROCK_HAVE_MPI
    if (mpi_ && size_ > 1) {
      int in = v ? 1 : 0, out = 0;
      MPI_Allreduce(&in, &out, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
      return out != 0;
    }
#endif
    return v;
  }

  void barrier() const {
#ifdef FLEXROCK_HAVE_MPI
    if (mpi_ && size_ > 1) MPI_Barrier(MPI_COMM_WORLD);
#endif
  }

 private:
  int rank_ = 0;
  int size_ = 1;
  bool mpi_ = false;
};

int error(const std::string& message, int code) {
  std::fflush(stdout);
  fmt::print(stderr, "flexrock: error: {}\n", message);
  return code;
}

void warning(const std::string& message) {
  std::fflush(stdout);
  fmt::print(stderr, "flexrock: warning: {}\n", message);
}

// how the progress is shown: a bar on a terminal's stderr, lines on a stdout that is no terminal
struct ProgressShow {
  bool bar = false;
  bool lines = false;
  double every = 60.0;  // [s] the longest wait between two lines
};

// runs `work` on a thread while the main thread draws the progress of `completed` of `total`
template <class Work>
auto with_progress(const ProgressShow& show, std::size_t total, std::atomic<std::size_t>& completed,
                   const std::string& note, Work&& work) {
  Progress progress(show.bar, static_cast<double>(total));
  ProgressLines lines(show.lines, static_cast<double>(total), show.every);
  lines.start(note);
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  auto future = std::async(std::launch::async, std::forward<Work>(work));
  while (future.wait_for(std::chrono::milliseconds(200)) != std::future_status::ready) {
    const auto done = static_cast<double>(completed.load(std::memory_order_relaxed));
    progress.draw_count(elapsed(), done, note);
    lines.update(elapsed(), done);
  }
  progress.clear();
  // the work's exception, if any, before the last line
  auto result = [&] {
    if constexpr (std::is_void_v<decltype(future.get())>) {
      future.get();
      return 0;
    } else {
      return future.get();
    }
  }();
  lines.end(elapsed(), static_cast<double>(completed.load(std::memory_order_relaxed)));
  return result;
}

std::string default_output(const std::string& input, const std::string& suffix) {
  return fs::path(input).stem().string() + suffix;
}

// the boundary CSV next to the cells: "x.spectrum.csv" -> "x.boundary.csv", "x.csv" ->
// "x.boundary.csv"
std::string default_boundary(const std::string& output) {
  fs::path p(output);
  std::string stem = p.stem().string();
  if (stem.ends_with(".spectrum")) stem.resize(stem.size() - 9);
  return (p.parent_path() / (stem + ".boundary.csv")).string();
}

// which part of the study this process runs, after its progress
std::string progress_note(const Processes& procs, const std::optional<io::Shard>& part) {
  if (part) return fmt::format("  (shard {} of {})", part->k, part->n);
  return procs.size() > 1 ? fmt::format("  (rank 0 of {})", procs.size()) : "";
}

// the outcome of every cell, counted
std::map<std::string, std::size_t> count_outcomes(const std::vector<study::SpectrumCell>& cells) {
  std::map<std::string, std::size_t> counts;
  for (const study::SpectrumCell& c : cells) ++counts[study::to_string(c.run.outcome)];
  return counts;
}

}  // namespace

// ---------------------------------------------------------------------------------------------

struct StudyCommands::Impl {
  CLI::App* spectrum = nullptr;
  CLI::App* sweep = nullptr;
  CLI::App* fragility = nullptr;
  CLI::App* merge = nullptr;

  std::string input, output, boundary_output, curve_output;
  int threads = -1;
  bool quiet = false, no_progress = false, no_bisect = false, worst_azimuth = false;
  std::string im = "pga_g", outcome = "overturned", body_name;
  std::vector<std::string> state_texts;  // --state, in the order given
  std::string analysis = "runs";         // runs, msa or ida
  double level = 0.0, confidence = 0.95;
  double curve_points = 50;  // read as a number, so that any value gets its range message

  double progress_every = 60.0;          // [s] --progress-every
  std::string shard_text;                // --shard k/N
  std::vector<std::string> shard_files;  // merge

  ProgressShow show_progress(const Processes& p) const {
    const bool on = !quiet && !no_progress && p.root();
    return {on && ::isatty(STDERR_FILENO), on && !::isatty(STDOUT_FILENO), progress_every};
  }

  std::optional<io::Shard> shard() const {
    if (shard_text.empty()) return std::nullopt;
    return io::parse_shard(shard_text);
  }

  void check_progress_every() const {
    if (!(progress_every > 0.0 && std::isfinite(progress_every))) {
      throw InputError("--progress-every: expected a number of seconds > 0, got " +
                       format_number(progress_every));
    }
  }

  study::RunOptions run_options(const Processes& p) const {
    study::RunOptions o;
    o.threads = threads > 0 ? threads : p.default_threads();
    o.rank = p.rank();
    o.ranks = p.size();
    o.cancel = &g_cancel;
    return o;
  }

  void check_threads() const {
    if (threads == 0 || threads < -1) {
      throw InputError("--threads: expected an integer >= 1, got " + std::to_string(threads));
    }
  }

  int run_spectrum(const Processes& procs);
  int run_sweep(const Processes& procs);
  int run_fragility();
  int run_merge();
};

int StudyCommands::Impl::run_spectrum(const Processes& procs) {
  check_threads();
  check_progress_every();
  const std::optional<io::Shard> part = shard();
  io::SpectrumFile f = io::load_spectrum_file(input);
  if (no_bisect) {
    f.pulse.bisect = false;
    f.record.bisect = false;
  }
  if (output.empty()) output = default_output(input, ".spectrum.csv");
  if (boundary_output.empty()) boundary_output = default_boundary(output);
  // the session checks every run before its journal exists, resumes from the journal, and
  // writes the CSVs from the cells; here: the options, the progress and the account
  io::SpectrumSession session(std::move(f), output, boundary_output, procs, part);
  const io::SpectrumFile& file = session.file();
  const study::SpectrumResult& grid = session.grid();
  const double g = session.body().g();
  const bool bisect = session.bisect();

  const SignalGuard signals;
  std::atomic<std::size_t> completed{0};
  study::RunOptions options = run_options(procs);
  options.completed = &completed;
  if (!quiet && procs.root() && session.resumed() > 0) {
    fmt::print("resuming: {} of {} cells and boundaries already in {}\n", session.resumed(),
               session.runs(), session.journal_path());
  }
  const auto start = std::chrono::steady_clock::now();
  // the cells left in rank 0's share, for its progress bar (the bisection's runs come on top)
  with_progress(show_progress(procs), session.share_cells(), completed, progress_note(procs, part),
                [&] { session.run(options); });
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string interrupted = fmt::format(
      "interrupted: finished cells are kept in {}{}; run the same command again to "
      "continue",
      session.journal_path(), procs.size() > 1 ? " (and .rank<N> files)" : "");
  if (procs.any(g_cancel.load())) {
    if (procs.root()) return error(interrupted, kExitRunFailed);
    return kExitRunFailed;
  }
  study::SpectrumResult res;
  try {
    res = session.finish(&g_cancel);
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    return error(std::string("could not write the outputs (the finished cells are kept in ") +
                     session.journal_path() + "): " + e.what(),
                 kExitRunFailed);
  }
  if (!procs.root()) return kExitOk;
  // a record spectrum's bisection on rank 0 was stopped: the journal stays
  if (res.cells.empty()) return error(interrupted, kExitRunFailed);
  if (part) {
    // a shard: its cells; the account of the whole comes with the merge
    std::size_t mine = 0;
    for (const study::SpectrumCell& c : res.cells) mine += c.computed ? 1 : 0;
    fmt::print("spectrum shard {}/{}: {} of {} cells\n", part->k, part->n, mine, session.cells());
    if (!quiet) fmt::print("wrote {}\n", session.written());
    return kExitOk;
  }
  const std::map<std::string, std::size_t> counts = count_outcomes(res.cells);

  // a short account on stdout
  fmt::print("spectrum: {} ({}), body from {}\n", file.name,
             file.is_record ? "record " + file.record_name + " x scales"
                            : file.pulse.pulse + " pulse, " +
                                  (file.pulse.normalized ? "normalized" : "physical") + " axes",
             file.body_source);
  fmt::print("body: g tan(alpha1) = {:.4g} m/s^2, alpha1 = {:.4g} rad, p = {:.4g} rad/s\n",
             g * grid.tan_alpha, grid.alpha, grid.p);
  fmt::print("cells: {}", session.cells());
  for (const auto& [k, n] : counts) fmt::print(", {} {}", k, n);
  fmt::print("\n");
  if (!quiet) {
    fmt::print("time: {:.3g} s on {} process{} x {} thread{}\n", seconds, procs.size(),
               procs.size() == 1 ? "" : "es", options.threads, options.threads == 1 ? "" : "s");
    fmt::print("wrote {}\n", output);
    if (bisect) fmt::print("wrote {}\n", boundary_output);
  }
  return kExitOk;
}

int StudyCommands::Impl::run_sweep(const Processes& procs) {
  check_threads();
  check_progress_every();
  const std::optional<io::Shard> part = shard();
  // the session checks every run before its journal exists, resumes from the journal, and
  // writes the CSV from the rows; here: the options, the progress and the account
  io::SweepManifest m = io::load_sweep_manifest(input);
  if (output.empty()) output = default_output(input, ".sweep.csv");
  io::SweepSession session(std::move(m), output, procs, part);
  const study::SweepSpec& spec = session.manifest().spec;
  const std::size_t runs = session.runs();

  const SignalGuard signals;
  std::atomic<std::size_t> completed{0};
  study::RunOptions options = run_options(procs);
  options.completed = &completed;
  if (!quiet && procs.root() && session.resumed() > 0) {
    fmt::print("resuming: {} of {} runs already in {}\n", session.resumed(), runs,
               session.journal_path());
  }
  const auto start = std::chrono::steady_clock::now();
  if (!session.share().empty()) {
    with_progress(show_progress(procs), session.share().size(), completed,
                  progress_note(procs, part), [&] { session.run(options); });
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (procs.any(g_cancel.load())) {
    // every finished run is in a journal; the next identical command goes on from there
    if (procs.root()) {
      return error(
          fmt::format("interrupted: finished runs are kept in {}{}; run the same "
                      "command again to continue",
                      session.journal_path(), procs.size() > 1 ? " (and .rank<N> files)" : ""),
          kExitRunFailed);
    }
    return kExitRunFailed;
  }
  std::vector<study::SweepRow> rows;
  try {
    rows = session.finish();
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    return error(std::string("could not write the outputs (the runs are kept in ") +
                     session.journal_path() + "): " + e.what(),
                 kExitRunFailed);
  }
  if (!procs.root()) return kExitOk;
  // the outcomes counted from the rows as data
  std::size_t over = 0, stopped = 0;
  for (const study::SweepRow& r : rows) {
    over += study::overturned(r.run.outcome) ? 1 : 0;
    stopped += r.run.outcome == study::Outcome::kStopped ? 1 : 0;
  }
  if (part) {
    fmt::print("sweep shard {}/{}: {} of {} runs: {} overturned, {} not classified (stopped)\n",
               part->k, part->n, rows.size(), runs, over, stopped);
  } else {
    fmt::print(
        "sweep: {} bodies x {} records x {} scales = {} runs: {} overturned, {} not classified "
        "(stopped)\n",
        spec.bodies.size(), spec.records.size(), spec.scales.size(), runs, over, stopped);
  }
  if (!quiet) {
    fmt::print("time: {:.3g} s for {} new runs on {} process{} x {} thread{}\n", seconds,
               part ? session.share().size() : session.remaining(), procs.size(),
               procs.size() == 1 ? "" : "es", options.threads, options.threads == 1 ? "" : "s");
    fmt::print("wrote {}\n", session.written());
  }
  return kExitOk;
}

namespace {

// one column of the fragility curve CSV (--curve): name, unit, meaning and its field at the
// intensity measure x of a body's fit. The header, the rows and the column reference of
// docs/studies.md are written from this table
struct CurveColumn {
  const char* name;
  const char* unit;
  const char* doc;
  std::string (*field)(const io::FragilityData& d, const study::FragilityFit& f, double x);
};

const CurveColumn kCurveColumns[] = {
    {"body", "-", "name of the body",
     [](const io::FragilityData& d, const study::FragilityFit&, double) { return d.body; }},
    {"im", "IM",
     "intensity measure: `--curve-points` values evenly spaced over the body's observed range",
     [](const io::FragilityData&, const study::FragilityFit&, double x) {
       return fmt::format("{}", x);
     }},
    {"probability", "-", "P(failure \\| IM) = Phi(ln(im/theta)/beta)",
     [](const io::FragilityData&, const study::FragilityFit& f, double x) {
       return fmt::format("{}", study::fragility_probability(f, x));
     }},
    {"lower", "-", "lower end of the pointwise confidence band Phi(eta - z_q sd(eta))",
     [](const io::FragilityData&, const study::FragilityFit& f, double x) {
       double l = 0.0, u = 0.0;
       study::fragility_band(f, x, l, u);
       return fmt::format("{}", l);
     }},
    {"upper", "-", "upper end: Phi(eta + z_q sd(eta))",
     [](const io::FragilityData&, const study::FragilityFit& f, double x) {
       double l = 0.0, u = 0.0;
       study::fragility_band(f, x, l, u);
       return fmt::format("{}", u);
     }},
    {"im_name", "-", "the intensity measure of `im`, as `--im` names it",
     [](const io::FragilityData& d, const study::FragilityFit&, double) { return d.im_name; }},
    {"im_unit", "-", "the unit of `im`",
     [](const io::FragilityData& d, const study::FragilityFit&, double) { return d.im_unit; }},
};

}  // namespace

int StudyCommands::Impl::run_fragility() {
  if (!(curve_points >= 1.0 && curve_points <= kMaxCurvePoints &&
        curve_points == std::floor(curve_points))) {
    throw InputError("--curve-points: expected an integer in [1, " +
                     std::to_string(kMaxCurvePoints) + "], got " + format_number(curve_points));
  }
  const int points = static_cast<int>(curve_points);
  io::check_distinct_files({{"sweep CSV", input}}, {{"output", output}, {"curve", curve_output}});
  io::CsvTable table = io::read_csv_table(input);
  // the options; the session checks them, reads the observations and fits
  io::FragilityOptions o;
  for (const std::string& text : state_texts) o.states.push_back(io::damage_state(text));
  if (!o.states.empty() && (fragility->count("--outcome") || fragility->count("--level"))) {
    throw InputError(
        "--state: give the damage states either with --state or with --outcome "
        "and --level, not both");
  }
  o.outcome = io::find_fragility_outcome(outcome)->outcome;  // CLI11 checked the name
  o.level = level;
  o.confidence = confidence;
  o.analysis = *value_named(io::kFragilityAnalysisNames, analysis);
  o.im = im;
  o.im_given = fragility->count("--im") > 0;
  o.body = body_name;
  o.worst_azimuth = worst_azimuth;
  const io::FragilitySession session(std::move(table), std::move(o));
  const std::vector<io::DamageState>& states = session.states();
  const std::string im_name = (worst_azimuth ? "rotd50:" : "") + session.measure().name;
  const std::string& unit = session.unit();
  const double conf = session.options().confidence;
  // what fails, as the fit is titled: "overturning", "max theta/alpha > 0.5", ...
  auto what = [](const io::DamageState& st) {
    const io::FragilityOutcomeInfo& info = io::fragility_outcome(st.outcome);
    return info.levelled ? fmt::format("{}{}{}", info.what, st.level, info.unit)
                         : std::string(info.what);
  };
  const std::vector<io::FragilityOrderNote> notes = session.order_notes();
  for (std::size_t k = 0; k < session.bodies(); ++k) {
    for (std::size_t s = 0; s < states.size(); ++s) {
      const io::FragilityData& d = session.data(s, k);
      if (!session.fitted(s, k)) {
        // the others are fitted; this one is reported with its reason, and has no rows
        fmt::print("{}: P({} | {}): not fitted\n", d.body, what(states[s]), im_name);
        warning(session.not_fitted(s, k));
        continue;
      }
      const study::FragilityFit& f = session.fit(s, k);
      const std::string left_out =
          d.excluded ? fmt::format(", {} runs stopped or lost contact: left out", d.excluded) : "";
      if (session.options().analysis == io::FragilityAnalysis::kCapacities) {
        fmt::print(
            "{}: P({} | {}) = Phi(ln(x/theta)/beta), capacities of {} records ({} failed "
            "within the levels, {} truncated at their highest{})\n",
            d.body, what(states[s]), im_name, f.samples, f.failures, f.samples - f.failures,
            left_out);
      } else {
        fmt::print("{}: P({} | {}) = Phi(ln(x/theta)/beta), {} runs ({} with the outcome{})\n",
                   d.body, what(states[s]), im_name, f.samples, f.failures, left_out);
      }
      if (session.options().analysis == io::FragilityAnalysis::kStripes) {
        for (const study::Stripe& st : session.stripes(s, k)) {
          fmt::print("  stripe {:.6g} {}: {} of {} runs failed ({:.3f}; fit {:.3f})\n", st.im, unit,
                     st.failures, st.runs,
                     static_cast<double>(st.failures) / static_cast<double>(st.runs),
                     study::fragility_probability(f, st.im));
        }
      }
      fmt::print("  theta = {:.5g} {}  [{:.5g}, {:.5g}] ({:.0f}% bounds)\n", f.theta, unit,
                 f.theta_lower, f.theta_upper, 100.0 * conf);
      fmt::print("  beta  = {:.5g}  [{:.5g}, {:.5g}]\n", f.beta, f.beta_lower, f.beta_upper);
    }
    for (const io::FragilityOrderNote& n : notes) {
      if (n.body != k) continue;
      const io::DamageState &a = states[n.state - 1], &b = states[n.state];
      if (n.medians_cross) {
        fmt::print(
            "  warning: the fitted medians cross: {} (theta = {:.5g}) is below {} (theta "
            "= {:.5g}), given before it as the less severe state\n",
            b.label, session.fit(n.state, k).theta, a.label, session.fit(n.state - 1, k).theta);
      }
      if (!std::isnan(n.crossing)) {
        fmt::print(
            "  note: the curves of {} and {} cross at {} = {:.5g} {}, inside the data "
            "range: above it the {} is the likelier\n",
            a.label, b.label, im_name, n.crossing, unit,
            n.latter_likelier_above ? "latter" : "former");
      }
    }
  }
  const bool several = session.several();
  try {
    if (!output.empty()) {
      io::write_atomically(output, [&](std::ostream& out) { session.write_fits(out); });
      if (!quiet) fmt::print("wrote {}\n", output);
    }
    if (!curve_output.empty()) {
      io::write_atomically(curve_output, [&](std::ostream& out) {
        for (const CurveColumn& c : kCurveColumns) {
          out << (&c == kCurveColumns ? "" : ",") << c.name;
          if (several && &c == kCurveColumns) out << ",state";
        }
        out << '\n';
        for (std::size_t k = 0; k < session.bodies(); ++k) {
          for (std::size_t s = 0; s < states.size(); ++s) {
            if (!session.fitted(s, k)) continue;
            const io::FragilityData& d = session.data(s, k);
            const auto [lo, hi] = session.range(k, s, s);
            for (int i = 0; i < points; ++i) {
              const double x =
                  points == 1 ? lo : lo + (hi - lo) * i / static_cast<double>(points - 1);
              for (const CurveColumn& c : kCurveColumns) {
                out << (&c == kCurveColumns ? "" : ",") << c.field(d, session.fit(s, k), x);
                if (several && &c == kCurveColumns) out << ',' << states[s].label;
              }
              out << '\n';
            }
          }
        }
      });
      if (!quiet) fmt::print("wrote {}\n", curve_output);
    }
  } catch (const std::exception& e) {
    return error(std::string("could not write the outputs: ") + e.what(), kExitRunFailed);
  }
  const std::size_t pairs = session.bodies() * states.size();
  if (session.fitted_count() < pairs) {
    warning(fmt::format(
        "fitted {} of {} {}; the others are reported above and have no rows in the "
        "outputs",
        session.fitted_count(), pairs, several ? "bodies and damage states" : "bodies"));
  }
  return kExitOk;
}

int StudyCommands::Impl::run_merge() {
  if (output.empty()) {
    // "out.csv.shard1of4" -> "out.csv"
    output = io::shard_output(shard_files.front());
    if (output.empty()) {
      throw InputError("merge: " + shard_files.front() +
                       ": not named OUT.shard<k>of<N>; give the output with -o");
    }
  }
  if (boundary_output.empty()) boundary_output = default_boundary(output);
  const io::MergeResult r = io::merge_shards(shard_files, output, boundary_output);
  fmt::print("merge: {} shards of a {} of {} runs\n", r.shards, r.kind, r.runs);
  if (!quiet) {
    fmt::print("wrote {}\n", output);
    if (r.boundary) fmt::print("wrote {}\n", boundary_output);
  }
  return kExitOk;
}

std::string fragility_curve_column_reference() {
  std::string s =
      "<!-- begin: written by `flexrock keys --markdown` from the table of fragility curve "
      "columns (apps/flexrock/study_commands.cpp); edit the table, not these lines -->\n"
      "| column | unit | meaning |\n"
      "|---|---|---|\n";
  for (const CurveColumn& c : kCurveColumns) {
    s.append("| `").append(c.name).append("` | ").append(c.unit).append(" | ").append(c.doc);
    s.append(" |\n");
  }
  return s + "<!-- end: written by `flexrock keys --markdown` -->\n";
}

StudyCommands::StudyCommands(CLI::App& app) : impl_(std::make_unique<Impl>()) {
  Impl& s = *impl_;
  s.spectrum = app.add_subcommand(
      "spectrum",
      "Overturning spectrum: a pulse grid (amplitude x frequency) or one record x "
      "scale factors; CSV of every cell and of the minimum overturning amplitudes");
  s.spectrum->add_option("SPEC", s.input, "spectrum file (TOML, docs/studies.md)")->required();
  s.spectrum->add_option("-o,--output", s.output, "cells CSV (default: <SPEC stem>.spectrum.csv)");
  s.spectrum->add_option("--boundary", s.boundary_output,
                         "minimum overturning amplitude CSV (default: <output stem>.boundary.csv)");
  s.spectrum->add_flag("--no-bisect", s.no_bisect, "grid only: no bisection, no boundary file");

  s.sweep =
      app.add_subcommand("sweep",
                         "Bodies x records x scale factors from a manifest: one CSV row per run; "
                         "resumable (rerun the same command after an interruption)");
  s.sweep->add_option("MANIFEST", s.input, "sweep manifest (TOML, docs/studies.md)")->required();
  s.sweep->add_option("-o,--output", s.output, "CSV (default: <MANIFEST stem>.sweep.csv)");

  for (CLI::App* c : {s.spectrum, s.sweep}) {
    c->add_option("-j,--threads", s.threads,
                  "worker threads (default: every core, shared among MPI processes)");
    c->add_flag("-q,--quiet", s.quiet, "print only the results: no progress, no file list");
    c->add_flag("--no-progress", s.no_progress,
                "no progress bar on a terminal, no progress lines in a log");
    c->add_option("--progress-every", s.progress_every,
                  "when stdout is not a terminal (a batch job's log): a progress line at least "
                  "every this many seconds, besides one per tenth of the runs (default 60)");
    c->add_option("--shard", s.shard_text,
                  "k/N: run only shard k of N (the runs, or a spectrum's columns, i with i mod N "
                  "== k-1), with its own journal, into OUTPUT.shard<k>of<N>; join the N files "
                  "with `flexrock merge` (docs/studies.md, \"Shards\")");
  }

  s.merge = app.add_subcommand(
      "merge",
      "Join the shard files of a sweep or spectrum run with --shard k/N into the files one run "
      "writes, byte for byte");
  s.merge->add_option("SHARDS", s.shard_files, "the N shard files (OUTPUT.shard<k>of<N>)")
      ->required();
  s.merge->add_option("-o,--output", s.output, "CSV (default: the shard files' OUTPUT)");
  s.merge->add_option("--boundary", s.boundary_output,
                      "a spectrum's boundary CSV (default: <output stem>.boundary.csv)");
  s.merge->add_flag("-q,--quiet", s.quiet, "no file list");

  s.fragility =
      app.add_subcommand("fragility",
                         "Lognormal fragility fit (maximum likelihood) from a sweep CSV, with "
                         "confidence bounds");
  s.fragility->add_option("SWEEP_CSV", s.input, "CSV written by flexrock sweep")->required();
  s.fragility->add_option(
      "--im", s.im,
      "intensity measure: pga_g (g, the default, as flexrock plot's), pga (m/s^2), pgv (m/s), "
      "scale, requested_level (the sweep's "
      "levels as its manifest wrote them), or one the sweep's [intensity] table asked for: pgd "
      "(m), arias (m/s), cav (m/s), d5_95 (s), pgv_over_pga (s), sa:T or sa:T:zeta (Sa at "
      "period T s, damping ratio zeta, 0.05 by default; in the sweep's [intensity] sa_units, "
      "m/s^2 by default)");
  s.fragility
      ->add_option("--outcome", s.outcome,
                   "failure: overturned, uplift (left full contact), theta (max theta/alpha > "
                   "level), energy (energy lost > "
                   "level J), offset (peak sliding offset > level m), residual_offset (|residual "
                   "offset| > level m; both need a sweep run with friction)")
      ->check(
          CLI::IsMember({"overturned", "uplift", "theta", "energy", "offset", "residual_offset"}));
  s.fragility
      ->add_option(
          "--state", s.state_texts,
          "a damage state of a family fitted at once (repeat it, least severe first): overturned, "
          "uplift, theta:X, energy:X, offset:X, residual_offset:X (X the level of --outcome of "
          "that "
          "name); one fit per state and body, written with a state column; fitted medians out of "
          "order are reported. Not with --outcome or --level")
      ->allow_extra_args(false);
  s.fragility
      ->add_option("--analysis", s.analysis,
                   "runs (default: every run an observation), msa (multiple-stripe analysis: "
                   "binomial likelihood over the sweep's levels, Baker 2015), ida (each record's "
                   "capacity from its first failure over increasing --im, records that never "
                   "fail truncated at their highest level)")
      ->check(CLI::IsMember({"runs", "msa", "ida"}));
  s.fragility->add_option("--level", s.level,
                          "threshold of --outcome theta, energy, offset or residual_offset");
  s.fragility->add_option("--body", s.body_name, "fit only this body (default: each body)");
  s.fragility->add_flag(
      "--worst-azimuth", s.worst_azimuth,
      "a sweep of record pairs ([[suite]] horizontal2): the azimuths of one pair at one level "
      "are one observation, failed if any azimuth failed, its measure their median (RotD50 of "
      "--im on the azimuth grid; with --im requested_level on a sweep to targets, the pair's "
      "RotD50 level). Without it every azimuth is one "
      "observation: the random-azimuth fragility");
  s.fragility->add_option("--confidence", s.confidence, "level of the bounds (default 0.95)");
  s.fragility->add_option("-o,--output", s.output, "fit CSV (default: none)");
  s.fragility->add_option("--curve", s.curve_output,
                          "CSV of the curve and its confidence band over the data's IM range");
  s.fragility->add_option(
      "--curve-points", s.curve_points,
      "points of --curve (default 50; an integer in [1, " + std::to_string(kMaxCurvePoints) + "])");
  s.fragility->add_flag("-q,--quiet", s.quiet, "no file list");
}

StudyCommands::~StudyCommands() = default;

bool StudyCommands::selected() const {
  return impl_->spectrum->parsed() || impl_->sweep->parsed() || impl_->fragility->parsed() ||
         impl_->merge->parsed();
}

int StudyCommands::run() {
  Impl& s = *impl_;
  if (s.fragility->parsed()) return s.run_fragility();
  if (s.merge->parsed()) return s.run_merge();
  const Processes procs;
  try {
    return s.spectrum->parsed() ? s.run_spectrum(procs) : s.run_sweep(procs);
  } catch (const InputError& e) {
    // every process reads the same input: one message is enough
    if (procs.root()) return error(e.what(), kExitBadInput);
    return kExitBadInput;
  } catch (const std::bad_alloc&) {
    if (procs.root() || procs.size() > 1) return error("out of memory", kExitRunFailed);
    return kExitRunFailed;
  } catch (const std::exception& e) {
    if (procs.root() || procs.size() > 1) return error(e.what(), kExitRunFailed);
    return kExitRunFailed;
  }
}

}  // namespace flexrock::cli
