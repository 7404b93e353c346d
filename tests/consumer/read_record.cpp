// SPDX-License-Identifier: BSD-3-Clause
// Reads a single-column record (in g) with an installed flexrock::io and checks its samples.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "flexrock/io/records.hpp"

int main(int argc, char** argv) {
  const std::string path = argc > 1 ? argv[1] : "record.txt";
  {
    std::ofstream out(path);
    out << "0.0\n0.25\n-0.5\n0.0\n";
  }
  const flexrock::io::Record r =
      flexrock::io::read_single_column(path, 0.01, flexrock::io::AccelUnit::kG);
  const bool ok = r.npts() == 4 && std::abs(r.duration() - 0.03) < 1e-15 && r.peak_index() == 2 &&
                  std::abs(r.to_si()[2] + 0.5 * 9.80665) < 1e-12;
  std::printf("%s: read %zu samples over %g s from %s\n", ok ? "ok" : "FAIL", r.npts(),
              r.duration(), path.c_str());
  return ok ? 0 : 1;
}
