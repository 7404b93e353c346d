// SPDX-License-Identifier: BSD-3-Clause
// Records as agencies publish them: the shipped USGS SMC pair against values read off the files
// by hand, the same record read as SMC and as AT2, small fixtures for K-NET/KiK-net, ESM and
// COSMOS V1/V2 written from the formats' public specifications, two-column files with units
// rows, semicolons and more columns, the table of formats, and malformed files refused with the
// file, the line and the field.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "flexrock/core/error.hpp"
#include "flexrock/io/records.hpp"
#include "support/expect_error.hpp"

namespace flexrock::io {
namespace {

namespace fs = std::filesystem;
using test::expect_input_error;

const std::string kData = FLEXROCK_SOURCE_DIR "/../shared/data/";

class AgencyFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           (std::string("flexrock_agency_") + info->test_suite_name() + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& content) const {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << content;
    return p.string();
  }
  fs::path dir_;
};

std::vector<std::string> file_lines(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<std::string> out;
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

// printf into a string
template <typename... A>
std::string fmt(const char* f, A... a) {
  char buf[256];
  std::snprintf(buf, sizeof buf, f, a...);
  return buf;
}

// ---- USGS SMC: the shipped pair (values read off the files, SOURCE.md) ------------------------

TEST(SmcRealRecords, CarsonCatskill090HasTheFilesCountRateUnitsAndEnds) {
  const Record r = read_smc(kData + "A-CAT090.AT2.smc");
  EXPECT_EQ(r.npts(), 1646u);          // integer header value 17
  EXPECT_DOUBLE_EQ(r.dt, 1.0 / 50.0);  // real header value 2: 50 samples/s
  EXPECT_EQ(r.units, AccelUnit::kCentimetersPerSecond2);
  EXPECT_DOUBLE_EQ(r.values.front(), 9.5746585E-04);  // line 37, first field
  EXPECT_DOUBLE_EQ(r.values[6], -5.7981615E-03);      // line 38, glued to its neighbour
  EXPECT_DOUBLE_EQ(r.values.back(), 4.1989844E-02);   // line 366, alone
  EXPECT_DOUBLE_EQ(r.time.back(), 1645 * 0.02);
  // the peak agrees with the one the header states (real values 29-30: 11.42 s, 41.35543)
  const std::size_t k = r.peak_index();
  EXPECT_DOUBLE_EQ(r.values[k], 41.355427);
  EXPECT_NEAR(r.values[k], 41.35543, 5e-6);
  EXPECT_NEAR(r.time[k], 11.42, 1e-12);
  // SOURCE.md: PGA 41.36 cm/s^2
  EXPECT_NEAR(std::abs(r.values[k]), 41.36, 5e-3);
  // 11 text lines and the 9 comment lines (integer header value 16)
  ASSERT_EQ(r.header.size(), 20u);
  EXPECT_EQ(r.header[0].substr(0, 9), "0 UNKNOWN");
  EXPECT_EQ(r.header.back().front(), '|');
}

TEST(SmcRealRecords, CarsonCatskill180HasTheFilesCountRateAndEnds) {
  const Record r = read_smc(kData + "A-CAT180.AT2.smc");
  EXPECT_EQ(r.npts(), 1646u);
  EXPECT_DOUBLE_EQ(r.dt, 0.02);
  EXPECT_EQ(r.units, AccelUnit::kCentimetersPerSecond2);
  EXPECT_DOUBLE_EQ(r.values.front(), 4.1843182E-03);
  EXPECT_DOUBLE_EQ(r.values.back(), 1.9560158E-02);
  // the header states the peak -58.00918 at 6.60 s
  const std::size_t k = r.peak_index();
  EXPECT_NEAR(r.values[k], -58.00918, 5e-6);
  EXPECT_NEAR(r.time[k], 6.60, 1e-12);
}

TEST(SmcRealRecords, MotionIsInMetresPerSecondSquared) {
  const GroundMotion m = read_smc(kData + "A-CAT090.AT2.smc").to_motion();
  EXPECT_EQ(m.samples(), 1646u);
  EXPECT_NEAR(m.at(11.42).x, 0.41355427, 1e-12);
}

// The shipped SMC files have no AT2 twin in shared/data (their PEER .AT2 originals are not
// shipped), so the twin is made here: the SMC file's data lines cut into their 14-character
// fields (not the reader's way of splitting them), written as an AT2 file in cm/s/s. Both readers
// must give the same samples, bit for bit, and the same times.
TEST_F(AgencyFiles, SmcAndAt2OfTheSameRecordGiveTheSameSamples) {
  for (const char* name : {"A-CAT090.AT2.smc", "A-CAT180.AT2.smc"}) {
    const std::vector<std::string> lines = file_lines(kData + name);
    std::string values;
    std::size_t n = 0;
    for (std::size_t i = 36; i < lines.size(); ++i) {
      for (std::size_t c = 0; c + 1 < lines[i].size(); c += 14) {
        values += lines[i].substr(c, 14) + " ";
        ++n;
      }
      values += "\n";
    }
    ASSERT_EQ(n, 1646u);
    const std::string at2 = write(std::string(name) + ".AT2",
                                  "PEER NGA STRONG MOTION DATABASE RECORD\n"
                                  "WHITTIER 10/01/87 14:42, CARSON-CATSKILL AVE\n"
                                  "ACCELERATION TIME HISTORY IN UNITS OF CM/S/S\n"
                                  "NPTS=   1646, DT=   .0200 SEC\n" +
                                      values);
    const Record a = read_at2(at2);
    const Record s = read_smc(kData + name);
    EXPECT_EQ(a.units, s.units);
    EXPECT_EQ(a.values, s.values) << name;
    EXPECT_EQ(a.time, s.time) << name;
    EXPECT_EQ(a.to_motion().at(7.31).x, s.to_motion().at(7.31).x);
  }
}

// ---- USGS SMC: fixtures (USGS Open-File Report on the SMC format; PEA2SMC's layout) ----------

// an SMC file: text line 1, 10 '*' lines, 48 integers (8I10), 50 reals (5E15.7), comments,
// then `data`
std::string smc(const std::string& line1, long npts, long comments, double rate,
                const std::string& data, const std::vector<std::string>& comment_lines = {}) {
  std::string s = line1 + "\n";
  for (int i = 0; i < 10; ++i) s += "*\n";
  std::vector<long> ints(48, -32768);
  ints[15] = comments;
  ints[16] = npts;
  for (int i = 0; i < 48; ++i) s += fmt("%10ld", ints[i]) + (i % 8 == 7 ? "\n" : "");
  std::vector<double> reals(50, 1.7e38);
  reals[1] = rate;
  for (int i = 0; i < 50; ++i) s += fmt("%15.7E", reals[i]) + (i % 5 == 4 ? "\n" : "");
  for (const std::string& c : comment_lines) s += c + "\n";
  return s + data;
}

TEST_F(AgencyFiles, SmcCorrectedAccelerogramWithGluedNegativesAndCrlf) {
  std::string data = " 1.0000000E+00-2.5000000E+00 3.0000000E-01\r\n-4.0000000E+01 5.0E+00\r\n";
  const std::string p = write(
      "f.smc", smc("2 CORRECTED ACCELEROGRAM", 5, 2, 200.0, data, {"| station 1", "| filtered"}));
  const Record r = read_smc(p);
  ASSERT_EQ(r.npts(), 5u);
  EXPECT_DOUBLE_EQ(r.dt, 0.005);
  EXPECT_EQ(r.values, (std::vector<double>{1.0, -2.5, 0.3, -40.0, 5.0}));
  EXPECT_DOUBLE_EQ(r.time[4], 0.02);
  EXPECT_EQ(r.units, AccelUnit::kCentimetersPerSecond2);
}

TEST_F(AgencyFiles, SmcRefusesVelocityNamingTheDataType) {
  const std::string p = write("v.smc", smc("3 VELOCITY", 2, 0, 100.0, "1.0 2.0\n"));
  expect_input_error([&] { read_smc(p); }, {p + ":1:", "key 'data type'", "accelerogram"});
}

TEST_F(AgencyFiles, SmcRefusesFewerValuesThanTheHeaderStates) {
  const std::string p = write("s.smc", smc("1 UNCORRECTED ACCELEROGRAM", 4, 0, 100.0, "1 2 3\n"));
  expect_input_error([&] { read_smc(p); },
                     {p + ":28:", "expected 4 values (integer header value 17), got only 3"});
}

TEST_F(AgencyFiles, SmcRefusesMoreValuesThanTheHeaderStates) {
  const std::string p = write("s.smc", smc("1 UNCORRECTED ACCELEROGRAM", 2, 0, 100.0, "1 2\n3\n"));
  expect_input_error([&] { read_smc(p); }, {p + ":29:", "more values than the 2 samples"});
}

TEST_F(AgencyFiles, SmcRefusesAnUnknownSamplingRate) {
  const std::string p = write("s.smc", smc("2 CORRECTED ACCELEROGRAM", 2, 0, 1.7e38, "1 2\n"));
  expect_input_error([&] { read_smc(p); },
                     {p + ":18:", "key 'real header value 2 (sampling rate)'", "unknown"});
}

TEST_F(AgencyFiles, SmcRefusesABadIntegerHeaderValue) {
  std::string s = smc("2 CORRECTED ACCELEROGRAM", 2, 0, 100.0, "1 2\n");
  s.replace(s.find("    -32768"), 10, "      12.5");
  const std::string p = write("s.smc", s);
  expect_input_error([&] { read_smc(p); },
                     {p + ":12:", "key 'integer header value 1'", "expected an integer", "12.5"});
}

TEST_F(AgencyFiles, SmcRefusesAMissingCommentLine) {
  const std::string p =
      write("s.smc", smc("2 CORRECTED ACCELEROGRAM", 2, 2, 100.0, "1 2\n", {"| only one"}));
  expect_input_error([&] { read_smc(p); },
                     {p + ":29:", "comment line 2 of 2", "starting with '|'"});
}

// ---- NIED K-NET / KiK-net ASCII (NIED's "K-NET/KiK-net ASCII data format": 17 header lines,
// counts 8 a line, acceleration = count x scale factor in gal) ----------------------------------

std::string knet_header(const std::string& freq, const std::string& scale,
                        const std::string& dir = "N-S") {
  return "Origin Time       2011/03/11 14:46:00\n"
         "Lat.              38.103\n"
         "Long.             142.860\n"
         "Depth. (km)       24\n"
         "Mag.              9.0\n"
         "Station Code      MYG004\n"
         "Station Lat.      38.7312\n"
         "Station Long.     141.0217\n"
         "Station Height(m) 170\n"
         "Record Time       2011/03/11 14:46:15\n"
         "Sampling Freq(Hz) " +
         freq +
         "\n"
         "Duration Time(s)  0.1\n"
         "Dir.              " +
         dir +
         "\n"
         "Scale Factor      " +
         scale +
         "\n"
         "Max. Acc. (gal)   3.92\n"
         "Last Correction   2011/03/11 14:46:00\n"
         "Memo.\n";
}

TEST_F(AgencyFiles, KnetCountsTimesTheScaleFactorInGal) {
  const std::string p =
      write("MYG0041103111446.NS", knet_header("100Hz", "1000(gal)/500000") +
                                       "      0   500  -500  1000 -1000  2000 -2000  1500\n"
                                       "     -1   250\n");
  const Record r = read_knet(p);
  ASSERT_EQ(r.npts(), 10u);
  EXPECT_DOUBLE_EQ(r.dt, 0.01);
  EXPECT_EQ(r.units, AccelUnit::kCentimetersPerSecond2);
  // 1000 gal per 500000 counts: 0.002 gal a count
  EXPECT_DOUBLE_EQ(r.values[0], 0.0);
  EXPECT_DOUBLE_EQ(r.values[1], 1.0);
  EXPECT_DOUBLE_EQ(r.values[6], -4.0);
  EXPECT_DOUBLE_EQ(r.values[8], -0.002);
  EXPECT_DOUBLE_EQ(r.values[9], 0.5);
  EXPECT_DOUBLE_EQ(r.time[9], 0.09);
  EXPECT_EQ(r.header.size(), 17u);
}

TEST_F(AgencyFiles, KiknetBoreholeWithTheNiedScaleFactor) {
  // KiK-net direction codes 1-3 (borehole) and the factor NIED writes for its recorders
  const std::string p = write("IWTH251103111446.EW1",
                              knet_header("200Hz", "7845(gal)/8223790", "2") + "  -3426  6182\n");
  const Record r = read_knet(p);
  ASSERT_EQ(r.npts(), 2u);
  EXPECT_DOUBLE_EQ(r.dt, 0.005);
  EXPECT_NEAR(r.values[0], -3426.0 * 7845.0 / 8223790.0, 1e-15);
  EXPECT_NEAR(r.values[0], -3.26820, 5e-6);  // by hand: 3426 x 0.000953931 gal
  EXPECT_EQ(record_format_for(p), find_record_format("knet"));
}

TEST_F(AgencyFiles, KnetRefusesAMissingScaleFactor) {
  std::string h = knet_header("100Hz", "x");
  h.replace(h.find("Scale Factor      x\n"), 20, "");
  const std::string p = write("a.NS", h + "1 2\n");
  expect_input_error([&] { read_knet(p); }, {p + ":16:", "key 'Scale Factor'", "missing"});
}

TEST_F(AgencyFiles, KnetRefusesAScaleFactorNotInGal) {
  const std::string p = write("a.NS", knet_header("100Hz", "39.2(m/s2)/6182761") + "1 2\n");
  expect_input_error([&] { read_knet(p); },
                     {p + ":14:", "key 'Scale Factor'", "3920(gal)/6182761"});
}

TEST_F(AgencyFiles, KnetRefusesABadCountNamingItsLine) {
  const std::string p = write("a.UD", knet_header("100Hz", "3920(gal)/6182761") + "1 2\n3 x4\n");
  expect_input_error([&] { read_knet(p); }, {p + ":19:", "count 4", "\"x4\""});
}

TEST_F(AgencyFiles, KnetRefusesABadSamplingFrequency) {
  const std::string p = write("a.EW", knet_header("fast", "3920(gal)/6182761") + "1 2\n");
  expect_input_error([&] { read_knet(p); }, {p + ":11:", "key 'Sampling Freq(Hz)'", "100Hz"});
}

// ---- ESM ASCII (the Engineering Strong Motion database's ASCII format: "KEY: value" header
// lines, then one value a line) ---------------------------------------------------------------

std::string esm_header(const std::string& ndata, const std::string& dt, const std::string& units,
                       const std::string& type = "ACCELERATION") {
  return "EVENT_NAME: CENTRAL_ITALY\n"
         "EVENT_ID: EMSC-20160824_0000006\n"
         "EVENT_DATE_YYYYMMDD: 20160824\n"
         "EVENT_TIME_HHMMSS: 013632\n"
         "NETWORK: IT\n"
         "STATION_CODE: AMT\n"
         "STATION_NAME: AMATRICE\n"
         "STREAM: HNE\n"
         "DATA_TYPE: " +
         type +
         "\n"
         "PROCESSING: manual (Paolucci et al., 2011)\n"
         "DATE_TIME_FIRST_SAMPLE_YYYYMMDD_HHMMSS: 20160824_013625.000\n"
         "UNITS: " +
         units +
         "\n"
         "NDATA: " +
         ndata +
         "\n"
         "SAMPLING_INTERVAL_S: " +
         dt +
         "\n"
         "PGA_CM/S^2: 850.799927\n"
         "USER5:\n";
}

TEST_F(AgencyFiles, EsmReadsNdataValuesAtTheSamplingInterval) {
  const std::string p =
      write("IT.AMT..HNE.D.20160824.013632.C.ACC.ASC",
            esm_header("4", "0.005000", "cm/s^2") + "-0.123450E+01\n0.5E+00\n850.799927\n-1e-3\n");
  const Record r = read_esm(p);
  ASSERT_EQ(r.npts(), 4u);
  EXPECT_DOUBLE_EQ(r.dt, 0.005);
  EXPECT_EQ(r.units, AccelUnit::kCentimetersPerSecond2);
  EXPECT_EQ(r.values, (std::vector<double>{-1.23450, 0.5, 850.799927, -0.001}));
  EXPECT_EQ(r.header.size(), 16u);
  EXPECT_EQ(record_format_for(p), find_record_format("esm"));
}

TEST_F(AgencyFiles, EsmHeaderKeysInAnyOrderAndCase) {
  const std::string p = write("x.txt",
                              "sampling_interval_s: 0.01\nunits: m/s^2\nNDATA: 2\n"
                              "EVENT_NAME: TEST\n1.0\n2.0\n");
  const Record r = read_esm(p);
  EXPECT_EQ(r.units, AccelUnit::kMetersPerSecond2);
  EXPECT_DOUBLE_EQ(r.time[1], 0.01);
}

TEST_F(AgencyFiles, EsmRefusesVelocityNamingTheField) {
  const std::string p = write("v.asc", esm_header("1", "0.01", "cm/s", "VELOCITY") + "1.0\n");
  expect_input_error([&] { read_esm(p); }, {p + ":9:", "key 'DATA_TYPE'", "acceleration"});
}

TEST_F(AgencyFiles, EsmRefusesAMissingNdata) {
  std::string h = esm_header("1", "0.01", "cm/s^2");
  h.replace(h.find("NDATA: 1\n"), 9, "");
  const std::string p = write("a.asc", h + "1.0\n");
  expect_input_error([&] { read_esm(p); }, {p + ":15:", "key 'NDATA'", "missing"});
}

TEST_F(AgencyFiles, EsmRefusesUnknownUnitsAndShortData) {
  const std::string u = write("u.asc", esm_header("1", "0.01", "ft/s^2") + "1.0\n");
  expect_input_error([&] { read_esm(u); }, {u + ":12:", "key 'UNITS'", "\"ft/s^2\""});
  const std::string n = write("n.asc", esm_header("3", "0.01", "cm/s^2") + "1.0\n2.0\n");
  expect_input_error([&] { read_esm(n); }, {n + ":18:", "expected 3 values (NDATA), got only 2"});
}

// ---- COSMOS V1/V2 (COSMOS Strong-Motion Data Format, version 1.20, 2001: 13 text lines, the
// integer header (10I8), the real header (6F13.6; value 62 the sample interval in ms, 63 the
// length in s), comments, then each data block after its data line) ----------------------------

struct CosmosFixture {
  std::string first = "Corrected acceleration  (Format v01.20 with 13 text lines) Src: test.v2";
  double dt_ms = 10.0;
  std::string units = "units=cm/sec2 (04)";
  std::string format = "(8F10.5)";
  std::vector<double> values{1.0, -2.5, -123.45678, 4.25, 0.0, 0.5, -0.125, 7.0, 9.0, -1.0};
  long npts = -1;  // -1: values.size()
};

std::string cosmos(const CosmosFixture& f) {
  std::string s = f.first + "\n";
  for (int i = 2; i <= 12; ++i) s += fmt("text line %d", i) + "\n";
  s += "Values used when parameter or data value is unknown/unspecified:   -999, -999.0\n";
  s += "  100 Integer-header values follow on  10 lines, Format= (10I8)\n";
  for (int i = 0; i < 100; ++i) s += fmt("%8d", i == 0 ? 2 : -999) + (i % 10 == 9 ? "\n" : "");
  s += "  100 Real-header values follow on  17 lines, Format= (6F13.6)\n";
  for (int i = 0; i < 100; ++i) {
    double v = -999.0;
    if (i == 61) v = f.dt_ms;
    if (i == 62) v = static_cast<double>(f.values.size()) * f.dt_ms / 1000.0;
    s += fmt("%13.6f", v) + (i % 6 == 5 || i == 99 ? "\n" : "");
  }
  s += "   1 Comment line(s) follow, each starting with a \"|\":\n| a comment\n";
  const long n = f.npts < 0 ? static_cast<long>(f.values.size()) : f.npts;
  s += fmt("%7ld acceleration pts, approx   0 secs, ", n) + f.units + ", Format=" + f.format + "\n";
  for (std::size_t i = 0; i < f.values.size(); ++i) {
    s += fmt("%10.5f", f.values[i]) + (i % 8 == 7 || i + 1 == f.values.size() ? "\n" : "");
  }
  s += "End-of-data for Chan  1 acceleration\n";
  s += fmt("%7ld velocity     pts, approx   0 secs, units=cm/sec (05), Format=(8F10.5)\n", n);
  return s + "   0.00000   1.00000\nEnd-of-data for Chan  1 velocity\n";
}

TEST_F(AgencyFiles, CosmosV2ReadsTheAccelerationBlockInItsFixedWidthFields) {
  const std::string p = write("CE13873.V2", cosmos({}));
  const Record r = read_cosmos(p);
  ASSERT_EQ(r.npts(), 10u);
  EXPECT_DOUBLE_EQ(r.dt, 0.01);
  EXPECT_EQ(r.units, AccelUnit::kCentimetersPerSecond2);
  // "-123.45678" fills its ten characters: glued to its neighbour, read by its field
  EXPECT_EQ(r.values,
            (std::vector<double>{1.0, -2.5, -123.45678, 4.25, 0.0, 0.5, -0.125, 7.0, 9.0, -1.0}));
  EXPECT_DOUBLE_EQ(r.time[9], 0.09);
  EXPECT_EQ(r.header.size(), 14u);  // 13 text lines and the comment
  EXPECT_EQ(record_format_for(p), find_record_format("cosmos"));
}

TEST_F(AgencyFiles, CosmosV1InG) {
  CosmosFixture f;
  f.first = "Uncorrected acceleration (Format v01.20 with 13 text lines) Src: test.v1";
  f.units = "units=g (02)";
  f.dt_ms = 5.0;
  const Record r = read_cosmos(write("a.v1", cosmos(f)));
  EXPECT_EQ(r.units, AccelUnit::kG);
  EXPECT_DOUBLE_EQ(r.dt, 0.005);
}

TEST_F(AgencyFiles, CosmosRefusesRawCounts) {
  CosmosFixture f;
  f.first = "Raw acceleration counts  (Format v01.20 with 13 text lines)";
  const std::string p = write("a.v0", cosmos(f));
  expect_input_error([&] { read_cosmos(p); }, {p + ":1:", "key 'data type'", "raw counts"});
}

TEST_F(AgencyFiles, CosmosRefusesAnUnknownSampleInterval) {
  CosmosFixture f;
  f.dt_ms = -999.0;
  const std::string p = write("a.v2", cosmos(f));
  // lines 1-13 text, 14 the integer count, 15-24 integers, 25 the real count, 26-42 reals 6 a
  // line: value 62 is the 2nd of line 26 + 10
  expect_input_error([&] { read_cosmos(p); },
                     {p + ":36:", "key 'real header value 62 (sample interval, ms)'", "-999"});
}

TEST_F(AgencyFiles, CosmosRefusesAMissingFormatAndUnknownUnits) {
  CosmosFixture f;
  f.format = "";
  const std::string p = write("a.v2", cosmos(f));
  expect_input_error([&] { read_cosmos(p); }, {p + ":45:", "key 'Format'", "(8F10.5)"});
  CosmosFixture u;
  u.units = "units=in/sec2 (07)";
  const std::string q = write("b.v2", cosmos(u));
  expect_input_error([&] { read_cosmos(q); }, {q + ":45:", "key 'units'", "cm/sec2"});
}

TEST_F(AgencyFiles, CosmosRefusesFewerValuesThanTheDataLineStates) {
  CosmosFixture f;
  f.npts = 12;
  const std::string p = write("a.v2", cosmos(f));
  // 43 the comment count, 44 the comment, 45 the data line, 46-47 the values: the count runs on
  // into line 48, "End-of-data ...", which is no number
  expect_input_error([&] { read_cosmos(p); }, {p + ":48:", "acceleration values 11 of 12"});
}

TEST_F(AgencyFiles, CosmosRefusesANonNumberField) {
  CosmosFixture f;
  std::string s = cosmos(f);
  s.replace(s.find("   4.25000"), 10, "   4.2x000");
  const std::string p = write("a.v2", s);
  expect_input_error([&] { read_cosmos(p); }, {p + ":46:", "acceleration values 4 of 10"});
}

// ---- two-column files as spreadsheets write them ----------------------------------------------

TEST_F(AgencyFiles, TimeSeriesUnitsRowStatesTheUnits) {
  const std::string p = write("t.csv", "time,acc\ns,cm/s^2\n0,1\n0.01,2\n0.02,-3\n");
  const Record r = read_time_series(p, std::nullopt);
  EXPECT_EQ(r.units, AccelUnit::kCentimetersPerSecond2);
  EXPECT_EQ(r.values, (std::vector<double>{1, 2, -3}));
  EXPECT_EQ(r.header.size(), 2u);
  // given units that agree are fine; others are refused at the units row
  EXPECT_NO_THROW(read_time_series(p, AccelUnit::kCentimetersPerSecond2));
  expect_input_error([&] { read_time_series(p, AccelUnit::kG); },
                     {p + ":2:", "key 'column 2'", "states the accelerations in cm/s^2"});
}

TEST_F(AgencyFiles, TimeSeriesNamesWithBracketedUnits) {
  const std::string p = write("t.txt", "time [s]   acc [g]\n0 0.1\n0.5 0.2\n");
  const Record r = read_time_series(p, std::nullopt);
  EXPECT_EQ(r.units, AccelUnit::kG);
  EXPECT_DOUBLE_EQ(r.dt, 0.5);
}

TEST_F(AgencyFiles, TimeSeriesSemicolonsWithDecimalCommas) {
  const std::string p = write("eu.csv", "t(s);a(gal)\r\n0,00;0,10\r\n0,01;-0,05\r\n0,02;1;\r\n");
  const Record r = read_time_series(p, std::nullopt);
  EXPECT_EQ(r.units, AccelUnit::kCentimetersPerSecond2);
  EXPECT_EQ(r.values, (std::vector<double>{0.10, -0.05, 1.0}));
  EXPECT_NEAR(r.dt, 0.01, 1e-15);
}

TEST_F(AgencyFiles, TimeSeriesThirdColumnIsNotRead) {
  // time, acceleration, velocity (not read)
  const std::string p = write("t.csv", "t,a,v\n0,1,10\n0.1,2,20\n0.2,3,x\n");
  const Record r = read_time_series(p, AccelUnit::kMetersPerSecond2);
  EXPECT_EQ(r.values, (std::vector<double>{1, 2, 3}));
}

TEST_F(AgencyFiles, TimeSeriesRefusesARowThatLostAColumn) {
  const std::string p = write("t.txt", "0 1 10\n0.1 2\n");
  expect_input_error([&] { read_time_series(p, AccelUnit::kG); },
                     {p + ":2:", "expected 3 columns", "as on line 1", "got 2"});
}

TEST_F(AgencyFiles, TimeSeriesRefusesTimesNotInSecondsAndUnknownUnits) {
  const std::string ms = write("ms.csv", "t,a\nms,g\n0,1\n");
  expect_input_error([&] { read_time_series(ms, std::nullopt); },
                     {ms + ":2:", "key 'column 1'", "time in seconds", "\"ms\""});
  const std::string ft = write("ft.csv", "t [s], a [ft/s^2]\n0,1\n1,2\n");
  expect_input_error([&] { read_time_series(ft, std::nullopt); },
                     {ft + ":1:", "key 'column 2'", "\"ft/s^2\""});
}

TEST_F(AgencyFiles, TimeSeriesRefusesMissingUnits) {
  const std::string p = write("t.csv", "t,a\n0,1\n1,2\n");
  expect_input_error([&] { read_time_series(p, std::nullopt); },
                     {p + ":1:", "does not state the units"});
}

// ---- the table of formats ----------------------------------------------------------------------

TEST(RecordFormats, EveryFormatHasAReaderADocLineAndAUniqueName) {
  std::vector<std::string> names;
  for (const RecordFormat& f : record_formats()) {
    EXPECT_NE(f.read, nullptr) << f.name;
    EXPECT_GT(std::string(f.doc).size(), 10u) << f.name;
    EXPECT_EQ(find_record_format(f.name), &f);
    for (const std::string& n : names) EXPECT_NE(n, f.name);
    names.emplace_back(f.name);
  }
  for (const char* n : {"at2", "smc", "knet", "esm", "cosmos", "single_column", "time_series"}) {
    EXPECT_NE(find_record_format(n), nullptr) << n;
  }
}

TEST(RecordFormats, FileNamesSelectTheirFormat) {
  const auto name = [](const std::string& p) {
    const RecordFormat* f = record_format_for(p);
    return f == nullptr ? std::string() : std::string(f->name);
  };
  EXPECT_EQ(name("x/RSN8884_14383980_13873090.AT2"), "at2");
  EXPECT_EQ(name("A-CAT090.AT2.smc"), "smc");
  EXPECT_EQ(name("MYG0041103111446.UD"), "knet");
  EXPECT_EQ(name("IWTH251103111446.ns2"), "knet");
  EXPECT_EQ(name("IT.AMT..HNE.D.20160824.013632.C.ACC.ASC"), "esm");
  EXPECT_EQ(name("CE13873.V2"), "cosmos");
  EXPECT_EQ(name("ci14383980.v1c"), "cosmos");
  EXPECT_EQ(name("record.csv"), "");
  EXPECT_EQ(name("IT.AMT..HNE.D.20160824.013632.C.VEL.ASC"), "");
}

TEST(RecordFormats, ReadRecordChecksGivenUnitsAgainstTheFile) {
  const std::string smc_path = kData + "A-CAT090.AT2.smc";
  EXPECT_EQ(read_record(smc_path, "", 0.0, std::nullopt).npts(), 1646u);
  expect_input_error([&] { read_record(smc_path, "", 0.0, AccelUnit::kG); },
                     {"units", "states its values in cm/s^2"});
  expect_input_error([&] { read_record(smc_path, "peer", 0.0, std::nullopt); },
                     {"unknown format \"peer\"", "smc"});
  expect_input_error([&] { read_record("values.txt", "", 0.0, std::nullopt); },
                     {"does not say the format", "single_column"});
  expect_input_error(
      [&] { read_record(kData + "elcentro_1940_ns.dat", "single_column", 0.0, AccelUnit::kG); },
      {"dt", "single_column"});
}

}  // namespace
}  // namespace flexrock::io
