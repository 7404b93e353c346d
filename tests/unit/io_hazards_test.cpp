// SPDX-License-Identifier: BSD-3-Clause
// Files that are not what they seem: FIFOs, devices, symbolic-link loops, over-long names,
// outputs that are inputs. Each is refused with an InputError naming the path; none may block
// (ctest gives this executable a TIMEOUT, so a FIFO that blocked would fail).
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "flexrock/core/error.hpp"
#include "flexrock/io/case_file.hpp"
#include "flexrock/io/files.hpp"
#include "flexrock/io/outputs.hpp"
#include "flexrock/io/records.hpp"
#include "flexrock/io/study_files.hpp"
#include "flexrock/model/body.hpp"
#include "flexrock/sim/simulate.hpp"
#include "support/expect_error.hpp"

namespace flexrock {
namespace {

namespace fs = std::filesystem;
using test::expect_input_error;

class IoHazards : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("flexrock_io_hazards_" + std::to_string(::getpid()) + "_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) const {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }
  std::string fifo(const std::string& name) const {
    const std::string p = (dir_ / name).string();
    EXPECT_EQ(::mkfifo(p.c_str(), 0600), 0);
    return p;
  }
  fs::path dir_;
};

const char* kRigid = "[body]\ntype = \"rigid_block\"\nwidth = 0.4\nheight = 2.0\nmass = 100.0\n";
const char* kPulse =
    "[excitation.horizontal]\ntype = \"one_sine\"\namplitude = 0.3\nunits = \"g\"\n"
    "period = 1.0\nduration = 2.0\n";

// --- every reader accepts only regular files --------------------------------------------

TEST_F(IoHazards, FifoAsAnyInputIsRefusedWithoutBlocking) {
  const std::string p = fifo("pipe");
  expect_input_error([&] { io::read_at2(p); }, {p, "FIFO", "record"});
  expect_input_error([&] { io::read_single_column(p, 0.01, io::AccelUnit::kG); }, {p, "FIFO"});
  expect_input_error([&] { io::read_time_series(p, io::AccelUnit::kG); }, {p, "FIFO"});
  expect_input_error([&] { (void)io::load_case(p); }, {p, "FIFO", "case"});
  expect_input_error([&] { (void)io::load_body(p); }, {p, "FIFO"});
  expect_input_error([&] { (void)io::load_sweep_manifest(p); }, {p, "FIFO", "sweep manifest"});
  expect_input_error([&] { (void)io::load_spectrum_file(p); }, {p, "FIFO", "spectrum"});
  expect_input_error([&] { (void)io::read_csv_table(p); }, {p, "FIFO", "CSV"});
  // named by a case: a nodes file and a record
  const std::string n = write("nodes.toml",
                              "[body]\ntype = \"lumped\"\nnodes_file = \"pipe\"\n"
                              "tip1_x = -0.5\ntip2_x = 0.5\n");
  expect_input_error([&] { (void)io::load_body(n); }, {p, "FIFO"});
  const std::string c = write("rec.toml", std::string(kRigid) +
                                              "[excitation.horizontal]\ntype = \"record\"\n"
                                              "file = \"pipe\"\nformat = \"single_column\"\n"
                                              "dt = 0.01\nunits = \"g\"\n");
  expect_input_error([&] { (void)io::load_case(c); }, {p, "FIFO", "rec.toml:8"});
}

TEST_F(IoHazards, DevicesAsStudyFilesAreRefused) {
  // /dev/zero never ends: the study loaders read it until memory ran out
  expect_input_error([] { (void)io::load_sweep_manifest("/dev/zero"); }, {"/dev/zero", "device"});
  expect_input_error([] { (void)io::load_spectrum_file("/dev/zero"); }, {"/dev/zero", "device"});
  expect_input_error([] { (void)io::read_csv_table("/dev/zero"); }, {"/dev/zero", "device"});
  const std::string m =
      write("m.toml", "[[body]]\nfile = \"/dev/zero\"\n[[record]]\nfile = \"r.at2\"\n");
  expect_input_error([&] { (void)io::load_sweep_manifest(m); }, {"/dev/zero", "device"});
  expect_input_error([&] { (void)io::load_spectrum_file(dir_.string()); },
                     {dir_.string(), "directory"});
}

TEST_F(IoHazards, SymlinkLoopsAndLongNamesAreInputErrors) {
  const fs::path a = dir_ / "a", b = dir_ / "b";
  fs::create_symlink(b, a);
  fs::create_symlink(a, b);
  const std::string loop = a.string();
  const std::string reason = "symbolic links";
  expect_input_error([&] { io::read_at2(loop); }, {loop, reason});
  expect_input_error([&] { (void)io::load_case(loop); }, {loop, reason});
  expect_input_error([&] { (void)io::load_sweep_manifest(loop); }, {loop, reason});
  expect_input_error([&] { (void)io::load_spectrum_file(loop); }, {loop, reason});
  // a name longer than NAME_MAX (255 bytes on Linux)
  const std::string longname = (dir_ / (std::string(300, 'x') + ".toml")).string();
  expect_input_error([&] { (void)io::load_case(longname); }, {"File name too long"});
  expect_input_error([&] { (void)io::load_sweep_manifest(longname); }, {"File name too long"});
  expect_input_error([&] { io::read_time_series(longname, io::AccelUnit::kG); },
                     {"File name too long"});
  // and the same-file test does not throw on either
  EXPECT_FALSE(io::same_file(loop, longname));
  EXPECT_TRUE(io::same_file(loop, loop));
}

TEST_F(IoHazards, MissingFilesSayNoSuchFile) {
  const std::string p = (dir_ / "absent.toml").string();
  expect_input_error([&] { (void)io::load_case(p); }, {p, "no such case file"});
  expect_input_error([&] { (void)io::load_sweep_manifest(p); }, {p, "no such sweep manifest"});
}

// --- same files -----------------------------------------------------------------------------

TEST_F(IoHazards, SameFileSeesLinksDotsAndFilesNotYetWritten) {
  const std::string f = write("f.txt", "x");
  fs::create_directories(dir_ / "sub");
  EXPECT_TRUE(io::same_file(f, (dir_ / "sub" / ".." / "f.txt").string()));
  fs::create_symlink(f, dir_ / "link.txt");
  EXPECT_TRUE(io::same_file(f, (dir_ / "link.txt").string()));
  fs::create_hard_link(f, dir_ / "hard.txt");
  EXPECT_TRUE(io::same_file(f, (dir_ / "hard.txt").string()));
  // neither exists yet: the same canonical parent and name
  fs::create_directory_symlink(dir_ / "sub", dir_ / "alias");
  EXPECT_TRUE(
      io::same_file((dir_ / "sub" / "out.csv").string(), (dir_ / "alias" / "out.csv").string()));
  EXPECT_TRUE(io::same_file((dir_ / "new" / "out.csv").string(),
                            (dir_ / "new" / "." / "out.csv").string()));
  EXPECT_FALSE(
      io::same_file((dir_ / "sub" / "out.csv").string(), (dir_ / "sub" / "out2.csv").string()));
  EXPECT_FALSE(io::same_file(f, ""));
}

TEST_F(IoHazards, OutputsMayNotBeInputsOrEachOther) {
  const std::string m = write("m.toml", "x");
  expect_input_error(
      [&] {
        io::check_distinct_files({{"sweep manifest", m}}, {{"output", m}, {"journal", ""}});
      },
      {"output " + m, "is the same file as the sweep manifest " + m});
  expect_input_error(
      [&] {
        io::check_distinct_files({{"case file", m}}, {{"time history", (dir_ / "o.csv").string()},
                                                      {"summary", (dir_ / "./o.csv").string()}});
      },
      {"summary", "is the same file as the time history"});
  io::check_distinct_files({{"case file", m}}, {{"time history", (dir_ / "o.csv").string()},
                                                {"summary", (dir_ / "o.json").string()},
                                                {"events", ""}});
}

// --- decimal commas are refused, never split ---------------------------------------------

TEST_F(IoHazards, DecimalCommasAreRefusedNamingFileAndLine) {
  // "-0,050" was read as two samples, -0 and 50 g
  const std::string v = write("eu.txt", "0,000\n-0,050\n0,020\n");
  expect_input_error([&] { io::read_single_column(v, 0.01, io::AccelUnit::kG); },
                     {v + ":1:", "\"0,000\"", "decimal comma", "write 0.000"});
  const std::string v2 = write("eu2.txt", "# header\n0.1\n-0,050\n");
  expect_input_error([&] { io::read_single_column(v2, 0.01, io::AccelUnit::kG); },
                     {v2 + ":3:", "\"-0,050\"", "write -0.050"});
  // two columns with blanks or semicolons between decimal-comma numbers
  const std::string t = write("eu.csv", "0,00 0,10\n0,01 -0,05\n");
  expect_input_error([&] { io::read_time_series(t, io::AccelUnit::kG); },
                     {t + ":1:", "decimal comma"});
  // with semicolons between the values a comma can only be a decimal mark: read as one
  const std::string t2 = write("eu2.csv", "time;acc\n0,00;0,10\n0,01;-0,05\n");
  EXPECT_EQ(io::read_time_series(t2, io::AccelUnit::kG).values, (std::vector<double>{0.1, -0.05}));
  const std::string a = write("eu.at2",
                              "PEER NGA STRONG MOTION DATABASE RECORD\nEVENT\n"
                              "ACCELERATION TIME HISTORY IN UNITS OF G\nNPTS= 2, DT= .01 SEC\n"
                              "0,01 -0,02\n");
  expect_input_error([&] { io::read_at2(a); }, {a + ":5:", "decimal comma"});
  // a nodes file "-0,5;0;10" is refused, not read as four numbers
  write("nodes.csv", "x;y;mass\n-0,5;0;10\n0,5;0;10\n0;2;100\n");
  const std::string n = write("n.toml",
                              "[body]\ntype = \"lumped\"\nnodes_file = \"nodes.csv\"\n"
                              "tip1_x = -0.5\ntip2_x = 0.5\nfrequencies_hz = [2.0]\n"
                              "phi_x = [[0.0], [0.0], [1.0]]\nphi_y = [[0.0], [0.0], [0.0]]\n");
  expect_input_error([&] { (void)io::load_body(n); }, {"nodes.csv:2:", "-0,5"});
}

TEST_F(IoHazards, CommaSeparatedValuesStillRead) {
  // commas between numbers with decimal points, or in two-column CSV rows, are separators
  const std::string v = write("v.txt", "0.0,0.1,-0.2\n0.3, 0\n1,2,3\n");
  const io::Record r = io::read_single_column(v, 0.01, io::AccelUnit::kG);
  EXPECT_EQ(r.values, (std::vector<double>{0.0, 0.1, -0.2, 0.3, 0.0, 1.0, 2.0, 3.0}));
  const std::string t = write("t.csv", "time,acc\n0,0\n1,5\n2,-0.5\n");
  const io::Record c = io::read_time_series(t, io::AccelUnit::kG);
  EXPECT_EQ(c.values, (std::vector<double>{0.0, 5.0, -0.5}));
  EXPECT_EQ(c.time, (std::vector<double>{0.0, 1.0, 2.0}));
}

// --- caps: typos that would take all the memory -------------------------------------------

TEST_F(IoHazards, HistoryRowsAreCappedNamingOutputDt) {
  const std::string c1 = write("dt.toml", std::string(kRigid) + kPulse + "[output]\ndt = 1e-300\n");
  expect_input_error([&] { (void)io::load_case(c1); },
                     {"dt.toml:13:", "key 'output.dt'", "at most 10000000 time-history rows"});
  // a record whose last time is 1e9 s, at the default output.dt = 0.01 s
  write("long.csv", "0,0\n1e9,0.1\n");
  const std::string c2 = write("long.toml", std::string(kRigid) +
                                                "[excitation.horizontal]\ntype = \"record\"\n"
                                                "file = \"long.csv\"\nformat = \"time_series\"\n"
                                                "units = \"g\"\n");
  expect_input_error([&] { (void)io::load_case(c2); }, {"key 'output.dt'", "1e+11"});
  // without a time history the same record is accepted
  const std::string c3 = write("long0.toml", std::string(kRigid) +
                                                 "[excitation.horizontal]\ntype = \"record\"\n"
                                                 "file = \"long.csv\"\nformat = \"time_series\"\n"
                                                 "units = \"g\"\n[output]\ndt = 0\n");
  EXPECT_NO_THROW((void)io::load_case(c3));
  // just under the cap is accepted: 2 s every 2e-7 s is 1e7 + 1 rows, every 4e-7 s half that
  const std::string c4 = write("ok.toml", std::string(kRigid) + kPulse + "[output]\ndt = 4e-7\n");
  EXPECT_NO_THROW((void)io::load_case(c4));
}

const char* kSpecHead =
    "[body]\ntype = \"rigid_block\"\nwidth = 0.4\nheight = 2.0\nmass = 100.0\n[spectrum]\n";

TEST_F(IoHazards, GridsAreCappedAndATinyStepIsNoUndefinedCast) {
  // step = 1e-300: (stop - start) / step = 1e300 used to be cast to long (undefined behaviour)
  const std::string s1 = write("s1.toml", std::string(kSpecHead) +
                                              "amplitudes = {start = 1.0, stop = 3.0, step = "
                                              "1e-300}\nfrequencies = [1.0]\n");
  expect_input_error(
      [&] { (void)io::load_spectrum_file(s1); },
      {"s1.toml:", "key 'spectrum.amplitudes.step'", "at most 1000000 grid points", "got 1e-300"});
  const std::string s2 = write("s2.toml", std::string(kSpecHead) +
                                              "amplitudes = {start = 1.0, stop = 3.0, step = "
                                              "1e-9}\nfrequencies = [1.0]\n");
  expect_input_error([&] { (void)io::load_spectrum_file(s2); },
                     {"key 'spectrum.amplitudes.step'", "at most 1000000"});
  const std::string s3 = write("s3.toml", std::string(kSpecHead) +
                                              "amplitudes = {start = 1.0, stop = 3.0, count = "
                                              "1000000000000}\nfrequencies = [1.0]\n");
  expect_input_error([&] { (void)io::load_spectrum_file(s3); },
                     {"key 'spectrum.amplitudes.count'", "at most 1000000", "got 1000000000000"});
  // each grid under its cap, their product over the cells' cap
  const std::string s4 = write("s4.toml", std::string(kSpecHead) +
                                              "amplitudes = {start = 1.0, stop = 3.0, count = "
                                              "100000}\nfrequencies = {start = 1.0, stop = 2.0, "
                                              "count = 100}\n");
  expect_input_error([&] { (void)io::load_spectrum_file(s4); },
                     {"key 'spectrum.amplitudes'", "at most 2000000 grid cells",
                      "100000 amplitudes x 100 frequencies"});
  // a sweep's scales
  write("b.toml", std::string(kRigid));
  write("r.txt", "0\n0.1\n0\n");
  const std::string m = write("m.toml",
                              "[[body]]\nfile = \"b.toml\"\n[[record]]\nfile = \"r.txt\"\n"
                              "format = \"single_column\"\ndt = 0.01\nunits = \"g\"\n"
                              "[scales]\nfactors = {start = 0.1, stop = 1.0, count = 5000000}\n");
  expect_input_error([&] { (void)io::load_sweep_manifest(m); },
                     {"m.toml:", "key 'scales.factors.count'", "at most 1000000"});
}

// --- atomic writes -----------------------------------------------------------------------------

// the soft file-size limit, lowered for one test so that writes fail with EFBIG
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    ::getrlimit(RLIMIT_FSIZE, &old_);
    std::signal(SIGXFSZ, SIG_IGN);  // the write then fails with EFBIG instead of killing us
    rlimit r = old_;
    r.rlim_cur = bytes;
    ::setrlimit(RLIMIT_FSIZE, &r);
  }
  ~FileSizeLimit() {
    ::setrlimit(RLIMIT_FSIZE, &old_);
    std::signal(SIGXFSZ, SIG_DFL);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

 private:
  rlimit old_{};
};

bool has_temporaries(const fs::path& dir) {
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().filename().string().find(".tmp.") != std::string::npos) return true;
  }
  return false;
}

TEST_F(IoHazards, AtomicWriteTakesNamesUpToNameMax) {
  // "NAME.tmp.<pid>" of a 250-byte name is over NAME_MAX (255): the temporary is named shorter
  for (std::size_t len : {240u, 250u, 255u}) {
    const std::string name = std::string(len - 4, 'n') + ".csv";
    const std::string path = (dir_ / name).string();
    io::write_atomically(path, [](std::ostream& out) { out << "a,b\n1,2\n"; });
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "a,b") << len;
  }
  EXPECT_FALSE(has_temporaries(dir_));
}

TEST_F(IoHazards, WriteErrorsSayWhy) {
  const std::string path = (dir_ / "big.csv").string();
  try {
    const FileSizeLimit limit(1000);
    io::write_atomically(path, [](std::ostream& out) {
      for (int i = 0; i < 100000; ++i) out << "0.123456789,0.987654321\n";
    });
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("File too large"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("big.csv"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(path));
  EXPECT_FALSE(has_temporaries(dir_));
  // a directory is not replaced by a file
  fs::create_directories(dir_ / "d.csv");
  EXPECT_THROW(io::write_atomically((dir_ / "d.csv").string(), [](std::ostream& o) { o << "x"; }),
               std::runtime_error);
  EXPECT_TRUE(fs::is_directory(dir_ / "d.csv"));
}

TEST_F(IoHazards, StaleTemporariesOfDeadProcessesAreRemoved) {
  // a process id that no longer runs: a child that has exited and been reaped
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ASSERT_GT(child, 0);
  ::waitpid(child, nullptr, 0);
  const std::string stale = write("r.csv.tmp." + std::to_string(child), "half");
  // a process that still runs (our parent) may be writing its temporary: kept
  const std::string live = write("r.csv.tmp." + std::to_string(::getppid()), "busy");
  const std::string other = write("s.csv.tmp." + std::to_string(child), "another file's");
  io::write_atomically((dir_ / "r.csv").string(), [](std::ostream& out) { out << "new\n"; });
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(live));
  EXPECT_TRUE(fs::exists(other));
}

TEST_F(IoHazards, AFailedRerunLeavesNoSummaryBesideNewFiles) {
  const std::string c = write(
      "c.toml", std::string(kRigid) + kPulse + "[output]\ndt = 1.0\nevents = \"c.events.csv\"\n");
  const io::Case cs = io::load_case(c);
  const Body body(cs.body);
  const SimulationResult r = simulate(body, cs.motion, cs.initial, cs.options);
  const std::string out = (dir_ / "out").string();
  const io::OutputPaths paths = io::write_outputs(cs, body, r, out);
  ASSERT_TRUE(fs::exists(paths.summary));
  const auto summary_size = fs::file_size(paths.summary);
  ASSERT_LT(fs::file_size(paths.time_history), 2000U);
  ASSERT_LT(fs::file_size(paths.events), 2000U);
  ASSERT_GT(summary_size, 2000U);
  // the rerun writes the time history and the event log, then fails on the summary
  {
    const FileSizeLimit limit(2000);
    EXPECT_THROW(io::write_outputs(cs, body, r, out), std::runtime_error);
  }
  EXPECT_TRUE(fs::exists(paths.time_history));
  EXPECT_FALSE(fs::exists(paths.summary)) << "an old summary beside the new files";
  EXPECT_FALSE(has_temporaries(out));
  // and an output that is an input is refused before anything is written
  io::Case same = cs;
  same.output.summary = c;
  expect_input_error([&] { io::write_outputs(same, body, r, out); },
                     {"summary " + c, "is the same file as the input " + c});
}

}  // namespace
}  // namespace flexrock
