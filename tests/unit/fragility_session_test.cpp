// SPDX-License-Identifier: BSD-3-Clause
// The fragility session: typed damage states over a sweep table held in memory, each state's
// observations as the rows define them, fits equal to the library's fit of those observations,
// the fit CSV with its state column, and the option errors of `flexrock fragility`.
#include "flexrock/io/fragility_session.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "support/expect_error.hpp"

namespace flexrock::io {
namespace {

// eight runs of one body: tilt ratio and overturning grow with the PGA, not monotonically
CsvTable table() {
  CsvTable t;
  t.source = "sweep.csv";
  t.columns = {"body", "record", "pga_m_per_s2", "outcome", "overturned", "max_theta_over_alpha"};
  const std::vector<std::vector<std::string>> rows = {
      {"b", "r1", "1", "no_uplift", "0", "0"},
      {"b", "r2", "1.5", "rocking", "0", "0.6"},
      {"b", "r1", "2", "rocking", "0", "0.3"},
      {"b", "r2", "2.5", "overturned_after_impacts", "1", "1e9"},
      {"b", "r1", "3", "rocking", "0", "0.8"},
      {"b", "r2", "3.5", "rocking", "0", "0.9"},
      {"b", "r1", "4", "overturned_without_impact", "1", "1e9"},
      {"b", "r2", "4.5", "stopped", "0", "0.1"},
  };
  for (std::size_t i = 0; i < rows.size(); ++i) {
    t.rows.push_back(rows[i]);
    t.lines.push_back(i + 2);
  }
  return t;
}

TEST(FragilitySession, FitsEveryStateAsTheLibraryFitsItsObservations) {
  FragilityOptions o;
  o.states = {damage_state("theta:0.5"), damage_state("overturned")};
  const FragilitySession s(table(), o);
  ASSERT_TRUE(s.several());
  ASSERT_EQ(s.bodies(), 1u);
  EXPECT_EQ(s.states()[0].outcome, FragilityOutcome::kTheta);
  EXPECT_EQ(s.measure().kind, FragilityMeasureKind::kPga);
  EXPECT_EQ(s.unit(), "m/s^2");
  // theta/alpha > 0.5, or overturned; the stopped run is left out
  EXPECT_EQ(s.data(0, 0).im, (std::vector<double>{1, 1.5, 2, 2.5, 3, 3.5, 4}));
  EXPECT_EQ(s.data(0, 0).failed, (std::vector<int>{0, 1, 0, 1, 1, 1, 1}));
  EXPECT_EQ(s.data(1, 0).failed, (std::vector<int>{0, 0, 0, 1, 0, 0, 1}));
  EXPECT_EQ(s.data(1, 0).excluded, 1u);
  for (std::size_t st = 0; st < 2; ++st) {
    const study::FragilityFit f = study::fit_lognormal(s.data(st, 0).im, s.data(st, 0).failed);
    EXPECT_EQ(s.fit(st, 0).theta, f.theta);
    EXPECT_EQ(s.fit(st, 0).beta, f.beta);
  }
  // the fit CSV: the state column after the body, one row per state
  std::ostringstream out;
  s.write_fits(out);
  std::istringstream in(out.str());
  std::string header, first, second, extra;
  std::getline(in, header);
  std::getline(in, first);
  std::getline(in, second);
  EXPECT_FALSE(std::getline(in, extra));
  EXPECT_EQ(header.rfind("body,state,samples,failures,excluded,theta,", 0), 0u) << header;
  EXPECT_EQ(first, fragility_state_row(s.data(0, 0), s.fit(0, 0), "theta:0.5"));
  EXPECT_EQ(second, fragility_state_row(s.data(1, 0), s.fit(1, 0), "overturned"));
  // the more severe state lies below: its median is the larger
  for (const FragilityOrderNote& n : s.order_notes()) EXPECT_FALSE(n.medians_cross);
}

TEST(FragilitySession, RefusesOptionsAsTheCommandLineNamesThem) {
  FragilityOptions o;
  o.states = {damage_state("uplift"), damage_state("uplift")};
  test::expect_input_error([&] { (void)FragilitySession(table(), o); },
                           {"--state 'uplift': given twice"});
  o = FragilityOptions{};
  o.outcome = FragilityOutcome::kEnergy;
  test::expect_input_error([&] { (void)FragilitySession(table(), o); },
                           {"--level: expected a number > 0 with --outcome energy"});
  o = FragilityOptions{};
  o.confidence = 1.0;
  test::expect_input_error([&] { (void)FragilitySession(table(), o); },
                           {"--confidence: expected a number in (0, 1), got 1"});
  o = FragilityOptions{};
  o.analysis = FragilityAnalysis::kStripes;
  o.im_given = true;
  test::expect_input_error([&] { (void)FragilitySession(table(), o); },
                           {"--analysis msa", "--im pga"});
  // without --im a stripe analysis reads the requested levels, which this table lacks
  o.im_given = false;
  test::expect_input_error([&] { (void)FragilitySession(table(), o); },
                           {"sweep.csv:1", "'requested_level'"});
}

}  // namespace
}  // namespace flexrock::io
