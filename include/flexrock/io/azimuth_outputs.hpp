// SPDX-License-Identifier: BSD-3-Clause
// The outputs of a planar body at every azimuth of a record pair (`flexrock azimuths`): one CSV
// row per azimuth, from one table of columns (azimuth_columns()) that the writer, `flexrock keys`
// and docs/case-file.md share, and the envelope in a summary JSON. Written atomically, the
// summary last, as the outputs of one run (outputs.hpp).
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "flexrock/excitation/intensity.hpp"
#include "flexrock/io/case_file.hpp"
#include "flexrock/model/body.hpp"
#include "flexrock/study/azimuths.hpp"

namespace flexrock::io {

/// One column of the per-azimuth CSV.
struct AzimuthColumn {
  const char* name;  // with its unit suffix
  const char* unit;
  const char* doc;
  std::string (*value)(const study::AzimuthRun& run);
};

/// Every column, in the CSV's order.
const std::vector<AzimuthColumn>& azimuth_columns();

/// The column reference, as the Markdown table of docs/case-file.md, with its begin and end
/// marker lines (`flexrock keys --markdown`).
std::string azimuth_column_reference();

/// The per-azimuth CSV: a header row, then one row per run.
void write_azimuth_table(std::ostream& out, const std::vector<study::AzimuthRun>& runs);

/// The azimuth sweep's summary JSON: the case, the pair, the grid, the envelope.
std::string azimuth_summary_json(const Case& c, const Body& body,
                                 const std::vector<study::AzimuthRun>& runs,
                                 const study::AzimuthEnvelope& envelope,
                                 const std::string& table_path);

/// RotD50 and RotD100 of the peak acceleration of a case's pair as it is run (scaled): of Sa at
/// kMinSpectralPeriod, where the oscillator follows the ground (intensity.hpp). The summary
/// JSON's pair.rotd50_pga_m_per_s2 and rotd100_pga_m_per_s2.
RotD pair_peak_rotd(const Case& c);

/// Where the sweep's outputs go: "<stem>.azimuths.csv" and "<stem>.azimuths.json" in
/// `output_dir` (the working directory when empty).
struct AzimuthPaths {
  std::string table;
  std::string summary;
};
AzimuthPaths azimuth_paths(const Case& c, const std::string& output_dir);

/// Throws InputError if an output is an input of the case or the two are one file.
void check_azimuth_paths(const Case& c, const AzimuthPaths& paths);

/// Writes both files (the summary last, after removing an old one); nothing is written when a
/// value is not finite. Throws std::runtime_error when a file cannot be written.
void write_azimuth_outputs(const Case& c, const Body& body,
                           const std::vector<study::AzimuthRun>& runs,
                           const study::AzimuthEnvelope& envelope, const AzimuthPaths& paths);

}  // namespace flexrock::io
