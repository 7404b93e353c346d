// SPDX-License-Identifier: BSD-3-Clause
// Validation driver: runs the engine on the cases of docs/validation.md and writes its numbers
// to one JSON file. Closed forms, the exact quadratures and the independent compliant-foundation
// model live in make_report.py; this program only asks the engine.
//
//   flexrock_validate --out DIR [--quick]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "flexrock/excitation/pulses.hpp"
#include "flexrock/io/outputs.hpp"
#include "flexrock/io/records.hpp"
#include "flexrock/model/builders.hpp"
#include "flexrock/sim/simulate.hpp"

namespace flexrock::validation {
namespace {

using json = nlohmann::json;
constexpr double g = kStandardGravity;
bool quick = false;

// uniform rectangular block of slenderness alpha and half-diagonal R [m]
Body block(double alpha, double R) {
  return Body(BodyParameters::rectangular_block(1000.0, R * std::sin(alpha), R * std::cos(alpha)));
}

std::vector<double> linspace(double a, double b, int n) {
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(n == 1 ? a : a + (b - a) * i / (n - 1));
  return v;
}

std::vector<double> geomspace(double a, double b, int n) {
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(a * std::pow(b / a, n == 1 ? 0.0 : double(i) / (n - 1)));
  return v;
}

SimulationOptions tight(double p) {
  SimulationOptions o;
  o.rtol = 1e-10;
  o.atol = 1e-12;
  o.max_step = 0.05 / p;
  return o;
}

// outcome of one pulse run: overturned, whether an impact came before the overturn, and whether
// the run stopped (could not go on: neither safe nor overturned, so not counted as safe)
struct Outcome {
  bool overturned = false;
  bool after_impact = false;
  bool stopped = false;
};

Outcome run_outcome(const Body& body, const GroundMotion& m, const SimulationOptions& o) {
  const auto r = simulate(body, m, {}, o);
  Outcome out;
  out.overturned = flexrock::overturned(r);
  out.stopped = r.status == Status::kStopped;
  out.after_impact = out.overturned && r.extremes.impacts > 0;
  return out;
}

// smallest amplitude that overturns: a geometric grid from `lo` (factor `step`) finds the first
// overturning amplitude, then bisection to a relative 1e-5 between it and the last safe one
struct Threshold {
  double value = -1.0;  // [same unit as the amplitudes] -1: none below `hi`
  bool after_impact = false;
};

Threshold min_overturn(const std::function<Outcome(double)>& run, double lo, double hi,
                       double step) {
  double safe = lo, a = lo;
  Outcome o = run(a);
  while (!o.overturned) {
    safe = a;
    a *= step;
    if (a > hi) return {};
    o = run(a);
  }
  if (a == lo) return {lo, o.after_impact};
  double over = a;
  Outcome at_over = o;
  while (over - safe > 1e-5 * over) {
    const double mid = 0.5 * (safe + over);
    const Outcome m = run(mid);
    if (m.overturned) {
      over = mid;
      at_over = m;
    } else {
      safe = mid;
    }
  }
  return {over, at_over.after_impact};
}

std::vector<Event> of_kind(const SimulationResult& r, EventKind k) {
  std::vector<Event> out;
  for (const auto& e : r.events)
    if (e.kind == k) out.push_back(e);
  return out;
}

// 1. Housner (1963)
json housner() {
  json out;
  // restitution over slenderness: first impact of free rocking
  {
    json rows = json::array();
    for (double alpha : linspace(0.02, 0.7, quick ? 8 : 18)) {
      const Body body = block(alpha, 1.0);
      InitialState init;
      init.theta = 0.5 * alpha;
      auto o = tight(body.rocking_frequency());
      o.t_end = 20.0;
      o.max_impacts = 1;
      const auto r = simulate(body, GroundMotion::none(o.t_end), init, o);
      const auto imp = of_kind(r, EventKind::kImpact);
      if (imp.empty()) continue;
      rows.push_back(
          {{"alpha", alpha}, {"ratio", imp[0].theta_dot_after / imp[0].theta_dot_before}});
    }
    out["restitution"] = rows;
  }
  // free rocking: quarter period from the first impact time, and the decay of the peaks
  for (double alpha : {0.05, 0.35}) {
    const std::string key = alpha < 0.1 ? "slender" : "stocky";
    const Body body = block(alpha, 1.0);
    const double p = body.rocking_frequency();
    json rows = json::array();
    for (double x : linspace(0.05, 0.95, quick ? 7 : 19)) {
      InitialState init;
      init.theta = x * alpha;
      auto o = tight(p);
      o.rtol = 1e-12;
      o.atol = 1e-14;
      o.t_end = 60.0 / p;
      o.max_impacts = 1;
      const auto r = simulate(body, GroundMotion::none(o.t_end), init, o);
      const auto imp = of_kind(r, EventKind::kImpact);
      rows.push_back({{"theta0_over_alpha", x}, {"period", 4.0 * imp.at(0).time}});
    }
    InitialState init;
    init.theta = 0.8 * alpha;
    auto o = tight(p);
    o.rtol = 1e-12;
    o.atol = 1e-14;
    o.t_end = 200.0 / p;
    const auto r = simulate(body, GroundMotion::none(o.t_end), init, o);
    json peaks = json::array();
    for (const auto& e : of_kind(r, EventKind::kPeak)) peaks.push_back({e.time, std::abs(e.theta)});
    out["free_rocking"][key] = {
        {"alpha", alpha}, {"R", 1.0}, {"p", p}, {"periods", rows}, {"peaks", peaks}};
  }
  // minimum overturning acceleration: rectangular pulse over p t1, half-sine over omega_p/p
  for (double alpha : {0.05, 0.35}) {
    const std::string key = alpha < 0.1 ? "slender" : "stocky";
    const Body body = block(alpha, 1.0);
    const double p = body.rocking_frequency();
    json rect = json::array(), half = json::array();
    for (double pt1 : geomspace(0.1, 6.0, quick ? 6 : 14)) {
      const double t1 = pt1 / p;
      const auto th = min_overturn(
          [&](double A) {
            auto o = tight(p);
            o.t_end = t1 + 30.0 / p;
            return run_outcome(body, rectangular_pulse(A * g * alpha, t1, o.t_end), o);
          },
          0.999 * std::tan(alpha) / alpha, 1e4, 1.05);
      rect.push_back(
          {{"p_t1", pt1}, {"a_over_g_alpha", th.value}, {"after_impact", th.after_impact}});
    }
    for (double w : linspace(0.5, 8.0, quick ? 6 : 16)) {
      const double wp = w * p;
      const auto th = min_overturn(
          [&](double A) {
            auto o = tight(p);
            o.t_end = M_PI / wp + 30.0 / p;
            return run_outcome(body, half_sine_pulse(A * g * std::tan(alpha), wp, o.t_end), o);
          },
          1.0, 200.0, 1.04);
      half.push_back({{"omega_ratio", w}, {"A", th.value}, {"after_impact", th.after_impact}});
    }
    out["rectangular"][key] = {{"alpha", alpha}, {"p", p}, {"rows", rect}};
    out["half_sine"][key] = {{"alpha", alpha}, {"p", p}, {"rows", half}};
  }
  return out;
}

// 2. Zhang & Makris (2001): overturning maps and minimum overturning spectra
json zhang_makris() {
  json out;
  for (double alpha : {0.15, 0.25}) {
    const Body body = block(alpha, 1.0);
    const double p = body.rocking_frequency();
    for (int type : {0, 1}) {
      const std::string key = std::string(type == 0 ? "A" : "B") + "_" + std::to_string(alpha);
      auto pulse = [&](double A, double w) {
        const double wp = w * p, tp = 2 * M_PI / wp;
        const double dur = tp + 30.0 / p;
        const double ap = A * g * std::tan(alpha);
        return type == 0 ? cycloidal_pulse_a(ap, wp, dur) : cycloidal_pulse_b(ap, wp, dur);
      };
      auto run = [&](double A, double w) {
        const auto m = pulse(A, w);
        auto o = tight(p);
        o.rtol = 1e-9;
        o.atol = 1e-11;
        o.t_end = m.duration();
        // the pulse may reverse a body past its tipping angle: overturned only at pi/2
        o.overturn = OverturnCriterion::kHalfPi;
        return run_outcome(body, m, o);
      };
      // the map: 0 safe, 1 overturned after impacts, 2 overturned without impact, 3 stopped
      // (the run could not go on: unresolved)
      const auto ws = linspace(1.0, 10.0, quick ? 10 : 37);
      const auto As = linspace(1.0, 20.0, quick ? 12 : 58);
      json map = json::array();
      for (double A : As) {
        json row = json::array();
        for (double w : ws) {
          const auto o = run(A, w);
          row.push_back(o.overturned ? (o.after_impact ? 1 : 2) : (o.stopped ? 3 : 0));
        }
        map.push_back(row);
      }
      // the minimum overturning amplitude, refined
      json spectrum = json::array();
      for (double w : linspace(1.0, 10.0, quick ? 7 : 19)) {
        const auto th = min_overturn([&](double A) { return run(A, w); }, 1.0, 200.0, 1.03);
        spectrum.push_back(
            {{"omega_ratio", w}, {"A", th.value}, {"after_impact", th.after_impact}});
      }
      out[key] = {{"alpha", alpha},  {"p", p},     {"type", type == 0 ? "A" : "B"}, {"omega", ws},
                  {"amplitude", As}, {"map", map}, {"spectrum", spectrum}};
    }
  }
  return out;
}

// 3. Similarity: blocks of one alpha under the same dimensionless pulse, sampled in p t
json similarity() {
  json out = json::array();
  const double alpha = 0.15, w = 4.0, A = 1.5;
  for (double R : {0.5, 2.0, 8.0, 3.3}) {
    const Body body = block(alpha, R);
    const double p = body.rocking_frequency();
    auto o = tight(p);
    o.atol = 1e-15;
    o.t_end = 40.0 / p;
    o.output_dt = 0.05 / p;
    const auto m = cycloidal_pulse_a(A * g * std::tan(alpha), w * p, o.t_end);
    const auto r = simulate(body, m, {}, o);
    json tau = json::array(), th = json::array();
    for (std::size_t i = 0; i < r.history.size(); ++i) {
      tau.push_back(p * r.history.time[i]);
      th.push_back(r.history.theta[i] / alpha);
    }
    out.push_back({{"R", R},
                   {"p", p},
                   {"tau", tau},
                   {"theta_over_alpha", th},
                   {"impacts", r.extremes.impacts}});
  }
  return out;
}

// oscillator on a slab: the body of section 4
struct Osc {
  double m = 1000, m0 = 500, H = 3.0, width = 1.2, f = 2.0, zeta = 0.05;
  Body body() const { return Body(oscillator_on_slab(m, f, m0, H, width, zeta)); }
};

// 4. Flexible bodies
json flexible() {
  json out;
  // steady-state uplift amplitude over frequency ratio and damping, by bisection from the
  // steady state (no transient)
  {
    json rows = json::array();
    for (double zeta : {0.02, 0.05, 0.10}) {
      Osc os;
      os.zeta = zeta;
      const Body body = os.body();
      const double wn = 2 * M_PI * os.f, k = os.m * wn * wn, c = 2 * zeta * wn * os.m;
      const double h = body.params().height;
      for (double r : geomspace(0.25, 3.0, quick ? 6 : 17)) {
        const double w = r * wn;
        auto uplifts = [&](double A) {
          // steady state of m u'' + c u' + k u = -m A sin(w t)
          const double den = (k - os.m * w * w) * (k - os.m * w * w) + c * c * w * w;
          const double re = -os.m * A * (k - os.m * w * w) / den, im = os.m * A * c * w / den;
          InitialState init;
          // U = re + i im (u = Im(U e^{iwt})): u(0) = im, u'(0) = w re
          init.q = VectorX::Constant(1, im / h);
          init.q_dot = VectorX::Constant(1, w * re / h);
          SimulationOptions o;
          o.t_end = 8 * 2 * M_PI / w;
          const auto res = simulate(body, harmonic(A, w, o.t_end), init, o);
          return res.extremes.first_uplift_time >= 0.0;
        };
        double lo = 0.0, hi = 4 * g * body.alpha1();
        while (!uplifts(hi)) hi *= 2;
        while (hi - lo > 1e-6 * hi) {
          const double mid = 0.5 * (lo + hi);
          (uplifts(mid) ? hi : lo) = mid;
        }
        rows.push_back({{"zeta", zeta}, {"r", r}, {"A_over_g", hi / g}});
      }
    }
    const Osc os;
    out["uplift"] = {{"m", os.m},           {"m0", os.m0}, {"H", os.H},
                     {"b", 0.5 * os.width}, {"f", os.f},   {"rows", rows}};
  }
  // static criterion (Chopra & Yim 1985): a slow ramp, started on its particular solution
  {
    json rows = json::array();
    for (double f : {0.5, 1.0, 2.0, 5.0, 20.0}) {
      Osc os;
      os.f = f;
      os.zeta = 0.2;
      const Body body = os.body();
      const double h = body.params().height;
      const double wn = 2 * M_PI * f, rate = 0.05 * g;
      InitialState init;
      // u_p = -(rate/wn^2)(t - 2 zeta/wn)
      init.q = VectorX::Constant(1, rate * 2 * os.zeta / (wn * wn * wn) / h);
      init.q_dot = VectorX::Constant(1, -rate / (wn * wn) / h);
      SimulationOptions o;
      o.t_end = 40.0;
      const auto m = GroundMotion::analytic(
          [&](double t) {
            return BaseAcceleration{rate * t, 0};
          },
          o.t_end);
      const auto r = simulate(body, m, init, o);
      rows.push_back({{"f", f},
                      {"zeta", os.zeta},
                      {"rate", rate},
                      {"A_over_g", rate * r.extremes.first_uplift_time / g}});
    }
    const Osc os;
    out["static"] = {
        {"m", os.m}, {"m0", os.m0}, {"H", os.H}, {"b", 0.5 * os.width}, {"rows", rows}};
  }
  // overturning spectra of one-sine pulses: rigid body of the same mass distribution vs flexible
  {
    Osc base;
    base.width = 0.6;  // b/h = 0.15
    const Body ref = base.body();
    const auto& pr = ref.params();
    const Body rigid(taken_rigid(pr));
    const double p = rigid.rocking_frequency(), alpha = rigid.alpha1();
    json curves = json::array();
    for (double f : {0.0, 5.0, 2.0, 1.0}) {
      Osc os = base;
      os.f = f;
      const Body body = f > 0 ? os.body() : rigid;
      json rows = json::array();
      for (double w : linspace(1.0, 10.0, quick ? 5 : 13)) {
        const double wp = w * p;
        const auto th = min_overturn(
            [&](double A) {
              auto o = tight(p);
              o.rtol = 1e-9;
              o.atol = 1e-11;
              o.t_end = 2 * M_PI / wp + 30.0 / p;
              o.overturn = OverturnCriterion::kHalfPi;
              return run_outcome(body, one_sine_pulse(A * g * alpha, wp, o.t_end), o);
            },
            0.3, 60.0, 1.04);
        rows.push_back({{"omega_ratio", w}, {"A", th.value}, {"after_impact", th.after_impact}});
      }
      curves.push_back(
          {{"f", f}, {"omega_n_over_p", f > 0 ? 2 * M_PI * f / p : -1.0}, {"rows", rows}});
    }
    out["spectra"] = {
        {"alpha", alpha}, {"p", p}, {"H", base.H}, {"b", 0.5 * base.width}, {"curves", curves}};
  }
  // energy lost at the first impact of free rocking: flexible over rigid
  {
    Osc base;
    base.width = 0.6;
    base.zeta = 0.0;
    const Body ref = base.body();
    const auto& pr = ref.params();
    const Body rigid(taken_rigid(pr));
    const double p = rigid.rocking_frequency();
    struct Landing {
      double loss = -1.0;                 // [J] energy lost at the first landing
      double ratio = 0.0;                 // its theta_dot+/theta_dot-
      std::string kind, status, message;  // its event kind, how the run ended and why
    };
    auto first_loss = [&](const Body& body, ImpactLaw law = ImpactLaw::kPaper) {
      InitialState init;
      init.theta = 0.5 * body.tipping_angle(1);
      auto o = tight(p);
      o.impact_law = law;
      o.t_end = 30.0 / p;
      o.max_impacts = 1;
      const auto r = simulate(body, GroundMotion::none(o.t_end), init, o);
      // a flexible body may land on both edges (the both-edges rule): that is its impact too
      for (const auto& e : r.events)
        if (e.kind == EventKind::kImpact || e.kind == EventKind::kRockingEnded)
          return Landing{e.energy_loss, e.theta_dot_after / e.theta_dot_before, to_string(e.kind),
                         to_string(r.status), r.message};
      return Landing{-1.0, 0.0, "", to_string(r.status), r.message};
    };
    const Landing l_rigid = first_loss(rigid);
    const double e_rigid = l_rigid.loss;
    json rows = json::array();
    for (double f : geomspace(0.5, 50.0, quick ? 5 : 11)) {
      Osc os = base;
      os.f = f;
      const Landing l = first_loss(os.body());
      // the same landing under the law for which the body is rigid during the impact
      const Landing lr = first_loss(os.body(), ImpactLaw::kRigidBody);
      rows.push_back({{"f", f},
                      {"omega_n_over_p", 2 * M_PI * f / p},
                      {"loss_ratio", l.loss / e_rigid},
                      {"event", l.kind},
                      {"status", l.status},
                      {"message", l.message},
                      {"rigid_body_loss_ratio", lr.loss / e_rigid},
                      {"rigid_body_event", lr.kind},
                      {"rigid_body_ratio_over_housner", lr.ratio / l_rigid.ratio}});
    }
    out["impact_energy"] = {{"rigid_loss", e_rigid}, {"rows", rows}};
  }
  return out;
}

// 5. The engine's side of the compliant-foundation comparison (the model is in compliant.py)
json foundation() {
  json out = json::array();
  struct Case {
    const char* name;
    bool flexible;
    double omega_ratio, A;  // one-sine pulse: omega_p/p, a_p/(g tan alpha)
  };
  for (const Case& c :
       {Case{"block_rocking", false, 4.0, 1.5}, Case{"block_overturn", false, 2.0, 1.7},
        Case{"oscillator_rocking", true, 4.0, 1.5}}) {
    Osc os;
    os.width = 0.6;
    const Body body = c.flexible ? os.body() : block(0.15, 1.0);
    // p and alpha of the rigid body with the same mass distribution
    const auto& pr = body.params();
    const Body rigid(taken_rigid(pr));
    const double p = rigid.rocking_frequency(), alpha = std::atan(rigid.alpha1());
    const double wp = c.omega_ratio * p;
    SimulationOptions o = tight(p);
    o.t_end = 2 * M_PI / wp + 12.0 / p;
    o.output_dt = 0.01;
    o.overturn = OverturnCriterion::kHalfPi;
    const auto r = simulate(body, one_sine_pulse(c.A * g * std::tan(alpha), wp, o.t_end), {}, o);
    json imp = json::array(), th = json::array();
    for (const auto& e : r.events)
      if (e.kind == EventKind::kImpact || e.kind == EventKind::kRockingEnded) imp.push_back(e.time);
    for (double v : r.history.theta) th.push_back(v);
    out.push_back({{"name", c.name},
                   {"flexible", c.flexible},
                   {"omega_ratio", c.omega_ratio},
                   {"A", c.A},
                   {"alpha", alpha},
                   {"tipping_angle", body.tipping_angle(1)},
                   {"p", p},
                   {"t_end", o.t_end},
                   {"first_uplift", r.extremes.first_uplift_time},
                   {"max_theta", std::max(r.extremes.max_theta_edge1, r.extremes.max_theta_edge2)},
                   {"impact_times", imp},
                   {"status", to_string(r.status)},
                   {"t_stop", r.t_end},
                   {"history_dt", 0.01},
                   {"theta", th}});
  }
  return out;
}

// 6. Records: scale sweeps and convergence
json records(const std::string& data_dir) {
  json out;
  const auto elc =
      io::read_single_column(data_dir + "/elcentro_1940_ns.dat", 0.02, io::AccelUnit::kG);
  const auto kobe = io::read_at2(data_dir + "/kobe_1995_nishi_akashi_090.AT2");
  Osc os;
  os.width = 0.6;
  os.f = 2.0;
  const Body flex = os.body();
  const Body rigid = block(0.15, 1.5);
  struct Named {
    std::string name;
    const io::Record* rec;
  };
  for (const auto& [name, rec] : {Named{"elcentro", &elc}, Named{"kobe", &kobe}}) {
    for (int which : {0, 1}) {
      const Body& body = which == 0 ? rigid : flex;
      const std::string key = name + (which == 0 ? "_rigid" : "_flexible");
      const double alpha = body.alpha1();
      auto opts = [&](double rtol) {
        SimulationOptions o;
        o.rtol = rtol;
        o.atol = rtol * 1e-2;
        o.overturn = OverturnCriterion::kHalfPi;
        return o;
      };
      // scale sweep at two tolerances
      json sweep = json::array();
      double first_over[2] = {-1, -1};
      for (double s : linspace(0.1, quick ? 2.0 : 3.0, quick ? 20 : 59)) {
        const auto m = rec->to_motion(s);
        json row = {{"scale", s}};
        int i = 0;
        for (double rtol : {1e-8, 1e-10}) {
          const auto r = simulate(body, m, {}, opts(rtol));
          const double mt = std::max(r.extremes.max_theta_edge1, r.extremes.max_theta_edge2);
          const bool over = flexrock::overturned(r);
          if (over && first_over[i] < 0) first_over[i] = s;
          row[i == 0 ? "loose" : "tight"] = {{"max_theta_over_alpha", mt / alpha},
                                             {"overturned", over},
                                             {"status", to_string(r.status)},
                                             {"impacts", r.extremes.impacts}};
          ++i;
        }
        sweep.push_back(row);
      }
      // event-by-event convergence at one scale with rocking but no overturning
      json conv = json::array();
      const double s_over = first_over[1] > 0 ? first_over[1] : 3.0;
      for (double s_conv : {0.6 * s_over, 0.95 * s_over})
        for (double rtol : {1e-6, 1e-8, 1e-10, 1e-12}) {
          auto o = opts(rtol);
          o.output_dt = 0.01;
          const auto r = simulate(body, rec->to_motion(s_conv), {}, o);
          json imp = json::array();
          for (const auto& e : r.events)
            if (e.kind == EventKind::kImpact || e.kind == EventKind::kRockingEnded)
              imp.push_back(e.time);
          json th = json::array();
          for (double v : r.history.theta) th.push_back(v / alpha);
          conv.push_back(
              {{"scale", s_conv},
               {"rtol", rtol},
               {"first_uplift", r.extremes.first_uplift_time},
               {"impact_times", imp},
               {"max_theta_over_alpha",
                std::max(r.extremes.max_theta_edge1, r.extremes.max_theta_edge2) / alpha},
               {"status", to_string(r.status)},
               {"dt", 0.01},
               {"theta_over_alpha", th}});
        }
      out[key] = {{"alpha", alpha},
                  {"p", body.rocking_frequency()},
                  {"sweep", sweep},
                  {"first_overturn_scale_loose", first_over[0]},
                  {"first_overturn_scale_tight", first_over[1]},
                  {"convergence", conv}};
    }
  }
  return out;
}

}  // namespace
}  // namespace flexrock::validation

int main(int argc, char** argv) {
  using namespace flexrock::validation;
  std::string out_dir = ".", data_dir = "../shared/data", only;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--out" && i + 1 < argc) {
      out_dir = argv[++i];
    } else if (a == "--data" && i + 1 < argc) {
      data_dir = argv[++i];
    } else if (a == "--only" && i + 1 < argc) {
      only = argv[++i];
    } else if (a == "--quick") {
      quick = true;
    } else {
      std::fprintf(
          stderr, "usage: flexrock_validate [--out DIR] [--data DIR] [--only SECTION] [--quick]\n");
      return 2;
    }
  }
  try {
    json j;
    j["quick"] = quick;
    auto section = [&](const char* name, const std::function<json()>& f) {
      if (!only.empty() && only != name) return;
      std::fprintf(stderr, "flexrock_validate: %s\n", name);
      j[name] = f();
    };
    section("housner", housner);
    section("zhang_makris", zhang_makris);
    section("similarity", similarity);
    section("flexible", flexible);
    section("foundation", foundation);
    section("records", [&] { return records(data_dir); });
    const std::string name = only.empty() ? "validation.json" : "validation_" + only + ".json";
    flexrock::io::write_atomically(out_dir + "/" + name, [&](std::ostream& s) { s << j.dump(); });
  } catch (const std::exception& e) {
    std::fprintf(stderr, "flexrock_validate: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
