// SPDX-License-Identifier: BSD-3-Clause
// Files planted or forged by someone else: symbolic and hard links at the names of temporaries
// and journals (never followed, their targets never touched, their content never echoed),
// binary and oversized inputs (named as such at their first block), a hand-edited sweep CSV
// (read through the journal's row checks), and solver values past their physical range (refused
// up front, naming the key and the range).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "flexrock/core/error.hpp"
#include "flexrock/excitation/pulses.hpp"
#include "flexrock/io/case_file.hpp"
#include "flexrock/io/files.hpp"
#include "flexrock/io/journal.hpp"
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

class HostileFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("flexrock_hostile_" + std::to_string(::getpid()) + "_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return path(name);
  }
  static std::string read(const std::string& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  fs::path dir_;
};

// --- temporaries ----------------------------------------------------------------------------

TEST_F(HostileFiles, ALinkPlantedAtTheTemporaryNameIsNotFollowed) {
  // a file of someone else's, and links to it and to a new name at the temporary's old,
  // predictable name (NAME.tmp.<pid>)
  const std::string victim = write("victim.txt", "precious\n");
  const std::string pid = std::to_string(::getpid());
  fs::create_symlink(victim, dir_ / ("r.csv.tmp." + pid));
  fs::create_symlink(path("elsewhere.csv"), dir_ / ("s.csv.tmp." + pid));
  io::write_atomically(path("r.csv"), [](std::ostream& out) { out << "new\n"; });
  io::write_atomically(path("s.csv"), [](std::ostream& out) { out << "new\n"; });
  EXPECT_EQ(read(victim), "precious\n");
  EXPECT_FALSE(fs::exists(dir_ / "elsewhere.csv"));
  for (const char* out : {"r.csv", "s.csv"}) {
    EXPECT_FALSE(fs::is_symlink(dir_ / out)) << out;
    EXPECT_EQ(read(path(out)), "new\n") << out;
  }
}

TEST_F(HostileFiles, TemporaryNamesCannotBeForeseen) {
  // the temporary seen while it is written: NAME.tmp.<pid>.<16 hex digits>, a new suffix each time
  std::set<std::string> names;
  for (int i = 0; i < 3; ++i) {
    io::write_atomically(path("r.csv"), [&](std::ostream& out) {
      for (const auto& e : fs::directory_iterator(dir_)) {
        const std::string n = e.path().filename().string();
        if (n.starts_with("r.csv.tmp.")) names.insert(n);
      }
      out << "x\n";
    });
  }
  ASSERT_EQ(names.size(), 3u);
  const std::string stem = "r.csv.tmp." + std::to_string(::getpid()) + ".";
  for (const std::string& n : names) {
    ASSERT_TRUE(n.starts_with(stem)) << n;
    const std::string suffix = n.substr(stem.size());
    EXPECT_EQ(suffix.size(), 16u) << n;
    EXPECT_EQ(suffix.find_first_not_of("0123456789abcdef"), std::string::npos) << n;
  }
}

TEST_F(HostileFiles, StaleTemporariesAreOnlyRegularFiles) {
  // a dead process's temporary is removed; a link of that form is left, its target untouched
  const std::string victim = write("victim.txt", "precious\n");
  fs::create_symlink(victim, dir_ / "r.csv.tmp.999999999.0123456789abcdef");
  io::write_atomically(path("r.csv"), [](std::ostream& out) { out << "new\n"; });
  EXPECT_TRUE(fs::is_symlink(dir_ / "r.csv.tmp.999999999.0123456789abcdef"));
  EXPECT_EQ(read(victim), "precious\n");
}

// --- journals -------------------------------------------------------------------------------

TEST_F(HostileFiles, ALinkAtTheJournalNameIsRefusedAndNotEchoed) {
  const std::string victim = write("victim.txt", "secret first line\n");
  const std::string journal = path("s.csv.partial");
  fs::create_symlink(victim, journal);
  expect_input_error([&] { io::Journal(journal, "sweep", 42, 10); },
                     {journal, "symbolic link", "not followed"});
  try {
    io::Journal(journal, "sweep", 42, 10);
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find("secret"), std::string::npos) << e.what();
  }
  EXPECT_EQ(read(victim), "secret first line\n");
  // a dangling link: its target is not created
  const std::string dangling = path("t.csv.partial");
  fs::create_symlink(path("created_elsewhere"), dangling);
  expect_input_error([&] { io::Journal(dangling, "sweep", 42, 10); }, {"symbolic link"});
  EXPECT_FALSE(fs::exists(dir_ / "created_elsewhere"));
}

TEST_F(HostileFiles, AJournalWithAnotherNameIsRefused) {
  // a hard link to a file elsewhere would be truncated and written through
  const std::string victim = write("victim.txt", "# flexrock sweep journal v3 inputs=0 runs=1\n");
  const std::string journal = path("s.csv.partial");
  fs::create_hard_link(victim, journal);
  expect_input_error([&] { io::Journal(journal, "sweep", 42, 10); }, {journal, "hard links"});
  EXPECT_EQ(read(victim), "# flexrock sweep journal v3 inputs=0 runs=1\n");
}

TEST_F(HostileFiles, AForeignFileAtTheJournalNameIsNotEchoed) {
  const std::string journal = write("s.csv.partial", "secret first line\nmore\n");
  expect_input_error([&] { io::Journal(journal, "sweep", 42, 10); },
                     {journal + ":1:", "not a flexrock journal"});
  try {
    io::Journal(journal, "sweep", 42, 10);
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find("secret"), std::string::npos) << e.what();
  }
  EXPECT_EQ(read(journal), "secret first line\nmore\n");
}

TEST_F(HostileFiles, AJournalOfNulBytesIsBinaryNotATornLine) {
  const std::string journal = write("s.csv.partial", std::string(100000, '\0'));
  expect_input_error([&] { io::Journal(journal, "sweep", 42, 10); },
                     {journal, "binary data (NUL byte at offset 0)"});
  EXPECT_EQ(fs::file_size(journal), 100000u);  // not truncated
}

// --- inputs ---------------------------------------------------------------------------------

TEST_F(HostileFiles, BinaryInputsAreNamedAtTheirFirstNul) {
  std::string bytes = "0.1\n0.2\n";
  bytes += std::string(1 << 20, '\0');  // a megabyte of NULs after two samples
  const std::string rec = write("rec.txt", bytes);
  expect_input_error([&] { io::read_single_column(rec, 0.01, io::AccelUnit::kG); },
                     {rec, "binary data (NUL byte at offset 8)", "expected a text record file"});
  const std::string at2 = write("rec.at2", std::string(4096, '\0'));
  expect_input_error([&] { io::read_at2(at2); }, {"binary data (NUL byte at offset 0)"});
  const std::string toml = write("case.toml", std::string("[body]\0", 7));
  expect_input_error([&] { io::load_case(toml); },
                     {toml, "binary data (NUL byte at offset 6)", "expected a text case file"});
}

TEST_F(HostileFiles, InputsOverTheirCapAreRefusedNamingIt) {
  const std::string p = write("big.txt", std::string(5000, '1') + "\n");
  expect_input_error([&] { io::read_input_file(p, "record", 4096); },
                     {p, "5001 bytes, over the 4096 bytes a record file may have"});
  EXPECT_EQ(io::read_input_file(p, "record", 5001).size(), 5001u);
  // the stated caps
  EXPECT_EQ(io::kMaxDataFileBytes, 256u << 20);
  EXPECT_EQ(io::kMaxTomlFileBytes, 16u << 20);
}

// --- a sweep CSV read back by fragility -----------------------------------------------------

std::string sweep_csv(const std::string& rows) {
  std::string csv;
  const std::vector<std::string> cols = io::sweep_columns();
  for (std::size_t i = 0; i < cols.size(); ++i) csv += (i ? "," : "") + cols[i];
  return csv + "\n" + rows;
}
// the sweep columns in order (docs/studies.md), the pull and tensile-landing ones zero
const char* kRow0 =
    "0,a,r,1,-,1,1.5,0.15,0.2,10,rocking,0,0,-1,0.1,0.5,3,1,0,0,2.5,0.1,0,0,0,0,0,completed,\n";
const char* kRow1 =
    "1,a,r,2,-,2,3.0,0.3,0.4,10,overturned_after_impacts,1,1,4,1,1,3,1,0,0,1.0,0.1,0,0,0,0,0,"
    "overturned,\n";

TEST_F(HostileFiles, AHandEditedSweepCsvIsReadThroughTheJournalChecks) {
  io::FragilityQuery q;
  // as written: read
  const io::CsvTable good =
      io::read_csv_table(write("good.csv", sweep_csv(std::string(kRow0) + kRow1)));
  EXPECT_EQ(io::fragility_data(good, q)[0].failed, (std::vector<int>{0, 1}));
  // an outcome that contradicts its flag
  std::string flipped = kRow1;
  flipped.replace(flipped.find("overturned_after_impacts,1"), 26, "overturned_after_impacts,0");
  const std::string p1 = write("flag.csv", sweep_csv(kRow0 + flipped));
  const io::CsvTable t1 = io::read_csv_table(p1);
  expect_input_error(
      [&] { io::fragility_data(t1, q); },
      {p1 + ":3:", "overturned = 0 does not go with outcome overturned_after_impacts"});
  // a run twice
  std::string again = kRow1;
  again[0] = '0';
  const std::string p2 = write("twice.csv", sweep_csv(kRow0 + again));
  const io::CsvTable t2 = io::read_csv_table(p2);
  expect_input_error([&] { io::fragility_data(t2, q); },
                     {p2 + ":3:", "run index 0 twice, first at line 2"});
  // an unknown status, an edge that is none of 0, 1, 2
  std::string status = kRow0;
  status.replace(status.find("completed"), 9, "finished");
  const std::string p3 = write("status.csv", sweep_csv(status));
  const io::CsvTable t3 = io::read_csv_table(p3);
  expect_input_error([&] { io::fragility_data(t3, q); }, {p3 + ":2:", "column 'status'"});
}

// --- solver values past their physical range ------------------------------------------------

const char* kCaseHead =
    "[body]\ntype = \"rigid_block\"\nwidth = 0.4\nheight = 2.0\nmass = 100.0\n"
    "[excitation.horizontal]\ntype = \"one_sine\"\namplitude = 0.3\nunits = \"g\"\n";

TEST_F(HostileFiles, UnboundedSolverValuesAreRefusedNamingKeyAndRange) {
  struct Bad {
    const char* solver;  // [solver] lines
    const char* key;
    const char* range;
  };
  const Bad bad[] = {
      {"restitution_factor = 1e308", "solver.restitution_factor", "[0, 2]"},
      {"impact_duration = 1e-300", "solver.impact_duration", "[1e-06, 1] s"},
      {"contact_model = \"compliant\"\ncontact_stiffness = 1e-300", "solver.contact_stiffness",
       "[1000, 1e+15] N/m"},
      {"contact_model = \"compliant\"\ncontact_stiffness = 1e300", "solver.contact_stiffness",
       "[1000, 1e+15] N/m"},
      {"contact_model = \"compliant\"\ncontact_stiffness = 1e8\ncontact_damping_ratio = 1e300",
       "solver.contact_damping_ratio", "[0, 100]"},
  };
  for (const Bad& b : bad) {
    const std::string p =
        write("case.toml", std::string(kCaseHead) + "period = 1.0\nduration = 2.0\n[solver]\n" +
                               b.solver + "\n");
    expect_input_error([&] { io::load_case(p); }, {"key '" + std::string(b.key) + "'", b.range});
  }
  // a pulse's period, or its frequency
  const std::string p =
      write("case.toml", std::string(kCaseHead) + "period = 1e-300\nduration = 2.0\n");
  expect_input_error([&] { io::load_case(p); },
                     {"key 'excitation.horizontal.period'", "[0.0001, 10000] s"});
  const std::string f =
      write("case.toml", std::string(kCaseHead) + "frequency_hz = 1e300\nduration = 2.0\n");
  expect_input_error([&] { io::load_case(f); },
                     {"key 'excitation.horizontal.frequency_hz'", "[0.0001, 10000] Hz"});
  // what still reads: the ends of the ranges
  const std::string ok = write("case.toml", std::string(kCaseHead) +
                                                "period = 1e-4\nduration = 2.0\n[solver]\n"
                                                "restitution_factor = 2\nimpact_duration = 1\n");
  EXPECT_NO_THROW(io::load_case(ok));
}

TEST_F(HostileFiles, TheEngineAppliesTheSameRanges) {
  // options set directly (Python, an uncertainty study's samples) meet the readers' ranges
  const Body body(BodyParameters::rectangular_block(100, 0.2, 1.0));
  SimulationOptions o;
  o.t_end = 0.1;
  o.restitution_factor = 1e308;
  expect_input_error([&] { simulate(body, GroundMotion::none(0.1), {}, o); },
                     {"restitution_factor", "[0, 2]", "1e+308"});
  o.restitution_factor = 1.0;
  o.impact_duration = 1e-300;
  expect_input_error([&] { simulate(body, GroundMotion::none(0.1), {}, o); },
                     {"impact_duration", "[1e-06, 1] s"});
  o.impact_duration = 0.002;
  o.contact_model = ContactModel::kCompliant;
  o.contact_stiffness = 1e300;
  expect_input_error([&] { simulate(body, GroundMotion::none(0.1), {}, o); },
                     {"contact_stiffness", "[1000, 1e+15] N/m"});
  o.contact_stiffness = 1e8;
  o.contact_damping_ratio = 1e300;
  expect_input_error([&] { simulate(body, GroundMotion::none(0.1), {}, o); },
                     {"contact_damping_ratio", "[0, 100]"});
  // a pulse made from the table (Python's keyword functions): its period in range
  const double omega = 2.0 * 3.141592653589793 / 1e-300;
  expect_input_error(
      [&] {
        make_pulse(pulse_kind("one_sine"), {1.0, omega, 2.0, Component::kHorizontal, {}});
      },
      {"one_sine", "period 1e-300 s", "[0.0001, 10000] s"});
  EXPECT_NO_THROW(
      make_pulse(pulse_kind("one_sine"),
                 {1.0, 2.0 * 3.141592653589793 / 1e-4, 2.0, Component::kHorizontal, {}}));
}

}  // namespace
}  // namespace flexrock
