// SPDX-License-Identifier: BSD-3-Clause
// Study files: manifests and spectrum specs (errors with file:line: key), what sweep and
// spectrum journals may hold, CSV input of fragility fits.
#include "flexrock/io/study_files.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "flexrock/io/case_file.hpp"
#include "flexrock/study/spectrum.hpp"
#include "flexrock/study/sweep.hpp"
#include "support/expect_error.hpp"

namespace flexrock::io {
namespace {

namespace fs = std::filesystem;

class StudyFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("flexrock_study_files_" +
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
  static std::string read(const std::string& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }
  fs::path dir_;
};

const char* kBody = "[body]\ntype = \"rigid_block\"\nwidth = 0.4\nheight = 2.0\nmass = 100.0\n";
const char* kRecord = "0.0\n0.1\n-0.2\n0.3\n0.0\n";

TEST_F(StudyFiles, ManifestLoadsBodiesRecordsAndScales) {
  write("b.toml", kBody);
  write("r.dat", kRecord);
  const std::string m = write("m.toml",
                              "[[body]]\nfile = \"b.toml\"\n"
                              "[[record]]\nfile = \"r.dat\"\nformat = \"single_column\"\n"
                              "dt = 0.01\nunits = \"g\"\nname = \"rec\"\n"
                              "[scales]\nfactors = { start = 0.5, stop = 2.0, step = 0.5 }\n");
  const SweepManifest sm = load_sweep_manifest(m);
  ASSERT_EQ(sm.spec.bodies.size(), 1u);
  EXPECT_EQ(sm.spec.bodies[0].name, "b");
  EXPECT_EQ(sm.spec.records[0].name, "rec");
  EXPECT_EQ(sm.spec.scales, (std::vector<double>{0.5, 1.0, 1.5, 2.0}));
  EXPECT_TRUE(sm.spec.levels.empty());  // factors: the levels are the scales
  // target PGAs: scales in m/s^2, the levels as written, for the CSV's requested_level
  const std::string t = write("t.toml",
                              "[[body]]\nfile = \"b.toml\"\n"
                              "[[record]]\nfile = \"r.dat\"\nformat = \"single_column\"\n"
                              "dt = 0.01\nunits = \"g\"\n"
                              "[scales]\ntarget_pga = [0.1, 0.3]\nunits = \"cm/s^2\"\n");
  const SweepManifest st = load_sweep_manifest(t);
  EXPECT_EQ(st.spec.levels, (std::vector<double>{0.1, 0.3}));
  EXPECT_EQ(st.spec.level_units, "cm/s^2");
  EXPECT_EQ(st.spec.scales, (std::vector<double>{0.1 * 0.01, 0.3 * 0.01}));
  // the hash follows the files the manifest names
  write("r.dat", "0.0\n0.1\n-0.2\n0.3\n0.01\n");
  EXPECT_NE(load_sweep_manifest(m).hash, sm.hash);
}

TEST_F(StudyFiles, ManifestErrorsNameFileLineAndKey) {
  write("b.toml", kBody);
  write("r.dat", kRecord);
  const std::string head =
      "[[body]]\nfile = \"b.toml\"\n[[record]]\nfile = \"r.dat\"\nformat = \"single_column\"\n"
      "dt = 0.01\nunits = \"g\"\n";
  const std::string m1 = write("m1.toml", head + "[scales]\nfactor = [1.0]\n");
  test::expect_input_error([&] { load_sweep_manifest(m1); }, {"m1.toml:8", "scales.factors"});
  const std::string m2 = write("m2.toml", head + "[scales]\nfactors = [1.0, -2.0]\n");
  test::expect_input_error([&] { load_sweep_manifest(m2); }, {"m2.toml:9", "> 0"});
  const std::string m3 = write("m3.toml", head + "[scales]\nfactors = [1.0]\n[solvr]\n");
  test::expect_input_error([&] { load_sweep_manifest(m3); }, {"m3.toml:10", "solvr", "solver"});
  const std::string m4 = write("m4.toml", "[[body]]\nfile = \"missing.toml\"\n");
  test::expect_input_error([&] { load_sweep_manifest(m4); }, {"missing.toml", "m4.toml:1"});
}

TEST_F(StudyFiles, SpectrumFileWithInlineBodyAndPhysicalAxes) {
  const std::string p = write("s.toml", std::string(kBody) +
                                            "[spectrum]\naxes = \"physical\"\n"
                                            "amplitude_units = \"g\"\nfrequency_units = \"Hz\"\n"
                                            "amplitudes = [0.5, 1.0]\nfrequencies = { start = 1, "
                                            "stop = 4, count = 4, spacing = \"log\" }\n");
  const SpectrumFile f = load_spectrum_file(p);
  EXPECT_FALSE(f.is_record);
  EXPECT_FALSE(f.pulse.normalized);
  // the grid stays in the units given, with their SI values beside it
  EXPECT_EQ(f.pulse.amplitudes[1], 1.0);
  ASSERT_EQ(f.pulse.frequencies.size(), 4u);
  EXPECT_NEAR(f.pulse.frequencies[3], 4.0, 1e-12);
  EXPECT_NEAR(f.pulse.frequencies[1], std::cbrt(4.0), 1e-12);
  EXPECT_EQ(f.pulse.units.amplitude, "g");
  EXPECT_EQ(f.pulse.units.amplitude_si, 9.80665);
  EXPECT_EQ(f.pulse.units.frequency, "Hz");
  EXPECT_EQ(f.pulse.units.frequency_si, 2.0 * std::acos(-1.0));
  const std::string bad =
      write("bad.toml", std::string(kBody) + "[spectrum]\npulse = \"one-sine\"\n");
  test::expect_input_error([&] { load_spectrum_file(bad); },
                           {"bad.toml:7", "spectrum.pulse", "did you mean \"one_sine\""});
}

TEST_F(StudyFiles, SweepJournalLinesMustBeThoseOfTheirRun) {
  write("b.toml", kBody);
  write("r.dat", kRecord);
  const std::string m = write("m.toml",
                              "[[body]]\nfile = \"b.toml\"\n"
                              "[[record]]\nfile = \"r.dat\"\nformat = \"single_column\"\n"
                              "dt = 0.01\nunits = \"g\"\nname = \"rec\"\n"
                              "[scales]\nfactors = [0.5, 40.0]\n");
  const SweepManifest sm = load_sweep_manifest(m);
  const JournalCheck check = sweep_journal_check(sm.spec);
  const std::string row0 = sweep_row(sm.spec, study::run_sweep_one(sm.spec, {0, 0, 0, 0}));
  const std::string row1 = sweep_row(sm.spec, study::run_sweep_one(sm.spec, {1, 0, 0, 1}));
  EXPECT_EQ(check(0, row0), "");
  EXPECT_EQ(check(1, row1), "");
  // the line of another run, a changed body name, scale or PGA
  EXPECT_NE(check(1, row0), "");
  // the line with field k (0-based) replaced
  auto with_field = [](const std::string& line, std::size_t k, const std::string& value) {
    std::size_t start = 0;
    for (std::size_t i = 0; i < k; ++i) start = line.find(',', start) + 1;
    const std::size_t end = line.find(',', start);
    return line.substr(0, start) + value + (end == std::string::npos ? "" : line.substr(end));
  };
  ASSERT_EQ(with_field(row0, 0, "0"), row0);
  const std::vector<std::string> cols = sweep_columns();
  auto at = [&cols](const char* name) {
    return static_cast<std::size_t>(std::find(cols.begin(), cols.end(), name) - cols.begin());
  };
  EXPECT_NE(check(0, with_field(row0, at("body"), "c")), "");
  EXPECT_NE(check(0, with_field(row0, at("record"), "r")), "");
  EXPECT_NE(check(0, with_field(row0, at("scale"), "0.6")), "");
  EXPECT_NE(check(0, with_field(row0, at("pga_m_per_s2"), "1.5")), "");
  EXPECT_NE(check(0, with_field(row0, at("duration_s"), "9")), "");
  // an unknown outcome, an overturned flag that does not go with it, a count that is not one,
  // text where a number belongs, a missing field, an unknown status
  EXPECT_NE(check(0, with_field(row0, at("outcome"), "no_upleft")), "");
  const bool over = row0.find(",overturned_") != std::string::npos;
  EXPECT_NE(check(0, with_field(row0, at("overturned"), over ? "0" : "1")), "");
  EXPECT_NE(check(0, with_field(row0, at("impacts"), "1.5")), "");
  EXPECT_NE(check(0, with_field(row0, at("max_theta_rad"), "abc")), "");
  EXPECT_NE(check(0, row0.substr(0, row0.rfind(','))), "");
  EXPECT_NE(check(0, with_field(row0, at("status"), "complete")), "");
  EXPECT_NE(check(5, row0), "");
}

TEST_F(StudyFiles, SweepRowsReadBackAsTheDataTheyWereWrittenFrom) {
  write("b.toml", kBody);
  write("r.dat", kRecord);
  const std::string m = write("m.toml",
                              "[[body]]\nfile = \"b.toml\"\n"
                              "[[record]]\nfile = \"r.dat\"\nformat = \"single_column\"\n"
                              "dt = 0.01\nunits = \"g\"\nname = \"rec\"\n"
                              "[scales]\nfactors = [0.5, 40.0]\n[intensity]\nmeasures = "
                              "[\"arias\"]\n[solver]\nfriction_coefficient = 0.6\n");
  const SweepManifest sm = load_sweep_manifest(m);
  const std::vector<ColumnInfo> info = sweep_column_info(sm.spec);
  ASSERT_EQ(info.size(), sweep_columns(sm.spec).size());
  for (std::size_t i = 0; i < 2; ++i) {
    const study::SweepRow row = study::run_sweep_one(sm.spec, study::sweep_runs(sm.spec)[i]);
    const std::string line = sweep_row(sm.spec, row);
    const study::SweepRow back = read_sweep_row(sm.spec, i, line);
    // every field as data, equal to the run's (bit for bit: the text is the shortest that reads
    // back to the same double)
    EXPECT_EQ(back.index, i);
    EXPECT_EQ(back.scale_index, row.scale_index);
    EXPECT_EQ(back.scale, row.scale);
    EXPECT_EQ(back.pga, row.pga);
    EXPECT_EQ(back.measures, row.measures);
    EXPECT_EQ(back.run.outcome, row.run.outcome);
    EXPECT_EQ(back.run.status, row.run.status);
    EXPECT_EQ(back.run.impacts, row.run.impacts);
    EXPECT_EQ(back.run.max_theta, row.run.max_theta);
    EXPECT_EQ(back.run.energy_lost, row.run.energy_lost);
    EXPECT_EQ(back.run.regime, row.run.regime);
    EXPECT_EQ(back.run.slips, row.run.slips);
    EXPECT_EQ(sweep_row(sm.spec, back), line);
    // the values by column, of the column's type
    const std::vector<FieldValue> v = sweep_values(sm.spec, back);
    ASSERT_EQ(v.size(), info.size());
    for (std::size_t k = 0; k < v.size(); ++k) {
      EXPECT_EQ(v[k].index(), static_cast<std::size_t>(info[k].type)) << info[k].name;
    }
  }
  // a field that does not follow from the others is named
  const std::string line = sweep_row(sm.spec, study::run_sweep_one(sm.spec, {0, 0, 0, 0}));
  std::string changed = line;
  changed.replace(changed.find(",rec,"), 5, ",reb,");
  test::expect_input_error([&] { read_sweep_row(sm.spec, 0, changed); },
                           {"field 3 (record)", "expected \"rec\""});
  test::expect_input_error([&] { read_sweep_row(sm.spec, 2, line); }, {"out of range"});
}

TEST_F(StudyFiles, FiguresWithNoFiniteValueAreEmptyFieldsNeverInf) {
  // M g h = 8.8e307 J is normal, but the record at factor 10 (3 g) gives a base shear of
  // M a = 3e308 N: the run stops, its message naming the output that overflowed
  write("heavy.toml", "[body]\ntype = \"rigid_block\"\nwidth = 4.0\nheight = 1.8\nmass = 1e307\n");
  write("r.dat", kRecord);
  const std::string m = write("m.toml",
                              "[[body]]\nfile = \"heavy.toml\"\n"
                              "[[record]]\nfile = \"r.dat\"\nformat = \"single_column\"\n"
                              "dt = 0.01\nunits = \"g\"\nname = \"rec\"\n"
                              "[scales]\nfactors = [0.5, 10.0]\n");
  const SweepManifest sm = load_sweep_manifest(m);
  const JournalCheck check = sweep_journal_check(sm.spec);
  const std::vector<std::string> cols = sweep_columns();
  auto at = [&cols](const char* name) {
    return static_cast<std::size_t>(std::find(cols.begin(), cols.end(), name) - cols.begin());
  };
  // the line up to its message, and field k of it
  auto figures = [&](const std::string& line) {
    std::size_t start = 0;
    for (std::size_t i = 0; i < at("message"); ++i) start = line.find(',', start) + 1;
    return line.substr(0, start);
  };
  auto field_at = [](const std::string& line, std::size_t k) {
    std::size_t start = 0;
    for (std::size_t i = 0; i < k; ++i) start = line.find(',', start) + 1;
    return line.substr(start, line.find(',', start) - start);
  };
  study::SweepRow over = study::run_sweep_one(sm.spec, {1, 0, 0, 1});
  ASSERT_EQ(over.run.status, Status::kStopped);
  EXPECT_NE(over.message.find("not finite"), std::string::npos) << over.message;
  std::string row = sweep_row(sm.spec, over);
  EXPECT_EQ(check(1, row), "") << row;
  for (const char* bad : {"inf", "nan"}) EXPECT_EQ(figures(row).find(bad), std::string::npos);
  // figures of such a run that did overflow (the summary of a run the engine stopped can hold
  // them: a sum of finite losses, a friction demand at a zero normal force) are empty fields
  constexpr double inf = std::numeric_limits<double>::infinity();
  over.run.energy_lost = inf;
  over.run.max_impulse = -inf;
  over.run.max_friction_demand = std::numeric_limits<double>::quiet_NaN();
  row = sweep_row(sm.spec, over);
  for (const char* bad : {"inf", "nan"})
    EXPECT_EQ(figures(row).find(bad), std::string::npos) << row;
  for (const char* name : {"energy_lost_J", "max_impulse_N_s", "max_friction_demand"})
    EXPECT_EQ(field_at(row, at(name)), "") << name << ": " << row;
  EXPECT_EQ(check(1, row), "") << row;
  // and a journal line with "inf" or "nan" where a number belongs is refused, as is a changed
  // input field; the run at factor 0.5 writes every figure
  auto with_field = [](const std::string& line, std::size_t k, const std::string& value) {
    std::size_t start = 0;
    for (std::size_t i = 0; i < k; ++i) start = line.find(',', start) + 1;
    const std::size_t end = line.find(',', start);
    return line.substr(0, start) + value + (end == std::string::npos ? "" : line.substr(end));
  };
  for (const char* bad : {"inf", "-inf", "nan"}) {
    EXPECT_NE(check(1, with_field(row, at("energy_lost_J"), bad)), "") << bad;
    EXPECT_NE(check(1, with_field(row, at("max_theta_rad"), bad)), "") << bad;
  }
  const std::string ok = sweep_row(sm.spec, study::run_sweep_one(sm.spec, {0, 0, 0, 0}));
  EXPECT_EQ(check(0, ok), "");
  EXPECT_EQ(figures(ok).find(",,"), std::string::npos) << ok;
}

TEST_F(StudyFiles, SpectrumJournalLinesMustBeThoseOfTheirCell) {
  const Body body(load_body(write("b.toml", kBody)));
  study::SpectrumSpec spec;
  spec.amplitudes = {0.5, 3.0, 6.0};
  spec.frequencies = {2.0, 4.0};
  spec.free_periods = 1.0;
  const study::SpectrumResult res = study::compute_spectrum(body, spec, {.threads = 1});
  const study::SpectrumResult grid = study::spectrum_grid(body, spec);
  const double g = body.g();
  const JournalCheck check = spectrum_journal_check(grid, true, g);
  for (std::size_t i = 0; i < res.cells.size(); ++i) {
    const std::string line = spectrum_row(res, res.cells[i], g);
    EXPECT_EQ(check(i, line), "") << line;
    // read back as data: the cell's run, which writes the same line
    const study::SpectrumCell back = read_spectrum_cell(grid, i, line, g);
    EXPECT_EQ(back.run.outcome, res.cells[i].run.outcome);
    EXPECT_EQ(back.run.impacts, res.cells[i].run.impacts);
    EXPECT_EQ(spectrum_row(res, back, g), line);
    EXPECT_NE(check((i + 1) % res.cells.size(), line), "");  // another cell's line
  }
  for (std::size_t j = 0; j < res.boundary.size(); ++j) {
    const std::string line = boundary_row(res, res.boundary[j], true, g);
    EXPECT_EQ(check(res.cells.size() + j, line), "") << line;
    EXPECT_NE(check(res.cells.size() + 1 - j, line), "");  // the other column's
    EXPECT_NE(check(j, line), "");                         // not a cell
    // read back as data: what the bisection found, which writes the same line
    const study::OverturnBoundary back = read_boundary(grid, j, line, true, g);
    EXPECT_EQ(back.kind, res.boundary[j].kind);
    EXPECT_EQ(back.bisection_runs, res.boundary[j].bisection_runs);
    if (back.kind != study::OverturnBoundary::Kind::kNone) {
      EXPECT_EQ(back.overturning, res.boundary[j].overturning);
      EXPECT_EQ(back.mode, res.boundary[j].mode);
    }
    EXPECT_EQ(boundary_row(res, back, true, g), line);
  }
  test::expect_input_error(
      [&] { read_boundary(grid, 0, boundary_row(res, res.boundary[1], true, g), true, g); },
      {"field"});
  std::string cell = spectrum_row(res, res.cells[0], g);
  cell.replace(cell.find(",no_uplift,0,"), 13, ",no_uplift,1,");
  EXPECT_NE(check(0, cell), "");
  EXPECT_NE(check(res.cells.size() + res.boundary.size(), "0,x"), "");
}

TEST_F(StudyFiles, SolverOptionsAreCheckedWhereTheyAreWritten) {
  write("b.toml", kBody);
  write("r.dat", kRecord);
  // refused by simulate(): refused here, at the key's own line (the rule is the table's)
  const std::string m = write("m.toml",
                              "[[body]]\nfile = \"b.toml\"\n"
                              "[[record]]\nfile = \"r.dat\"\nformat = \"single_column\"\n"
                              "dt = 0.01\nunits = \"g\"\n"
                              "[scales]\nfactors = [1.0]\n[solver]\nevent_samples = 100\n");
  test::expect_input_error([&] { load_sweep_manifest(m); }, {"m.toml:11", "solver.event_samples"});
  const std::string s = write("s.toml", std::string(kBody) +
                                            "[spectrum]\namplitudes = [1.0]\nfrequencies = [1.0]\n"
                                            "[solver]\nevent_samples = 100\n");
  test::expect_input_error([&] { load_spectrum_file(s); }, {"s.toml:10", "event_samples"});
  const std::string t = write("t.toml", std::string(kBody) +
                                            "[spectrum]\namplitudes = [1.0]\nfrequencies = [1.0]\n"
                                            "bisection_tolerance = 1e-16\n");
  test::expect_input_error([&] { load_spectrum_file(t); },
                           {"t.toml:9", "spectrum.bisection_tolerance", "1e-12"});
}

TEST_F(StudyFiles, FragilityDataFromASweepCsv) {
  std::string csv;
  for (std::size_t i = 0; i < sweep_columns().size(); ++i)
    csv += (i ? "," : "") + sweep_columns()[i];
  csv += "\n";
  // index body record requested_level requested_units scale pga pga_g pgv duration outcome
  // overturned edge t_over theta theta/alpha impacts t_up uplift impulse energy friction
  // tension_episodes pull tension_time tensile_landings tensile_impulse status message
  csv +=
      "0,a,r,1,-,1,1.5,0.15,0.2,10,rocking,0,0,-1,0.1,0.5,3,1,0,0,2.5,0.1,0,0,0,0,0,completed,\n";
  csv +=
      "1,a,r,2,-,2,3.0,0.3,0.4,10,overturned_after_impacts,1,1,4,1,1,3,1,0,0,1.0,0.1,0,0,0,0,0,"
      "overturned,\n";
  csv +=
      "2,a,r,3,-,3,4.5,0.45,0.6,10,stopped,0,0,-1,0,0,0,-1,0,0,0,0,0,0,0,0,0,stopped,step "
      "collapse\n";
  csv += "3,b,r,1,-,1,1.5,0.15,0.2,10,no_uplift,0,0,-1,0,0,0,-1,0,0,0,0.1,0,0,0,0,0,completed,\n";
  const std::string p = write("s.csv", csv);
  const CsvTable t = read_csv_table(p);
  FragilityQuery q;
  auto d = fragility_data(t, q);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0].body, "a");
  EXPECT_EQ(d[0].im, (std::vector<double>{1.5, 3.0}));
  EXPECT_EQ(d[0].failed, (std::vector<int>{0, 1}));
  EXPECT_EQ(d[0].excluded, 1u);
  q.outcome = "theta";
  q.level = 0.4;
  q.im = "pgv";
  q.body = "a";
  d = fragility_data(t, q);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].failed, (std::vector<int>{1, 1}));
  EXPECT_EQ(d[0].im, (std::vector<double>{0.2, 0.4}));
  q.im = "requested_level";
  q.outcome = "overturned";
  EXPECT_EQ(fragility_data(t, q)[0].im, (std::vector<double>{1.0, 2.0}));
  q.im = "sa";
  test::expect_input_error([&] { fragility_data(t, q); }, {"'sa'", "pga, pga_g, pgv, scale"});
  // a figure that is not finite (written by no flexrock) is refused, naming it
  std::string inf_csv = csv;
  inf_csv.replace(inf_csv.find(",2.5,0.1,0,0,0,0,0,completed"), 4, ",inf");
  const CsvTable ti = read_csv_table(write("inf.csv", inf_csv));
  q.outcome = "energy";
  q.level = 1.0;
  q.im = "pga";
  test::expect_input_error([&] { fragility_data(ti, q); },
                           {"inf.csv:2", "energy_lost_J", "expected a finite number", "inf"});
  const std::string bad = write("bad.csv", "index,body\n1,a,b\n");
  test::expect_input_error([&] { read_csv_table(bad); }, {"bad.csv:2", "expected 2 fields"});
}

}  // namespace
}  // namespace flexrock::io
