// SPDX-License-Identifier: BSD-3-Clause
// Qualifications (io/qualify.hpp): SHA-256 against the FIPS 180-4 vectors, bad qualification
// files refused with file, line and key, the report's numbers read back and compared with the
// runs made independently (run_sweep_one, run_record_cell, newmark_sliding), and a qualification
// stopped part-way and resumed giving the same report.
#include "flexrock/io/qualify.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <thread>

#include "flexrock/core/error.hpp"
#include "flexrock/study/hand_estimates.hpp"
#include "flexrock/study/spectrum.hpp"

namespace flexrock::io {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

TEST(Sha256, MatchesTheFipsVectors) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256_hex(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

class QualifyFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        fs::temp_directory_path() /
        ("flexrock_qualify_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
         "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    // a record of two sine bursts, 0.01 s, in g
    std::ofstream r(dir_ / "rec.txt");
    for (int i = 0; i < 600; ++i) {
      const double t = 0.01 * i;
      r << 0.3 * std::sin(2.0 * std::numbers::pi * 1.5 * t) * std::sin(std::numbers::pi * t / 6.0)
        << "\n";
    }
    std::ofstream r2(dir_ / "rec2.txt");
    for (int i = 0; i < 500; ++i) {
      const double t = 0.01 * i;
      r2 << 0.25 * std::sin(2.0 * std::numbers::pi * 0.8 * t + 0.3) *
                std::sin(std::numbers::pi * t / 5.0)
         << "\n";
    }
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return (dir_ / name).string();
  }

  // a rigid block, two records, the criteria: `extra` is put before [design]
  std::string qualification(const std::string& ranges, const std::string& extra = "",
                            const std::string& body = kRigid,
                            const std::string& ida =
                                "[ida]\nfactors = [0.5, 1, 2, 4]\ntolerance = "
                                "0.02\n") {
    return write("q.toml", body + ranges +
                               "[[record]]\nfile = \"rec.txt\"\nformat = \"single_column\"\ndt = "
                               "0.01\nunits = \"g\"\n"
                               "[[record]]\nfile = \"rec2.txt\"\nformat = \"single_column\"\ndt = "
                               "0.01\nunits = \"g\"\n" +
                               extra +
                               "[design]\npga = 0.3\nunits = \"g\"\n"
                               "[criteria]\ntilt_fraction = 0.5\nsliding_clearance = 0.05\n"
                               "impact_force = 1e5\nuplift = 0.05\n" +
                               ida);
  }

  // the message of the InputError loading `path` throws
  std::string error_of(const std::string& path) {
    try {
      load_qualify_file(path);
    } catch (const InputError& e) {
      return e.what();
    }
    ADD_FAILURE() << "no error for " << path;
    return "";
  }

  static inline const std::string kRigid =
      "name = \"block\"\n[body]\ntype = \"rigid_block\"\nwidth = 0.5\nheight = 1.5\nmass = "
      "200.0\n";
  static inline const std::string kFlexible =
      "[body]\ntype = \"uniform_cantilever\"\nheight = 6.0\nwidth = 2.0\nmass_per_length = "
      "2000.0\nbending_stiffness = 7.5e7\nmodes = 1\nbase_mass = 2000.0\ndamping_ratio = 0.02\n";
  fs::path dir_;
};

TEST_F(QualifyFiles, BadFilesAreRefusedWithFileLineAndKey) {
  struct Bad {
    std::string ranges, extra, body, expect;
  };
  const std::vector<Bad> bad = {
      {"[ranges]\nfriction = [0.3, -1.0]\n", "", kRigid,
       "q.toml:8: key 'ranges.friction': expected values > 0: static Coulomb coefficients to "
       "bound, each > 0 (inf: no sliding): every one is a case [-], got -1"},
      {"[ranges]\nfriction = [0.3, 0.3]\n", "", kRigid, "expected distinct values"},
      {"[ranges]\nkinetic_ratio = 1.5\n", "", kRigid, "q.toml:8: key 'ranges.kinetic_ratio'"},
      {"[ranges]\nmass_tolerance = 1.0\n", "", kRigid, "key 'ranges.mass_tolerance'"},
      {"[ranges]\ncg_offset_tolerance = 0.3\n", "", kRigid,
       "q.toml:8: key 'ranges.cg_offset_tolerance': expected a number below b1 = 0.25 m"},
      {"[ranges]\ncg_height_tolerance = 0.1\n", "", kFlexible,
       "key 'ranges.cg_height_tolerance': expected a rigid body"},
      {"[ranges]\ndamping_ratio = [0.01, 0.03]\n", "", kRigid,
       "key 'ranges.damping_ratio': expected a body with modes"},
      {"[ranges]\nfricton = [0.3]\n", "", kRigid,
       "q.toml:8: key 'ranges.fricton': unknown key in [ranges] (see docs/qualify.md) (did you "
       "mean 'ranges.friction'?)"},
      {"[ranges]\nfriction = [0.3]\n", "[solver]\nfriction_coefficient = 0.5\n", kRigid,
       "q.toml:8: key 'ranges.friction': expected no [solver] friction_coefficient"},
      {"", "[report]\ncontact_stiffness = 1e-3\n", kRigid,
       "key 'report.contact_stiffness': expected a stiffness the compliant contact takes"},
      {"", "[solver]\ncontact_model = \"compliant\"\ncontact_stiffness = 1e8\n", kRigid,
       "key 'criteria.impact_force': expected the impulsive contact"},
  };
  for (const Bad& b : bad) {
    const std::string path = qualification(b.ranges, b.extra, b.body);
    EXPECT_NE(error_of(path).find(b.expect), std::string::npos)
        << error_of(path) << "\n  expected: " << b.expect;
  }
  // criteria, design and IDA keys
  const std::string base = kRigid +
                           "[[record]]\nfile = \"rec.txt\"\nformat = \"single_column\"\ndt = "
                           "0.01\nunits = \"g\"\n";
  const std::vector<std::pair<std::string, std::string>> more = {
      {"[design]\npga = 0.3\n[criteria]\ntilt_fraction = 1.5\n",
       "q.toml:15: key 'criteria.tilt_fraction': expected allowed largest tilt"},
      {"[design]\npga = 0.3\n[criteria]\ntilt_fracton = 0.5\n",
       "q.toml:15: key 'criteria.tilt_fracton': unknown key in [criteria] (see docs/qualify.md) "
       "(did you mean 'criteria.tilt_fraction'?)"},
      {"[design]\npga = 0.3\n[criteria]\n", "expected at least one criterion"},
      {"[design]\npga = 0.3\nfactor = 2\n[criteria]\nuplift = 0.1\n",
       "key 'design.factor': expected exactly one of 'pga' (with 'units') or 'factor'"},
      {"[design]\nfactor = 2\nunits = \"g\"\n[criteria]\nuplift = 0.1\n",
       "q.toml:14: key 'design.units': only with 'pga'"},
      {"[criteria]\nuplift = 0.1\n", "table [design]: missing"},
      {"[design]\npga = 0.3\n[criteria]\nuplift = 0.1\n[ida]\ntolerance = 0\n",
       "q.toml:17: key 'ida.tolerance'"},
      {"[design]\npga = 0.3\n[criteria]\nuplift = 0.1\n[ida]\nfactors = [2, 1]\n",
       "key 'ida.factors'"},
      {"[design]\npga = 0.3\n[criteria]\nuplift = 0.1\n[report]\nhistory_dt = -1\n",
       "key 'report.history_dt'"},
  };
  for (const auto& [tail, expect] : more) {
    const std::string path = write("q.toml", base + tail);
    EXPECT_NE(error_of(path).find(expect), std::string::npos)
        << error_of(path) << "\n  expected: " << expect;
  }
}

TEST_F(QualifyFiles, CasesAreTheCornersOfTheRanges) {
  const QualifyFile f = load_qualify_file(
      qualification("[ranges]\nfriction = [0.3, inf]\nkinetic_ratio = 0.8\nmass_tolerance = 0.1\n"
                    "cg_height_tolerance = 0.05\ncg_offset_tolerance = 0.02\n"));
  ASSERT_EQ(f.cases.size(), 2u * 2u * 2u * 2u);
  for (const QualifyCase& c : f.cases) {
    EXPECT_NEAR(c.body.mass, 200.0 * c.mass_factor, 1e-12);
    EXPECT_NEAR(c.body.height, 0.75 * c.cg_height_factor, 1e-12);
    EXPECT_NEAR(c.body.b1, 0.25 + c.cg_offset, 1e-15);
    EXPECT_NEAR(c.body.b2, 0.25 - c.cg_offset, 1e-15);
    EXPECT_EQ(c.kinetic_friction, std::isfinite(c.friction) ? 0.8 * c.friction : c.friction);
  }
  EXPECT_EQ(f.cases.front().name, "mu=0.3 M- h- cg->1");
  EXPECT_EQ(f.cases.back().name, "mu=inf M+ h+ cg->2");
  EXPECT_EQ(f.spec.bodies.size(), f.cases.size());
  EXPECT_EQ(f.input_files.size(), 3u);  // the file (with its body) and two records
}

// the report's numbers against runs made here, independently of the session
TEST_F(QualifyFiles, TheReportsNumbersAreTheRuns) {
  const QualifyFile f =
      load_qualify_file(qualification("[ranges]\nfriction = [0.2, 0.6]\n",
                                      "[report]\nfragility = true\ncontact_stiffness = 1e8\n"));
  QualifySession session(f, (dir_ / "runs").string());
  study::RunOptions o;
  o.threads = 2;
  session.run(o);
  const QualifyReport rep = session.finish();
  const Json j = Json::parse(rep.json);
  const study::SweepSpec& spec = f.spec;
  const std::vector<study::SweepRun> runs = study::sweep_runs(spec);
  ASSERT_EQ(j["runs"].size(), runs.size());
  const double tau = spec.solver.impact_duration;
  std::vector<double> tilt(f.cases.size(), 0.0);
  for (const study::SweepRun& run : runs) {
    const study::SweepRow row = study::run_sweep_one(spec, run);
    const Json& r = j["runs"][run.index];
    EXPECT_EQ(r["scale"].get<double>(), row.scale);
    EXPECT_EQ(r["max_theta_over_alpha"].get<double>(), row.run.max_theta_over_alpha);
    EXPECT_EQ(r["max_offset_m"].get<double>(), row.run.max_offset);
    EXPECT_EQ(r["max_uplift_m"].get<double>(), row.run.max_uplift);
    EXPECT_EQ(r["impact_force_N"].get<double>(),
              std::numbers::pi * row.run.max_impulse / (2.0 * tau));
    EXPECT_EQ(r["outcome"].get<std::string>(), study::to_string(row.run.outcome));
    tilt[run.body] = std::max(tilt[run.body], row.run.max_theta_over_alpha);
    // Newmark's block beside the run, at the run's scale
    const Json& h = j["hand_estimates"]["per_case"][run.body]["records"][run.record];
    const GroundMotion& m = spec.records[run.record].motion;
    std::vector<double> a = m.horizontal();
    for (double& v : a) v *= row.scale;
    const QualifyCase& c = f.cases[run.body];
    EXPECT_EQ(
        h["newmark_max_offset_m"].get<double>(),
        study::newmark_sliding(m.times(), a, c.friction, c.kinetic_friction, 9.80665).max_offset);
  }
  // the tilt criterion: largest per case, the governing case and the ratio
  const Json& crit = j["criteria"][0];
  ASSERT_EQ(crit["name"], "tilt");
  double gov = 0.0;
  for (std::size_t c = 0; c < f.cases.size(); ++c) {
    EXPECT_EQ(crit["per_case"][c]["max"].get<double>(), tilt[c]);
    gov = std::max(gov, tilt[c]);
  }
  EXPECT_EQ(crit["ratio"].get<double>(), gov / 0.5);
  EXPECT_EQ(crit["pass"].get<bool>(), gov <= 0.5);
  // the IDA: the margin overturns the case's body, the safe end does not
  ASSERT_EQ(j["ida"]["per"].size(), f.cases.size() * spec.records.size());
  int found = 0;
  for (const Json& p : j["ida"]["per"]) {
    const std::size_t c = p["case"].get<std::size_t>();
    const double s = p["design_scale"].get<double>();
    study::RecordSpectrumSpec rs;
    const std::size_t r = p["record"] == spec.records[0].name ? 0 : 1;
    rs.motion = spec.records[r].motion;
    rs.free_periods = spec.free_periods;
    rs.solver = spec.solver;
    rs.solver.friction_coefficient = f.cases[c].friction;
    rs.solver.kinetic_friction_coefficient = f.cases[c].kinetic_friction;
    const Body body(f.cases[c].body);
    if (p["kind"] == "found") {
      ++found;
      const double m = p["margin"].get<double>(), safe = p["safe_margin"].get<double>();
      EXPECT_TRUE(study::overturned(study::run_record_cell(body, rs, m * s).outcome));
      EXPECT_FALSE(study::overturned(study::run_record_cell(body, rs, safe * s).outcome));
      EXPECT_LE(m - safe, 0.02 * m * (1 + 1e-12));  // the stated resolution
    }
  }
  EXPECT_GT(found, 0) << "the test needs some IDA curve that overturns";
  // the smallest margin refined stays in its bracket, within the stated resolution
  const Json& ref = j["ida"]["refined"];
  EXPECT_TRUE(ref["within_coarse_bracket"].get<bool>());
  EXPECT_LE(std::abs(ref["relative_change"].get<double>()), 0.02);
  // the fragility is the fit of the IDA's capacity intervals
  for (std::size_t c = 0; c < f.cases.size(); ++c) {
    std::vector<study::CapacityInterval> caps;
    for (std::size_t r = 0; r < spec.records.size(); ++r) {
      const Json& p = j["ida"]["per"][c * spec.records.size() + r];
      if (p["kind"] == "found") {
        caps.push_back({p["safe_margin"].get<double>(), p["margin"].get<double>()});
      } else if (p["kind"] == "below_grid") {
        caps.push_back({0.0, p["margin"].get<double>()});
      } else {
        caps.push_back({4.0, std::numeric_limits<double>::infinity()});
      }
    }
    const Json& e = j["fragility"]["per_case"][c];
    try {
      const study::FragilityFit fit = study::fit_capacity_intervals(caps);
      EXPECT_EQ(e["theta"].get<double>(), fit.theta);
      EXPECT_EQ(e["beta"].get<double>(), fit.beta);
    } catch (const InputError& err) {
      EXPECT_EQ(e["error"].get<std::string>(), err.what());
    }
  }
  // the demands CSV: a row a run, the tilt in rad
  EXPECT_EQ(rep.demands_csv.substr(0, rep.demands_csv.find('\n')),
            ",1-ROT-0-1,1-SLD-0-1,1-IMF-0-1,1-UPL-0-1");
  // the validation checks cited are on the validation page, their agreement quoted as it is
  std::ifstream vin(std::string(FLEXROCK_SOURCE_DIR) + "/docs/validation.md");
  const std::string page((std::istreambuf_iterator<char>(vin)), std::istreambuf_iterator<char>());
  ASSERT_FALSE(j["validation"].empty());
  for (const Json& v : j["validation"]) {
    const std::string section =
        v["section"].get<std::string>().substr(std::string("docs/validation.md, ").size());
    EXPECT_NE(page.find("# " + section + "\n"), std::string::npos) << section;
    EXPECT_NE(page.find(v["agreement"].get<std::string>()), std::string::npos) << v["agreement"];
    EXPECT_TRUE(fs::exists(fs::path(FLEXROCK_SOURCE_DIR) / v["test"].get<std::string>()))
        << v["test"];
  }
  // the impact force's sensitivity: the estimate scales as 1 / impact_duration, and the
  // compliant contact's resolved force is there
  const Json& var = j["impact_sensitivity"]["variants"];
  ASSERT_EQ(var.size(), 6u);
  const double as_given = var[0]["impact_force_N"].get<double>();
  EXPECT_DOUBLE_EQ(var[3]["impact_force_N"].get<double>(), 2.0 * as_given);
  EXPECT_DOUBLE_EQ(var[4]["impact_force_N"].get<double>(), 0.5 * as_given);
  EXPECT_GT(var[5]["impact_force_N"].get<double>(), 0.0);
  // the work CSVs were written and the journals removed
  EXPECT_TRUE(fs::exists(dir_ / "runs" / "design.csv"));
  EXPECT_FALSE(fs::exists(dir_ / "runs" / "design.csv.partial"));
}

TEST_F(QualifyFiles, AFlexibleBodyIsBoundedByItsDampingAndCitesTheFlexibleChecks) {
  const QualifyFile f = load_qualify_file(qualification("[ranges]\ndamping_ratio = [0.01, 0.05]\n",
                                                        "", kFlexible, "[ida]\nenabled = false\n"));
  ASSERT_EQ(f.cases.size(), 2u);
  EXPECT_EQ(f.cases[0].name, "mu=inf zeta=0.01");
  for (const QualifyCase& c : f.cases) {
    const Body b(c.body);
    for (Eigen::Index i = 0; i < b.damping_ratios().size(); ++i)
      EXPECT_NEAR(b.damping_ratios()(i), *c.damping, 1e-12);
  }
  QualifySession session(f, (dir_ / "runs").string());
  EXPECT_EQ(session.ida_sessions(), 0u);
  session.run({});
  const Json j = Json::parse(session.finish().json);
  std::ifstream vin(std::string(FLEXROCK_SOURCE_DIR) + "/docs/validation.md");
  const std::string page((std::istreambuf_iterator<char>(vin)), std::istreambuf_iterator<char>());
  int flexible = 0;
  for (const Json& v : j["validation"]) {
    flexible += v["feature"] == "flexible";
    EXPECT_NE(page.find(v["agreement"].get<std::string>()), std::string::npos) << v["agreement"];
  }
  EXPECT_EQ(flexible, 2);
  EXPECT_TRUE(j["ida"]["min_margin"].is_null());
}

TEST_F(QualifyFiles, AStoppedQualificationResumesToTheSameReport) {
  const QualifyFile f = load_qualify_file(qualification("[ranges]\nfriction = [0.2, 0.6]\n"));
  std::string whole;
  {
    QualifySession s(f, (dir_ / "a").string());
    s.run({});
    whole = s.finish().json;
  }
  // stopped after a few runs, then opened again on the same directory
  std::atomic<bool> stop{false};
  std::atomic<std::size_t> done{0};
  {
    QualifySession s(f, (dir_ / "b").string());
    study::RunOptions o;
    o.threads = 1;
    o.cancel = &stop;
    o.completed = &done;
    std::jthread watch([&] {
      while (done.load() < 3 && !stop.load())
        std::this_thread::sleep_for(std::chrono::microseconds(50));
      stop.store(true);
    });
    s.run(o);
    stop.store(true);
  }
  QualifySession again(f, (dir_ / "b").string());
  EXPECT_GT(again.resumed(), 0u);
  again.run({});
  std::string resumed = again.finish().json;
  // the JSON names the work files' inputs, not the work directory: equal bytes
  EXPECT_EQ(resumed, whole);
}

}  // namespace
}  // namespace flexrock::io
