// SPDX-License-Identifier: BSD-3-Clause
// The table of [solver] keys states each key's rule once: the case reader and the engine's check
// of its options refuse the same values with the same words, the reader at the key's own line.
#include "flexrock/sim/solver_keys.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <string>
#include <type_traits>
#include <variant>

#include "flexrock/core/error.hpp"
#include "flexrock/core/format.hpp"
#include "flexrock/io/case_file.hpp"
#include "flexrock/model/body.hpp"
#include "flexrock/sim/simulate.hpp"
#include "support/expect_error.hpp"

namespace flexrock {
namespace {

namespace fs = std::filesystem;

// a rigid block under a short pulse; [solver] is appended
const std::string kCase = R"([body]
type = "rigid_block"
width = 0.4
height = 2.0
mass = 100.0
[excitation.horizontal]
type = "one_sine"
amplitude = 0.3
units = "g"
period = 1.0
duration = 3.0
[solver]
)";
constexpr int kSolverLine = 13;  // the first line after [solver]

class SolverKeys : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / (std::string("flexrock_solver_keys_") + info->name());
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

// the keys (written first) and options that let `k` apply: its floor and its impact law
std::string prerequisites(const SolverKey& k, SimulationOptions& o) {
  if (k.scope == SolverScope::kCompliant) {
    o.contact_model = ContactModel::kCompliant;
    o.contact_stiffness = 1e8;
    return std::string("contact_model = \"compliant\"\n") +
           (std::string(k.name) == "contact_stiffness" ? "" : "contact_stiffness = 1e8\n");
  }
  if (k.scope == SolverScope::kRestitutionLaw) {
    o.impact_law = ImpactLaw::kRestitution;
    return "impact_law = \"restitution\"\n";
  }
  return "";
}

// a value outside the key's own rule
double bad_value(const SolverKey& k) {
  if (k.bound) return k.bound->hi + 1.0;
  return -2.0;  // below every other rule, and no key's default
}

TEST_F(SolverKeys, ReaderAndEngineRefuseTheSameValuesInTheSameWords) {
  const Body body(BodyParameters::rectangular_block(100.0, 0.4, 2.0));
  const GroundMotion motion = GroundMotion::none(1.0);
  int checked = 0;
  for (const SolverKey& k : kSolverKeys) {
    if (k.rule == SolverRule::kChoice) continue;
    SCOPED_TRACE(k.name);
    SimulationOptions o;
    const std::string pre = prerequisites(k, o);
    const double v = bad_value(k);
    const bool integral = k.rule == SolverRule::kCount;
    const std::string value = integral ? std::to_string(static_cast<long>(v)) : "-2.0";
    const std::string path =
        write(std::string(k.name) + ".toml",
              kCase + pre + k.name + " = " + (k.bound ? format_number(v) : value) + "\n");
    const int line = kSolverLine + static_cast<int>(std::count(pre.begin(), pre.end(), '\n'));
    test::expect_input_error([&] { io::load_case(path); },
                             {".toml:" + std::to_string(line), std::string("solver.") + k.name,
                              "expected " + solver_rule_text(k)});
    // the engine, given the same value (t_end < 0 is its "end of the motion"; a shorthand sets
    // others)
    if (k.scope == SolverScope::kCaseFile) continue;
    std::visit(
        [&](auto field) {
          if constexpr (!std::is_same_v<decltype(field), std::monostate>) {
            using T = std::remove_cvref_t<decltype(o.*field)>;
            if constexpr (std::is_arithmetic_v<T>) o.*field = static_cast<T>(v);
            test::expect_input_error(
                [&] { simulate(body, motion, {}, o); },
                {std::string("options: ") + k.name + " must be " + solver_rule_text(k)});
            ++checked;
          }
        },
        k.field);
  }
  EXPECT_GE(checked, 15);
}

// event_samples past the engine's 32 passed `flexrock check` and failed the run without a line
TEST_F(SolverKeys, EventSamplesBeyondTheEnginesBuffersAreRefusedWhereWritten) {
  const std::string path = write("c.toml", kCase + "event_samples = 33\n");
  test::expect_input_error([&] { io::load_case(path); },
                           {"c.toml:" + std::to_string(kSolverLine), "solver.event_samples",
                            "an integer in [1, 32]", "got 33"});
  const std::string ok = write("ok.toml", kCase + "event_samples = 32\n");
  EXPECT_EQ(io::load_case(ok).options.event_samples, 32);
}

// the friction pair's rule, stated once (friction_coefficient_ok, kinetic_..._ok)
TEST(SolverRules, FrictionCoefficients) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(friction_coefficient_ok(0.5));
  EXPECT_TRUE(friction_coefficient_ok(inf));
  for (const double bad : {0.0, -0.1, -inf, std::nan("")})
    EXPECT_FALSE(friction_coefficient_ok(bad));
  EXPECT_TRUE(kinetic_friction_coefficient_ok(0.4, 0.5));
  EXPECT_TRUE(kinetic_friction_coefficient_ok(0.5, 0.5));
  EXPECT_TRUE(kinetic_friction_coefficient_ok(inf, 0.5));  // equal to the static one
  EXPECT_TRUE(kinetic_friction_coefficient_ok(0.4, inf));
  EXPECT_FALSE(kinetic_friction_coefficient_ok(0.6, 0.5));
  EXPECT_FALSE(kinetic_friction_coefficient_ok(0.0, 0.5));
  EXPECT_FALSE(kinetic_friction_coefficient_ok(std::nan(""), 0.5));
}

// one row a key, one key an option
TEST(SolverRules, EveryKeyAndEveryOptionOnce) {
  std::set<std::string> names;
  for (const SolverKey& k : kSolverKeys) {
    EXPECT_TRUE(names.insert(k.name).second) << k.name;
    EXPECT_TRUE(*k.doc) << k.name;
    EXPECT_TRUE(k.rule != SolverRule::kBounded || k.bound) << k.name;
    EXPECT_TRUE(k.bound == nullptr || std::string(k.bound->key) == k.name) << k.name;
  }
  EXPECT_EQ(names.size(), std::size(kSolverKeys));
  EXPECT_EQ(find_solver_key("friction_coefficient")->rule, SolverRule::kCoefficient);
  EXPECT_EQ(find_solver_key("nonsense"), nullptr);
}

// the impact_law key's reference lists every row of the impact laws' table with its description,
// so that a new law is written in its row only (the reference once listed them by hand)
TEST(SolverRules, ImpactLawReferenceListsTheLawsRows) {
  const SolverKey* key = find_solver_key("impact_law");
  ASSERT_NE(key, nullptr);
  const std::string doc = solver_key_doc(*key);
  const std::string reference = io::solver_key_reference();
  EXPECT_NE(reference.find(doc), std::string::npos);
  for (const ImpactLawInfo& law : kImpactLaws) {
    const std::string entry = std::string("`") + law.name + "` (" + law.description + ")";
    EXPECT_NE(doc.find(entry), std::string::npos) << law.name;
  }
  // keys without a table of their own keep their doc as written
  EXPECT_EQ(solver_key_doc(*find_solver_key("rtol")), find_solver_key("rtol")->doc);
}

}  // namespace
}  // namespace flexrock
