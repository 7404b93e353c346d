// SPDX-License-Identifier: BSD-3-Clause
// The logic of the fuzz targets, shared by the libFuzzer executables (clang) and the regression
// test that replays fuzz/corpus/ and fuzz/regressions/ in the normal test suite (any compiler).
//
// Each function feeds one input to a reader through a file in a private scratch directory. A
// reader may reject the input only with flexrock::InputError; anything else escaping (another
// exception, a crash, a hang) is a bug, and the libFuzzer executables report it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace flexrock::fuzz {

/// PEER .AT2 reader: the input is the file.
void at2(const std::uint8_t* data, std::size_t size);

/// Values (single-column) reader: the first byte picks dt and the units, the rest is the file.
void values(const std::uint8_t* data, std::size_t size);

/// CSV / two-column time-series reader: the first byte picks the units, the rest is the file.
void csv(const std::uint8_t* data, std::size_t size);

/// Agency record readers: the first byte picks SMC, K-NET, ESM or COSMOS (modulo 4), the rest
/// is the file.
void agency(const std::uint8_t* data, std::size_t size);

/// TOML case loader (load_case, then load_body): the input is the case file. Record files it may
/// name sit next to it: rec.at2, rec.txt (values), rec.csv and nodes.csv.
void case_file(const std::uint8_t* data, std::size_t size);

/// Sweep manifest loader (load_sweep_manifest, then the runs): the input is the manifest. Files
/// it may name sit next to it: body.toml (a rigid block), lumped.toml (a lumped body reading
/// nodes.csv), rec.at2, rec.txt, rec.csv.
void sweep_manifest(const std::uint8_t* data, std::size_t size);

/// Spectrum spec loader (load_spectrum_file): the input is the spec; the same files lie next to
/// it as for sweep_manifest().
void spectrum_file(const std::uint8_t* data, std::size_t size);

/// Runs `target` ("fuzz_at2", "fuzz_values", "fuzz_csv", "fuzz_agency", "fuzz_case",
/// "fuzz_sweep" or "fuzz_spectrum") on the bytes of a file.
/// Returns false for an unknown target.
bool run_file(const std::string& target, const std::string& path);

}  // namespace flexrock::fuzz
