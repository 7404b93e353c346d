// SPDX-License-Identifier: BSD-3-Clause
// Lumped bodies from modal files as finite-element programs write them: an ANSYS PRNSOL listing
// (mass-normalised shapes, one paginated table a mode, UX UY UZ USUM columns) and an Abaqus/CAE
// field output report (shapes normalised to a unit maximum, one table a frame, rows in another
// order than the nodes), both printed to 4 significant digits, with a nodes CSV whose header names
// its columns (a node-id column first) and massless nodes. Both must give the body built from
// the exact modes to the precision of the printed digits.
//
// The model: a two-storey shear frame on a rigid base slab, masses 200 kg at 1.5 m and 100 kg at
// 3 m, storey stiffnesses 3e5 and 2e5 N/m: K = [[5e5, -2e5], [-2e5, 2e5]], M = diag(200, 100);
// det(K - lambda M) = 0 gives lambda^2 - 4500 lambda + 3e6 = 0, lambda = 2250 -+ sqrt(2062500),
// and the shapes (1, (5e5 - 200 lambda)/2e5) normalised to a unit maximum.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "flexrock/core/error.hpp"
#include "flexrock/io/case_file.hpp"
#include "flexrock/model/body.hpp"
#include "flexrock/model/builders.hpp"

namespace flexrock::io {
namespace {

namespace fs = std::filesystem;

const std::string kFe = FLEXROCK_SOURCE_DIR "/tests/data/fe/";

// the exact modes of the frame
struct Exact {
  double lambda[2];
  double shape[2][2];  // [mode][storey], max |.| = 1
  Exact() {
    for (int k = 0; k < 2; ++k) {
      lambda[k] = 2250.0 + (k == 0 ? -1.0 : 1.0) * std::sqrt(2062500.0);
      const double x2 = (5e5 - 200.0 * lambda[k]) / 2e5;
      const double big = std::max(1.0, std::abs(x2));
      shape[k][0] = 1.0 / big;
      shape[k][1] = x2 / big;
    }
  }
};

// the same body from exact values: the nodes of frame_nodes.csv and the exact shapes
BodyParameters exact_body() {
  const Exact e;
  LumpedModel m;
  m.nodes = {{-0.6, 0, 0, 0},  {0.6, 0, 0, 0},   {0, 0, 150, 20},
             {0, 1.5, 200, 0}, {0, 3.0, 100, 0}, {0.3, 3.0, 0, 0}};
  m.tip1_x = -0.6;
  m.tip2_x = 0.6;
  m.phi_x = MatrixX::Zero(6, 2);
  m.phi_y = MatrixX::Zero(6, 2);
  m.frequencies.resize(2);
  for (int k = 0; k < 2; ++k) {
    m.phi_x(3, k) = e.shape[k][0];
    m.phi_x(4, k) = m.phi_x(5, k) = e.shape[k][1];
    m.frequencies(k) = std::sqrt(e.lambda[k]);
  }
  return from_lumped_model(m);
}

class FeModalFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / (std::string("flexrock_fe_") + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& content) const {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << content;
    return p.string();
  }

  // a case reading `nodes` and `shapes` (paths) with the printed frequencies
  Case load(const std::string& nodes, const std::string& shapes) const {
    return load_case(write("case.toml", R"(
[body]
type = "lumped"
tip1_x = -0.6
tip2_x = 0.6
nodes_file = ")" + nodes + R"("
shapes_file = ")" + shapes + R"("
frequencies_hz = [4.540, 9.663]
[excitation.horizontal]
type = "one_sine"
amplitude = 0.3
units = "g"
period = 1.0
duration = 2.0
)"));
  }

  std::string error_of(const std::string& nodes, const std::string& shapes) const {
    try {
      load(nodes, shapes);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  }

  fs::path dir_;
};

// the printed body against the exact one: 4 significant digits in the shapes and frequencies
void expect_close_to_exact(const Case& c) {
  const BodyParameters x = exact_body();
  const BodyParameters& p = c.body;
  EXPECT_DOUBLE_EQ(p.mass, x.mass);
  EXPECT_DOUBLE_EQ(p.height, x.height);
  EXPECT_DOUBLE_EQ(p.zeta2, x.zeta2);
  ASSERT_EQ(p.mu.rows(), 2);
  // re-orthogonalised: no coupling left through the mass
  EXPECT_LT(std::abs(p.mu(0, 1)), 1e-12 * p.mu(0, 0));
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(p.mu(i, i), x.mu(i, i), 1e-3 * x.mu(i, i)) << "mode " << i + 1;
    EXPECT_NEAR(p.kappa(i, i), x.kappa(i, i), 1e-3 * x.kappa(i, i)) << "mode " << i + 1;
    EXPECT_NEAR(p.psi_x(i), x.psi_x(i), 1e-3 * std::abs(x.psi_x(i))) << "mode " << i + 1;
    EXPECT_NEAR(p.beta(i), x.beta(i), 1e-3 * std::abs(x.beta(i))) << "mode " << i + 1;
  }
  // the frequencies the body computes are the printed ones
  const Body body(p);
  EXPECT_NEAR(body.natural_frequencies()(0) / (2 * std::numbers::pi), 4.540, 1e-9);
  EXPECT_NEAR(body.natural_frequencies()(1) / (2 * std::numbers::pi), 9.663, 1e-9);
  ASSERT_EQ(c.notes.size(), 1u);
  EXPECT_NE(c.notes[0].find("re-orthogonalised"), std::string::npos) << c.notes[0];
  EXPECT_NE(c.notes[0].find("modes 1 and 2"), std::string::npos) << c.notes[0];
}

TEST_F(FeModalFiles, AnsysPrnsolListingGivesTheExactBody) {
  expect_close_to_exact(load(kFe + "frame_nodes.csv", kFe + "frame_modes_ansys.lis"));
}

TEST_F(FeModalFiles, AbaqusFieldReportGivesTheExactBody) {
  expect_close_to_exact(load(kFe + "frame_nodes.csv", kFe + "frame_modes_abaqus.rpt"));
}

TEST_F(FeModalFiles, AnsysAndAbaqusFilesAgree) {
  const Case a = load(kFe + "frame_nodes.csv", kFe + "frame_modes_ansys.lis");
  const Case b = load(kFe + "frame_nodes.csv", kFe + "frame_modes_abaqus.rpt");
  EXPECT_TRUE(a.body.mu.isApprox(b.body.mu, 1e-3));
  EXPECT_TRUE(a.body.kappa.isApprox(b.body.kappa, 1e-3));
}

TEST_F(FeModalFiles, ColumnsAreReadByNameInAnyOrder) {
  // the node-id column last and the columns shuffled: the same body as the file in order
  const std::string nodes =
      write("nodes.csv",
            "mass (kg); y; x; rotary_inertia; node\n0;0;-0.6;0;1\n0;0;0.6;0;2\n"
            "150;0;0;20;3\n200;1.5;0;0;4\n100;3;0;0;5\n0;3;0.3;0;6\n");
  const std::string shapes = write("shapes.csv",
                                   "node, phi_y_2, phi_x_2, phi_y_1, phi_x_1\n"
                                   "6, 0, -1.000, 0, 1.000\n5, 0, -1.000, 0, 1.000\n"
                                   "4, 0, 0.8431, 0, 0.5931\n3, 0, 0, 0, 0\n1, 0, 0, 0, 0\n"
                                   "2, 0, 0, 0, 0\n");
  expect_close_to_exact(load(nodes, shapes));
  expect_close_to_exact(load(kFe + "frame_nodes.csv", shapes));
}

TEST_F(FeModalFiles, ANodeIdColumnWithoutAHeaderIsRejected) {
  // four columns, no header: node, x, y, mass would shift into x, y, mass, rotary_inertia
  const std::string nodes = write("nodes.csv", "1 -0.6 0 0\n2 0.6 0 0\n3 0 0 150\n");
  const std::string msg = error_of(nodes, kFe + "frame_modes_ansys.lis");
  EXPECT_NE(msg.find("nodes.csv:1:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("expected 3 columns x, y, mass without a header row, got 4"),
            std::string::npos)
      << msg;
  EXPECT_NE(msg.find("case.toml:"), std::string::npos) << msg;
}

TEST_F(FeModalFiles, BadTablesAreRejectedWithFileAndLine) {
  const std::string shapes = kFe + "frame_modes_ansys.lis";
  // an unknown column, with the closest known name
  std::string msg = error_of(write("n1.csv", "node,x,y,mas\n1,0,0,1\n"), shapes);
  EXPECT_NE(msg.find("n1.csv:1: unknown column \"mas\" (did you mean \"mass\"?)"),
            std::string::npos)
      << msg;
  // a node the shapes do not cover
  msg = error_of(write("n2.csv", "node,x,y,mass\n1,-0.6,0,0\n9,0,1,10\n"), shapes);
  EXPECT_NE(msg.find("n2.csv:3: node 9 has no row in the mode shapes"), std::string::npos) << msg;
  // the same node twice
  msg = error_of(write("n3.csv", "node,x,y,mass\n1,-0.6,0,0\n1,0,1,10\n"), shapes);
  EXPECT_NE(msg.find("n3.csv:3: node 1 is listed twice (also on line 2)"), std::string::npos)
      << msg;
  // a negative mass
  msg = error_of(write("n4.csv", "node,x,y,mass\n1,-0.6,0,-1\n"), shapes);
  EXPECT_NE(msg.find("n4.csv:2: expected a node mass and rotary inertia >= 0"), std::string::npos)
      << msg;
  // more mode tables than frequencies
  msg = error_of(kFe + "frame_nodes.csv",
                 write("s1.lis", "NODE UX UY\n1 0 0\n\nNODE UX UY\n1 0 0\n\nNODE UX UY\n1 0 0\n"));
  EXPECT_NE(msg.find("s1.lis: expected 2 mode tables"), std::string::npos) << msg;
  EXPECT_NE(msg.find("found 3"), std::string::npos) << msg;
  // a row of the wrong width
  msg = error_of(kFe + "frame_nodes.csv", write("s2.lis", "NODE UX UY\n1 0 0\n2 0\n"));
  EXPECT_NE(msg.find("s2.lis:3: expected 3 values"), std::string::npos) << msg;
  // no header a table of shapes can be read from
  msg = error_of(kFe + "frame_nodes.csv", write("s3.lis", "NODE A B\n1 0 0\n"));
  EXPECT_NE(msg.find("s3.lis:2: a row of numbers with no header row"), std::string::npos) << msg;
}

TEST_F(FeModalFiles, ShapesFarFromOrthogonalAreRejectedWithTheRelativeFigure) {
  // mode 2 of the printed file with node 4 at 0.5 instead of 0.8431:
  // m_12 = 200 (0.5931)(0.5) - 100 = -40.69, m_11 = 170.35, m_22 = 150: 0.2545 relative
  const std::string shapes =
      write("s.csv",
            "node,phi_x_1,phi_y_1,phi_x_2,phi_y_2\n1,0,0,0,0\n2,0,0,0,0\n3,0,0,0,0\n"
            "4,0.5931,0,0.5,0\n5,1,0,-1,0\n6,1,0,-1,0\n");
  const std::string msg = error_of(kFe + "frame_nodes.csv", shapes);
  EXPECT_NE(msg.find("modes 1 and 2 are not mass-orthogonal: |m_ij| / sqrt(m_ii m_jj) = 0.2545"),
            std::string::npos)
      << msg;
  EXPECT_NE(msg.find("more than the 0.01"), std::string::npos) << msg;
}

}  // namespace
}  // namespace flexrock::io
