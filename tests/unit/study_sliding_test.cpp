// SPDX-License-Identifier: BSD-3-Clause
// Studies with Coulomb friction at the base: sweep rows and spectrum cells report the peak and
// residual offset, the time sliding and the regime, checked against the closed-form slip of a
// rigid block under a rectangular pulse and the thresholds of the regime at initiation
// (docs/theory.md §20); per-body friction in manifests with errors naming file, line and key;
// journals; fragility with "sliding offset above a level" as the failure.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "flexrock/excitation/pulses.hpp"
#include "flexrock/io/study_files.hpp"
#include "flexrock/study/fragility.hpp"
#include "flexrock/study/spectrum.hpp"
#include "flexrock/study/sweep.hpp"
#include "support/expect_error.hpp"

namespace flexrock {
namespace {

namespace fs = std::filesystem;
constexpr double g = kStandardGravity;
constexpr double kInf = std::numeric_limits<double>::infinity();

// the closed-form slip of a block that cannot uplift under a rectangular pulse A over t1
// (docs/theory.md §20): |d| = A (A - mu g) t1^2 / (2 mu g), over t1 A / (mu g)
double slip_distance(double A, double t1, double mu) {
  return A > mu * g ? A * (A - mu * g) * t1 * t1 / (2.0 * mu * g) : 0.0;
}

// mu_req(a) of a uniform block at uplift (docs/theory.md §20): above it the block rocks sticking
double mu_required(double a, double alpha) {
  return (a * (1.0 + 4.0 * alpha * alpha) + 3.0 * alpha) / (4.0 + alpha * alpha + 3.0 * alpha * a);
}

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> f;
  std::stringstream ss(line);
  std::string s;
  while (std::getline(ss, s, ',')) f.push_back(s);
  if (!line.empty() && line.back() == ',') f.emplace_back();
  return f;
}

// one rectangular pulse, four bodies whose friction puts each in one regime at initiation
study::SweepSpec regime_sweep(double A, double t1) {
  study::SweepSpec s;
  const BodyParameters squat = BodyParameters::rectangular_block(100.0, 1.0, 0.5);    // b/h = 2
  const BodyParameters slender = BodyParameters::rectangular_block(100.0, 0.2, 1.0);  // b/h = 0.2
  s.bodies.push_back({"squat_slides", squat});  // the solver's mu = 0.3 < A/g < b/h
  s.bodies.push_back({"squat_holds", squat});
  s.bodies.back().friction_coefficient = 0.7;  // > A/g: no slip, and A/g < b/h: no uplift
  s.bodies.push_back({"slender_rocks", slender});
  s.bodies.back().friction_coefficient = 2.0;  // above (zeta^2 + alpha^2)/alpha: rocks sticking
  s.bodies.push_back({"slender_slide_rocks", slender});
  s.bodies.back().friction_coefficient = 0.25;  // alpha <= mu < mu_req(A/g): slide-rock
  s.bodies.back().kinetic_friction_coefficient = 0.25;
  s.records.push_back({"rect", rectangular_pulse(A, t1, 3.0)});
  s.scales = {1.0};
  s.free_periods = 0.5;
  s.solver.friction_coefficient = 0.3;
  return s;
}

TEST(StudySliding, SweepRowsReportOffsetsTimeSlidingAndRegime) {
  const double A = 0.6 * g, t1 = 0.1;
  ASSERT_GT(mu_required(0.6, 0.2), 0.25);  // the slide-rock body's mu is below the demand
  ASSERT_LT(mu_required(0.6, 0.2), 2.0);
  const study::SweepSpec s = regime_sweep(A, t1);
  ASSERT_TRUE(study::has_friction(s));
  const std::vector<study::SweepRow> rows = study::run_sweep(s, {});
  ASSERT_EQ(rows.size(), 4u);
  // the squat block slides the closed-form distance, backwards
  const study::RunSummary& slides = rows[0].run;
  const double d = slip_distance(A, t1, 0.3);
  EXPECT_NEAR(slides.final_offset, -d, 1e-9 * d);
  EXPECT_NEAR(slides.max_offset, d, 1e-9 * d);
  EXPECT_NEAR(slides.sliding_time, t1 * A / (0.3 * g), 1e-9);
  EXPECT_EQ(slides.slips, 1);
  EXPECT_EQ(slides.regime, study::Regime::kSliding);
  EXPECT_EQ(slides.outcome, study::Outcome::kNoUplift);
  // its own mu = 0.7 holds it
  EXPECT_EQ(rows[1].run.regime, study::Regime::kNone);
  EXPECT_EQ(rows[1].run.max_offset, 0.0);
  EXPECT_EQ(rows[1].run.sliding_time, 0.0);
  // the slender block rocks, sticking or with its pivot sliding
  EXPECT_EQ(rows[2].run.regime, study::Regime::kRocking);
  EXPECT_EQ(rows[2].run.max_offset, 0.0);
  EXPECT_EQ(rows[3].run.regime, study::Regime::kSlidingRocking);
  EXPECT_GT(rows[3].run.max_offset, 0.0);
  EXPECT_GT(rows[3].run.sliding_time, 0.0);

  // the CSV: the sliding columns after the last one, one field each
  const std::vector<std::string> plain = io::sweep_columns(), cols = io::sweep_columns(true);
  ASSERT_EQ(cols.size(), plain.size() + 5);
  EXPECT_EQ(std::vector<std::string>(cols.begin(), cols.begin() + plain.size()), plain);
  EXPECT_EQ(cols[plain.size()], "regime");
  const std::vector<std::string> f = fields(io::sweep_row(s, rows[0]));
  ASSERT_EQ(f.size(), cols.size());
  EXPECT_EQ(f[plain.size()], "sliding");
  EXPECT_EQ(std::stod(f[plain.size() + 2]), slides.final_offset);
  EXPECT_EQ(f.back(), "1");
  // a journal takes these lines and refuses a broken sliding field
  const io::JournalCheck check = io::sweep_journal_check(s);
  for (const study::SweepRow& r : rows) EXPECT_EQ(check(r.index, io::sweep_row(s, r)), "");
  std::string bad = io::sweep_row(s, rows[0]);
  bad.replace(bad.find(",sliding,"), 9, ",slipping,");
  EXPECT_NE(check(0, bad), "");
  EXPECT_NE(check(0, bad.substr(0, bad.rfind(','))), "");
}

TEST(StudySliding, WithoutFrictionTheRowsKeepTheirColumns) {
  study::SweepSpec s = regime_sweep(0.6 * g, 0.1);
  s.solver.friction_coefficient = kInf;
  for (study::SweepBody& b : s.bodies) b.friction_coefficient.reset();
  ASSERT_FALSE(study::has_friction(s));
  const study::SweepRow row = study::run_sweep_one(s, {0, 0, 0, 0});
  EXPECT_EQ(fields(io::sweep_row(s, row)).size(), io::sweep_columns().size());
  EXPECT_EQ(row.run.regime, study::Regime::kNone);
  // a body's own finite coefficient is enough to add the columns
  s.bodies[2].friction_coefficient = 0.5;
  EXPECT_TRUE(study::has_friction(s));
  EXPECT_EQ(fields(io::sweep_row(s, row)).size(), io::sweep_columns(true).size());
  // an infinite one is none
  s.bodies[2].friction_coefficient = kInf;
  EXPECT_FALSE(study::has_friction(s));
}

TEST(StudySliding, SpectrumCellsCarryTheSlidingFields) {
  const Body body(BodyParameters::rectangular_block(100.0, 1.0, 0.5));
  study::SpectrumSpec spec;
  spec.pulse = "one_sine";
  spec.normalized = false;
  spec.amplitudes = {0.1 * g, 0.6 * g};
  spec.frequencies = {2.0 * M_PI};
  spec.bisect = false;
  spec.solver.friction_coefficient = 0.3;
  const study::SpectrumResult res = study::compute_spectrum(body, spec);
  ASSERT_TRUE(res.sliding);
  // below mu g nothing slides; above it the cell is the run itself
  EXPECT_EQ(res.cells[0].run.regime, study::Regime::kNone);
  EXPECT_EQ(res.cells[1].run.regime, study::Regime::kSliding);
  const study::RunSummary direct = study::run_pulse_cell(body, spec, 0.6 * g, 2.0 * M_PI);
  EXPECT_EQ(res.cells[1].run.final_offset, direct.final_offset);
  EXPECT_GT(res.cells[1].run.max_offset, 0.0);
  const std::vector<std::string> cols = io::spectrum_columns(true);
  ASSERT_EQ(cols.size(), io::spectrum_columns().size() + 5);
  const std::vector<std::string> f = fields(io::spectrum_row(res, res.cells[1], g));
  ASSERT_EQ(f.size(), cols.size());
  EXPECT_EQ(f[io::spectrum_columns().size()], "sliding");
  const io::JournalCheck check = io::spectrum_journal_check(res, false, g);
  EXPECT_EQ(check(1, io::spectrum_row(res, res.cells[1], g)), "");
  // without friction: the columns as before
  spec.solver.friction_coefficient = kInf;
  const study::SpectrumResult plain = study::spectrum_grid(body, spec);
  EXPECT_FALSE(plain.sliding);
  EXPECT_EQ(fields(io::spectrum_row(plain, plain.cells[0], g)).size(),
            io::spectrum_columns().size());
}

class StudySlidingFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("flexrock_study_sliding_" +
            std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p.string();
  }
  fs::path dir_;
};

const char* kBody = "[body]\ntype = \"rigid_block\"\nwidth = 0.4\nheight = 2.0\nmass = 100.0\n";
const char* kRecord = "0.0\n0.1\n-0.2\n0.3\n0.0\n";
const char* kRecordTable =
    "[[record]]\nfile = \"r.dat\"\nformat = \"single_column\"\ndt = 0.01\nunits = \"g\"\n"
    "[scales]\nfactors = [1.0]\n";

TEST_F(StudySlidingFiles, ManifestBodiesTakeTheirOwnFriction) {
  write("b.toml", kBody);
  write("r.dat", kRecord);
  const std::string m =
      write("m.toml", std::string("[[body]]\nfile = \"b.toml\"\nname = \"a\"\n"
                                  "friction_coefficient = 0.4\n"
                                  "kinetic_friction_coefficient = 0.3\n"
                                  "[[body]]\nfile = \"b.toml\"\nname = \"b\"\n") +
                          kRecordTable + "[solver]\nfriction_coefficient = 0.6\n");
  const io::SweepManifest sm = io::load_sweep_manifest(m);
  ASSERT_EQ(sm.spec.bodies.size(), 2u);
  EXPECT_EQ(sm.spec.bodies[0].friction_coefficient, 0.4);
  EXPECT_EQ(sm.spec.bodies[0].kinetic_friction_coefficient, 0.3);
  EXPECT_FALSE(sm.spec.bodies[1].friction_coefficient);
  EXPECT_TRUE(study::has_friction(sm.spec));
  // each run gets its body's pair, or the solver's
  study::SweepRow row;
  row.body = 0;
  SimulationOptions o = study::run_options(sm.spec, row);
  EXPECT_EQ(o.friction_coefficient, 0.4);
  EXPECT_EQ(o.kinetic_friction_coefficient, 0.3);
  row.body = 1;
  o = study::run_options(sm.spec, row);
  EXPECT_EQ(o.friction_coefficient, 0.6);
  EXPECT_EQ(o.kinetic_friction_coefficient, kInf);
  // no friction anywhere: none added
  const std::string n = write("n.toml", std::string("[[body]]\nfile = \"b.toml\"\n") +
                                            kRecordTable + "[solver]\nrtol = 1e-9\n");
  EXPECT_FALSE(study::has_friction(io::load_sweep_manifest(n).spec));
}

TEST_F(StudySlidingFiles, BadFrictionInAManifestNamesFileLineAndKey) {
  write("b.toml", kBody);
  write("r.dat", kRecord);
  auto manifest = [&](const std::string& name, const std::string& body_keys) {
    return write(name, "[[body]]\nfile = \"b.toml\"\n" + body_keys + kRecordTable);
  };
  const std::string m1 = manifest("m1.toml", "friction_coefficient = -0.2\n");
  test::expect_input_error([&] { io::load_sweep_manifest(m1); },
                           {"m1.toml:3", "friction_coefficient", "> 0"});
  const std::string m2 = manifest("m2.toml", "friction_coefficient = \"low\"\n");
  test::expect_input_error([&] { io::load_sweep_manifest(m2); },
                           {"m2.toml:3", "friction_coefficient"});
  const std::string m3 = manifest("m3.toml", "kinetic_friction_coefficient = 0.2\n");
  test::expect_input_error([&] { io::load_sweep_manifest(m3); },
                           {"m3.toml:3", "kinetic_friction_coefficient", "same [[body]]"});
  const std::string m4 =
      manifest("m4.toml", "friction_coefficient = 0.2\nkinetic_friction_coefficient = 0.3\n");
  test::expect_input_error([&] { io::load_sweep_manifest(m4); },
                           {"m4.toml:4", "kinetic_friction_coefficient", "at most"});
  const std::string m5 = manifest("m5.toml", "friction_coeficient = 0.2\n");
  test::expect_input_error([&] { io::load_sweep_manifest(m5); },
                           {"m5.toml:3", "friction_coeficient"});
}

TEST_F(StudySlidingFiles, SpectrumSolverFrictionAddsTheColumns) {
  const std::string p = write("s.toml", std::string(kBody) +
                                            "[spectrum]\namplitudes = [1.0]\nfrequencies = [1.0]\n"
                                            "[solver]\nfriction_coefficient = 0.3\n"
                                            "kinetic_friction_coefficient = 0.25\n");
  const io::SpectrumFile f = io::load_spectrum_file(p);
  EXPECT_EQ(f.pulse.solver.friction_coefficient, 0.3);
  EXPECT_EQ(f.pulse.solver.kinetic_friction_coefficient, 0.25);
  EXPECT_TRUE(study::spectrum_grid(Body(f.body), f.pulse).sliding);
  const std::string bad = write("bad.toml", std::string(kBody) +
                                                "[spectrum]\namplitudes = [1.0]\nfrequencies = "
                                                "[1.0]\n[solver]\nfriction_coefficient = 0.3\n"
                                                "kinetic_friction_coefficient = 0.5\n");
  test::expect_input_error([&] { io::load_spectrum_file(bad); },
                           {"bad.toml:11", "kinetic_friction_coefficient", "at most"});
}

// Fragility of the squat block's slip: two pulse lengths make the failures overlap in PGA, so
// the fit has a finite estimate; every failure flag is the closed-form slip above the level.
TEST_F(StudySlidingFiles, FragilityOfTheSlidingOffset) {
  study::SweepSpec s;
  s.bodies.push_back({"squat", BodyParameters::rectangular_block(100.0, 1.0, 0.5)});
  s.records.push_back({"short", rectangular_pulse(1.0, 0.1, 2.0)});
  s.records.push_back({"long", rectangular_pulse(1.0, 0.25, 2.0)});
  for (double a = 0.35; a < 1.5; a += 0.1) s.scales.push_back(a * g);
  s.free_periods = 0.2;
  s.solver.friction_coefficient = 0.3;
  const std::vector<study::SweepRow> rows = study::run_sweep(s, {});
  std::string csv;
  const std::vector<std::string> cols = io::sweep_columns(study::has_friction(s));
  for (std::size_t i = 0; i < cols.size(); ++i) csv += (i ? "," : "") + cols[i];
  csv += "\n";
  for (const study::SweepRow& r : rows) csv += io::sweep_row(s, r) + "\n";
  const io::CsvTable t = io::read_csv_table(write("s.csv", csv));
  io::FragilityQuery q;
  q.outcome = "offset";
  q.level = 0.1;  // [m]
  const std::vector<io::FragilityData> data = io::fragility_data(t, q);
  ASSERT_EQ(data.size(), 1u);
  ASSERT_EQ(data[0].failed.size(), rows.size());
  int failures = 0;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const double t1 = rows[k].record == 0 ? 0.1 : 0.25;
    const double d = slip_distance(rows[k].pga, t1, 0.3);
    ASSERT_GT(std::abs(d - q.level), 1e-6) << "a run on the level: pick another";
    EXPECT_EQ(data[0].failed[k], d > q.level ? 1 : 0) << k << " " << d;
    EXPECT_EQ(data[0].im[k], rows[k].pga);
    failures += data[0].failed[k];
  }
  EXPECT_GT(failures, 2);
  const study::FragilityFit fit = study::fit_lognormal(data[0].im, data[0].failed);
  // the median lies between the PGAs at which each pulse slides 0.1 m
  auto pga_at = [](double t1) {
    // A (A - mu g) t1^2 / (2 mu g) = 0.1: the positive root
    const double c = 2.0 * 0.3 * g * 0.1 / (t1 * t1), m = 0.3 * g;
    return 0.5 * (m + std::sqrt(m * m + 4.0 * c));
  };
  EXPECT_GT(fit.theta, pga_at(0.25));
  EXPECT_LT(fit.theta, pga_at(0.1));
  // the residual offset is the same slip here (one slip, backwards): |final| > level
  q.outcome = "residual_offset";
  EXPECT_EQ(io::fragility_data(t, q)[0].failed, data[0].failed);
  // a sweep without friction has no offset column: say so
  study::SweepSpec plain = s;
  plain.solver.friction_coefficient = kInf;
  std::string csv2;
  for (std::size_t i = 0; i < io::sweep_columns().size(); ++i)
    csv2 += (i ? "," : "") + io::sweep_columns()[i];
  csv2 += "\n" + io::sweep_row(plain, rows[0]) + "\n";
  const io::CsvTable t2 = io::read_csv_table(write("p.csv", csv2));
  q.outcome = "offset";
  test::expect_input_error([&] { io::fragility_data(t2, q); },
                           {"p.csv:1", "max_offset_m", "finite friction coefficient"});
}

}  // namespace
}  // namespace flexrock
