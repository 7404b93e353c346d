// SPDX-License-Identifier: BSD-3-Clause
// The names of the study enumerations come from one table each (core/enum_names.hpp): every value
// has one name, every name reads back to its value, and a name no table holds is refused by the
// readers of study files.
#include <gtest/gtest.h>

#include <cstddef>
#include <set>
#include <string>

#include "flexrock/io/records.hpp"
#include "flexrock/io/study_files.hpp"
#include "flexrock/study/outcome.hpp"
#include "flexrock/study/spectrum.hpp"
#include "flexrock/study/uncertain.hpp"
#include "support/expect_error.hpp"

namespace flexrock {
namespace {

// every row's name is distinct and reads back to its value; `count` rows (the enumerators)
template <class E, std::size_t N>
void expect_bijection(const EnumName<E> (&table)[N], std::size_t count) {
  EXPECT_EQ(N, count);
  std::set<std::string> names;
  for (const EnumName<E>& row : table) {
    EXPECT_TRUE(names.insert(row.name).second) << "name twice: " << row.name;
    EXPECT_EQ(value_named(table, row.name), row.value) << row.name;
    EXPECT_STREQ(name_of(table, row.value), row.name);
  }
  EXPECT_FALSE(value_named(table, "unknown").has_value());
}

TEST(StudyNames, EveryEnumerationIsOneTableReadBothWays) {
  expect_bijection(study::kOutcomeNames, static_cast<std::size_t>(study::Outcome::kStopped) + 1);
  expect_bijection(study::kRegimeNames,
                   static_cast<std::size_t>(study::Regime::kSlidingRocking) + 1);
  expect_bijection(study::kBoundaryKindNames,
                   static_cast<std::size_t>(study::OverturnBoundary::Kind::kNone) + 1);
  expect_bijection(study::kDistributionNames,
                   static_cast<std::size_t>(study::Distribution::kLognormal) + 1);
  EXPECT_STREQ(study::to_string(study::Outcome::kOverturnedAfterImpacts),
               "overturned_after_impacts");
  EXPECT_STREQ(study::to_string(study::Regime::kSlidingRocking), "sliding_rocking");
}

TEST(StudyNames, AccelerationUnitsNameAndSizeFromOneTable) {
  EXPECT_EQ(std::size(io::kAccelUnits),
            static_cast<std::size_t>(io::AccelUnit::kCentimetersPerSecond2) + 1);
  EXPECT_EQ(io::unit_name(io::AccelUnit::kG), "g");
  EXPECT_EQ(io::to_si_factor(io::AccelUnit::kG), kStandardGravity);
  EXPECT_EQ(io::unit_name(io::AccelUnit::kCentimetersPerSecond2), "cm/s^2");
  EXPECT_EQ(io::to_si_factor(io::AccelUnit::kCentimetersPerSecond2), 0.01);
}

// "unknown", what a name lookup gives for a value it lacks, is no outcome a sweep writes
TEST(StudyNames, ASweepRowWithAnUnknownOutcomeIsRefused) {
  io::CsvTable t;
  t.source = "sweep.csv";
  t.columns = {"index", "outcome", "overturned"};
  t.rows = {{"0", "rocking", "0"}};
  t.lines = {2};
  io::check_sweep_table(t);
  t.rows = {{"0", "unknown", "0"}};
  test::expect_input_error([&] { io::check_sweep_table(t); },
                           {"sweep.csv:2", "unknown outcome \"unknown\""});
}

}  // namespace
}  // namespace flexrock
