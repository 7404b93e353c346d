// SPDX-License-Identifier: BSD-3-Clause
// Replays the fuzz seed corpus (fuzz/corpus/<target>/) and every input the fuzzers ever found
// wrong (fuzz/regressions/<target>/) through the fuzz targets' logic, in the normal test suite
// and with any compiler. Each input must be read or refused with flexrock::InputError: another
// exception fails the test, a crash or a hang fails the executable.
#include <gtest/gtest.h>

#include <algorithm>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "fuzz_inputs.hpp"

namespace {

namespace fs = std::filesystem;

// the files under fuzz/<kind>/<target>, sorted
std::vector<fs::path> inputs(const std::string& kind, const std::string& target) {
  std::vector<fs::path> files;
  const fs::path dir = fs::path(FLEXROCK_SOURCE_DIR) / "fuzz" / kind / target;
  if (!fs::is_directory(dir)) return files;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.is_regular_file() && e.path().filename() != "README.md") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

class FuzzReplay : public ::testing::TestWithParam<std::string> {};

TEST_P(FuzzReplay, EveryCorpusAndRegressionInputIsReadOrRefusedCleanly) {
  const std::string target = GetParam();
  const auto corpus = inputs("corpus", target);
  EXPECT_GE(corpus.size(), 4U) << "seed corpus of " << target << " is missing";
  const auto regressions = inputs("regressions", target);
  for (const auto* set : {&corpus, &regressions}) {
    for (const fs::path& p : *set) {
      SCOPED_TRACE(p.string());
      try {
        ASSERT_TRUE(flexrock::fuzz::run_file(target, p.string()));
      } catch (const std::exception& e) {
        ADD_FAILURE() << "escaped: " << e.what();
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Targets, FuzzReplay,
                         ::testing::Values("fuzz_at2", "fuzz_values", "fuzz_csv", "fuzz_agency",
                                           "fuzz_case", "fuzz_sweep", "fuzz_spectrum"));

}  // namespace
