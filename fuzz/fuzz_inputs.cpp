// SPDX-License-Identifier: BSD-3-Clause
#include "fuzz_inputs.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <vector>

#include "flexrock/core/error.hpp"
#include "flexrock/io/case_file.hpp"
#include "flexrock/io/records.hpp"
#include "flexrock/io/study_files.hpp"
#include "flexrock/model/body.hpp"
#include "flexrock/study/sweep.hpp"

namespace flexrock::fuzz {
namespace {

namespace fs = std::filesystem;

// a private scratch directory for this process, with the record files a case may name; removed
// at exit
struct Scratch {
  fs::path dir;
  Scratch() : dir(fs::temp_directory_path() / ("flexrock_fuzz." + std::to_string(::getpid()))) {
    fs::create_directories(dir);
    auto put = [&](const char* name, const char* text) { std::ofstream(dir / name) << text; };
    put("rec.at2",
        "PEER NGA STRONG MOTION DATABASE RECORD\nEVENT\nACCELERATION TIME HISTORY IN UNITS OF G\n"
        "NPTS=    5, DT=   .0100 SEC\n0.0 0.01 -0.02 0.03 0.0\n");
    // a vertical on rec.at2's time grid, for record suites
    put("up.at2",
        "PEER NGA STRONG MOTION DATABASE RECORD\nEVENT\nACCELERATION TIME HISTORY IN UNITS OF G\n"
        "NPTS=    5, DT=   .0100 SEC\n0.0 -0.5 -1.5 -0.5 0.0\n");
    put("rec.txt", "0 0.01 -0.02\n0.03 0\n");
    put("rec.csv", "time,acc\n0,0\n0.01,0.1\n0.02,-0.1\n0.03,0\n");
    put("nodes.csv", "x,y,mass\n-0.5,0,10\n0.5,0,10\n0,2,100\n");
    put("body.toml", "[body]\ntype = \"rigid_block\"\nwidth = 0.4\nheight = 2.0\nmass = 100.0\n");
    put("lumped.toml",
        "[body]\ntype = \"lumped\"\nnodes_file = \"nodes.csv\"\ntip1_x = -0.5\ntip2_x = 0.5\n"
        "frequencies_hz = [2.0]\nphi_x = [[0.0], [0.0], [1.0]]\nphi_y = [[0.0], [0.0], [0.0]]\n");
  }
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;
};

const fs::path& scratch() {
  static const Scratch s;
  return s.dir;
}

// writes the bytes to scratch()/name and returns the path
std::string put_file(const std::string& name, const std::uint8_t* data, std::size_t size) {
  const fs::path p = scratch() / name;
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  if (!out) std::abort();  // the harness itself failed, not the reader
  return p.string();
}

// a record that was read must be usable: a motion (or a clear error), finite values
void use(const io::Record& r) {
  for (double v : r.values) {
    if (!std::isfinite(v)) std::abort();
  }
  if (r.time.size() != r.values.size()) std::abort();
  for (std::size_t i = 1; i < r.time.size(); ++i) {
    if (!(r.time[i] > r.time[i - 1])) std::abort();
  }
  (void)r.peak_index();
  try {
    const GroundMotion m = r.to_motion(0.5);
    (void)m.at(0.5 * m.duration());
    (void)io::combine(r, &r, 2.0);
  } catch (const InputError&) {
  }
}

constexpr io::AccelUnit kUnits[] = {io::AccelUnit::kG, io::AccelUnit::kMetersPerSecond2,
                                    io::AccelUnit::kCentimetersPerSecond2};

}  // namespace

void at2(const std::uint8_t* data, std::size_t size) {
  const std::string path = put_file("input.at2", data, size);
  try {
    use(io::read_at2(path));
  } catch (const InputError&) {
  }
}

void values(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return;
  // dt: ordinary, tiny, huge and invalid steps (the invalid ones must be refused cleanly)
  static constexpr double kDt[] = {0.01,
                                   0.005,
                                   1e-9,
                                   1e3,
                                   0.0,
                                   -0.01,
                                   1e300,
                                   5e-324,
                                   std::numeric_limits<double>::quiet_NaN(),
                                   std::numeric_limits<double>::infinity()};
  const double dt = kDt[data[0] % std::size(kDt)];
  const io::AccelUnit units = kUnits[(data[0] / std::size(kDt)) % std::size(kUnits)];
  const std::string path = put_file("input.txt", data + 1, size - 1);
  try {
    use(io::read_single_column(path, dt, units));
  } catch (const InputError&) {
  }
}

void csv(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return;
  const io::AccelUnit units = kUnits[data[0] % std::size(kUnits)];
  const std::string path = put_file("input.csv", data + 1, size - 1);
  try {
    use(io::read_time_series(path, units));
  } catch (const InputError&) {
  }
}

void agency(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return;
  static constexpr const char* kNames[] = {"input.smc", "input.NS", "input.ACC.ASC", "input.V2"};
  const std::size_t k = data[0] % std::size(kNames);
  const std::string path = put_file(kNames[k], data + 1, size - 1);
  try {
    switch (k) {
      case 0:
        use(io::read_smc(path));
        break;
      case 1:
        use(io::read_knet(path));
        break;
      case 2:
        use(io::read_esm(path));
        break;
      default:
        use(io::read_cosmos(path));
        break;
    }
  } catch (const InputError&) {
  }
}

void case_file(const std::uint8_t* data, std::size_t size) {
  const std::string path = put_file("case.toml", data, size);
  try {
    (void)io::load_case(path);
  } catch (const InputError&) {
  }
  try {
    std::string type;
    (void)io::load_body(path, &type);
  } catch (const InputError&) {
  }
}

void sweep_manifest(const std::uint8_t* data, std::size_t size) {
  const std::string path = put_file("manifest.toml", data, size);
  try {
    const io::SweepManifest m = io::load_sweep_manifest(path);
    // what the sweep command does next with a manifest: its runs, in index order
    study::validate(m.spec);
    const std::vector<study::SweepRun> runs = study::sweep_runs(m.spec);
    if (runs.size() != m.spec.bodies.size() * m.spec.records.size() * m.spec.scales.size()) {
      std::abort();
    }
  } catch (const InputError&) {
  }
}

void spectrum_file(const std::uint8_t* data, std::size_t size) {
  const std::string path = put_file("spectrum.toml", data, size);
  try {
    const io::SpectrumFile f = io::load_spectrum_file(path);
    // grids that were read are what a spectrum needs: finite, positive, amplitudes increasing
    const std::vector<double>& a = f.is_record ? f.record.scales : f.pulse.amplitudes;
    for (std::size_t i = 0; i < a.size(); ++i) {
      if (!(std::isfinite(a[i]) && a[i] > 0.0) || (i > 0 && !(a[i] > a[i - 1]))) std::abort();
    }
    for (double w : f.pulse.frequencies) {
      if (!(std::isfinite(w) && w > 0.0)) std::abort();
    }
    const Body body(f.body);
    (void)body.rocking_frequency();
  } catch (const InputError&) {
  }
}

bool run_file(const std::string& target, const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)),
                                std::istreambuf_iterator<char>());
  const auto* d = reinterpret_cast<const std::uint8_t*>(bytes.data());
  if (target == "fuzz_at2") {
    at2(d, bytes.size());
  } else if (target == "fuzz_values") {
    values(d, bytes.size());
  } else if (target == "fuzz_csv") {
    csv(d, bytes.size());
  } else if (target == "fuzz_agency") {
    agency(d, bytes.size());
  } else if (target == "fuzz_case") {
    case_file(d, bytes.size());
  } else if (target == "fuzz_sweep") {
    sweep_manifest(d, bytes.size());
  } else if (target == "fuzz_spectrum") {
    spectrum_file(d, bytes.size());
  } else {
    return false;
  }
  return true;
}

}  // namespace flexrock::fuzz
