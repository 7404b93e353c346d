// SPDX-License-Identifier: BSD-3-Clause
// taken_rigid (model/builders.hpp), the one way a deformable body is taken as rigid (a case file's
// `rigid = true`, the bench's n = 0, the validation's rigid references): the rigid constants are
// kept, every modal term is dropped.
#include <gtest/gtest.h>

#include "flexrock/model/body.hpp"
#include "flexrock/model/builders.hpp"

namespace flexrock {
namespace {

TEST(TakenRigid, KeepsTheRigidConstantsAndDropsEveryMode) {
  BodyParameters p = oscillator_on_slab(800.0, 2.0, 400.0, 2.0, 1.0, 0.02);
  p.gravity = 9.81;
  ASSERT_EQ(Body(p).modes(), 1);
  const BodyParameters r = taken_rigid(p);
  EXPECT_EQ(r.mass, p.mass);
  EXPECT_EQ(r.height, p.height);
  EXPECT_EQ(r.b1, p.b1);
  EXPECT_EQ(r.b2, p.b2);
  EXPECT_EQ(r.zeta2, p.zeta2);
  EXPECT_EQ(r.gravity, 9.81);
  EXPECT_EQ(r.mu.size() + r.kappa.size() + r.gamma.size(), 0);
  EXPECT_EQ(r.psi_x.size() + r.psi_y.size() + r.delta.size() + r.beta.size(), 0);
  EXPECT_EQ(r.damping.kind, DampingKind::kNone);
  const Body rigid(r), flexible(p);
  EXPECT_EQ(rigid.modes(), 0);
  // the same rigid body as the one built from its constants
  const Body built(BodyParameters::rigid(p.mass, p.height, p.b1, p.b2, p.zeta2));
  EXPECT_EQ(rigid.alpha1(), flexible.alpha1());
  // p^2 = M g R / I_O grows with g: the kept gravity is the one the rigid body rocks under
  EXPECT_DOUBLE_EQ(rigid.rocking_frequency() * rigid.rocking_frequency(),
                   built.rocking_frequency() * built.rocking_frequency() * 9.81 / kStandardGravity);
}

}  // namespace
}  // namespace flexrock
