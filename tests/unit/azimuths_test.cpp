// SPDX-License-Identifier: BSD-3-Clause
// Two horizontal components: the record pair of a case file, the projection at every azimuth of
// a planar body, the sweep's envelope and RotD50/RotD100, each against something computed
// independently: the projected record written as a file and run as an ordinary case, closed
// forms for one component, the symmetries of swapping the components and turning the body.
#include "flexrock/study/azimuths.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "flexrock/core/error.hpp"
#include "flexrock/excitation/azimuth.hpp"
#include "flexrock/excitation/intensity.hpp"
#include "flexrock/io/case_file.hpp"
#include "flexrock/io/records.hpp"

namespace {

using namespace flexrock;
namespace fs = std::filesystem;

const std::string kData = FLEXROCK_SOURCE_DIR "/../shared/data/";
const std::string kH1 = kData + "RSN8884_14383980_13873090.AT2";
const std::string kH2 = kData + "RSN8884_14383980_13873360.AT2";

class Scratch {
 public:
  Scratch() {
    dir_ = fs::temp_directory_path() /
           ("flexrock_azimuths_" + std::to_string(::getpid()) + "_" + std::to_string(count_++));
    fs::create_directories(dir_);
  }
  ~Scratch() { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) const {
    const std::string p = (dir_ / name).string();
    std::ofstream(p) << text;
    return p;
  }

 private:
  fs::path dir_;
  static inline int count_ = 0;
};

// a slender rigid block (b = 0.25 m, h = 1.5 m) or a one-mode cantilever, a pair, options
std::string body_toml(bool flexible) {
  if (flexible) {
    return "[body]\ntype = \"uniform_cantilever\"\nheight = 3.0\nwidth = 0.8\n"
           "mass_per_length = 500.0\nbending_stiffness = 2.0e6\nmodes = 1\nbase_mass = 200.0\n"
           "damping_ratio = 0.02\n";
  }
  return "[body]\ntype = \"rigid_block\"\nwidth = 0.5\nheight = 3.0\nmass = 1000.0\n";
}

std::string pair_case(bool flexible, const std::string& h1, const std::string& h2,
                      const std::string& extra, double scale = 3.0) {
  return body_toml(flexible) + "[excitation]\nscale = " + std::to_string(scale) + "\n" + extra +
         "[excitation.horizontal]\ntype = \"record\"\nfile = \"" + h1 +
         "\"\n[excitation.horizontal2]\ntype = \"record\"\nfile = \"" + h2 +
         "\"\n[solver]\nt_end = 40.0\n[output]\ndt = 0\n";
}

// the sweep's outcome at an azimuth is the ordinary run of the projected record, written as a
// file of m/s^2 (17 significant digits read back to the same doubles) and read as a new case
void expect_sweep_equals_file_runs(bool flexible) {
  Scratch s;
  const io::Case pc = io::load_case(s.write("pair.toml", pair_case(flexible, kH1, kH2, "")));
  const Body body(pc.body);
  const std::vector<double> azimuths{0.0, 35.0, 90.0, 130.0, 215.0, 302.5};
  const auto rows = study::run_azimuths(
      body, azimuths, [&](double b) { return io::azimuth_motion(pc, b); }, pc.initial, pc.options);
  // the projection computed here from the two files as read, in m/s^2
  const io::Record r1 = io::read_at2(kH1), r2 = io::read_at2(kH2);
  for (std::size_t k = 0; k < azimuths.size(); ++k) {
    const double beta = azimuths[k] * std::numbers::pi / 180.0;
    std::string values;
    char buf[40];
    for (std::size_t i = 0; i < r1.npts(); ++i) {
      double c = 0.0, sn = 0.0;
      direction_cosines(azimuths[k], c, sn);
      // the closed form of the direction (not the grid's exact multiples)
      EXPECT_NEAR(c, std::cos(beta), 1e-15);
      EXPECT_NEAR(sn, std::sin(beta), 1e-15);
      const double a =
          c * (kStandardGravity * r1.values[i]) + sn * (kStandardGravity * r2.values[i]);
      std::snprintf(buf, sizeof buf, "%.17g\n", a);
      values += buf;
    }
    const std::string file = s.write("proj" + std::to_string(k) + ".txt", values);
    const std::string single = body_toml(flexible) +
                               "[excitation]\nscale = 3.0\n[excitation.horizontal]\ntype = "
                               "\"record\"\nfile = \"" +
                               file +
                               "\"\nformat = \"single_column\"\ndt = 0.005\nunits = "
                               "\"m/s^2\"\n[solver]\nt_end = 40.0\n[output]\ndt = 0\n";
    const io::Case c = io::load_case(s.write("single" + std::to_string(k) + ".toml", single));
    const SimulationResult r = simulate(body, c.motion, c.initial, c.options);
    const study::AzimuthRun want = study::azimuth_run(body, azimuths[k], r);
    const study::AzimuthRun& got = rows[k];
    SCOPED_TRACE("azimuth " + std::to_string(azimuths[k]));
    EXPECT_EQ(got.summary.max_theta, want.summary.max_theta);
    EXPECT_EQ(got.max_theta_edge1, want.max_theta_edge1);
    EXPECT_EQ(got.max_theta_edge2, want.max_theta_edge2);
    EXPECT_EQ(got.summary.impacts, want.summary.impacts);
    EXPECT_EQ(got.summary.outcome, want.summary.outcome);
    EXPECT_EQ(got.summary.overturn_time, want.summary.overturn_time);
    EXPECT_EQ(got.max_impact_force, want.max_impact_force);
    EXPECT_EQ(got.summary.t_end, want.summary.t_end);
    EXPECT_EQ(got.summary.energy_lost, want.summary.energy_lost);
    EXPECT_GT(got.summary.max_theta, 0.0);  // the body rocks: the comparison means something
    // the peaks along and across the plane: the projected file's, and the file's at beta + 90
    EXPECT_EQ(got.pga_along, peak_acceleration(c.motion).x);
    EXPECT_EQ(got.pga_across, peak_acceleration(io::azimuth_motion(pc, azimuths[k] + 90.0)).x);
    EXPECT_NE(got.pga_across, got.pga_along);
  }
}

TEST(AzimuthSweep, EachAzimuthIsTheRunOfItsProjectedRecordRigid) {
  expect_sweep_equals_file_runs(false);
}

TEST(AzimuthSweep, EachAzimuthIsTheRunOfItsProjectedRecordOneMode) {
  expect_sweep_equals_file_runs(true);
}

TEST(AzimuthSweep, SwappingTheComponentsMapsBetaToNinetyMinusBeta) {
  Scratch s;
  const io::Case a = io::load_case(s.write("a.toml", pair_case(false, kH1, kH2, "")));
  const io::Case b = io::load_case(s.write("b.toml", pair_case(false, kH2, kH1, "")));
  const Body body(a.body);
  const std::vector<double> betas{0.0, 20.0, 45.0, 130.0, 250.0};
  std::vector<double> mapped;
  for (double beta : betas) mapped.push_back(std::fmod(450.0 - beta, 360.0));
  const auto ra = study::run_azimuths(
      body, betas, [&](double x) { return io::azimuth_motion(a, x); }, a.initial, a.options);
  const auto rb = study::run_azimuths(
      body, mapped, [&](double x) { return io::azimuth_motion(b, x); }, b.initial, b.options);
  for (std::size_t k = 0; k < betas.size(); ++k) {
    SCOPED_TRACE("beta " + std::to_string(betas[k]));
    // the same record, bit for bit (direction_cosines keeps the symmetry exact)
    EXPECT_EQ(io::projected_record(*a.pair, betas[k]), io::projected_record(*b.pair, mapped[k]));
    EXPECT_EQ(ra[k].max_theta_edge1, rb[k].max_theta_edge1);
    EXPECT_EQ(ra[k].max_theta_edge2, rb[k].max_theta_edge2);
    EXPECT_EQ(ra[k].summary.impacts, rb[k].summary.impacts);
  }
  // and the azimuths differ: the map is not the identity in disguise
  EXPECT_NE(ra[1].summary.max_theta, ra[3].summary.max_theta);
}

// b1 = b2: the record at beta + 180 is exactly minus the one at beta, and the body's response is
// its mirror image (theta -> -theta): edge 1 and edge 2 swap. So [0, 180) holds the whole envelope
// of a symmetric body. (The engine keeps it bit for bit today; 1e-12 leaves room for arithmetic
// that is not written symmetrically.)
void expect_half_turn_mirrors(bool flexible) {
  Scratch s;
  const io::Case c = io::load_case(s.write("a.toml", pair_case(flexible, kH1, kH2, "")));
  const Body body(c.body);
  ASSERT_EQ(c.body.b1, c.body.b2);
  const std::vector<double> betas{10.0, 190.0, 75.0, 255.0, 135.0, 315.0};
  const auto r = study::run_azimuths(
      body, betas, [&](double x) { return io::azimuth_motion(c, x); }, c.initial, c.options);
  for (std::size_t k = 0; k < betas.size(); k += 2) {
    SCOPED_TRACE("beta " + std::to_string(betas[k]));
    const std::vector<double> p = io::projected_record(*c.pair, betas[k]);
    std::vector<double> q = io::projected_record(*c.pair, betas[k + 1]);
    for (double& v : q) v = -v;
    EXPECT_EQ(p, q);
    EXPECT_GT(std::abs(r[k].max_theta_edge1 - r[k].max_theta_edge2),
              1e-3 * r[k].summary.max_theta);  // the response itself is not symmetric
    EXPECT_NEAR(r[k].max_theta_edge1, r[k + 1].max_theta_edge2, 1e-12 * r[k].summary.max_theta);
    EXPECT_NEAR(r[k].max_theta_edge2, r[k + 1].max_theta_edge1, 1e-12 * r[k].summary.max_theta);
    EXPECT_EQ(r[k].summary.impacts, r[k + 1].summary.impacts);
  }
}

TEST(AzimuthSweep, HalfATurnMirrorsASymmetricRigidBlock) { expect_half_turn_mirrors(false); }

TEST(AzimuthSweep, HalfATurnMirrorsASymmetricOneModeBody) { expect_half_turn_mirrors(true); }

TEST(AzimuthSweep, EnvelopeTakesTheLargestOfEachAndItsFirstAzimuth) {
  std::vector<study::AzimuthRun> runs(4);
  const double az[] = {0, 90, 180, 270};
  const double theta[] = {0.1, 0.3, 0.3, 0.2};
  const double offset[] = {0.0, 0.0, 0.02, 0.01};
  const double force[] = {5, 1, 2, 7};
  for (int i = 0; i < 4; ++i) {
    runs[i].azimuth_deg = az[i];
    runs[i].summary.max_theta = theta[i];
    runs[i].summary.max_offset = offset[i];
    runs[i].max_impact_force = force[i];
  }
  runs[3].summary.outcome = study::Outcome::kOverturnedAfterImpacts;
  runs[3].summary.overturn_time = 12.0;
  runs[1].summary.outcome = study::Outcome::kOverturnedWithoutImpact;
  runs[1].summary.overturn_time = 14.0;
  const study::AzimuthEnvelope e = study::envelope(runs);
  EXPECT_EQ(e.max_theta, 0.3);
  EXPECT_EQ(e.max_theta_azimuth, 90.0);
  EXPECT_EQ(e.max_offset, 0.02);
  EXPECT_EQ(e.max_offset_azimuth, 180.0);
  EXPECT_EQ(e.max_impact_force, 7.0);
  EXPECT_EQ(e.max_impact_force_azimuth, 270.0);
  EXPECT_EQ(e.overturned_azimuths, (std::vector<double>{90.0, 270.0}));
  EXPECT_EQ(e.first_overturn_time, 12.0);
  EXPECT_EQ(e.first_overturn_azimuth, 270.0);
  // an overturning governs the tilt, whatever tilt the run stopped at
  runs[3].summary.max_theta = 1.6;
  runs[1].summary.max_theta = 1.5708;
  const study::AzimuthEnvelope f = study::envelope(runs);
  EXPECT_EQ(f.max_theta, 1.5708);
  EXPECT_EQ(f.max_theta_azimuth, 90.0);
}

TEST(AzimuthSweep, GridCoversTheCircleAndRefusesStepsThatDoNotDivideIt) {
  const std::vector<double> g = study::azimuth_grid(5.0);
  ASSERT_EQ(g.size(), 72u);
  EXPECT_EQ(g.front(), 0.0);
  EXPECT_EQ(g.back(), 355.0);
  EXPECT_EQ(study::azimuth_grid(7.5).size(), 48u);
  EXPECT_THROW(study::azimuth_grid(7.0), InputError);
  EXPECT_THROW(study::azimuth_grid(0.0), InputError);
}

// --- the case file

TEST(RecordPairCase, AzimuthDegRunsTheProjectionScaled) {
  Scratch s;
  const io::Case c =
      io::load_case(s.write("a.toml", pair_case(false, kH1, kH2, "azimuth_deg = 30\n", 2.0)));
  ASSERT_TRUE(c.pair);
  ASSERT_TRUE(c.azimuth);
  EXPECT_EQ(*c.azimuth, 30.0);
  EXPECT_EQ(c.azimuth_step, 5.0);
  const io::Record r1 = io::read_at2(kH1), r2 = io::read_at2(kH2);
  ASSERT_EQ(c.motion.samples(), r1.npts());
  const double cs = std::cos(std::numbers::pi / 6.0), sn = 0.5;
  for (std::size_t i = 0; i < r1.npts(); i += 997) {
    const double want = 2.0 * kStandardGravity * (cs * r1.values[i] + sn * r2.values[i]);
    EXPECT_NEAR(c.motion.horizontal()[i], want, 1e-14 * kStandardGravity);
  }
  EXPECT_NE(std::find(c.input_files.begin(), c.input_files.end(), kH2), c.input_files.end());
}

TEST(RecordPairCase, TheKeysOfTheTableAreTheKeysTheReaderTakes) {
  // the docs and `flexrock keys` are written from kPairKeys: each of its names, spelt as there,
  // is read (and an azimuth set through it changes the motion)
  Scratch s;
  ASSERT_EQ(std::size(io::kPairKeys), 3u);
  const std::string h2 = io::kPairKeys[0].name;
  ASSERT_EQ(h2, "[excitation.horizontal2]");
  const std::string text = body_toml(false) + "[excitation]\n" + io::kPairKeys[1].name + " = 90\n" +
                           io::kPairKeys[2].name + " = 10\n" +
                           "[excitation.horizontal]\ntype = \"record\"\nfile = \"" + kH1 + "\"\n" +
                           h2 + "\ntype = \"record\"\nfile = \"" + kH2 + "\"\n";
  const io::Case c = io::load_case(s.write("a.toml", text));
  EXPECT_EQ(*c.azimuth, 90.0);
  EXPECT_EQ(c.azimuth_step, 10.0);
  EXPECT_EQ(c.motion.horizontal()[1000], c.pair->h2.to_si()[1000]);
  // the default step is the table's
  const io::Case d = io::load_case(s.write("b.toml", pair_case(false, kH1, kH2, "")));
  EXPECT_EQ(d.azimuth_step, std::stod(io::kPairKeys[2].default_text));
}

TEST(RecordPairCase, ComponentsOfDifferentLengthsAreCutToTheShorter) {
  Scratch s;
  const std::string h1 = kData + "RSN8883_14383980_13849090.AT2";  // 16396 samples
  const io::Case c = io::load_case(s.write("a.toml", pair_case(false, h1, kH2, "")));
  EXPECT_EQ(c.pair->h1.npts(), 16396u);
  EXPECT_EQ(c.pair->h2.npts(), 16396u);
  ASSERT_FALSE(c.notes.empty());
  EXPECT_NE(c.notes.back().find("cut to the shorter"), std::string::npos) << c.notes.back();
}

TEST(RecordPairCase, TheVerticalIsTheSameAtEveryAzimuth) {
  Scratch s;
  std::string v;
  char buf[40];
  for (int i = 0; i < 4000; ++i) {
    std::snprintf(buf, sizeof buf, "%.17g\n", 0.1 * std::sin(0.01 * i));
    v += buf;
  }
  const std::string vf = s.write("v.txt", v);
  const std::string text = pair_case(false, kH1, kH2, "") +
                           "[excitation.vertical]\ntype = \"record\"\nfile = \"" + vf +
                           "\"\nformat = \"single_column\"\ndt = 0.005\nunits = \"g\"\n";
  const io::Case c = io::load_case(s.write("a.toml", text));
  const GroundMotion m0 = io::azimuth_motion(c, 0.0), m1 = io::azimuth_motion(c, 123.0);
  ASSERT_TRUE(m0.has_vertical());
  EXPECT_EQ(m0.vertical(), m1.vertical());
  // scaled like the horizontal (excitation.scale = 3), zero past its end
  EXPECT_NEAR(m0.vertical()[100], 3.0 * 0.1 * std::sin(1.0) * kStandardGravity, 1e-14);
  EXPECT_EQ(m0.vertical()[5000], 0.0);
  EXPECT_NE(m0.horizontal(), m1.horizontal());
}

void expect_error(const std::string& text, const std::vector<std::string>& parts) {
  Scratch s;
  const std::string path = s.write("bad.toml", text);
  try {
    io::load_case(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(path + ":"), std::string::npos) << m;
    for (const std::string& p : parts) EXPECT_NE(m.find(p), std::string::npos) << m;
  }
}

TEST(RecordPairCase, MismatchedTimeStepsNameBothFiles) {
  const std::string smc = kData + "A-CAT180.AT2.smc";  // dt 0.02 s
  expect_error(pair_case(false, kH1, smc, ""),
               {"excitation.horizontal2.file", "same time step", "RSN8884_14383980_13873090.AT2",
                "A-CAT180.AT2.smc", "0.005", "0.02"});
}

TEST(RecordPairCase, MissingComponentAndMisplacedKeysAreRefused) {
  // no file for H2
  expect_error(body_toml(false) + "[excitation.horizontal]\ntype = \"record\"\nfile = \"" + kH1 +
                   "\"\n[excitation.horizontal2]\ntype = \"record\"\n",
               {"excitation.horizontal2.file", "missing"});
  // a synthetic H2
  expect_error(body_toml(false) + "[excitation.horizontal]\ntype = \"record\"\nfile = \"" + kH1 +
                   "\"\n[excitation.horizontal2]\ntype = \"harmonic\"\namplitude = 0.1\nunits = "
                   "\"g\"\nfrequency_hz = 1\nduration = 5\n",
               {"excitation.horizontal2.type", "expected \"record\""});
  // azimuth keys without a pair
  expect_error(body_toml(false) +
                   "[excitation]\nazimuth_deg = 10\n[excitation.horizontal]\ntype "
                   "= \"record\"\nfile = \"" +
                   kH1 + "\"\n",
               {"excitation.azimuth_deg", "only with a record pair"});
  // a step that does not divide the circle
  expect_error(pair_case(false, kH1, kH2, "azimuth_step_deg = 7\n"),
               {"excitation.azimuth_step_deg", "divides 360"});
  // a misspelt key
  expect_error(pair_case(false, kH1, kH2, "azimuth_degs = 10\n"),
               {"azimuth_degs", "did you mean", "azimuth_deg"});
  // a target with a pair
  expect_error(pair_case(false, kH1, kH2, "target_pga = 0.3\n"),
               {"excitation.target_pga", "record pair"});
}

TEST(RecordPairCase, EveryRecordFormatMakesAPair) {
  // the SMC pair of one station: the reader of each component is the format table's
  Scratch s;
  const io::Case c = io::load_case(
      s.write("a.toml", pair_case(false, kData + "A-CAT090.AT2.smc", kData + "A-CAT180.AT2.smc",
                                  "azimuth_deg = 90\n", 1.0)));
  const io::Record r2 = io::read_smc(kData + "A-CAT180.AT2.smc");
  ASSERT_EQ(c.motion.samples(), r2.npts());
  for (std::size_t i = 0; i < r2.npts(); ++i) {
    ASSERT_EQ(c.motion.horizontal()[i], 0.01 * r2.values[i]) << i;  // 90 deg: H2 exactly
  }
}

// --- RotD50 and RotD100

TEST(RotD, OneComponentGivesSaAndItsMedianOverAngles) {
  const io::Record r1 = io::read_at2(kH1);
  const std::vector<double> a = r1.to_si();
  const std::vector<double> zero(a.size(), 0.0);
  for (double period : {0.1, 0.5, 2.0}) {
    const RotD r = rotd_spectral_acceleration(r1.time, a, zero, period);
    const double sa = spectral_acceleration(r1.time, a, period);
    EXPECT_DOUBLE_EQ(r.rotd100, sa) << period;
    // |cos theta| over 0..179 deg: 0 once, 1 once, cos k twice for k = 1..89; the 90th and 91st
    // of the sorted 180 are both cos 45 deg
    EXPECT_NEAR(r.rotd50, sa * std::sqrt(0.5), 1e-12 * sa) << period;
  }
}

TEST(RotD, EachAngleIsSaOfTheRotatedRecordAndRotatingThePairLeavesThemUnchanged) {
  const io::Record r1 = io::read_at2(kH1), r2 = io::read_at2(kH2);
  const std::vector<double> a1 = r1.to_si(), a2 = r2.to_si();
  const double period = 0.7;
  const RotD r = rotd_spectral_acceleration(r1.time, a1, a2, period);
  for (int k : {0, 17, 90, 133}) {
    const double sa = spectral_acceleration(r1.time, project_horizontal(a1, a2, k), period);
    EXPECT_NEAR(r.by_angle[static_cast<std::size_t>(k)], sa, 1e-12 * sa) << k;
  }
  EXPECT_GT(r.rotd100, r.rotd50);
  EXPECT_GE(r.rotd100, spectral_acceleration(r1.time, a1, period));
  EXPECT_GE(r.rotd100, spectral_acceleration(r1.time, a2, period));
  // the pair turned by 37 deg: the same set of directions
  const std::vector<double> b1 = project_horizontal(a1, a2, 37.0);
  const std::vector<double> b2 = project_horizontal(a1, a2, 127.0);
  const RotD t = rotd_spectral_acceleration(r1.time, b1, b2, period);
  EXPECT_NEAR(t.rotd50, r.rotd50, 1e-12 * r.rotd50);
  EXPECT_NEAR(t.rotd100, r.rotd100, 1e-12 * r.rotd100);
}

TEST(RotD, RefusesComponentsOfDifferentLengths) {
  const std::vector<double> t{0.0, 0.01, 0.02}, a{0.0, 1.0, 0.0}, b{0.0, 1.0};
  EXPECT_THROW(rotd_spectral_acceleration(t, a, b, 0.5), InputError);
}

}  // namespace
