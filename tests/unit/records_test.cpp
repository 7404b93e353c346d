// SPDX-License-Identifier: BSD-3-Clause
// Record readers: the real records of shared/data, every AT2 line-4 form, malformed files with
// their messages, units and scale factors, and combining horizontal and vertical components.
#include "flexrock/io/records.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

#include "flexrock/core/error.hpp"
#include "flexrock/core/types.hpp"
#include "support/expect_error.hpp"

namespace flexrock::io {
namespace {

namespace fs = std::filesystem;

const std::string kData = FLEXROCK_SOURCE_DIR "/../shared/data/";

using test::expect_input_error;

// a fresh temporary directory per test, removed afterwards
class TempDir : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string("flexrock_") + info->test_suite_name() + "_" + info->name();
    for (char& c : name) {
      if (c == '/') c = '_';
    }
    dir_ = fs::temp_directory_path() / name;
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // writes `content` byte for byte to dir/name and returns the path
  std::string write(const std::string& name, const std::string& content) const {
    const fs::path p = dir_ / name;
    std::ofstream out(p, std::ios::binary);
    out << content;
    return p.string();
  }

  fs::path dir_;
};

// an AT2 file with the given line 4 and values text
std::string at2(const std::string& line4, const std::string& values,
                const std::string& units_line = "ACCELERATION TIME HISTORY IN UNITS OF G") {
  return "PEER NGA STRONG MOTION DATABASE RECORD\n"
         "KOBE 01/16/95 2046, NISHI-AKASHI, 090 (CUE)\n" +
         units_line + "\n" + line4 + "\n" + values;
}

const std::string kSixValues =
    "   0.100000E-01   0.200000E-01  -0.300000E-01   0.400000E-01   0.500000E-01\n"
    "  -0.600000E-01\n";

// ---- real records ----------------------------------------------------------------------------

TEST(RealRecords, KobeAt2HasExactCountStepPeakAndEndValues) {
  const Record r = read_at2(kData + "kobe_1995_nishi_akashi_090.AT2");
  EXPECT_EQ(r.npts(), 4096u);
  EXPECT_DOUBLE_EQ(r.dt, 0.01);
  EXPECT_EQ(r.units, AccelUnit::kG);
  ASSERT_EQ(r.time.size(), 4096u);
  EXPECT_DOUBLE_EQ(r.time.front(), 0.0);
  EXPECT_DOUBLE_EQ(r.values.front(), 0.233833e-06);
  EXPECT_DOUBLE_EQ(r.values.back(), 0.496963e-04);
  const std::size_t k = r.peak_index();
  // the file holds -0.502749 g; SOURCE.md rounds it to 0.5028 g (0.5027 would be the nearest)
  EXPECT_DOUBLE_EQ(r.values[k], -0.502749);
  EXPECT_NEAR(std::abs(r.values[k]), 0.5028, 1e-4);
  EXPECT_NEAR(r.time[k], 7.09, 1e-12);
  ASSERT_EQ(r.header.size(), 4u);
  EXPECT_EQ(r.header[0], "PEER NGA STRONG MOTION DATABASE RECORD");
}

TEST(RealRecords, ElCentroSingleColumnKeepsZeroPadAndPeak) {
  const Record r = read_single_column(kData + "elcentro_1940_ns.dat", 0.02, AccelUnit::kG);
  EXPECT_EQ(r.npts(), 1560u);
  EXPECT_DOUBLE_EQ(r.dt, 0.02);
  EXPECT_DOUBLE_EQ(r.values.front(), 0.00630);
  EXPECT_DOUBLE_EQ(r.values.back(), 0.0);
  const std::size_t k = r.peak_index();
  EXPECT_DOUBLE_EQ(r.values[k], -0.31882);
  EXPECT_NEAR(std::abs(r.values[k]), 0.3188, 5e-5);
  EXPECT_NEAR(r.time[k], 2.02, 1e-12);
  // 6 leading comment lines plus "#*** End Data ***"
  ASSERT_EQ(r.header.size(), 7u);
  EXPECT_EQ(r.header.back(), "#*** End Data ***");
}

TEST(RealRecords, KobeMotionIsInMetresPerSecondSquared) {
  const Record r = read_at2(kData + "kobe_1995_nishi_akashi_090.AT2");
  const GroundMotion m = r.to_motion();
  EXPECT_EQ(m.samples(), 4096u);
  EXPECT_NEAR(m.duration(), 40.95, 1e-9);
  EXPECT_NEAR(std::abs(m.at(7.09).x), 0.502749 * kStandardGravity, 1e-9);
  EXPECT_DOUBLE_EQ(m.at(7.09).y, 0.0);
}

// ---- AT2 line 4: every form of SOURCE.md --------------------------------------------------------

struct Line4Case {
  const char* name;
  const char* line4;
};

class At2Line4 : public TempDir, public ::testing::WithParamInterface<Line4Case> {};

TEST_P(At2Line4, ReadsNptsAndDt) {
  const std::string path = write("r.AT2", at2(GetParam().line4, kSixValues));
  const Record r = read_at2(path);
  EXPECT_EQ(r.npts(), 6u);
  EXPECT_DOUBLE_EQ(r.dt, 0.01);
  EXPECT_DOUBLE_EQ(r.values[2], -0.03);
  EXPECT_DOUBLE_EQ(r.time[5], 0.05);
}

INSTANTIATE_TEST_SUITE_P(
    AllForms, At2Line4,
    ::testing::Values(Line4Case{"CountsThenLabels", "6    0.0100    NPTS, DT"},
                      Line4Case{"DtFirstThenLabels", "0.0100    6    DT, NPTS"},
                      Line4Case{"NgaWest2", "NPTS=      6, DT=   .0100 SEC,"},
                      Line4Case{"DtBeforeNpts", "DT=   .0100 SEC, NPTS=      6,"},
                      Line4Case{"NoCommas", "NPTS=      6 DT=   .0100 SEC"},
                      Line4Case{"NoEqualsSigns", "NPTS   6   DT   .0100"},
                      Line4Case{"Unlabelled", "6    0.0100"},
                      Line4Case{"UnlabelledDtFirst", "0.0100    6"},
                      Line4Case{"LowerCaseAndGluedSec", "npts=6, dt=0.0100sec"}),
    [](const ::testing::TestParamInfo<Line4Case>& p) { return std::string(p.param.name); });

// ---- AT2: accepted variations -----------------------------------------------------------------

class At2Reader : public TempDir {};

TEST_F(At2Reader, AcceptsNgaWest2HeaderWithThreeFieldLine2) {
  const std::string text =
      "PEER NGA STRONG MOTION DATABASE RECORD\n"
      "Northridge-01, 1/17/1994, Newhall - Fire Sta, 90\n"
      "ACCELERATION TIME SERIES IN UNITS OF G\n"
      "NPTS=      6, DT=   .0100 SEC,\n" +
      kSixValues;
  const Record r = read_at2(write("west2.AT2", text));
  EXPECT_EQ(r.npts(), 6u);
  EXPECT_EQ(r.units, AccelUnit::kG);
}

TEST_F(At2Reader, AcceptsENotationWithoutLeadingZeroAndSigns) {
  const Record r =
      read_at2(write("e.AT2", at2("NPTS= 4, DT= .005 SEC", " .1394908E-02 -.25E+01 +1.5e-3 7\n")));
  ASSERT_EQ(r.npts(), 4u);
  EXPECT_DOUBLE_EQ(r.values[0], 0.1394908e-02);
  EXPECT_DOUBLE_EQ(r.values[1], -2.5);
  EXPECT_DOUBLE_EQ(r.values[2], 1.5e-3);
  EXPECT_DOUBLE_EQ(r.values[3], 7.0);
  EXPECT_DOUBLE_EQ(r.dt, 0.005);
}

TEST_F(At2Reader, AcceptsCrlfTrailingBlanksAndWhitespaceOnlyLastLine) {
  const std::string text =
      "PEER NGA STRONG MOTION DATABASE RECORD\r\nEVENT, DATE, STATION, COMP\r\n"
      "ACCELERATION TIME HISTORY IN UNITS OF G\r\n3    0.0200    NPTS, DT\r\n"
      "  1.0E-01   2.0E-01   \r\n 3.0E-01  \r\n   \r\n\r\n";
  const Record r = read_at2(write("crlf.AT2", text));
  ASSERT_EQ(r.npts(), 3u);
  EXPECT_DOUBLE_EQ(r.values[2], 0.3);
  EXPECT_DOUBLE_EQ(r.dt, 0.02);
}

TEST_F(At2Reader, AcceptsAnyValueCountPerLine) {
  const Record r = read_at2(write("n.AT2", at2("NPTS= 7, DT= .01", "1\n2 3 4 5 6 7 \n")));
  ASSERT_EQ(r.npts(), 7u);
  EXPECT_DOUBLE_EQ(r.values[6], 7.0);
}

TEST_F(At2Reader, ReadsCentimetreUnitsAndConvertsThem) {
  const Record r =
      read_at2(write("cm.AT2", at2("NPTS= 2, DT= .01", "100.0 -50.0\n",
                                   "ACCELERATION TIME HISTORY IN UNITS OF CM/SEC/SEC")));
  EXPECT_EQ(r.units, AccelUnit::kCentimetersPerSecond2);
  const std::vector<double> si = r.to_si();
  EXPECT_DOUBLE_EQ(si[0], 1.0);
  EXPECT_DOUBLE_EQ(si[1], -0.5);
}

// ---- AT2: malformed files, messages checked -----------------------------------------------------

TEST_F(At2Reader, RejectsNptsLargerThanData) {
  const std::string path = write("short.AT2", at2("NPTS= 7, DT= .01", kSixValues + "\n"));
  // 4 header lines, 2 value lines, 1 blank line: the end of the file is line 7
  expect_input_error([&] { read_at2(path); },
                     {path + ":7:", "expected NPTS = 7 values", "got only 6", "end of the file"});
}

TEST_F(At2Reader, RejectsMoreDataThanNpts) {
  const std::string path = write("long.AT2", at2("NPTS= 5, DT= .01", kSixValues));
  expect_input_error([&] { read_at2(path); }, {path + ":6:", "more values than NPTS = 5", "value 6",
                                               "-0.600000E-01", "expected exactly 5 values"});
}

TEST_F(At2Reader, RejectsNonNumericToken) {
  const std::string path = write("bad.AT2", at2("NPTS= 3, DT= .01", "0.1 0.2\n0.3x\n"));
  expect_input_error([&] { read_at2(path); },
                     {path + ":6:", "expected a number for value 3 of 3", "\"0.3x\""});
}

TEST_F(At2Reader, RejectsLabelsWithoutNumbers) {
  const std::string path = write("labels.AT2", at2("NPTS=      , DT=      SEC,", kSixValues));
  expect_input_error([&] { read_at2(path); }, {path + ":4:", "expected NPTS and DT",
                                               "labels but no numbers", "NPTS=      , DT="});
}

TEST_F(At2Reader, RejectsLabelWithoutItsNumber) {
  const std::string path = write("half.AT2", at2("NPTS= 6, DT= SEC", kSixValues));
  expect_input_error([&] { read_at2(path); }, {path + ":4:", "no number after DT"});
}

TEST_F(At2Reader, RejectsNan) {
  const std::string path = write("nan.AT2", at2("NPTS= 3, DT= .01", "0.1\n0.2 NaN\n"));
  expect_input_error([&] { read_at2(path); },
                     {path + ":6:", "expected a finite number for value 3 of 3", "\"NaN\""});
}

TEST_F(At2Reader, RejectsInfinity) {
  const std::string path = write("inf.AT2", at2("NPTS= 3, DT= .01", "0.1 -inf 0.2\n"));
  expect_input_error([&] { read_at2(path); },
                     {path + ":5:", "expected a finite number for value 2 of 3", "\"-inf\""});
}

TEST_F(At2Reader, RejectsOverflowingValue) {
  const std::string path = write("big.AT2", at2("NPTS= 2, DT= .01", "0.1 1e999\n"));
  expect_input_error([&] { read_at2(path); }, {path + ":5:", "expected a finite number"});
}

TEST_F(At2Reader, RejectsMissingHeaderLines) {
  const std::string path =
      write("head.AT2", "PEER NGA STRONG MOTION DATABASE RECORD\nEVENT, DATE, STATION, COMP\n");
  expect_input_error([&] { read_at2(path); },
                     {path + ":3:", "expected header line 3", "UNITS OF G", "end of the file"});
}

TEST_F(At2Reader, RejectsMissingLine4) {
  const std::string path =
      write("head4.AT2", "PEER NGA\nEVENT\nACCELERATION TIME HISTORY IN UNITS OF G\n");
  expect_input_error([&] { read_at2(path); },
                     {path + ":4:", "expected header line 4 (NPTS and DT)", "end of the file"});
}

TEST_F(At2Reader, RejectsEmptyFile) {
  const std::string path = write("empty.AT2", "");
  expect_input_error([&] { read_at2(path); },
                     {path + ":1:", "empty file", "expected a PEER NGA .AT2 record"});
}

TEST_F(At2Reader, RejectsWhitespaceOnlyFile) {
  const std::string path = write("blank.AT2", "  \n\r\n\n");
  expect_input_error([&] { read_at2(path); }, {path + ":1:", "empty file"});
}

TEST_F(At2Reader, RejectsMissingFile) {
  const std::string path = (dir_ / "absent.AT2").string();
  expect_input_error([&] { read_at2(path); }, {path, "cannot open"});
}

TEST_F(At2Reader, RejectsFileWithoutHeader) {
  const std::string path = write("noheader.AT2", "0.1 0.2\n0.3 0.4\n0.5 0.6\n0.7\n");
  expect_input_error([&] { read_at2(path); },
                     {path + ":3:", "expected the units line", "IN UNITS OF G", "\"0.5 0.6\""});
}

TEST_F(At2Reader, RejectsVelocityFile) {
  const std::string path = write(
      "v.VT2", at2("NPTS= 6, DT= .01", kSixValues, "VELOCITY TIME HISTORY IN UNITS OF CM/SEC"));
  expect_input_error([&] { read_at2(path); },
                     {path + ":3:", "expected an acceleration record", "VELOCITY"});
}

TEST_F(At2Reader, RejectsUnknownUnits) {
  const std::string path = write(
      "u.AT2", at2("NPTS= 6, DT= .01", kSixValues, "ACCELERATION TIME HISTORY IN UNITS OF FT/S/S"));
  expect_input_error([&] { read_at2(path); }, {path + ":3:", "units G, CM/S/S or M/S/S", "FT/S/S"});
}

TEST_F(At2Reader, RejectsNonIntegerNpts) {
  const std::string path = write("npts.AT2", at2("NPTS= 6.5, DT= .01", kSixValues));
  expect_input_error([&] { read_at2(path); },
                     {path + ":4:", "expected NPTS to be a positive integer", "\"6.5\""});
}

TEST_F(At2Reader, RejectsZeroDt) {
  const std::string path = write("dt.AT2", at2("NPTS= 6, DT= 0.0 SEC", kSixValues));
  expect_input_error([&] { read_at2(path); },
                     {path + ":4:", "expected DT to be a positive time step", "\"0.0\""});
}

TEST_F(At2Reader, RejectsAmbiguousUnlabelledLine4) {
  const std::string path = write("amb.AT2", at2("6    100", kSixValues));
  expect_input_error([&] { read_at2(path); },
                     {path + ":4:", "an integer NPTS and a decimal DT", "\"6    100\""});
}

TEST_F(At2Reader, RejectsUnknownWordInLine4) {
  const std::string path = write("word.AT2", at2("NPTS= 6, STEP= .01", kSixValues));
  expect_input_error([&] { read_at2(path); }, {path + ":4:", "unexpected \"STEP\""});
}

// ---- single-column files ---------------------------------------------------------------------

class SingleColumnReader : public TempDir {};

TEST_F(SingleColumnReader, ReadsSeveralValuesPerLineWithCommentsAndCommas) {
  const std::string path = write("s.dat",
                                 "# header\n  0.1 0.2, 0.3\n\n   # indented comment\n"
                                 "-0.4   # inline comment\r\n0.5\n");
  const Record r = read_single_column(path, 0.005, AccelUnit::kMetersPerSecond2);
  ASSERT_EQ(r.npts(), 5u);
  EXPECT_DOUBLE_EQ(r.values[3], -0.4);
  EXPECT_DOUBLE_EQ(r.time[4], 0.02);
  EXPECT_EQ(r.header.size(), 2u);
  EXPECT_EQ(r.units, AccelUnit::kMetersPerSecond2);
}

TEST_F(SingleColumnReader, RejectsNonNumericValueNamingTheLine) {
  const std::string path = write("s.dat", "# c\n0.1 0.2\n0.3 abc\n");
  expect_input_error([&] { read_single_column(path, 0.01, AccelUnit::kG); },
                     {path + ":3:", "expected a number for value 4", "\"abc\""});
}

TEST_F(SingleColumnReader, RejectsInfinity) {
  const std::string path = write("s.dat", "0.1\ninf\n");
  expect_input_error([&] { read_single_column(path, 0.01, AccelUnit::kG); },
                     {path + ":2:", "expected a finite number for value 2"});
}

TEST_F(SingleColumnReader, RejectsNonPositiveDt) {
  const std::string path = write("s.dat", "0.1\n0.2\n");
  expect_input_error([&] { read_single_column(path, -0.01, AccelUnit::kG); },
                     {path, "argument 'dt' = -0.01", "expected a positive finite time step"});
}

TEST_F(SingleColumnReader, RejectsFileWithOnlyComments) {
  const std::string path = write("s.dat", "# a\n# b\n\n");
  expect_input_error([&] { read_single_column(path, 0.01, AccelUnit::kG); },
                     {path + ":3:", "expected acceleration values", "only comments"});
}

TEST_F(SingleColumnReader, RejectsEmptyFile) {
  const std::string path = write("s.dat", "");
  expect_input_error([&] { read_single_column(path, 0.01, AccelUnit::kG); },
                     {path + ":1:", "empty file"});
}

// ---- two-column time series ---------------------------------------------------------------

class TimeSeriesReader : public TempDir {};

TEST_F(TimeSeriesReader, ReadsWhitespaceColumnsAndDetectsUniformStep) {
  const std::string path = write("t.txt", "# t a\n0.00 0.0\n0.01\t0.5\n  0.02   -0.25\n0.03 0\n");
  const Record r = read_time_series(path, AccelUnit::kG);
  ASSERT_EQ(r.npts(), 4u);
  EXPECT_NEAR(r.dt, 0.01, 1e-15);
  EXPECT_DOUBLE_EQ(r.values[2], -0.25);
  const GroundMotion m = r.to_motion();
  EXPECT_NEAR(m.at(0.015).x, 0.125 * kStandardGravity, 1e-12);
}

TEST_F(TimeSeriesReader, UniformRecordStartingLaterKeepsItsStartTime) {
  const std::string path = write("t.txt", "1.0 0.1\n1.5 0.2\n2.0 0.3\n");
  const Record r = read_time_series(path, AccelUnit::kMetersPerSecond2);
  EXPECT_DOUBLE_EQ(r.dt, 0.5);
  const GroundMotion m = r.to_motion();
  EXPECT_DOUBLE_EQ(m.at(0.5).x, 0.0);  // before the record
  EXPECT_DOUBLE_EQ(m.at(1.25).x, 0.15);
  GroundMotion::Cursor c;
  EXPECT_DOUBLE_EQ(m.next_breakpoint(0.0, c), 1.0);
  EXPECT_DOUBLE_EQ(m.next_breakpoint(1.2, c), 1.5);
}

TEST_F(TimeSeriesReader, ReadsCsvWithHeaderRowAndCrlf) {
  const std::string path = write("t.csv", "time_s,accel_cm_s2\r\n0.0,0\r\n0.5, 100\r\n2.0,-50\r\n");
  const Record r = read_time_series(path, AccelUnit::kCentimetersPerSecond2);
  ASSERT_EQ(r.npts(), 3u);
  EXPECT_EQ(r.header.size(), 1u);
  EXPECT_DOUBLE_EQ(r.dt, 0.0);  // not uniform
  const GroundMotion m = r.to_motion();
  EXPECT_EQ(m.samples(), 3u);
  EXPECT_DOUBLE_EQ(m.at(0.5).x, 1.0);
  EXPECT_DOUBLE_EQ(m.at(1.25).x, 0.25);
  GroundMotion::Cursor c;
  EXPECT_DOUBLE_EQ(m.next_breakpoint(0.5, c), 2.0);
}

TEST_F(TimeSeriesReader, RejectsNonIncreasingTimesNamingBothLines) {
  const std::string path = write("t.txt", "0.0 0\n0.1 1\n# c\n0.1 2\n");
  expect_input_error(
      [&] { read_time_series(path, AccelUnit::kG); },
      {path + ":4:", "expected strictly increasing times", "t = 0.1 s", "on line 2"});
}

TEST_F(TimeSeriesReader, RejectsDecreasingTimes) {
  const std::string path = write("t.csv", "t,a\n0.0,0\n0.2,1\n0.1,2\n");
  expect_input_error([&] { read_time_series(path, AccelUnit::kG); },
                     {path + ":4:", "strictly increasing", "on line 3"});
}

TEST_F(TimeSeriesReader, RejectsWrongColumnCount) {
  const std::string path = write("t.txt", "0.0 0\n0.1 1 5\n");
  expect_input_error([&] { read_time_series(path, AccelUnit::kG); },
                     {path + ":2:", "expected 2 columns", "got 3"});
}

TEST_F(TimeSeriesReader, RejectsEmptyCsvField) {
  const std::string path = write("t.csv", "0.0,0\n0.1,\n");
  expect_input_error([&] { read_time_series(path, AccelUnit::kG); },
                     {path + ":2:", "expected 2 columns", "got 1"});
}

TEST_F(TimeSeriesReader, RejectsSecondHeaderRow) {
  const std::string path = write("t.csv", "t,a\n0,0\nt,a\n");
  expect_input_error([&] { read_time_series(path, AccelUnit::kG); },
                     {path + ":3:", "expected a number for the time", "\"t\""});
}

TEST_F(TimeSeriesReader, RejectsHeaderOnly) {
  const std::string path = write("t.csv", "t,a\n");
  expect_input_error([&] { read_time_series(path, AccelUnit::kG); },
                     {path + ":1:", "expected time, acceleration pairs, got none"});
}

// ---- units and scale factors -----------------------------------------------------------------

TEST(Units, FactorsToMetresPerSecondSquared) {
  EXPECT_DOUBLE_EQ(to_si_factor(AccelUnit::kG), 9.80665);
  EXPECT_DOUBLE_EQ(to_si_factor(AccelUnit::kMetersPerSecond2), 1.0);
  EXPECT_DOUBLE_EQ(to_si_factor(AccelUnit::kCentimetersPerSecond2), 0.01);
  EXPECT_EQ(unit_name(AccelUnit::kG), "g");
  EXPECT_EQ(unit_name(AccelUnit::kCentimetersPerSecond2), "cm/s^2");
}

// a small in-memory record
Record make_record(std::vector<double> time, std::vector<double> values, AccelUnit units,
                   double dt) {
  Record r;
  r.source = "mem";
  r.time = std::move(time);
  r.values = std::move(values);
  r.units = units;
  r.dt = dt;
  return r;
}

TEST(Units, ToMotionConvertsUnitsThenScales) {
  const Record g = make_record({0.0, 0.1, 0.2}, {0.1, -0.2, 0.3}, AccelUnit::kG, 0.1);
  const GroundMotion m = g.to_motion(2.0);
  EXPECT_DOUBLE_EQ(m.at(0.1).x, -0.2 * 9.80665 * 2.0);
  EXPECT_DOUBLE_EQ(m.at(0.1).y, 0.0);
  EXPECT_FALSE(m.has_vertical());
  const Record cm = make_record({0.0, 0.1}, {250.0, 0.0}, AccelUnit::kCentimetersPerSecond2, 0.1);
  EXPECT_DOUBLE_EQ(cm.to_motion(0.5).at(0.0).x, 1.25);
  EXPECT_DOUBLE_EQ(cm.to_si(-1.0)[0], -2.5);
}

TEST(Units, RejectsNonFiniteScale) {
  const Record g = make_record({0.0, 0.1}, {0.1, 0.2}, AccelUnit::kG, 0.1);
  expect_input_error([&] { g.to_motion(std::nan("")); }, {"mem", "scale factor must be finite"});
}

TEST(Units, RejectsSingleSampleMotion) {
  const Record g = make_record({0.0}, {0.1}, AccelUnit::kG, 0.1);
  expect_input_error([&] { g.to_motion(); }, {"mem", "at least 2 samples, got 1"});
}

// ---- combining components ----------------------------------------------------------------------

TEST(Combine, NullVerticalGivesHorizontalOnly) {
  const Record h = make_record({0.0, 0.1}, {1.0, 2.0}, AccelUnit::kMetersPerSecond2, 0.1);
  const GroundMotion m = combine(h, nullptr, 3.0);
  EXPECT_DOUBLE_EQ(m.at(0.1).x, 6.0);
  EXPECT_FALSE(m.has_vertical());
}

TEST(Combine, SameGridTakesVerticalValuesWithTheirOwnUnits) {
  const Record h = make_record({0.0, 0.1, 0.2}, {0.1, 0.2, 0.3}, AccelUnit::kG, 0.1);
  const Record v =
      make_record({0.0, 0.1, 0.2}, {10.0, 20.0, 30.0}, AccelUnit::kCentimetersPerSecond2, 0.1);
  const GroundMotion m = combine(h, &v, 2.0);
  EXPECT_TRUE(m.has_vertical());
  EXPECT_DOUBLE_EQ(m.at(0.2).x, 0.3 * 9.80665 * 2.0);
  EXPECT_DOUBLE_EQ(m.at(0.2).y, 0.6);
  EXPECT_DOUBLE_EQ(m.vertical()[1], 0.4);
}

TEST(Combine, ResamplesVerticalLinearlyAndZeroOutsideItsSpan) {
  // horizontal every 0.1 s on [0, 0.4]; vertical every 0.15 s on [0.05, 0.35]
  const Record h =
      make_record({0.0, 0.1, 0.2, 0.3, 0.4}, {0, 0, 0, 0, 0}, AccelUnit::kMetersPerSecond2, 0.1);
  const Record v =
      make_record({0.05, 0.20, 0.35}, {1.0, 4.0, -2.0}, AccelUnit::kMetersPerSecond2, 0.15);
  const GroundMotion m = combine(h, &v);
  const std::vector<double>& y = m.vertical();
  ASSERT_EQ(y.size(), 5u);
  EXPECT_DOUBLE_EQ(y[0], 0.0);                          // before the vertical starts
  EXPECT_NEAR(y[1], 1.0 + 3.0 * (0.05 / 0.15), 1e-12);  // between 0.05 and 0.20
  EXPECT_NEAR(y[2], 4.0, 1e-12);
  EXPECT_NEAR(y[3], 4.0 - 6.0 * (0.10 / 0.15), 1e-12);
  EXPECT_DOUBLE_EQ(y[4], 0.0);  // after it ends
}

TEST(Combine, RejectsRecordsThatDoNotOverlap) {
  Record h = make_record({0.0, 1.0}, {0, 0}, AccelUnit::kG, 1.0);
  h.source = "h.AT2";
  Record v = make_record({2.0, 3.0}, {0, 0}, AccelUnit::kG, 1.0);
  v.source = "v.AT2";
  expect_input_error([&] { combine(h, &v); },
                     {"v.AT2", "h.AT2", "does not overlap", "(2 s to 3 s)", "(0 s to 1 s)"});
}

TEST(Combine, RealRecordWithItselfAsVertical) {
  const Record h = read_at2(kData + "kobe_1995_nishi_akashi_090.AT2");
  const GroundMotion m = combine(h, &h, 0.5);
  EXPECT_DOUBLE_EQ(m.at(7.09).x, m.at(7.09).y);
  EXPECT_NEAR(std::abs(m.at(7.09).y), 0.5 * 0.502749 * kStandardGravity, 1e-9);
}

}  // namespace
}  // namespace flexrock::io
