// SPDX-License-Identifier: BSD-3-Clause
// Case files: every body type and excitation kind loads to the right parameters, and each kind of
// bad input gives an InputError naming the file, the line and the key.
#include "flexrock/io/case_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <numbers>
#include <string>

#include "flexrock/core/error.hpp"
#include "flexrock/excitation/intensity.hpp"
#include "flexrock/excitation/pulses.hpp"
#include "flexrock/model/builders.hpp"
#include "support/expect_error.hpp"

namespace flexrock::io {
namespace {

namespace fs = std::filesystem;

const std::string kData = FLEXROCK_SOURCE_DIR "/../shared/data/";

// a rigid block and a short pulse: the smallest valid case
const std::string kBlock = R"(
[body]
type = "rigid_block"
width = 0.4
height = 2.0
mass = 100.0
)";
const std::string kPulse = R"(
[excitation.horizontal]
type = "one_sine"
amplitude = 0.3
units = "g"
period = 1.0
duration = 3.0
)";

class CaseFile : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           (std::string("flexrock_case_") + info->test_suite_name() + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& content) const {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << content;
    return p.string();
  }

  // expects load_case(file with `content`) to throw InputError holding every one of `parts`
  void expect_error(const std::string& content, std::initializer_list<std::string> parts) {
    const std::string path = write("case.toml", content);
    try {
      load_case(path);
    } catch (const InputError& e) {
      const std::string what = e.what();
      for (const std::string& p : parts) {
        EXPECT_NE(what.find(p), std::string::npos) << "message lacks \"" << p << "\": " << what;
      }
      return;
    }
    ADD_FAILURE() << "no InputError for:\n" << content;
  }

  fs::path dir_;
};

TEST(EditDistance, CountsEditsAndSuggestsTypos) {
  EXPECT_EQ(edit_distance("rtol", "rtol"), 0u);
  EXPECT_EQ(edit_distance("rtoll", "rtol"), 1u);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(closest_key("rtoll", {"atol", "rtol", "max_step"}), "rtol");
  EXPECT_EQ(closest_key("restitution", {"restitution_factor", "chatter_ratio"}),
            "restitution_factor");
  EXPECT_EQ(closest_key("zzzzzz", {"rtol", "atol"}), "");
}

TEST_F(CaseFile, MinimalCaseGetsDocumentedDefaults) {
  const Case c = load_case(write("block.toml", kBlock + kPulse));
  EXPECT_EQ(c.name, "block");
  EXPECT_EQ(c.stem, "block");
  EXPECT_EQ(c.body_type, "rigid_block");
  EXPECT_DOUBLE_EQ(c.body.mass, 100.0);
  EXPECT_DOUBLE_EQ(c.body.height, 1.0);
  EXPECT_DOUBLE_EQ(c.body.b1, 0.2);
  EXPECT_DOUBLE_EQ(c.motion.duration(), 3.0);
  EXPECT_NEAR(c.motion.at(0.25).x, 0.3 * kStandardGravity, 1e-12);
  EXPECT_EQ(c.output.time_history, "block.csv");
  EXPECT_EQ(c.output.summary, "block.summary.json");
  EXPECT_EQ(c.output.events, "");
  EXPECT_DOUBLE_EQ(c.options.output_dt, 0.01);
  EXPECT_DOUBLE_EQ(c.options.rtol, SimulationOptions{}.rtol);
  EXPECT_TRUE(std::isinf(c.options.friction_coefficient));
  EXPECT_EQ(c.options.overturn, OverturnCriterion::kHalfPi);
}

TEST_F(CaseFile, SolverInitialAndOutputTablesAreRead) {
  const Case c =
      load_case(write("full.toml", "name = \"x\"\ndescription = \"d\"\n" + kBlock + kPulse + R"(
[solver]
t_end = 2.5
rtol = 1e-8
atol = 1e-10
max_step = 0.005
event_samples = 6
overturn = "half_pi"
chatter_ratio = 0.02
restitution_factor = 0.9
friction_coefficient = 0.5
max_steps = 1000000
max_impacts = 500
[initial]
theta = 0.05
theta_dot = -0.1
[output]
dt = 0.02
time_history = "out/th.csv"
summary = "s.json"
events = "ev.csv"
)"));
  EXPECT_EQ(c.name, "x");
  EXPECT_EQ(c.description, "d");
  EXPECT_DOUBLE_EQ(c.options.t_end, 2.5);
  EXPECT_DOUBLE_EQ(c.options.rtol, 1e-8);
  EXPECT_DOUBLE_EQ(c.options.atol, 1e-10);
  EXPECT_DOUBLE_EQ(c.options.max_step, 0.005);
  EXPECT_EQ(c.options.event_samples, 6);
  EXPECT_EQ(c.options.overturn, OverturnCriterion::kHalfPi);
  EXPECT_DOUBLE_EQ(c.options.chatter_ratio, 0.02);
  EXPECT_DOUBLE_EQ(c.options.restitution_factor, 0.9);
  EXPECT_DOUBLE_EQ(c.options.friction_coefficient, 0.5);
  EXPECT_EQ(c.options.max_steps, 1000000);
  EXPECT_EQ(c.options.max_impacts, 500);
  EXPECT_DOUBLE_EQ(c.initial.theta, 0.05);
  EXPECT_DOUBLE_EQ(c.initial.theta_dot, -0.1);
  EXPECT_DOUBLE_EQ(c.options.output_dt, 0.02);
  EXPECT_EQ(c.output.time_history, "out/th.csv");
  EXPECT_EQ(c.output.summary, "s.json");
  EXPECT_EQ(c.output.events, "ev.csv");
}

TEST_F(CaseFile, EveryBodyTypeMatchesItsBuilder) {
  auto body = [&](const std::string& table) {
    return load_case(write("b.toml", "[body]\n" + table + kPulse)).body;
  };
  const BodyParameters rb = body(
      "type = \"rigid_body\"\nmass = 300\ninertia_cg = 108\n"
      "height = 0.9\nb1 = 0.2\nb2 = 0.35\n");
  const BodyParameters rb_ref = rigid_body(300, 108, 0.9, 0.2, 0.35);
  EXPECT_DOUBLE_EQ(rb.zeta2, rb_ref.zeta2);
  EXPECT_DOUBLE_EQ(rb.b2, 0.35);

  const BodyParameters os = body(
      "type = \"oscillator_on_slab\"\ntop_mass = 1000\nfrequency_hz = 2\nbase_mass = 500\n"
      "height = 3\nbase_width = 1.5\ndamping_ratio = 0.05\n");
  const BodyParameters os_ref = oscillator_on_slab(1000, 2, 500, 3, 1.5, 0.05);
  ASSERT_EQ(os.kappa.rows(), 1);
  EXPECT_DOUBLE_EQ(os.kappa(0, 0), os_ref.kappa(0, 0));
  EXPECT_DOUBLE_EQ(os.psi_x(0), os_ref.psi_x(0));

  const BodyParameters uc = body(
      "type = \"uniform_cantilever\"\nheight = 6\nwidth = 2\nmass_per_length = 2000\n"
      "bending_stiffness = 7.5e7\nmodes = 2\nbase_mass = 2000\ndamping_ratio = 0.02\n");
  const BodyParameters uc_ref = uniform_cantilever(6, 2, 2000, 7.5e7, 2, 2000, 0.02);
  ASSERT_EQ(uc.mu.rows(), 2);
  EXPECT_TRUE(uc.mu.isApprox(uc_ref.mu));
  EXPECT_TRUE(uc.kappa.isApprox(uc_ref.kappa));

  // the same body taken rigid keeps M, h, b1, b2 and zeta2 and drops the modes
  const Case rigid = load_case(
      write("r.toml",
            "[body]\ntype = \"uniform_cantilever\"\nheight = 6\nwidth = 2\n"
            "mass_per_length = 2000\nbending_stiffness = 7.5e7\nmodes = 2\nrigid = true\n" +
                kPulse));
  EXPECT_TRUE(rigid.rigid);
  EXPECT_EQ(rigid.body.mu.rows(), 0);
  EXPECT_DOUBLE_EQ(rigid.body.zeta2, uniform_cantilever(6, 2, 2000, 7.5e7, 2).zeta2);

  const BodyParameters pp = body(
      "type = \"paper\"\nmass = 10\nheight = 1\nb1 = 0.3\nb2 = 0.3\nzeta2 = 0.4\n"
      "mu = [[0.5]]\nkappa = [[20.0]]\npsi_x = [0.4]\nbeta = [-0.1]\ndamping_ratios = [0.05]\n");
  ASSERT_EQ(pp.mu.rows(), 1);
  EXPECT_DOUBLE_EQ(pp.kappa(0, 0), 20.0);
  EXPECT_DOUBLE_EQ(pp.psi_x(0), 0.4);
  EXPECT_DOUBLE_EQ(pp.psi_y(0), 0.0);
  EXPECT_EQ(pp.damping.kind, DampingKind::kModal);
}

// a two-node lumped model: base nodes on the tipping points, one top mass swaying
const std::string kLumped = R"(
[body]
type = "lumped"
tip1_x = -0.5
tip2_x = 0.5
nodes = [[-0.5, 0.0, 100.0], [0.5, 0.0, 100.0], [0.0, 2.0, 500.0, 10.0]]
frequencies_hz = [2.0]
phi_x = [[0.0], [0.0], [1.0]]
phi_y = [[0.0], [0.0], [0.0]]
)";

TEST_F(CaseFile, LumpedModelInlineAndFromCsvAgree) {
  const BodyParameters inline_p = load_case(write("l.toml", kLumped + kPulse)).body;
  write("nodes.csv", "x,y,mass,rotary_inertia\n-0.5,0,100,0\n0.5,0,100,0\n0,2,500,10\n");
  write("shapes.csv", "# mode 1\nphi_x_1,phi_y_1\n0,0\n0,0\n1,0\n");
  const BodyParameters csv_p = load_case(write("c.toml", R"(
[body]
type = "lumped"
tip1_x = -0.5
tip2_x = 0.5
nodes_file = "nodes.csv"
frequencies_hz = [2.0]
shapes_file = "shapes.csv"
)" + kPulse))
                                   .body;
  ASSERT_EQ(inline_p.mu.rows(), 1);
  EXPECT_TRUE(inline_p.mu.isApprox(csv_p.mu));
  EXPECT_TRUE(inline_p.kappa.isApprox(csv_p.kappa));
  EXPECT_DOUBLE_EQ(inline_p.zeta2, csv_p.zeta2);
}

TEST_F(CaseFile, RecordsResolveRelativeToTheCaseFile) {
  const std::string rel = fs::relative(kData, dir_).string();
  const Case c = load_case(write("r.toml", kBlock + R"(
[excitation]
scale = 0.5
[excitation.horizontal]
type = "record"
file = ")" + rel + R"(/elcentro_1940_ns.dat"
format = "single_column"
dt = 0.02
units = "g"
[excitation.vertical]
type = "record"
file = ")" + rel + R"(/kobe_1995_nishi_akashi_090.AT2"
scale = 0.5
)"));
  EXPECT_TRUE(c.motion.is_sampled());
  EXPECT_TRUE(c.motion.has_vertical());
  EXPECT_EQ(c.horizontal.format, "single_column");
  EXPECT_EQ(c.vertical.format, "at2");
  // El Centro's peak 0.3188 g at 2.02 s, halved
  EXPECT_NEAR(std::abs(c.motion.at(2.02).x), 0.5 * 0.3188 * kStandardGravity, 2e-3);
}

// a case with the Kobe record horizontal and `excitation` keys
std::string kobe_case(const std::string& rel, const std::string& excitation) {
  return kBlock + "[excitation]\n" + excitation + R"(
[excitation.horizontal]
type = "record"
file = ")" +
         rel + R"(/kobe_1995_nishi_akashi_090.AT2"
scale = 2.0
)";
}

TEST_F(CaseFile, RecordsScaleToATargetPgaPgvOrSa) {
  const std::string rel = fs::relative(kData, dir_).string();
  const double g = kStandardGravity;
  // the file's own intensity is reported before any factor
  const Case plain = load_case(write("p.toml", kobe_case(rel, "")));
  EXPECT_GT(plain.horizontal.pga, 0.0);
  EXPECT_GT(plain.horizontal.pgv, 0.0);
  EXPECT_GT(plain.horizontal.duration, 10.0);
  EXPECT_GT(plain.horizontal.dt, 0.0);
  EXPECT_DOUBLE_EQ(plain.excitation_scale, 1.0);

  // PGA: the scaled motion's largest sample is the target (the component's scale included)
  const Case a = load_case(write("a.toml", kobe_case(rel, "target_pga = 0.5")));
  EXPECT_NEAR(a.excitation_scale * 2.0 * a.horizontal.pga, 0.5 * g, 1e-12);
  const auto& times = a.motion.times();
  double peak = 0.0;
  for (double t : times) peak = std::max(peak, std::abs(a.motion.at(t).x));
  EXPECT_NEAR(peak, 0.5 * g, 1e-9);
  EXPECT_EQ(a.scaled_to, "PGA 0.5 g");

  // PGV and Sa: linear in the factor
  const Case v = load_case(write("v.toml", kobe_case(rel, "target_pgv = 0.8")));
  EXPECT_NEAR(v.excitation_scale * 2.0 * v.horizontal.pgv, 0.8, 1e-12);
  const Case s = load_case(write("s.toml", kobe_case(rel, "target_sa = 1.2\nsa_period = 0.3")));
  std::vector<double> acc;
  for (double t : s.motion.times()) acc.push_back(s.motion.at(t).x);
  EXPECT_NEAR(spectral_acceleration(s.motion.times(), acc, 0.3, 0.05), 1.2 * g, 1e-9 * g);
  EXPECT_EQ(s.scaled_to, "Sa(0.3 s, 5 %) 1.2 g");
}

TEST_F(CaseFile, TargetScalingMistakesAreRejected) {
  const std::string rel = fs::relative(kData, dir_).string();
  expect_error(kobe_case(rel, "target_pga = 0.5\ntarget_pgv = 0.3"),
               {"case.toml:", "target_pga", "got several"});
  expect_error(kobe_case(rel, "scale = 2\ntarget_pga = 0.5"),
               {"case.toml:8:", "'excitation.scale'", "either scale or target_pga"});
  expect_error(kobe_case(rel, "target_sa = 0.5"), {"'excitation.sa_period'", "missing"});
  expect_error(kobe_case(rel, "sa_period = 0.5"),
               {"'excitation.sa_period'", "only with target_sa"});
  expect_error(kobe_case(rel, "target_pga = -1"), {"'excitation.target_pga'", "> 0"});
  expect_error(kBlock + "[excitation]\ntarget_pga = 0.5\n" + kPulse,
               {"'excitation.target_pga'", "type \"record\"", "got \"one_sine\""});
}

TEST_F(CaseFile, RecordWithSyntheticVerticalCombines) {
  const std::string rel = fs::relative(kData, dir_).string();
  const Case c = load_case(write("r.toml", kBlock + R"(
[excitation.horizontal]
type = "record"
file = ")" + rel + R"(/kobe_1995_nishi_akashi_090.AT2"
[excitation.vertical]
type = "rectangular"
amplitude = -2.0
units = "m/s^2"
length = 1.0
duration = 50.0
)"));
  EXPECT_DOUBLE_EQ(c.motion.duration(), 50.0);
  EXPECT_DOUBLE_EQ(c.motion.at(0.5).y, -2.0);
  EXPECT_DOUBLE_EQ(c.motion.at(2.0).y, 0.0);
  EXPECT_NE(c.motion.at(7.09).x, 0.0);
}

// two pulses on the two components stay described as sinusoids (a rigid body's rocking series
// expands them), scaled with the motion; a record with a pulse is not so described
TEST_F(CaseFile, TwoPulsesCombineIntoSinusoids) {
  const Case c = load_case(write("two.toml", kBlock + R"(
[excitation]
scale = 1.5
[excitation.horizontal]
type = "one_sine"
amplitude = 2.0
units = "m/s^2"
period = 0.8
duration = 5.0
[excitation.vertical]
type = "harmonic"
amplitude = 1.0
units = "m/s^2"
frequency_hz = 3.0
cycles = 2
phase = 0.7
duration = 5.0
)"));
  ASSERT_TRUE(c.motion.is_sinusoidal());
  ASSERT_EQ(c.motion.sinusoids().size(), 2u);
  for (double t = 0.0; t < 5.0; t += 0.0137) {
    BaseAcceleration sum;
    for (const SinusoidPiece& p : c.motion.sinusoids()) {
      if (p.begin <= t && t < p.end)
        (p.vertical ? sum.y : sum.x) += p.amplitude * std::sin(p.omega * t + p.phase);
    }
    EXPECT_NEAR(sum.x, c.motion.at(t).x, 1e-14) << t;
    EXPECT_NEAR(sum.y, c.motion.at(t).y, 1e-14) << t;
  }
  EXPECT_NEAR(c.motion.at(0.2).x, 1.5 * 2.0, 1e-14);  // the peak of the one-sine pulse, scaled
  const std::string rel = fs::relative(kData, dir_).string();
  const Case r = load_case(write("r.toml", kBlock + R"(
[excitation.horizontal]
type = "record"
file = ")" + rel + R"(/kobe_1995_nishi_akashi_090.AT2"
[excitation.vertical]
type = "harmonic"
amplitude = 1.0
units = "m/s^2"
frequency_hz = 3.0
duration = 50.0
)"));
  EXPECT_FALSE(r.motion.is_sinusoidal());
}

TEST_F(CaseFile, SyntheticMotionsOfEveryKindLoad) {
  for (const std::string spec :
       {"type = \"harmonic\"\nfrequency_hz = 2\n",
        "type = \"harmonic\"\nperiod = 0.5\ncycles = 3\n", "type = \"half_sine\"\nperiod = 1\n",
        "type = \"cycloidal_a\"\nperiod = 1\n", "type = \"cycloidal_b\"\nperiod = 1\n",
        "type = \"cycloidal_c\"\nperiod = 1\nn = 2\n",
        "type = \"ricker\"\nfrequency_hz = 1\ncenter = 2\n",
        "type = \"rectangular\"\nlength = 0.3\n"}) {
    const Case c = load_case(write("s.toml", kBlock + "[excitation.horizontal]\n" + spec +
                                                 "amplitude = 100\nunits = \"cm/s^2\"\n"
                                                 "duration = 5\n"));
    EXPECT_DOUBLE_EQ(c.motion.duration(), 5.0) << spec;
    EXPECT_EQ(c.horizontal.amplitude, 1.0) << spec;
  }
}

// ---------------------------------------------------------------------------------------------
// bad input: one test for each kind, each checking file, line and key

TEST_F(CaseFile, TomlSyntaxErrorNamesFileLineAndColumn) {
  expect_error(kBlock + "[excitation.horizontal\n", {"case.toml:7:", "TOML syntax error"});
}

TEST_F(CaseFile, MissingKeyNamesTableLine) {
  expect_error("[body]\ntype = \"rigid_block\"\nwidth = 0.4\nmass = 100\n" + kPulse,
               {"case.toml:1:", "key 'body.height'", "missing", "[m]"});
}

TEST_F(CaseFile, MisspeltRequiredKeyIsNamedRatherThanMissing) {
  // "widht" instead of "width": the typo is the cause, so it is what the message names
  expect_error("[body]\ntype = \"rigid_block\"\nwidht = 0.4\nheight = 1.8\nmass = 100\n" + kPulse,
               {"case.toml:3:", "key 'body.widht'", "unknown key", "did you mean 'body.width'",
                "is required"});
}

TEST_F(CaseFile, MissingTableIsNamed) {
  expect_error(kBlock, {"case.toml", "[excitation]", "missing"});
}

TEST_F(CaseFile, UnknownKeySuggestsTheClosest) {
  expect_error(
      kBlock + kPulse + "[solver]\nrtoll = 1e-8\n",
      {"case.toml:15:", "key 'solver.rtoll'", "unknown key", "did you mean 'solver.rtol'"});
  expect_error(kBlock + "widht = 1\n" + kPulse,
               {"case.toml:7:", "key 'body.widht'", "did you mean 'body.width'"});
}

TEST_F(CaseFile, UnknownChoiceSuggestsTheClosest) {
  expect_error("[body]\ntype = \"rigid_blok\"\n" + kPulse,
               {"case.toml:2:", "key 'body.type'", "did you mean \"rigid_block\""});
}

TEST_F(CaseFile, WrongTypeSaysExpectedAndGot) {
  expect_error("[body]\ntype = \"rigid_block\"\nwidth = \"wide\"\nheight = 2\nmass = 1\n" + kPulse,
               {"case.toml:3:", "key 'body.width'", "expected a number > 0 [m]", "got \"wide\""});
}

TEST_F(CaseFile, ErrorCarriesFileLineAndKeyAsFields) {
  const std::string path = write(
      "case.toml", "[body]\ntype = \"rigid_block\"\nwidth = -0.4\nheight = 2\nmass = 1\n" + kPulse);
  try {
    load_case(path);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.line(), 3u);
    EXPECT_EQ(e.key(), "body.width");
    EXPECT_EQ(e.detail(), "expected a number > 0 [m], got -0.4");
    // the message is built from the fields
    EXPECT_EQ(std::string(e.what()), path + ":3: key 'body.width': " + e.detail());
  }
  // a pulse function's own check is placed at the component's table
  const std::string late = write("late.toml", kBlock + R"(
[excitation.horizontal]
type = "one_sine"
amplitude = 0.3
units = "g"
period = 2.0
duration = 1.0
)");
  try {
    load_case(late);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), late);
    EXPECT_EQ(e.line(), 8u);
    EXPECT_NE(e.detail().find("one_sine_pulse: argument 'duration' = 1 s"), std::string::npos)
        << e.what();
  }
}

TEST_F(CaseFile, EveryPulseTypeOfTheTableLoads) {
  // the loader reads each type's keys from the table: a case of every type with its required
  // keys loads, and its motion is the one make_pulse gives with the table's defaults
  for (const PulseKind& k : pulse_kinds()) {
    std::string keys;
    PulseArgs args{
        0.3 * 9.80665, k.frequency ? 2.0 * std::numbers::pi : 0.0, 5.0, Component::kHorizontal, {}};
    for (const PulseKey& key : k.keys) {
      if (!key.required) continue;
      keys += std::string(key.name) + " = 0.5\n";
      args.keys.emplace(key.name, 0.5);
    }
    const std::string path = write(std::string(k.name) + ".toml",
                                   kBlock + "[excitation.horizontal]\ntype = \"" + k.name +
                                       "\"\namplitude = 0.3\nunits = \"g\"\nduration = 5.0\n" +
                                       (k.frequency ? "frequency_hz = 1.0\n" : "") + keys);
    const Case c = load_case(path);
    EXPECT_EQ(c.horizontal.type, k.name);
    const GroundMotion expected = make_pulse(k, args);
    for (const double t : {0.05, 0.3, 0.71, 1.9, 4.2}) {
      EXPECT_EQ(c.motion.at(t).x, expected.at(t).x) << k.name << " at t = " << t;
    }
  }
  test::expect_input_error([] { pulse_kind("one-sine"); }, {"one_sine", "rectangular", "one-sine"});
  test::expect_input_error(
      [] {
        make_pulse(pulse_kind("one_sine"), {1.0, 1.0, 10.0, Component::kHorizontal, {{"n", 2.0}}});
      },
      {"one_sine: unknown key 'n'", "none"});
}

TEST_F(CaseFile, EveryBodyTypeOfTheTableLoads) {
  // the loader reads the keys of a body type with a builder from the table: a case of every such
  // type with its required keys loads to the body make_body gives with the table's defaults
  int built = 0;
  for (const BodyKind& k : body_kinds()) {
    if (!k.make) continue;
    std::string keys;
    BodyArgs args;
    double v = 1.5;
    for (const BodyKey& key : k.keys) {
      if (!key.required) continue;
      keys += std::string(key.name) + " = " + std::to_string(v) + "\n";
      args.keys.emplace(key.name, v);
      v += 0.25;
    }
    const std::string path =
        write(std::string(k.name) + ".toml",
              "[body]\ntype = \"" + std::string(k.name) + "\"\n" + keys + kPulse);
    const Case c = load_case(path);
    EXPECT_EQ(c.body_type, k.name);
    const BodyParameters expected = make_body(k, args);
    EXPECT_EQ(c.body.mass, expected.mass) << k.name;
    EXPECT_EQ(c.body.height, expected.height) << k.name;
    EXPECT_EQ(c.body.zeta2, expected.zeta2) << k.name;
    EXPECT_EQ(c.body.kappa, expected.kappa) << k.name;
    // what `flexrock check` prints: every number key, the defaults marked
    ASSERT_EQ(c.body_keys.size(), k.keys.size()) << k.name;
    for (std::size_t i = 0; i < k.keys.size(); ++i) {
      EXPECT_EQ(c.body_keys[i].name, k.keys[i].name);
      EXPECT_EQ(c.body_keys[i].unit, k.keys[i].unit);
      EXPECT_EQ(c.body_keys[i].given, k.keys[i].required);
    }
    ++built;
  }
  EXPECT_GE(built, 4);
  // an unknown type names the file, the line, the key and every type of the table
  std::vector<std::string> want = {"case.toml:3:", "key 'body.type'", "sphere"};
  for (const std::string& n : body_kind_names()) want.push_back(n);
  const std::string bad =
      write("case.toml", "[body]\nrigid = false\ntype = \"sphere\"\nwidth = 1\n" + kPulse);
  try {
    load_case(bad);
    ADD_FAILURE() << "an unknown body type loaded";
  } catch (const InputError& e) {
    for (const std::string& p : want)
      EXPECT_NE(std::string(e.what()).find(p), std::string::npos) << e.what();
  }
  // and so does an unknown key of a type (with the closest one)
  expect_error("[body]\ntype = \"rigid_block\"\nwidth = 0.4\nheight = 2\nmas = 1\n" + kPulse,
               {"case.toml:5:", "mas", "mass"});
  test::expect_input_error([] { body_kind("sphere"); }, {"rigid_block", "lumped", "sphere"});
  test::expect_input_error(
      [] {
        make_body(body_kind("rigid_block"), {{{"width", 1.0}}});
      },
      {"rigid_block", "height", "missing"});
  test::expect_input_error(
      [] {
        make_body(body_kind("uniform_cantilever"), {{{"height", 10.0},
                                                     {"width", 3.0},
                                                     {"mass_per_length", 2000.0},
                                                     {"bending_stiffness", 5e9},
                                                     {"modes", 1.5}}});
      },
      {"uniform_cantilever", "modes", "integer >= 1", "1.5"});
  test::expect_input_error([] { make_body(body_kind("paper"), {}); }, {"paper", "not all numbers"});
}

TEST_F(CaseFile, NegativeOrZeroSizeIsRejected) {
  expect_error("[body]\ntype = \"rigid_block\"\nwidth = -0.4\nheight = 2\nmass = 1\n" + kPulse,
               {"case.toml:3:", "key 'body.width'", "expected a number > 0", "got -0.4"});
  expect_error("[body]\ntype = \"rigid_block\"\nwidth = 0.4\nheight = 2\nmass = 0\n" + kPulse,
               {"case.toml:5:", "key 'body.mass'", "got 0"});
}

TEST_F(CaseFile, NanAndInfAreRejected) {
  expect_error("[body]\ntype = \"rigid_block\"\nwidth = nan\nheight = 2\nmass = 1\n" + kPulse,
               {"case.toml:3:", "key 'body.width'", "finite", "got nan"});
  expect_error(kBlock + kPulse + "[solver]\nrtol = inf\n", {"case.toml:15:", "solver.rtol"});
}

TEST_F(CaseFile, NanInRecordNamesTheRecordLine) {
  write("bad.dat", "0.1\n0.2\nnan\n0.3\n");
  expect_error(kBlock + R"(
[excitation.horizontal]
type = "record"
file = "bad.dat"
format = "single_column"
dt = 0.01
units = "g"
)",
               {"bad.dat:3:", "excitation.horizontal.file", "case.toml:10"});
}

TEST_F(CaseFile, NonIncreasingTimesAreRejected) {
  write("t.csv", "time,acc\n0.0,0.1\n0.1,0.2\n0.1,0.3\n");
  expect_error(kBlock + R"(
[excitation.horizontal]
type = "record"
file = "t.csv"
format = "time_series"
units = "m/s^2"
)",
               {"t.csv:4:", "increas"});
}

TEST_F(CaseFile, MalformedAt2IsRejected) {
  write("m.AT2",
        "PEER NGA STRONG MOTION DATABASE RECORD\nX\nACCELERATION IN UNITS OF G\n"
        "NPTS, DT\n0.1 0.2\n");
  expect_error(kBlock + "[excitation.horizontal]\ntype = \"record\"\nfile = \"m.AT2\"\n",
               {"m.AT2:4:", "NPTS", "excitation.horizontal.file"});
}

TEST_F(CaseFile, TruncatedAt2IsRejected) {
  write("t.AT2",
        "PEER NGA STRONG MOTION DATABASE RECORD\nX\nACCELERATION IN UNITS OF G\n"
        "5 0.01 NPTS, DT\n0.1 0.2 0.3\n");
  expect_error(kBlock + "[excitation.horizontal]\ntype = \"record\"\nfile = \"t.AT2\"\n",
               {"t.AT2", "5", "excitation.horizontal.file"});
}

TEST_F(CaseFile, MissingRecordUnitsAreRequired) {
  expect_error(kBlock +
                   "[excitation.horizontal]\ntype = \"record\"\nfile = \"x.dat\"\n"
                   "format = \"single_column\"\ndt = 0.01\n",
               {"case.toml:7:", "excitation.horizontal.units", "missing"});
}

TEST_F(CaseFile, ModalMassNotPositiveDefiniteIsRejected) {
  expect_error(
      "[body]\ntype = \"paper\"\nmass = 10\nheight = 1\nb1 = 0.3\nb2 = 0.3\nzeta2 = 0.4\n"
      "mu = [[1.0, 2.0], [2.0, 1.0]]\nkappa = [[20.0, 0.0], [0.0, 30.0]]\n" +
          kPulse,
      {"case.toml:1:", "[body]", "mu", "positive definite"});
}

TEST_F(CaseFile, ModeShapesMustVanishAtTheTippingPoints) {
  std::string bad = kLumped;
  bad.replace(bad.find("phi_x = [[0.0], [0.0]"), 21, "phi_x = [[0.2], [0.0]");
  expect_error(bad + kPulse, {"case.toml:2:", "[body]", "tipping point"});
}

TEST_F(CaseFile, BodyKeysOfAnotherTypeAreUnknown) {
  expect_error(kBlock + "b1 = 0.2\n" + kPulse,
               {"case.toml:7:", "key 'body.b1'", "unknown key for body type 'rigid_block'"});
}

TEST_F(CaseFile, InitialTiltPastOverturningIsRejected) {
  expect_error(kBlock + kPulse + "[initial]\ntheta = 1.6\n",
               {"case.toml:15:", "key 'initial.theta'", "overturning angle"});
}

TEST_F(CaseFile, InitialModalStateMustMatchTheModes) {
  expect_error(kBlock + kPulse + "[initial]\nq = [0.1]\n",
               {"case.toml:15:", "key 'initial.q'", "expected 0 values"});
}

TEST_F(CaseFile, SyntheticNeedsUnitsAndOneFrequency) {
  expect_error(kBlock +
                   "[excitation.horizontal]\ntype = \"one_sine\"\namplitude = 1\n"
                   "units = \"g\"\nfrequency_hz = 1\nperiod = 1\nduration = 2\n",
               {"case.toml:7:", "exactly one of 'frequency_hz'"});
  expect_error(kBlock +
                   "[excitation.horizontal]\ntype = \"one_sine\"\namplitude = 1\n"
                   "units = \"gee\"\nperiod = 1\nduration = 2\n",
               {"case.toml:10:", "excitation.horizontal.units", "did you mean \"g\""});
}

TEST_F(CaseFile, LoadBodyReadsOnlyTheBodyTable) {
  std::string type;
  const BodyParameters p = load_body(write("body.toml", kBlock), &type);
  EXPECT_EQ(type, "rigid_block");
  EXPECT_DOUBLE_EQ(p.mass, 100.0);
}

TEST_F(CaseFile, CompliantContactRefusesTheImpactLawsKeys) {
  // keys the compliant contact would ignore are refused with the file's line; a tangential
  // stiffness of 0 is refused (omitting it gives the default)
  const std::string compliant =
      "[solver]\ncontact_model = \"compliant\"\ncontact_stiffness = 1e8\n";
  for (const char* key :
       {"impact_law = \"rigid_body\"", "restitution_factor = 0.9", "impact_duration = 0.004"}) {
    const std::string line = key;
    expect_error(kBlock + kPulse + compliant + line + "\n",
                 {line.substr(0, line.find(' ')), "contact_model = \"impulsive\"", "case.toml"});
  }
  expect_error(kBlock + kPulse + compliant + "contact_tangential_stiffness = 0\n",
               {"contact_tangential_stiffness", "omit it for the default"});
  EXPECT_LT(
      load_case(write("ok.toml", kBlock + kPulse + compliant)).options.contact_tangential_stiffness,
      0.0);
}

}  // namespace
}  // namespace flexrock::io
