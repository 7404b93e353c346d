// SPDX-License-Identifier: BSD-3-Clause
// Messages of the study and excitation layers give the numbers they refuse as the user wrote them
// (format_number: the shortest text that reads back to the same double), never as a fixed count
// of decimals that turns a tolerance of 1e-15 into "0.000000".
#include <gtest/gtest.h>

#include <vector>

#include "flexrock/excitation/ground_motion.hpp"
#include "flexrock/model/body.hpp"
#include "flexrock/model/builders.hpp"
#include "flexrock/study/fragility.hpp"
#include "flexrock/study/spectrum.hpp"
#include "support/expect_error.hpp"

namespace flexrock::study {
namespace {

using test::expect_input_error;

TEST(StudyMessages, ABisectionToleranceBelowTheFloorIsNamedAsWritten) {
  const Body body(rigid_block(0.4, 2.0, 1000.0));
  SpectrumSpec spec;
  spec.amplitudes = {1.0, 2.0};
  spec.frequencies = {2.0};
  spec.bisection_tolerance = 1e-15;
  expect_input_error([&] { spectrum_grid(body, spec); }, {"bisection_tolerance", "got 1e-15 "});
}

TEST(StudyMessages, ASpectrumGridValueIsNamedAsWritten) {
  const Body body(rigid_block(0.4, 2.0, 1000.0));
  SpectrumSpec spec;
  spec.amplitudes = {1.0, 2.0};
  spec.frequencies = {-2.5e-7};
  expect_input_error([&] { spectrum_grid(body, spec); }, {"frequencies[0]", "got -2.5e-07"});
}

TEST(StudyMessages, AFragilityObservationIsNamedAsWritten) {
  expect_input_error(
      [] {
        fit_lognormal({0.5, -1e-9, 0.7}, {0, 1, 1});
      },
      {"observation 2", "got -1e-09"});
}

TEST(StudyMessages, ACapacityIntervalIsNamedAsWritten) {
  expect_input_error(
      [] {
        fit_capacity_intervals({{0.25, 0.125}, {0.5, 0.75}});
      },
      {"record 1", "got (0.25, 0.125]"});
}

TEST(StudyMessages, AGroundMotionStepIsNamedAsWritten) {
  expect_input_error([] { GroundMotion::uniform(-1e-12, {0.0, 1.0}); }, {"got -1e-12"});
  expect_input_error([] { GroundMotion::none(-0.125); }, {"got -0.125"});
}

}  // namespace
}  // namespace flexrock::study
