// SPDX-License-Identifier: BSD-3-Clause
// The extremes of a stepped contact mode (a flexible body's rocking by DOP853, the compliant
// contact's steps): located between the step's samples (locate_peaks_between), so that they do
// not depend on how many samples a step takes, and bound every point of the motion the dense
// output gives.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "flexrock/excitation/ground_motion.hpp"
#include "flexrock/io/records.hpp"
#include "flexrock/model/builders.hpp"
#include "flexrock/sim/simulate.hpp"

namespace flexrock {
namespace {

// the bench's oscillator on a slab: 1 t at 2 Hz with 5 % damping on a 0.5 t slab 2 m tall and
// 0.8 m wide (bench/cases.hpp, case (d) with n = 1)
Body oscillator() { return Body(oscillator_on_slab(1000.0, 2.0, 500.0, 2.0, 0.8, 0.05)); }

// 4 s sampled at 0.01 s: rest, or two cycles of a 1.5 Hz sine of amplitude a_p [m/s^2], then rest
GroundMotion record(double a_p) {
  std::vector<double> a;
  for (int i = 0; i <= 400; ++i) {
    const double t = 0.01 * i;
    a.push_back(t < 2.0 / 1.5 ? a_p * std::sin(2.0 * 3.141592653589793 * 1.5 * t) : 0.0);
  }
  return GroundMotion::uniform(0.01, a);
}

// the bench's record: Kobe 1995 (Nishi-Akashi, 090) scaled to a PGA of pga_g
GroundMotion kobe(double pga_g) {
  const io::Record r =
      io::read_at2(FLEXROCK_SOURCE_DIR "/../shared/data/kobe_1995_nishi_akashi_090.AT2");
  double pga = 0.0;
  for (const double v : r.values) pga = std::max(pga, std::abs(v));
  return r.to_motion(pga_g / pga);
}

SimulationResult rock(const GroundMotion& m, const InitialState& init, int samples,
                      double output_dt = 0.0) {
  SimulationOptions o;
  o.rtol = 1e-10;
  o.atol = 1e-12;
  o.event_samples = samples;
  o.output_dt = output_dt;
  return simulate(oscillator(), m, init, o);
}

struct Case {
  const char* name;
  GroundMotion motion;
  InitialState init;
};

std::vector<Case> cases() {
  InitialState tilted;
  tilted.theta = 0.1;  // the slab's alpha is atan(0.4 / 2) = 0.197
  return {{"free rocking from 0.1 rad", record(0.0), tilted},
          {"two cycles of a 1.5 Hz sine of 0.35 g", record(0.35 * kStandardGravity), {}}};
}

// Sampled at a step's points alone, the shear, the moment and max|u| missed about 1e-4 of their
// peaks at the default 4 samples, and moved by as much from 2 to 32 samples; located, they agree
// to the search's tolerance (a peak found to 2^-19 of the triple's span, far below 1e-9 of it)
TEST(StepExtremes, DoNotDependOnTheSamplesAStepTakes) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const SimulationResult ref = rock(c.motion, c.init, 32);
    ASSERT_EQ(ref.status, Status::kCompleted) << ref.message;
    ASSERT_GT(ref.extremes.impacts, 2);
    for (const int samples : {2, 4, 9}) {
      SCOPED_TRACE("event_samples " + std::to_string(samples));
      const SimulationResult r = rock(c.motion, c.init, samples);
      const Extremes &e = r.extremes, &f = ref.extremes;
      EXPECT_EQ(e.impacts, f.impacts);
      EXPECT_NEAR(e.max_base_shear, f.max_base_shear, 1e-9 * f.max_base_shear);
      EXPECT_NEAR(e.max_overturning_moment, f.max_overturning_moment,
                  1e-9 * f.max_overturning_moment);
      EXPECT_NEAR(e.max_friction_demand, f.max_friction_demand, 1e-9 * f.max_friction_demand);
      EXPECT_NEAR(e.max_abs_q(0), f.max_abs_q(0), 1e-9 * f.max_abs_q(0));
    }
  }
}

// rows every 0.1 ms are the motion at those times: the located extremes are above every one of
// them, and within what the rows' spacing can miss of the largest: the reaction has kinks at the
// record's samples, where the forcing's slope changes, and jumps at impacts (a first-order miss);
// u peaks smoothly, but while rocking with the coupled motion's frequency, several times the
// oscillator's 2 Hz ((omega 5e-5 s)^2 / 2 is about 1e-6 at 5 Hz)
TEST(StepExtremes, BoundEveryRowOfTheMotion) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const SimulationResult r = rock(c.motion, c.init, 4, 1e-4);
    ASSERT_EQ(r.status, Status::kCompleted) << r.message;
    const History& h = r.history;
    double shear = 0.0, moment = 0.0, demand = 0.0, u = 0.0;
    for (std::size_t k = 0; k < h.size(); ++k) {
      shear = std::max(shear, std::abs(h.reaction_x[k]));
      // the moment about the c.g. projection in the body's frame: the reaction's component
      // along the body's axis times the resultant's distance (the pivot's while rocking)
      const double sn = std::sin(h.theta[k]), cs = std::cos(h.theta[k]);
      moment = std::max(moment,
                        std::abs(h.resultant[k] * (h.reaction_y[k] * cs - h.reaction_x[k] * sn)));
      demand = std::max(demand, h.friction_demand[k]);
      u = std::max(u, std::abs(h.q[k]));
    }
    const Extremes& e = r.extremes;
    EXPECT_GE(e.max_base_shear, shear * (1.0 - 1e-12));
    EXPECT_GE(e.max_overturning_moment, moment * (1.0 - 1e-12));
    EXPECT_GE(e.max_friction_demand, demand * (1.0 - 1e-12));
    EXPECT_GE(e.max_abs_q(0), u * (1.0 - 1e-12));
    EXPECT_LE(e.max_base_shear, shear * (1.0 + 1e-3));
    EXPECT_LE(e.max_overturning_moment, moment * (1.0 + 1e-3));
    EXPECT_LE(e.max_friction_demand, demand * (1.0 + 1e-3));
    EXPECT_LE(e.max_abs_q(0), u * (1.0 + 1e-5));
  }
}

// The state just before an event is a point of the motion too: sticking under a pulse, the
// friction demand |F_I|/F_J rises until it reaches mu_s, where the base slips (the friction
// limit's guard mu_s F_J - |F_I| = 0), and while sliding it is mu_k < mu_s. Its largest value is
// then mu_s itself, reached only at the slip; from the samples before it the extreme fell short
// by up to 1.5 % (0.0985 at 4 samples)
TEST(StepExtremes, FrictionDemandReachesTheStaticCoefficientAtTheSlip) {
  const double wp = 2.0 * 3.141592653589793 * 2.0;
  for (const double a_p : {0.08, 0.15}) {
    const GroundMotion m = GroundMotion::analytic(
        [=](double t) {
          return BaseAcceleration{
              t < 2.0 * 3.141592653589793 / wp ? a_p * kStandardGravity * std::sin(wp * t) : 0.0,
              0.0};
        },
        3.0, {2.0 * 3.141592653589793 / wp});
    for (const int samples : {4, 32}) {
      SCOPED_TRACE("a_p " + std::to_string(a_p) + " g, event_samples " + std::to_string(samples));
      SimulationOptions o;
      o.friction_coefficient = 0.1;
      o.kinetic_friction_coefficient = 0.08;
      o.event_samples = samples;
      const SimulationResult r = simulate(oscillator(), m, {}, o);
      ASSERT_EQ(r.status, Status::kCompleted) << r.message;
      ASSERT_GE(r.extremes.slips, 1);
      EXPECT_EQ(r.extremes.first_uplift_time, -1.0);
      EXPECT_NEAR(r.extremes.max_friction_demand, 0.1, 1e-9);
    }
  }
}

// quantity `of` of the runs at 2, 4 and 9 samples a step equals that of `ref`, at 32, to 1e-9
template <class Run, class Of>
void expect_as_at_32_samples(const SimulationResult& ref, Run&& run, Of&& of) {
  const double at_32 = of(ref.extremes);
  for (const int samples : {2, 4, 9}) {
    SCOPED_TRACE("event_samples " + std::to_string(samples));
    EXPECT_NEAR(of(run(samples).extremes), at_32, 1e-9 * at_32);
  }
}

// The friction demand |F_I|/F_J counts only while the floor presses with at least 5 % of the
// weight, and rises toward that limit where F_J dips: its peak then lies at the switch, which
// no parabola finds (the switch is bisected and observed). The bench's cantilever with n = 4
// under Kobe at 1.2 g: its demand, about 4, peaks at such a dip while it rocks; from the
// parabolas alone it was 0.6 % short at 2 samples and 6e-7 at 4
TEST(StepExtremes, FrictionDemandPeaksWhereTheFloorStopsPressing) {
  const Body cantilever(uniform_cantilever(6.0, 1.2, 800.0, 1.3e7, 4, 2000.0, 0.02));
  const GroundMotion m = kobe(1.2);
  auto run = [&](int samples) {
    SimulationOptions o;
    o.rtol = 1e-10;
    o.atol = 1e-12;
    o.event_samples = samples;
    return simulate(cantilever, m, {}, o);
  };
  const SimulationResult ref = run(32);
  ASSERT_EQ(ref.status, Status::kCompleted) << ref.message;
  ASSERT_GT(ref.extremes.max_friction_demand, 1.0);
  expect_as_at_32_samples(ref, run, [](const Extremes& e) { return e.max_friction_demand; });
}

// the compliant contact at rtol 1e-10 with `samples` a step: the body bouncing on both springs 300
// times as fast as it rocks, critically damped. The rigid block at rtol 1e-12: its friction demand
// peaks where the floor's pressing falls through kPressingFraction at about 7000/s after its
// landing corner rebounds (the sticking corners' tangential springs hold a share of a normal force
// that vanishes), so the integration's own error at rtol 1e-10, 1.3e-7 there and the same at every
// sample count, would hide what the samples change (4e-8 at 1e-11, 1e-9 at 1e-12)
SimulationOptions compliant_floor(const Body& body, int samples) {
  SimulationOptions o;
  o.rtol = body.modes() == 0 ? 1e-12 : 1e-10;
  o.atol = 1e-2 * o.rtol;
  o.event_samples = samples;
  o.contact_model = ContactModel::kCompliant;
  const double wv = 300.0 * body.rocking_frequency();
  o.contact_stiffness = 0.5 * body.params().mass * wv * wv;
  o.contact_damping_ratio = 1.0;
  return o;
}

// The compliant contact's stepper (spring-dashpots at the tipping points) locates its extremes
// between its samples the same way, for every quantity it reports: the reaction, the friction
// demand, u, the tilt on either edge, the uplift, the offset and each corner's normal force (the
// touch's peak). Sampled, the rigid block of case (c) under Kobe moved its shear by 9e-5 and its
// friction demand from 0.69 to 0.82 between 1 and 32 samples
TEST(StepExtremes, CompliantContactDoesNotDependOnTheSamplesAStepTakes) {
  const Body block(rigid_block(0.3, 1.5, 1000.0));
  for (const auto& [body, c] : {std::pair{oscillator(), cases()[0]},
                                {oscillator(), cases()[1]},
                                {block, cases()[0]},
                                {block, cases()[1]}}) {
    SCOPED_TRACE(std::string(c.name) + (body.modes() == 0 ? ", rigid block" : ", oscillator"));
    auto run = [&](int samples) {
      return simulate(body, c.motion, c.init, compliant_floor(body, samples));
    };
    const SimulationResult ref = run(32);
    ASSERT_EQ(ref.status, Status::kCompleted) << ref.message;
    ASSERT_GT(ref.extremes.impacts, 2);
    for (const int samples : {2, 4, 9}) {
      SCOPED_TRACE("event_samples " + std::to_string(samples));
      const SimulationResult r = run(samples);
      const Extremes &e = r.extremes, &f = ref.extremes;
      EXPECT_EQ(e.impacts, f.impacts);
      auto near = [](double a, double b, const char* what) { EXPECT_NEAR(a, b, 1e-8 * b) << what; };
      near(e.max_base_shear, f.max_base_shear, "max_base_shear");
      near(e.max_overturning_moment, f.max_overturning_moment, "max_overturning_moment");
      near(e.max_friction_demand, f.max_friction_demand, "max_friction_demand");
      if (body.modes() > 0) near(e.max_abs_q(0), f.max_abs_q(0), "max_abs_q(0)");
      near(e.max_theta_edge1, f.max_theta_edge1, "max_theta_edge1");
      near(e.max_theta_edge2, f.max_theta_edge2, "max_theta_edge2");
      near(e.max_uplift, f.max_uplift, "max_uplift");
      near(e.max_offset, f.max_offset, "max_offset");
      near(e.max_contact_force, f.max_contact_force, "max_contact_force");
      near(e.max_impact_force, f.max_impact_force, "max_impact_force");
    }
  }
}

// A touching corner's force is clipped at zero where its dashpot would pull. As the corner that
// leaves the floor at an impact unloads, the moment rises until that force reaches zero and peaks
// at the kink, which no parabola finds (the kink is bisected and observed). The slender block of
// the bench's case (c) (0.2 m by 1 m) under Kobe at 0.5 g on a critically damped floor: its
// moment peaks at such a kink at its third impact (8.33 s), which the parabolas alone missed by
// 2e-5 of it at 4 samples
TEST(StepExtremes, CompliantMomentPeaksWhereALeavingCornerUnloads) {
  const Body block(BodyParameters::rectangular_block(1000.0, 0.2, 1.0));
  const GroundMotion m = kobe(0.5);
  auto run = [&](int samples) {
    SimulationOptions o = compliant_floor(block, samples);
    o.t_end = 9.0;
    return simulate(block, m, {}, o);
  };
  const SimulationResult ref = run(32);
  ASSERT_EQ(ref.status, Status::kCompleted) << ref.message;
  ASSERT_GE(ref.extremes.impacts, 3);
  expect_as_at_32_samples(ref, run, [](const Extremes& e) { return e.max_overturning_moment; });
}

}  // namespace
}  // namespace flexrock
