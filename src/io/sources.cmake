# SPDX-License-Identifier: BSD-3-Clause
# included from src/CMakeLists.txt; paths are relative to src/

# flexrock::io: record files (PEER .AT2, single-column, time/acceleration text and CSV)
add_library(flexrock_io io/records.cpp)
add_library(flexrock::io ALIAS flexrock_io)
target_link_libraries(flexrock_io PUBLIC flexrock::core PRIVATE flexrock_warnings)
flexrock_apply_sanitizers(flexrock_io)


# case files (toml++) and outputs (CSV, summary JSON): flexrock::io
target_sources(flexrock_io PRIVATE io/case_file.cpp io/outputs.cpp)
find_package(tomlplusplus CONFIG QUIET)
find_package(nlohmann_json 3.9 REQUIRED)
if(TARGET tomlplusplus::tomlplusplus)
  target_link_libraries(flexrock_io PRIVATE tomlplusplus::tomlplusplus)
else()
  # header-only use when no CMake package is installed
  target_compile_definitions(flexrock_io PRIVATE TOML_HEADER_ONLY=1)
endif()
target_link_libraries(flexrock_io PRIVATE nlohmann_json::nlohmann_json)

# study files (spectrum specs, sweep manifests and journals, fragility input): flexrock::io
target_sources(flexrock_io PRIVATE io/study_files.cpp)
target_link_libraries(flexrock_io PUBLIC flexrock::study)
