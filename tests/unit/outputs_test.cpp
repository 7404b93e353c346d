// SPDX-License-Identifier: BSD-3-Clause
// Outputs: the CSV header names every column with its unit, one row per output time; the summary
// JSON carries the documented keys; files are written atomically and never left half-written.
#include "flexrock/io/outputs.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>

#include "flexrock/io/case_file.hpp"
#include "flexrock/sim/simulate.hpp"
#include "flexrock/version.hpp"

namespace flexrock::io {
namespace {

namespace fs = std::filesystem;

// a rigid block rocked by a one-sine pulse, with an event log
const std::string kCase = R"(
name = "pulse"
[body]
type = "rigid_block"
width = 0.4
height = 2.0
mass = 100.0
[excitation.horizontal]
type = "one_sine"
amplitude = 0.3
units = "g"
period = 1.0
duration = 2.0
[output]
dt = 0.05
events = "pulse.events.csv"
)";

class Outputs : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / (std::string("flexrock_outputs_") + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    const fs::path p = dir_ / "pulse.toml";
    std::ofstream(p) << kCase;
    case_ = load_case(p.string());
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::vector<std::string> lines(const fs::path& p) const {
    std::ifstream in(p);
    std::vector<std::string> v;
    for (std::string s; std::getline(in, s);) v.push_back(s);
    return v;
  }

  fs::path dir_;
  Case case_;
};

TEST(TimeHistoryColumns, NameEveryColumnWithItsUnit) {
  const auto c = time_history_columns(2);
  ASSERT_GE(c.size(), 5u);
  EXPECT_EQ(c[0], "time_s");
  EXPECT_EQ(c[2], "theta_rad");
  EXPECT_EQ(c[3], "theta_dot_rad_per_s");
  EXPECT_EQ(c[5], "q1");
  EXPECT_EQ(c[6], "q2");
  EXPECT_EQ(c[7], "q1_dot_per_s");
  EXPECT_EQ(c.back(), "lift_m");
  EXPECT_EQ(c[c.size() - 2], "offset_m");
  EXPECT_EQ(c[c.size() - 3], "impact_loss_J");
  EXPECT_EQ(time_history_columns(0).size() + 4, c.size());
}

TEST_F(Outputs, CsvHasOneRowPerOutputTime) {
  const Body body(case_.body);
  const SimulationResult r = simulate(body, case_.motion, case_.initial, case_.options);
  std::ostringstream out;
  write_time_history(out, r, body);
  std::istringstream in(out.str());
  std::string header, row;
  std::getline(in, header);
  std::string expected;
  for (const auto& c : time_history_columns(0)) expected += (expected.empty() ? "" : ",") + c;
  EXPECT_EQ(header, expected);
  std::size_t rows = 0, fields = 0;
  while (std::getline(in, row)) {
    ++rows;
    fields = static_cast<std::size_t>(std::count(row.begin(), row.end(), ',')) + 1;
  }
  EXPECT_EQ(rows, r.history.size());
  EXPECT_EQ(fields, time_history_columns(0).size());
  // every output time up to where the run ended (the block may overturn under this pulse)
  EXPECT_NEAR(static_cast<double>(rows), r.t_end / 0.05 + 1.0, 1.0);
}

TEST_F(Outputs, WritesAllFilesAndTheSummaryNamesThem) {
  const Body body(case_.body);
  const SimulationResult r = simulate(body, case_.motion, case_.initial, case_.options);
  const OutputPaths paths = write_outputs(case_, body, r, (dir_ / "out").string());
  EXPECT_TRUE(fs::exists(paths.time_history));
  EXPECT_TRUE(fs::exists(paths.events));
  EXPECT_TRUE(fs::exists(paths.summary));
  EXPECT_EQ(lines(paths.events).front().substr(0, 13), "time_s,event,");
  EXPECT_EQ(lines(paths.events).size(), r.events.size() + 1);
  // no temporary files left behind
  for (const auto& e : fs::directory_iterator(dir_ / "out")) {
    EXPECT_EQ(e.path().string().find(".tmp."), std::string::npos) << e.path();
  }

  std::ifstream in(paths.summary);
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j.at("schema"), "flexrock.summary");
  EXPECT_EQ(j.at("schema_version"), kSummarySchemaVersion);
  // the writer's version: the library's, which is the one the headers declare
  EXPECT_EQ(j.at("flexrock_version"), std::string(flexrock::version()));
  EXPECT_EQ(std::string(flexrock::version()), FLEXROCK_VERSION_STRING);
  EXPECT_EQ(FLEXROCK_VERSION,
            FLEXROCK_VERSION_MAJOR * 10000 + FLEXROCK_VERSION_MINOR * 100 + FLEXROCK_VERSION_PATCH);
  EXPECT_EQ(j.at("case").at("name"), "pulse");
  EXPECT_EQ(j.at("outcome").at("status"), to_string(r.status));
  EXPECT_DOUBLE_EQ(j.at("peaks").at("max_theta_edge1_rad").get<double>(),
                   r.extremes.max_theta_edge1);
  EXPECT_EQ(j.at("peaks").at("impacts").get<long>(), r.extremes.impacts);
  EXPECT_DOUBLE_EQ(j.at("energy").at("residual_J").get<double>(), r.energy.residual);
  EXPECT_TRUE(j.at("solver").at("friction_coefficient").is_null());  // no limit
  EXPECT_NEAR(j.at("excitation").at("pga_x_g").get<double>(), 0.3, 1e-6);
  EXPECT_EQ(j.at("outputs").at("time_history"), paths.time_history);
  for (const char* key : {"case", "body", "excitation", "outcome", "peaks", "energy", "warnings",
                          "solver", "outputs"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  // the block rocks under this pulse: uplift time recorded, no overturning time
  EXPECT_TRUE(j.at("outcome").at("uplifted").get<bool>());
  EXPECT_TRUE(j.at("outcome").at("first_uplift_time_s").is_number());
}

TEST_F(Outputs, FailedWriteLeavesNothing) {
  const fs::path target = dir_ / "x.csv";
  EXPECT_THROW(write_atomically(target.string(),
                                [](std::ostream& out) {
                                  out << "half a file";
                                  throw std::runtime_error("interrupted");
                                }),
               std::runtime_error);
  EXPECT_FALSE(fs::exists(target));
  for (const auto& e : fs::directory_iterator(dir_)) {
    EXPECT_EQ(e.path().string().find(".tmp."), std::string::npos) << e.path();
  }
}

TEST_F(Outputs, AtomicWriteReplacesAnOldFile) {
  const fs::path target = dir_ / "y.txt";
  std::ofstream(target) << "old";
  write_atomically(target.string(), [](std::ostream& out) { out << "new"; });
  EXPECT_EQ(lines(target).front(), "new");
}

TEST_F(Outputs, UnwritableDirectoryThrows) {
  EXPECT_THROW(write_atomically((dir_ / "no" / "such" / "dir" / "f.csv").string(),
                                [](std::ostream& out) { out << "x"; }),
               std::runtime_error);
}

}  // namespace
}  // namespace flexrock::io
