// SPDX-License-Identifier: BSD-3-Clause
// Every run ends with an answer (docs/validation.md, "Every run ends with an answer"): ordinary
// flexible bodies under the shared records run to the end of the record or overturn, the chatter
// cut-off decides no outcome, and a toppling block is overturned for every entry point.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "flexrock/excitation/pulses.hpp"
#include "flexrock/io/case_file.hpp"
#include "flexrock/io/records.hpp"
#include "flexrock/model/builders.hpp"
#include "flexrock/sim/simulate.hpp"
#include "flexrock/study/outcome.hpp"
#include "flexrock/study/spectrum.hpp"

namespace flexrock {
namespace {

const std::string kData = FLEXROCK_SOURCE_DIR "/../shared/data/";
const std::vector<double> kScales = {0.25, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0};

struct NamedBody {
  std::string name;
  BodyParameters params;
};

// the six flexible bodies of tools/validation/contact_grid.py
std::vector<NamedBody> flexible_bodies() {
  std::vector<NamedBody> b;
  for (double f : {1.0, 2.0, 5.0})
    b.push_back({"oscillator_" + std::to_string(static_cast<int>(f)) + "hz",
                 oscillator_on_slab(800.0, f, 400.0, 2.0, 1.0, 0.02)});
  b.push_back({"tank", io::load_body(FLEXROCK_SOURCE_DIR "/examples/cases/flexible_tank.toml")});
  b.push_back({"cabinet", uniform_cantilever(2.2, 0.6, 180.0, 8.6e5, 2, 50.0, 0.03)});
  b.push_back({"transformer", oscillator_on_slab(6000.0, 3.0, 2000.0, 1.4, 1.2, 0.03)});
  return b;
}

struct NamedRecord {
  std::string name;
  io::Record record;
};

const std::vector<NamedRecord>& records() {
  static const std::vector<NamedRecord> r = {
      {"elcentro", io::read_single_column(kData + "elcentro_1940_ns.dat", 0.02, io::AccelUnit::kG)},
      {"kobe", io::read_at2(kData + "kobe_1995_nishi_akashi_090.AT2")}};
  return r;
}

// overturned and on which side, or rocked, or stayed down
std::string outcome_class(const Body& body, const SimulationResult& r) {
  const study::RunSummary s = study::summarize(body, r);
  if (study::overturned(s.outcome)) return "overturned_edge" + std::to_string(s.overturn_edge);
  return study::to_string(s.outcome);
}

TEST(ContactModes, OrdinaryFlexibleBodiesRunToTheEndOfEveryRecord) {
  int runs = 0, uplifted = 0, flew = 0, over = 0;
  for (const NamedBody& nb : flexible_bodies()) {
    const Body body(nb.params);
    for (const NamedRecord& rec : records()) {
      for (double scale : kScales) {
        const GroundMotion m = io::combine(rec.record, nullptr, scale);
        const SimulationResult r = simulate(body, m);
        ++runs;
        const std::string where = nb.name + " " + rec.name + " x" + std::to_string(scale);
        ASSERT_NE(r.status, Status::kStopped) << where << ": " << r.message;
        if (r.status == Status::kCompleted) {
          EXPECT_EQ(r.t_end, m.duration()) << where;
        } else {
          ++over;
        }
        uplifted += r.extremes.first_uplift_time >= 0.0;
        flew += r.extremes.lift_offs > 0;
        // the balance closes through every lift-off and landing
        EXPECT_LT(std::abs(r.energy.residual), 1e-6 * r.energy.scale) << where;
      }
    }
  }
  EXPECT_EQ(runs, 84);
  std::printf("flexible grid: %d runs, %d uplifted, %d flew, %d overturned, 0 ended early\n", runs,
              uplifted, flew, over);
}

// outcome under the default chatter criterion and with it 10 and 100 times finer
TEST(ContactModes, ChatterCutOffDecidesNoOutcome) {
  std::vector<NamedBody> bodies = {
      {"statue", rigid_block(0.4, 1.8, 800.0)},
      {"slender_block", rigid_block(0.4, 2.0, 600.0)},
      {"squat_cabinet", rigid_block(0.8, 1.6, 300.0)},
  };
  const auto flex = flexible_bodies();
  bodies.push_back(flex[1]);  // 2 Hz oscillator on a slab
  bodies.push_back(flex[3]);  // the tank
  const double r0 = SimulationOptions{}.chatter_ratio;
  int runs = 0, cutoffs = 0;
  for (const NamedBody& nb : bodies) {
    const Body body(nb.params);
    for (const NamedRecord& rec : records()) {
      for (double scale : kScales) {
        const GroundMotion m = io::combine(rec.record, nullptr, scale);
        std::string first;
        for (double f : {1.0, 0.1, 0.01}) {
          SimulationOptions o;
          o.chatter_ratio = r0 * f;
          const SimulationResult r = simulate(body, m, {}, o);
          ASSERT_NE(r.status, Status::kStopped) << r.message;
          const std::string c = outcome_class(body, r);
          if (f == 1.0) {
            first = c;
            cutoffs += static_cast<int>(r.extremes.chatter_cutoffs);
          }
          EXPECT_EQ(c, first) << nb.name << " " << rec.name << " x" << scale << " ratio "
                              << o.chatter_ratio;
          ++runs;
        }
      }
    }
  }
  std::printf("chatter convergence: %d runs, %d cut-offs at the default ratio %g\n", runs, cutoffs,
              r0);
}

TEST(ContactModes, ToppingBlockIsOverturnedBySimulateSummaryAndSpectrumAlike) {
  // a slender block (b/h = 0.2) under a one-sine pulse strong enough to throw it over: it leaves
  // or strains its pivot on the way down and must still be reported overturned, on its side
  const Body body(rigid_block(0.4, 2.0, 600.0));
  const double p = body.rocking_frequency();
  for (double amp : {1.0, 3.0}) {
    const double a_p = amp * kStandardGravity, w_p = 2.0 * p;
    const double duration = 2.0 * std::numbers::pi / w_p + 10.0 * 2.0 * std::numbers::pi / p;
    const SimulationResult r = simulate(body, one_sine_pulse(a_p, w_p, duration));
    ASSERT_EQ(r.status, Status::kOverturned) << "a_p = " << amp << " g: " << r.message;
    EXPECT_TRUE(overturned(r));
    const study::RunSummary s = study::summarize(body, r);
    EXPECT_TRUE(study::overturned(s.outcome));
    EXPECT_EQ(s.overturn_edge, r.extremes.overturn_edge);
    // a one-sine pulse pushes first toward edge 2's side: the block tips onto edge 1 first
    EXPECT_EQ(r.extremes.first_uplift_edge, 1);
    study::SpectrumSpec spec;
    spec.pulse = "one_sine";
    spec.solver = study::study_solver_defaults();
    const study::RunSummary cell = study::run_pulse_cell(body, spec, a_p, w_p);
    EXPECT_EQ(cell.outcome, s.outcome);
    EXPECT_EQ(cell.overturn_edge, s.overturn_edge);
  }
}

// The same six bodies on floors with friction, sliding, rocking with a sliding pivot and flying:
// every run ends with an answer (completed or overturned), its energy balance closed and no
// event gaining energy. The last body is a grazing hop found by a random search: an impact whose
// sticking continuation needs more friction than the floor has, whose sliding one has no pivot
// force and whose flight does not rise; it used to loop through lift-off and landing at one
// instant until the run stopped.
TEST(ContactModes, FlexibleBodiesOnFloorsWithFrictionRunToTheEnd) {
  std::vector<NamedBody> bodies = flexible_bodies();
  bodies.push_back({"grazing_hop", uniform_cantilever(6.73848582477058, 1.3844674446040088, 2000.0,
                                                      7.5e7, 1, 2000.0, 0.02)});
  int runs = 0, slid = 0, rocked_sliding = 0;
  for (const NamedBody& nb : bodies) {
    const Body body(nb.params);
    for (const NamedRecord& rec : records()) {
      for (double scale : {1.0, 2.0, 3.8422659198866356}) {
        for (auto [mu_s, mu_k] : {std::pair{0.2, 0.2}, std::pair{0.5, 0.4},
                                  std::pair{0.7516607104862956, 0.6479047667501824}}) {
          const GroundMotion m = io::combine(rec.record, nullptr, scale);
          SimulationOptions opt;
          opt.friction_coefficient = mu_s;
          opt.kinetic_friction_coefficient = mu_k;
          const SimulationResult r = simulate(body, m, {}, opt);
          const std::string what = nb.name + " " + rec.name + " x" + std::to_string(scale) +
                                   " mu " + std::to_string(mu_s);
          ++runs;
          EXPECT_NE(r.status, Status::kStopped) << what << ": " << r.message;
          EXPECT_FALSE(r.energy_unbalanced) << what;
          EXPECT_FALSE(r.impact_gained_energy) << what;
          if (r.extremes.slips > 0) ++slid;
          for (const Event& e : r.events) {
            if (e.kind == EventKind::kSlipStart && e.edge != 0) {
              ++rocked_sliding;
              break;
            }
          }
        }
      }
    }
  }
  EXPECT_EQ(runs, 7 * 2 * 3 * 3);
  EXPECT_GT(slid, runs / 2);
  EXPECT_GT(rocked_sliding, 5);
}

}  // namespace
}  // namespace flexrock
