// SPDX-License-Identifier: BSD-3-Clause
// Adversarial inputs: each either is refused with a clear error (the message is checked) or runs
// to a correct finish with its status. None may crash or hang: ctest gives this executable a
// TIMEOUT, so a hang fails (docs/reliability.md lists every case and its outcome).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "flexrock/core/error.hpp"
#include "flexrock/excitation/ground_motion.hpp"
#include "flexrock/excitation/pulses.hpp"
#include "flexrock/io/case_file.hpp"
#include "flexrock/io/records.hpp"
#include "flexrock/model/body.hpp"
#include "flexrock/model/builders.hpp"
#include "flexrock/sim/simulate.hpp"
#include "support/expect_error.hpp"

namespace flexrock {
namespace {

namespace fs = std::filesystem;
using test::expect_input_error;

constexpr double kPi = 3.14159265358979323846;
constexpr double kG = kStandardGravity;

class Adversarial : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("flexrock_adversarial_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) const {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }
  fs::path dir_;
};

// every number a result holds is finite, and the energy balance closes
void expect_sound(const SimulationResult& r) {
  EXPECT_TRUE(std::isfinite(r.t_end));
  EXPECT_TRUE(std::isfinite(r.final_theta) && std::isfinite(r.final_theta_dot));
  EXPECT_TRUE(r.final_q.allFinite() && r.final_q_dot.allFinite());
  EXPECT_TRUE(std::isfinite(r.energy.residual) && std::isfinite(r.energy.scale));
  EXPECT_LE(std::abs(r.energy.residual), 1e-5 * r.energy.scale) << "residual " << r.energy.residual;
  EXPECT_FALSE(r.impact_gained_energy);
}

const char* kAt2Head =
    "PEER NGA STRONG MOTION DATABASE RECORD\nEVENT\nACCELERATION TIME HISTORY IN UNITS OF G\n";

// --- records ------------------------------------------------------------------------------

TEST_F(Adversarial, EmptyRecordFilesAreRefusedNamingTheFile) {
  const std::string at2 = write("empty.at2", "");
  expect_input_error([&] { io::read_at2(at2); }, {at2 + ":1:", "empty file"});
  const std::string txt = write("empty.txt", "\n\n");
  expect_input_error([&] { io::read_single_column(txt, 0.01, io::AccelUnit::kG); },
                     {txt + ":1:", "empty file"});
  const std::string csv = write("empty.csv", "");
  expect_input_error([&] { io::read_time_series(csv, io::AccelUnit::kG); }, {csv, "empty"});
  const std::string zero = write("zero.at2", std::string(kAt2Head) + "NPTS= 0, DT= .01 SEC\n");
  expect_input_error([&] { io::read_at2(zero); }, {zero + ":4:", "NPTS"});
}

TEST_F(Adversarial, DevicesAndDirectoriesAreRefusedInsteadOfReadForever) {
  // /dev/zero never ends: reading it would hang and exhaust memory
  expect_input_error([] { io::read_at2("/dev/zero"); }, {"/dev/zero", "device"});
  expect_input_error([] { io::read_single_column("/dev/zero", 0.01, io::AccelUnit::kG); },
                     {"/dev/zero", "device"});
  expect_input_error([] { io::read_time_series("/dev/zero", io::AccelUnit::kG); },
                     {"/dev/zero", "device"});
  expect_input_error([] { (void)io::load_case("/dev/zero"); }, {"/dev/zero", "device"});
  expect_input_error([&] { io::read_at2(dir_.string()); }, {dir_.string(), "directory"});
  const std::string c = write("dev.toml",
                              "[body]\ntype = \"rigid_block\"\nwidth = 0.4\nheight = 2.0\n"
                              "mass = 100.0\n[excitation.horizontal]\ntype = \"record\"\n"
                              "file = \"/dev/zero\"\nformat = \"single_column\"\ndt = 0.01\n"
                              "units = \"g\"\n");
  expect_input_error([&] { (void)io::load_case(c); }, {"/dev/zero", "device", "dev.toml:8"});
  const std::string n = write("nodes.toml",
                              "[body]\ntype = \"lumped\"\nnodes_file = \"/dev/zero\"\n"
                              "tip1_x = -0.5\ntip2_x = 0.5\n");
  expect_input_error([&] { (void)io::load_body(n); }, {"/dev/zero", "device"});
}

TEST_F(Adversarial, OneSampleRecordIsReadButIsNoGroundMotion) {
  const std::string at2 = write("one.at2", std::string(kAt2Head) + "NPTS= 1, DT= .01 SEC\n0.1\n");
  const io::Record r = io::read_at2(at2);
  ASSERT_EQ(r.npts(), 1U);
  expect_input_error([&] { (void)r.to_motion(); }, {at2, "at least 2 samples", "got 1"});
  expect_input_error([&] { (void)io::combine(r, nullptr); }, {at2, "at least 2 samples"});
  // a case naming it says which key and which file
  const std::string c = write("one.toml",
                              "[body]\ntype = \"rigid_block\"\nwidth = 0.4\nheight = 2.0\n"
                              "mass = 100.0\n[excitation.horizontal]\ntype = \"record\"\n"
                              "file = \"one.at2\"\n");
  expect_input_error([&] { (void)io::load_case(c); }, {"one.toml", "file", "2 samples"});
  expect_input_error([&] { (void)GroundMotion::sampled({0.0}, {1.0}); },
                     {"at least 2 samples", "got 1"});
}

TEST_F(Adversarial, HugeDtWhoseTimesOverflowIsRefused) {
  const std::string txt = write("huge.txt", "0.1 0.2 0.3\n");
  expect_input_error([&] { io::read_single_column(txt, 1e308, io::AccelUnit::kG); },
                     {txt, "dt", "1e+308"});
  const std::string at2 =
      write("huge.at2", std::string(kAt2Head) + "NPTS= 3, DT= 1e308 SEC\n0.1 0.2 0.3\n");
  expect_input_error([&] { io::read_at2(at2); }, {at2, "DT"});
}

TEST_F(Adversarial, HugeDtThatFitsRunsToTheEndOfTheRecord) {
  // three samples 1000 s apart: a slow ramp far below uplift; the run ends at the last sample
  const std::string txt = write("slow.txt", "0.0 0.001 0.0\n");
  const GroundMotion m = io::read_single_column(txt, 1000.0, io::AccelUnit::kG).to_motion();
  const Body body(rigid_block(0.4, 2.0, 100.0));
  const SimulationResult r = simulate(body, m);
  EXPECT_EQ(r.status, Status::kCompleted) << r.message;
  EXPECT_DOUBLE_EQ(r.t_end, 2000.0);
  EXPECT_TRUE(r.events.empty());
  expect_sound(r);
}

TEST_F(Adversarial, HugeNptsInAShortFileFailsOnTheCountWithoutAGiantAllocation) {
  const std::string at2 =
      write("npts.at2", std::string(kAt2Head) + "NPTS= 99999999, DT= .01 SEC\n0.1 0.2\n");
  expect_input_error([&] { io::read_at2(at2); },
                     {at2, "expected NPTS = 99999999 values", "got only 2"});
  const std::string over =
      write("over.at2", std::string(kAt2Head) + "NPTS= 1000000000, DT= .01 SEC\n0.1\n");
  expect_input_error([&] { io::read_at2(over); }, {over + ":4:", "at most 1e8"});
}

TEST_F(Adversarial, TenMillionSamplesAreReadAndRun) {
  // 10^7 samples of a small sine every 1 ms (10^4 s): read, convert, then simulate its first 20 s
  constexpr std::size_t kSamples = 10'000'000;
  const fs::path p = dir_ / "long.txt";
  {
    std::ofstream out(p);
    for (std::size_t i = 0; i < kSamples; ++i) out << (i % 2 == 0 ? "0.01\n" : "-0.01\n");
  }
  const io::Record rec = io::read_single_column(p.string(), 0.001, io::AccelUnit::kG);
  ASSERT_EQ(rec.npts(), kSamples);
  EXPECT_DOUBLE_EQ(rec.duration(), 9999.999);
  const GroundMotion m = rec.to_motion();
  ASSERT_EQ(m.samples(), kSamples);
  const Body body(rigid_block(0.4, 2.0, 100.0));
  SimulationOptions opt;
  opt.t_end = 20.0;
  const SimulationResult r = simulate(body, m, {}, opt);
  EXPECT_EQ(r.status, Status::kCompleted) << r.message;
  EXPECT_DOUBLE_EQ(r.t_end, 20.0);
  expect_sound(r);
}

// --- extreme motions and bodies -----------------------------------------------------------------

TEST(AdversarialMotion, HundredGHorizontalPulseLiftsABlockIntoFlight) {
  // the block uplifts at once; rocking that fast needs the floor to pull: it leaves the floor
  // (or, where it could only do so by sliding, the pivot is flagged) and the run goes on to an
  // answer
  const Body body(rigid_block(0.4, 2.0, 100.0));
  const SimulationResult r = simulate(body, one_sine_pulse(100 * kG, 2 * kPi * 2.0, 2.0));
  EXPECT_NE(r.status, Status::kStopped) << r.message;
  EXPECT_GE(r.extremes.first_uplift_time, 0.0);
  EXPECT_TRUE(r.extremes.lift_offs > 0 || r.pivot_tension);
  EXPECT_EQ(r.status, Status::kOverturned) << r.message;
  expect_sound(r);
}

TEST(AdversarialMotion, ResultsThatOverflowStopTheRunNamingThem) {
  // every input is finite and the body's derived quantities are normal (M g h = 8.8e307 J), but
  // a 2 g pulse on 1e307 kg makes the base shear M a = 2e308 N: inf. The run used to complete
  // with that inf in its extremes and time history; it must end stopped, naming the output
  const Body body(rigid_block(4.0, 1.8, 1e307));
  SimulationOptions opt;
  opt.output_dt = 0.01;
  const SimulationResult r = simulate(body, one_sine_pulse(2 * kG, 2 * kPi, 2.0), {}, opt);
  EXPECT_EQ(r.status, Status::kStopped);
  EXPECT_NE(r.message.find("the results are not finite (max base shear = inf)"), std::string::npos)
      << r.message;
  EXPECT_NE(r.message.find("overflow double precision"), std::string::npos) << r.message;
  ASSERT_FALSE(r.events.empty());
  EXPECT_EQ(r.events.back().kind, EventKind::kStopped);
  EXPECT_FALSE(non_finite_output(r).empty());
  // the same body under 0.5 g (a shear of 4.9e307 N) completes: the check is no false alarm
  const SimulationResult ok = simulate(body, one_sine_pulse(0.5 * kG, 2 * kPi, 2.0), {}, opt);
  EXPECT_EQ(ok.status, Status::kCompleted) << ok.message;
  EXPECT_EQ(non_finite_output(ok), "");
}

TEST(AdversarialMotion, NonFiniteOutputsAreNamedButInfiniteFrictionDemandIsNone) {
  // built by hand: a friction demand of +inf (a zero normal force: |F_I|/0) is a legitimate
  // output, but runs reach F_J = 0 exactly only at isolated instants, so each field's rule is
  // checked on a constructed result rather than on a run that happens to hit one
  constexpr double inf = std::numeric_limits<double>::infinity();
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  SimulationResult r;
  r.history.time = {0.0, 0.5};
  r.history.friction_demand = {0.2, inf};
  Event e;
  e.kind = EventKind::kFrictionExceeded;
  e.friction_demand = inf;
  r.events.push_back(e);
  r.extremes.max_friction_demand = inf;
  EXPECT_EQ(non_finite_output(r), "");
  r.history.friction_demand[1] = nan;
  EXPECT_EQ(non_finite_output(r), "time history friction_demand = nan at t = 0.5 s");
  r.history.friction_demand[1] = inf;
  r.history.kinetic = {1.0, -inf};
  EXPECT_EQ(non_finite_output(r), "time history kinetic = -inf at t = 0.5 s");
  r.events.front().impulse_y = nan;
  EXPECT_EQ(non_finite_output(r), "event 1 (friction_exceeded) impulse_y = nan");
  r.energy.residual = nan;
  EXPECT_EQ(non_finite_output(r), "energy.residual = nan");
  r.final_q = VectorX::Zero(2);
  r.final_q(1) = inf;
  EXPECT_EQ(non_finite_output(r), "final q[1] = inf");
}

TEST(AdversarialMotion, HundredGDownwardBaseLosesContactAtOnce) {
  // the floor falls faster than gravity: the body flies from t = 0 and is still in the air at the
  // end (it rose 99 g x 0.25 s^2 / 2 relative to the floor)
  const Body body(rigid_block(0.4, 2.0, 100.0));
  const SimulationResult r =
      simulate(body, rectangular_pulse(-100 * kG, 0.5, 1.0, Component::kVertical));
  EXPECT_EQ(r.status, Status::kCompleted) << r.message;
  ASSERT_FALSE(r.events.empty());
  EXPECT_EQ(r.events.front().kind, EventKind::kLiftOff);
  EXPECT_EQ(r.events.front().time, 0.0);
  EXPECT_EQ(r.final_phase, ContactMode::kFlight);
  expect_sound(r);
}

TEST(AdversarialMotion, HundredGUpwardBaseOnlyPressesTheBodyDown) {
  const Body body(uniform_cantilever(6.0, 2.0, 2000.0, 7.5e7, 2, 2000.0, 0.02));
  const SimulationResult r =
      simulate(body, half_sine_pulse(100 * kG, 2 * kPi * 5.0, 1.0, Component::kVertical));
  EXPECT_EQ(r.status, Status::kCompleted) << r.message;
  EXPECT_DOUBLE_EQ(r.extremes.first_uplift_time, -1.0);
  expect_sound(r);
}

TEST(AdversarialBody, NanometreBaseEdgeOverturnsUnderAnyPush) {
  // b1 = b2 = 1e-9 m under a 2 m c.g.: a needle; overturning angle 5e-10 rad
  const Body body(rigid_body(100.0, 100.0 * 4.0 / 3.0, 2.0, 1e-9, 1e-9));
  EXPECT_NEAR(body.tipping_angle(1), 5e-10, 1e-15);
  // (at its static overturning angle: falling to pi/2 from 5e-10 rad takes longer than the run)
  SimulationOptions at_static;
  at_static.overturn = OverturnCriterion::kStaticInstability;
  const SimulationResult r = simulate(body, one_sine_pulse(0.01 * kG, 2 * kPi, 2.0), {}, at_static);
  EXPECT_EQ(r.status, Status::kOverturned) << r.message;
  expect_sound(r);
  // at rest it stays: nothing pushes it
  const SimulationResult still = simulate(body, GroundMotion::none(1.0));
  EXPECT_EQ(still.status, Status::kCompleted) << still.message;
  EXPECT_TRUE(still.events.empty());
}

// a two-node-mode lumped body whose modes are at f1 and f2 [Hz]
BodyParameters two_mode_body(double f1, double f2) {
  LumpedModel m;
  m.tip1_x = -0.5;
  m.tip2_x = 0.5;
  m.nodes = {{-0.5, 0.0, 500.0, 0.0},
             {0.5, 0.0, 500.0, 0.0},
             {0.0, 1.0, 2000.0, 100.0},
             {0.0, 2.0, 100.0, 0.0},
             {0.0, 3.0, 100.0, 0.0}};
  m.phi_x = MatrixX::Zero(5, 2);
  m.phi_y = MatrixX::Zero(5, 2);
  m.phi_x(3, 0) = 1.0;
  m.phi_x(4, 1) = 1.0;
  m.frequencies.resize(2);
  m.frequencies << 2 * kPi * f1, 2 * kPi * f2;
  return from_lumped_model(m);
}

TEST(AdversarialBody, TenKilohertzModeNextToATenthHertzOneRunsToTheEnd) {
  // a stiff system (frequency ratio 1e5): the explicit integrator needs small steps, but the run
  // must end, balanced, with the modes where they are
  const Body body(two_mode_body(0.1, 1e4));
  EXPECT_NEAR(body.natural_frequencies()(0) / (2 * kPi), 0.1, 1e-6);
  EXPECT_NEAR(body.natural_frequencies()(1) / (2 * kPi), 1e4, 1e-2);
  SimulationOptions opt;
  opt.t_end = 0.5;
  const SimulationResult r = simulate(body, harmonic(0.75 * kG, 2 * kPi * 2.0, 1.0), {}, opt);
  // it uplifts, and runs to the end through whatever contact modes it visits
  EXPECT_GT(r.extremes.first_uplift_time, 0.0);
  EXPECT_EQ(r.status, Status::kCompleted) << r.message;
  expect_sound(r);
}

TEST(AdversarialBody, NearlySingularModalMassIsRefusedNamingMu) {
  BodyParameters p = BodyParameters::rigid(100.0, 1.0, 0.25, 0.25, 0.1);
  p.mu.resize(2, 2);
  p.mu << 0.1, 0.1 * (1 - 1e-14), 0.1 * (1 - 1e-14), 0.1;
  p.kappa = MatrixX::Identity(2, 2) * 10.0;
  p.gamma = MatrixX::Zero(2, 2);
  p.psi_x = p.psi_y = p.delta = p.beta = VectorX::Zero(2);
  expect_input_error([&] { Body b(p); }, {"body: mu", "positive definite", "smallest eigenvalue"});
}

TEST(AdversarialBody, IllConditionedButAcceptedModalMassRuns) {
  // two nearly dependent modes (condition number 1e8): accepted, and the run stays sound
  BodyParameters p = BodyParameters::rigid(100.0, 1.0, 0.25, 0.25, 0.1);
  p.mu.resize(2, 2);
  p.mu << 0.01, 0.01 * (1 - 1e-8), 0.01 * (1 - 1e-8), 0.01;
  p.kappa = MatrixX::Identity(2, 2) * 10.0;
  p.gamma = MatrixX::Zero(2, 2);
  p.psi_x = VectorX::Constant(2, 0.01);
  p.psi_y = p.delta = p.beta = VectorX::Zero(2);
  const Body body(p);
  SimulationOptions opt;
  opt.t_end = 0.2;
  const SimulationResult r = simulate(body, harmonic(0.5 * kG, 2 * kPi, 1.0), {}, opt);
  EXPECT_NE(r.status, Status::kStopped) << r.message;
  expect_sound(r);
}

// --- endless chatter --------------------------------------------------------------------------

TEST(AdversarialChatter, InelasticBlockChattersToRestAndCompletes) {
  // e = 0.5 on every impact: impact times converge geometrically; the chatter cut-off ends it
  const Body body(rigid_block(0.4, 2.0, 100.0));
  SimulationOptions opt;
  opt.restitution_factor = 0.5;
  InitialState init;
  init.theta = 0.1;
  const SimulationResult r = simulate(body, GroundMotion::none(5.0), init, opt);
  EXPECT_EQ(r.status, Status::kCompleted) << r.message;
  EXPECT_TRUE(r.chatter_cut_off);
  EXPECT_EQ(r.final_phase, Phase::kFullContact);
  EXPECT_LT(r.extremes.impacts, 100);
  expect_sound(r);
}

TEST(AdversarialChatter, WithoutTheCutOffEndlessChatterStopsWithAReason) {
  // chatter_ratio = 0 switches the cut-off off: infinitely many impacts in finite time (Zeno).
  // The run must stop with a message, or come to rest, never hang. Stepped by DOPRI5 with sampled
  // guards the impact intervals fall below the step's resolution and the run stops, saying why;
  // the rocking series locates every impact on its polynomial down to velocities at rounding,
  // where the impact map ends rocking: the block rests at the accumulation point
  const Body body(rigid_block(0.4, 2.0, 100.0));
  SimulationOptions opt;
  opt.restitution_factor = 0.5;
  opt.chatter_ratio = 0.0;
  opt.max_impacts = 100'000;
  InitialState init;
  init.theta = 0.1;
  const SimulationResult rest = simulate(body, GroundMotion::none(5.0), init, opt);
  EXPECT_EQ(rest.status, Status::kCompleted) << rest.message;
  EXPECT_EQ(rest.final_phase, Phase::kFullContact);
  EXPECT_GT(rest.extremes.impacts, 20);
  expect_sound(rest);
  opt.methods.series_rocking = false;
  const SimulationResult r = simulate(body, GroundMotion::none(5.0), init, opt);
  // the impact interval shrinks geometrically until impacts pile up within 1e-9 s (Zeno) or the
  // step size collapses: a stop, with why
  EXPECT_EQ(r.status, Status::kStopped) << r.message;
  EXPECT_TRUE(r.message.find("Zeno") != std::string::npos ||
              r.message.find("step collapsed") != std::string::npos)
      << r.message;
  // the message names the cause and the limit as a number (not "0.000000")
  EXPECT_NE(r.message.find("chatter cut-off disabled"), std::string::npos) << r.message;
  EXPECT_EQ(r.message.find("0.000000"), std::string::npos) << r.message;
  ASSERT_FALSE(r.events.empty());
  EXPECT_EQ(r.events.back().kind, EventKind::kStopped);
  EXPECT_GT(r.extremes.impacts, 10);
  EXPECT_LT(r.extremes.impacts, opt.max_impacts);
  EXPECT_LT(r.t_end, 5.0);
  EXPECT_TRUE(std::isfinite(r.t_end) && std::isfinite(r.energy.residual));
  EXPECT_FALSE(r.impact_gained_energy);
}

TEST(AdversarialChatter, ImpactLimitStopsAnElasticRockerWithTheLimitNamed) {
  // e = 1 (energy kept) rocks forever; a small impact limit must stop it cleanly
  const Body body(rigid_block(0.4, 2.0, 100.0));
  SimulationOptions opt;
  opt.max_impacts = 50;
  InitialState init;
  init.theta = 0.1;
  const SimulationResult r = simulate(body, GroundMotion::none(1000.0), init, opt);
  EXPECT_EQ(r.status, Status::kStopped);
  EXPECT_NE(r.message.find("impact"), std::string::npos) << r.message;
  EXPECT_LE(r.extremes.impacts, 51);
  expect_sound(r);
}

}  // namespace
}  // namespace flexrock
