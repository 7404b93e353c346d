# SPDX-License-Identifier: BSD-3-Clause
# included from src/CMakeLists.txt; paths are relative to src/

# flexrock::io: record files (PEER .AT2, USGS SMC, K-NET, ESM, COSMOS, single-column,
# time/acceleration text and CSV)
add_library(flexrock_io io/records.cpp io/agency_records.cpp io/files.cpp)
add_library(flexrock::io ALIAS flexrock_io)
set_target_properties(flexrock_io PROPERTIES EXPORT_NAME io)
target_link_libraries(flexrock_io PUBLIC flexrock::core
                                  PRIVATE $<BUILD_INTERFACE:flexrock_warnings>)
flexrock_apply_sanitizers(flexrock_io)


# case files (toml++) and outputs (CSV, summary JSON): flexrock::io
target_sources(flexrock_io PRIVATE io/case_file.cpp io/modal_tables.cpp io/outputs.cpp
                                   io/restraint_io.cpp)
# record pairs at every azimuth: needs flexrock::study (linked below)
target_sources(flexrock_io PRIVATE io/azimuth_outputs.cpp)
# a body of revolution in 3D (docs/theory.md §27)
target_sources(flexrock_io PRIVATE io/rim_outputs.cpp)
find_package(tomlplusplus CONFIG QUIET)
find_package(nlohmann_json 3.9 REQUIRED)
if(TARGET tomlplusplus::tomlplusplus)
  # a compiled library: an installed flexrock::io links it (flexrockConfig.cmake finds it)
  target_link_libraries(flexrock_io PRIVATE tomlplusplus::tomlplusplus)
  set(FLEXROCK_IO_LINKS_TOMLPLUSPLUS ON CACHE INTERNAL "")
else()
  # header-only use when no CMake package is installed
  target_compile_definitions(flexrock_io PRIVATE TOML_HEADER_ONLY=1)
  set(FLEXROCK_IO_LINKS_TOMLPLUSPLUS OFF CACHE INTERNAL "")
endif()
# header-only: not part of an installed flexrock::io's link interface
target_link_libraries(flexrock_io PRIVATE $<BUILD_INTERFACE:nlohmann_json::nlohmann_json>)

# study files (spectrum specs, sweep manifests and journals, fragility input): flexrock::io
target_sources(flexrock_io PRIVATE io/study_files.cpp io/study_suites.cpp io/study_spectrum.cpp
                                   io/study_sweep.cpp io/study_journal.cpp
                                   io/study_fragility_input.cpp io/fragility_session.cpp
                                   io/journal.cpp io/uncertain_tables.cpp
                                   io/study_session.cpp io/study_shards.cpp io/qualify.cpp)
target_link_libraries(flexrock_io PUBLIC flexrock::study)
