// SPDX-License-Identifier: BSD-3-Clause
// The cost of uncertain parameters per run, next to the run itself: a sweep manifest's sample
// design (built once per sweep), each run's draw (the values of its sample), its sampled body
// (apply + Body) and its simulation. Prints microseconds per run (medians of 5 repetitions).
//   flexrock_uncertain_cost [MANIFEST] (default examples/studies/uncertain_sweep.toml)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "flexrock/io/study_files.hpp"
#include "flexrock/study/sweep.hpp"

namespace {

using Clock = std::chrono::steady_clock;

template <class F>
double median_seconds(F&& f) {
  std::vector<double> t;
  for (int k = 0; k < 5; ++k) {
    const auto t0 = Clock::now();
    f();
    t.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
  }
  std::sort(t.begin(), t.end());
  return t[2];
}

}  // namespace

int main(int argc, char** argv) {
  using namespace flexrock;
  const std::string path =
      argc > 1 ? argv[1]
               : std::string(FLEXROCK_SOURCE_DIR) + "/examples/studies/uncertain_sweep.toml";
  const study::SweepSpec spec = io::load_sweep_manifest(path).spec;
  const std::vector<study::SweepRun> runs = study::sweep_runs(spec);
  const double n = static_cast<double>(runs.size());
  std::printf("%s: %zu runs, %zu uncertain parameters, %s\n", path.c_str(), runs.size(),
              spec.uncertainty.parameters.size(),
              spec.uncertainty.sampling.method == study::SamplingMethod::kLatinHypercube
                  ? "Latin hypercube"
                  : "random");
  double sink = 0.0;
  // once per sweep: the design (the hypercube's permutations)
  const double design =
      median_seconds([&] { sink += static_cast<double>(study::sample_design(spec).samples()); });
  const study::SampleDesign d = study::sample_design(spec);
  // per run, repeated 1000 times over the sweep's runs: the draw, then the sampled body too
  const int reps = 1000;
  const double draw = median_seconds([&] {
    for (int r = 0; r < reps; ++r) {
      for (const study::SweepRun& run : runs) sink += d.values(study::sample_index(spec, run))[0];
    }
  });
  const double body = median_seconds([&] {
    for (int r = 0; r < reps; ++r) {
      for (const study::SweepRun& run : runs) {
        const std::vector<double> v = d.values(study::sample_index(spec, run));
        sink += Body(study::run_body(spec, run, v)).rocking_frequency();
      }
    }
  });
  // the runs themselves, on one thread
  const double sweep =
      median_seconds([&] { sink += static_cast<double>(study::run_sweep(spec, {}, {1}).size()); });
  // a large Latin hypercube: 1e6 samples of the manifest's parameters
  const double big = median_seconds([&] {
    sink += static_cast<double>(study::SampleDesign(spec.uncertainty, 1'000'000).samples());
  });
  std::printf("design, once per sweep:        %10.3f us (%.3f us per run)\n", design * 1e6,
              design * 1e6 / n);
  std::printf("draw of a run's values:        %10.3f us per run\n", draw * 1e6 / (reps * n));
  std::printf("draw + sampled body (Body):    %10.3f us per run\n", body * 1e6 / (reps * n));
  std::printf("simulation, 1 thread:          %10.1f us per run\n", sweep * 1e6 / n);
  std::printf("design of 1e6 samples:         %10.3f s (%.3f us per sample)\n", big, big);
  return sink == 0.5 ? 1 : 0;
}
