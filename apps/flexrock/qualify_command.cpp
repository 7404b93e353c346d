// SPDX-License-Identifier: BSD-3-Clause
#include "qualify_command.hpp"

#include <fmt/core.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "flexrock/io/files.hpp"
#include "flexrock/io/outputs.hpp"
#include "flexrock/io/qualify.hpp"
#include "plot_command.hpp"

#ifndef FLEXROCK_PYTHON_DIR
#define FLEXROCK_PYTHON_DIR ""
#endif
#ifndef FLEXROCK_PYTHON_EXECUTABLE
#define FLEXROCK_PYTHON_EXECUTABLE "/usr/bin/python3"
#endif

namespace flexrock::cli {

namespace fs = std::filesystem;

namespace {

std::atomic<bool> g_stop{false};

extern "C" void on_qualify_signal(int sig) {
  g_stop.store(true);
  std::signal(sig, SIG_DFL);
}

// the first SIGINT/SIGTERM asks the runs to stop (finished ones are journaled), from before the
// journals exist until the runs are over; a second one ends the process the default way
struct StopOnSignal {
  StopOnSignal() {
    g_stop.store(false);
    std::signal(SIGINT, on_qualify_signal);
    std::signal(SIGTERM, on_qualify_signal);
  }
  ~StopOnSignal() { restore(); }
  void restore() {
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
  }
};

// python3 -m flexrock.report JSON --html H --pdf P; its exit code
int render(const std::string& json, const std::string& html, const std::string& pdf) {
  const std::string python =
      drawing_python("flexrock/report.py", "the HTML and PDF report need Python 3 with matplotlib",
                     "the JSON is written (--no-render skips the report)");
  if (python.empty()) return 1;
  std::vector<std::string> args = {python,   "-m", "flexrock.report", json,
                                   "--html", html, "--pdf",           pdf};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t pid = ::fork();
  if (pid < 0) return 1;
  if (pid == 0) {
    ::execv(python.c_str(), argv.data());
    std::_Exit(127);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1;
}

}  // namespace

CLI::App* add_qualify_command(CLI::App& app, QualifyOptions& o) {
  CLI::App* q = app.add_subcommand(
      "qualify",
      "Qualify an unanchored body: bounding cases x records at the design level, an IDA to "
      "overturning, hand estimates, and a report (JSON, pelicun demand CSV, HTML, PDF); see "
      "docs/qualify.md");
  q->add_option("FILE", o.file, "qualification file (TOML)")->required();
  q->add_option("-o,--output-dir", o.output_dir,
                "directory of the report (default: the working directory); the runs are "
                "journaled in <stem>.runs/ there");
  q->add_option("-j,--threads", o.threads, "worker threads (default: every core)")
      ->check(CLI::Range(1, 4096));
  q->add_flag("-q,--quiet", o.quiet, "print only the verdict");
  q->add_flag("--no-render", o.no_render,
              "write the JSON and the demand CSV only (no HTML or PDF: no Python needed)");
  return q;
}

int run_qualify(const QualifyOptions& o) {
  io::QualifyFile file = io::load_qualify_file(o.file);
  const std::string dir = o.output_dir.empty() ? "." : o.output_dir;
  const std::string stem = fs::path(o.file).stem().string();
  auto out = [&](const std::string& suffix) { return (fs::path(dir) / (stem + suffix)).string(); };
  const std::string json = out(".qualify.json"), csv = out(".demands.csv"), html = out(".html"),
                    pdf = out(".pdf"), work = out(".runs");
  std::vector<io::NamedPath> inputs, outputs;
  for (const std::string& f : file.input_files) inputs.push_back({"input", f});
  for (const std::string& f : {json, csv, html, pdf}) outputs.push_back({"report output", f});
  io::check_distinct_files(inputs, outputs);

  StopOnSignal signals;
  io::QualifySession session(std::move(file), work);
  const io::QualifyFile& q = session.file();
  if (!o.quiet) {
    fmt::print("qualify: {} cases x {} records at the design level", q.cases.size(),
               q.spec.records.size());
    if (q.ida) fmt::print(", {} IDA curves", session.ida_sessions());
    fmt::print("\n");
    if (session.resumed() > 0)
      fmt::print("resuming: {} runs and cells already in {}\n", session.resumed(), work);
  }
  study::RunOptions options;
  options.threads = o.threads;
  options.cancel = &g_stop;
  const auto start = std::chrono::steady_clock::now();
  session.run(options);
  signals.restore();
  if (g_stop.load()) {
    fmt::print(stderr,
               "flexrock: error: interrupted: finished runs are kept in {}; run the same command "
               "again to continue\n",
               work);
    return 1;
  }
  const io::QualifyReport rep = session.finish();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  io::write_atomically(json, [&](std::ostream& s) { s << rep.json; });
  io::write_atomically(csv, [&](std::ostream& s) { s << rep.demands_csv; });
  fmt::print("{}: {}\n", q.name, rep.pass ? "PASSES every criterion" : "DOES NOT PASS");
  if (!o.quiet) {
    for (const std::string& line : rep.summary) fmt::print("  {}\n", line);
    fmt::print("time: {:.3g} s\nwrote {}\nwrote {}\n", seconds, json, csv);
  }
  if (o.no_render) return 0;
  const int rc = render(json, html, pdf);
  if (rc != 0) return rc == 2 ? 2 : 1;
  if (!o.quiet) fmt::print("wrote {}\nwrote {}\n", html, pdf);
  return 0;
}

}  // namespace flexrock::cli
