// SPDX-License-Identifier: BSD-3-Clause
// The impact map of a block on a moving support (include/flexrock/contact/support_impact.hpp)
// against the derivation's impacts (tools/derive/support.py), each of which the script checked
// mass by mass on a random body of point masses: the linear momentum of block and support and the
// block's moment of momentum about the landing corner.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "flexrock/contact/support_impact.hpp"

namespace flexrock {
namespace {

TEST(SupportReference, ImpactMapMatchesTheMassByMassDerivation) {
  std::ifstream in(FLEXROCK_BINARY_DIR "/sympy_reference.json");
  ASSERT_TRUE(in) << "run the derive_sympy_reference test first";
  const nlohmann::json ref = nlohmann::json::parse(in);
  ASSERT_TRUE(ref.contains("support"));
  const auto& impacts = ref["support"]["impacts"];
  ASSERT_GE(impacts.size(), 8u);
  for (const auto& c : impacts) {
    const double m = c["M"], ms = c["m_s"], h = c["h"], b1 = c["b1"], b2 = c["b2"];
    const double z2 = c["zeta2"], thm = c["theta_dot_minus"], udm = c["u_dot_minus"];
    const int landing = c["landing_edge"];
    const double a_pre = landing == 1 ? b2 / h : -b1 / h;
    const double a_post = landing == 1 ? -b1 / h : b2 / h;
    const SupportImpact s = support_impact(m, ms, z2, a_pre, a_post);
    const double thp = s.ratio * thm;
    const double udp = support_velocity_after(s, h, thm, thp, udm);
    const double loss = support_kinetic_at_rest_angle(m, ms, h, z2, a_pre, thm, udm) -
                        support_kinetic_at_rest_angle(m, ms, h, z2, a_post, thp, udp);
    const double tp = c["theta_dot_plus"], up = c["u_dot_plus"], e = c["energy_loss"];
    EXPECT_NEAR(thp, tp, 1e-12 * std::abs(tp));
    EXPECT_NEAR(udp, up, 1e-12 * (std::abs(up) + std::abs(h * thm)));
    EXPECT_NEAR(loss, e, 1e-10 * std::abs(e) + 1e-12);
    EXPECT_GE(loss, 0.0);
  }
}

}  // namespace
}  // namespace flexrock
