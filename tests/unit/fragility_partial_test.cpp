// SPDX-License-Identifier: BSD-3-Clause
// A fragility study with one body that never fails and one damage state that cannot be fitted:
// the others are fitted exactly as they are alone, the fit CSV has their rows only, and each
// left-out body or state keeps its reason; nothing fitted at all is an error naming them all.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "flexrock/io/fragility_session.hpp"
#include "support/expect_error.hpp"

namespace flexrock::io {
namespace {

// body "b" rocks and overturns over the PGA range; body "never" rocks at every level
CsvTable table(bool with_never = true) {
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
      {"never", "r1", "1", "rocking", "0", "0.1"},
      {"never", "r2", "2", "rocking", "0", "0.2"},
      {"never", "r1", "3", "rocking", "0", "0.3"},
      {"never", "r2", "4", "rocking", "0", "0.4"},
  };
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (!with_never && rows[i][0] == "never") continue;
    t.rows.push_back(rows[i]);
    t.lines.push_back(i + 2);
  }
  return t;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

TEST(FragilityPartial, ABodyThatNeverFailsLeavesTheOtherFitted) {
  const FragilitySession s(table(), FragilityOptions{});
  ASSERT_EQ(s.bodies(), 2u);
  EXPECT_TRUE(s.fitted(0, 0));
  EXPECT_FALSE(s.fitted(0, 1));
  EXPECT_EQ(s.fitted_count(), 1u);
  // the reason, with the file and the body
  EXPECT_NE(s.not_fitted(0, 1).find("sweep.csv: body 'never': "), std::string::npos);
  EXPECT_NE(s.not_fitted(0, 1).find("is 0"), std::string::npos) << s.not_fitted(0, 1);
  test::expect_input_error([&] { (void)s.fit(0, 1); }, {"body 'never'"});
  // the fitted body as it is alone
  const FragilitySession alone(table(false), FragilityOptions{});
  EXPECT_EQ(s.fit(0, 0).theta, alone.fit(0, 0).theta);
  EXPECT_EQ(s.fit(0, 0).beta, alone.fit(0, 0).beta);
  // its row only
  std::ostringstream out, out_alone;
  s.write_fits(out);
  alone.write_fits(out_alone);
  EXPECT_EQ(out.str(), out_alone.str());
  EXPECT_EQ(lines_of(out.str()).size(), 2u);
}

TEST(FragilityPartial, AnUnfittableStateLeavesTheOtherStatesFitted) {
  // theta/alpha > 0.05: every run of "b" exceeds it but the first (no_uplift, 0): a single
  // non-failure below every failure separates them perfectly; overturning fits
  FragilityOptions o;
  o.states = {damage_state("theta:0.05"), damage_state("overturned")};
  o.body = std::string(1, 'b');  // not = "b": GCC 12 warns falsely on it here (PR 105651)
  const FragilitySession s(table(), o);
  EXPECT_FALSE(s.fitted(0, 0));
  EXPECT_TRUE(s.fitted(1, 0));
  EXPECT_NE(s.not_fitted(0, 0).find("body 'b', state 'theta:0.05'"), std::string::npos);
  EXPECT_NE(s.not_fitted(0, 0).find("perfectly separated"), std::string::npos)
      << s.not_fitted(0, 0);
  // no order note pairs a state without a fit
  EXPECT_TRUE(s.order_notes().empty());
  std::ostringstream out;
  s.write_fits(out);
  const std::vector<std::string> rows = lines_of(out.str());
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1].rfind("b,overturned,", 0), 0u) << rows[1];
}

TEST(FragilityPartial, NothingFittedIsAnErrorNamingEveryBodyAndState) {
  FragilityOptions o;
  o.states = {damage_state("theta:0.05")};
  test::expect_input_error([&] { (void)FragilitySession(table(), o); },
                           {"nothing could be fitted:", "body 'b', state 'theta:0.05'",
                            "body 'never', state 'theta:0.05'"});
  // one body alone: its reason as it was
  o.body = "never";
  o.states = {};
  test::expect_input_error([&] { (void)FragilitySession(table(), o); },
                           {"sweep.csv: body 'never': ", "is 0"});
}

}  // namespace
}  // namespace flexrock::io
