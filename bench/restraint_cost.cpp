// SPDX-License-Identifier: BSD-3-Clause
// The cost of restraints (docs/theory.md §26) next to the free block's, and the outcomes of a
// post-tensioned rocking pier and of an anchored cabinet under El Centro and Kobe at several
// scales. Medians of repeated runs; timings belong here, never in tests.
//
//   flexrock_restraint_cost [repeats]      (FLEXROCK_DATA: the records' folder)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "flexrock/io/records.hpp"
#include "flexrock/sim/restraints.hpp"

using namespace flexrock;

namespace {

std::string data_dir() {
  return std::getenv("FLEXROCK_DATA") ? std::getenv("FLEXROCK_DATA")
                                      : FLEXROCK_SOURCE_DIR "/../shared/data";
}

// a record scaled to a PGA of `pga_g` [g]
GroundMotion scaled(const io::Record& r, double pga_g) {
  double pga = 0.0;
  for (double v : r.values) pga = std::max(pga, std::abs(v));
  return r.to_motion(pga_g / pga);
}

template <class F>
double median_seconds(int repeats, F&& f) {
  std::vector<double> t;
  for (int i = 0; i < repeats; ++i) {
    const auto a = std::chrono::steady_clock::now();
    f();
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count());
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

Restraint tendon(double top, double depth, double k, double p0, double fy) {
  Restraint r;
  r.kind = RestraintKind::kTendon;
  r.body_y = top;
  r.floor_y = -depth;
  r.stiffness = k;
  r.prestress = p0;
  r.yield_force = fy;
  return r;
}

Restraint anchor(double x, double length, double k, double slack, double fy, double fracture) {
  Restraint r;
  r.kind = RestraintKind::kAnchor;
  r.body_x = r.floor_x = x;
  r.floor_y = -length;
  r.stiffness = k;
  r.slack = slack;
  r.yield_force = fy;
  r.fracture_elongation = fracture;
  return r;
}

const char* outcome(const RestrainedResult& r) {
  switch (r.result.status) {
    case Status::kOverturned:
      return "overturned";
    case Status::kStopped:
      return "stopped (flight)";
    case Status::kCompleted:
      break;
  }
  return r.result.extremes.first_uplift_time >= 0.0 ? "rocked" : "no uplift";
}

std::string damage(const std::vector<Restraint>& in, const RestrainedResult& r) {
  std::string s;
  for (std::size_t i = 0; i < in.size(); ++i) {
    const RestraintKindInfo& k = restraint_kind_info(in[i].kind);
    const RestraintSummary& x = r.restraints[i];
    std::string d = x.fractured ? k.fractured : x.yielded ? k.yielded : "";
    if (d.empty() || s.find(d) != std::string::npos) continue;
    s += (s.empty() ? "" : ", ") + d;
  }
  return s.empty() ? "none" : s;
}

}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::atoi(argv[1]) : 7;
  const io::Record elcentro =
      io::read_single_column(data_dir() + "/elcentro_1940_ns.dat", 0.02, io::AccelUnit::kG);
  const io::Record kobe = io::read_at2(data_dir() + "/kobe_1995_nishi_akashi_090.AT2");
  struct Rec {
    const char* name;
    const io::Record* r;
  };
  const Rec recs[] = {{"El Centro", &elcentro}, {"Kobe", &kobe}};

  // the closed forms of tools/derive/restraints.py (tests/data/restraints_reference.json) against
  // the engine: the uplift under a slow ramp, the equation's residual on the pushover
  {
    std::ifstream in(FLEXROCK_SOURCE_DIR "/tests/data/restraints_reference.json");
    const nlohmann::json ref = nlohmann::json::parse(in);
    std::printf(
        "closed forms against the engine\n| case | uplift, closed form [m/s^2] | engine, "
        "slow ramp | rel. diff | max engine theta_ddot on the pushover / (g/h) | "
        "restoring moment, max rel. diff |\n|---|---|---|---|---|---|\n");
    for (const nlohmann::json& c : ref["cases"]) {
      const double h = c["h"], b1 = c["b1"], b2 = c["b2"];
      const Body body(BodyParameters::rigid(c["M"], h, b1, b2, (b1 * b1 + h * h) / (3.0 * h * h)));
      Restraint r;
      r.body_x = c["xb"];
      r.body_y = c["yb"];
      r.floor_x = c["xf"];
      r.floor_y = c["yf"];
      r.stiffness = c["k"];
      r.prestress = c["P0"];
      r.slack = c["s"];
      const double a_up = c["uplift_acceleration"], rate = 0.5, t_max = 3.0 * a_up / rate;
      SimulationOptions o;
      o.t_end = 1.2 * a_up / rate;
      const RestrainedResult res = simulate_restrained(
          body, {r}, GroundMotion::sampled({0.0, t_max}, {0.0, rate * t_max}), {}, o);
      double worst = 0.0, worst_m = 0.0;
      for (const nlohmann::json& pt : c["points"]) {
        const double th = pt["theta"], a = pt["pushover_acceleration"];
        worst =
            std::max(worst, std::abs(restrained_rocking_acceleration(body, {r}, 1, th, {a, 0.0})) /
                                body.g_over_h());
        worst_m = std::max(worst_m, std::abs(restoring_moment(body, {r}, 1, th) /
                                                 pt["restoring_moment"].get<double>() -
                                             1.0));
      }
      const double engine = rate * res.result.extremes.first_uplift_time;
      std::printf("| %s | %.12g | %.12g | %.1e | %.1e | %.1e |\n",
                  c["name"].get<std::string>().c_str(), a_up, engine, std::abs(engine / a_up - 1.0),
                  worst, worst_m);
    }
    std::printf("\n");
  }

  // cost: the bench's slender block (b = 0.2 m, h = 1 m, 1 t) at PGA 0.5 g
  const Body block(BodyParameters::rectangular_block(1000.0, 0.2, 1.0));
  const double mg = 1000.0 * block.g();
  const std::vector<Restraint> tendons{tendon(2.0, 1.0, 2.0e6, 0.5 * mg, 4.0 * mg)};
  const std::vector<Restraint> anchors{anchor(-0.2, 0.2, 5.0e7, 2e-4, 0.5 * mg, 0.02),
                                       anchor(0.2, 0.2, 5.0e7, 2e-4, 0.5 * mg, 0.02)};
  const std::vector<Restraint> slack_ties{tendon(2.0, 1.0, 0.0, 0.0, INFINITY)};
  std::printf("cost, slender block (b = 0.2 m, h = 1 m) at PGA 0.5 g, rtol 1e-9, median of %d\n",
              repeats);
  std::printf(
      "| record | free (default) | free (DOPRI5) | ties k = 0 | tendon | anchors | "
      "tendon/free | anchors/free | tendon/free DOPRI5 |\n|---|---|---|---|---|---|---|---|---|\n");
  for (const Rec& rec : recs) {
    const GroundMotion m = scaled(*rec.r, 0.5);
    SimulationOptions opt;
    SimulationOptions dopri = opt;
    dopri.methods.series_rocking = false;
    dopri.methods.closed_form_free_rocking = false;
    const double tf = median_seconds(repeats, [&] { (void)simulate(block, m, {}, opt); });
    const double td = median_seconds(repeats, [&] { (void)simulate(block, m, {}, dopri); });
    const double t0 =
        median_seconds(repeats, [&] { (void)simulate_restrained(block, slack_ties, m, {}, opt); });
    const double tt =
        median_seconds(repeats, [&] { (void)simulate_restrained(block, tendons, m, {}, opt); });
    const double ta =
        median_seconds(repeats, [&] { (void)simulate_restrained(block, anchors, m, {}, opt); });
    std::printf("| %s | %.3f ms | %.3f ms | %.3f ms | %.3f ms | %.3f ms | %.2f | %.2f | %.2f |\n",
                rec.name, 1e3 * tf, 1e3 * td, 1e3 * t0, 1e3 * tt, 1e3 * ta, tt / tf, ta / tf,
                tt / td);
    // what each run did: the restrained bodies rock longer and land more often
    const SimulationResult f = simulate(block, m, {}, opt);
    const RestrainedResult z = simulate_restrained(block, slack_ties, m, {}, opt);
    const RestrainedResult rt = simulate_restrained(block, tendons, m, {}, opt);
    const RestrainedResult ra = simulate_restrained(block, anchors, m, {}, opt);
    std::printf("|   steps, impacts | %ld, %ld | | %ld, %ld | %ld, %ld | %ld, %ld | | | |\n",
                f.steps, f.extremes.impacts, z.result.steps, z.result.extremes.impacts,
                rt.result.steps, rt.result.extremes.impacts, ra.result.steps,
                ra.result.extremes.impacts);
  }

  // outcomes: a post-tensioned rocking pier (1.2 m x 6 m, 18 t; central tendon 300 kN, yield
  // 900 kN) and an anchored cabinet (0.6 m x 2 m, 400 kg; two bolts, 0.5 mm slack, 3 kN
  // capacity, breaking at 10 mm)
  const Body pier(BodyParameters::rectangular_block(18000.0, 0.6, 3.0));
  const std::vector<Restraint> pier_ties{tendon(6.0, 3.0, 3.25e7, 3.0e5, 9.0e5)};
  const Body cabinet(BodyParameters::rectangular_block(400.0, 0.3, 1.0));
  const std::vector<Restraint> cabinet_ties{anchor(-0.3, 0.3, 2.0e7, 5e-4, 3.0e3, 0.01),
                                            anchor(0.3, 0.3, 2.0e7, 5e-4, 3.0e3, 0.01)};
  struct Sys {
    const char* name;
    const Body* body;
    const std::vector<Restraint>* ties;
  };
  const Sys systems[] = {{"post-tensioned pier", &pier, &pier_ties},
                         {"anchored cabinet", &cabinet, &cabinet_ties}};
  std::printf("\noutcomes (free body in the last columns)\n");
  std::printf(
      "| body | record | PGA | outcome | max theta/alpha | damage | max tie force | "
      "plastic work | free outcome | free max theta/alpha |\n"
      "|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Sys& sys : systems) {
    const double alpha = sys.body->tipping_angle(1);
    for (const Rec& rec : recs) {
      for (double pga : {0.2, 0.4, 0.6, 0.8, 1.0}) {
        const GroundMotion m = scaled(*rec.r, pga);
        const RestrainedResult r = simulate_restrained(*sys.body, *sys.ties, m);
        const SimulationResult f = simulate(*sys.body, m);
        double fmax = 0.0;
        for (const RestraintSummary& x : r.restraints) fmax = std::max(fmax, x.max_force);
        const double th =
            std::max(r.result.extremes.max_theta_edge1, r.result.extremes.max_theta_edge2);
        const double thf = std::max(f.extremes.max_theta_edge1, f.extremes.max_theta_edge2);
        std::printf("| %s | %s | %.1f g | %s | %.4f | %s | %.4g N | %.4g J | %s | %.4f |\n",
                    sys.name, rec.name, pga, outcome(r), th / alpha, damage(*sys.ties, r).c_str(),
                    fmax, r.plastic_work,
                    f.status == Status::kOverturned       ? "overturned"
                    : f.extremes.first_uplift_time >= 0.0 ? "rocked"
                                                          : "no uplift",
                    thf / alpha);
      }
    }
  }
  // the outcomes with rtol 10x finer: the same statuses and damage states, and the change of
  // the peak tilt (answers that do not depend on the tolerance)
  int cells = 0, changed = 0;
  double worst = 0.0;
  for (const Sys& sys : systems) {
    for (const Rec& rec : recs) {
      for (double pga : {0.2, 0.4, 0.6, 0.8, 1.0}) {
        const GroundMotion m = scaled(*rec.r, pga);
        SimulationOptions fine;
        fine.rtol = 1e-10;
        fine.atol = 1e-12;
        const RestrainedResult a = simulate_restrained(*sys.body, *sys.ties, m);
        const RestrainedResult c = simulate_restrained(*sys.body, *sys.ties, m, {}, fine);
        bool same = a.result.status == c.result.status;
        for (std::size_t i = 0; i < a.restraints.size(); ++i)
          same = same && a.restraints[i].yielded == c.restraints[i].yielded &&
                 a.restraints[i].fractured == c.restraints[i].fractured;
        ++cells;
        changed += same ? 0 : 1;
        const double ta =
            std::max(a.result.extremes.max_theta_edge1, a.result.extremes.max_theta_edge2);
        const double tc =
            std::max(c.result.extremes.max_theta_edge1, c.result.extremes.max_theta_edge2);
        if (a.result.status != Status::kOverturned && ta > 1e-6)
          worst = std::max(worst, std::abs(ta - tc) / ta);
      }
    }
  }
  std::printf(
      "\nrtol 1e-9 vs 1e-10: %d cells, %d with another outcome or damage state, largest "
      "relative change of the peak tilt %.2e\n",
      cells, changed, worst);
  return 0;
}
