# SPDX-License-Identifier: BSD-3-Clause
# the engine (flexrock::core, flexrock::study) needs Eigen and Boost only; the io layer (toml++,
# nlohmann_json) and everything above it (the command line with CLI11 and fmt, the Python module,
# the tests) can be left out for a consumer of the engine alone
option(FLEXROCK_BUILD_IO "Build flexrock::io (case files, records, outputs) and what needs it" ON)
include(CMakeDependentOption)
cmake_dependent_option(FLEXROCK_BUILD_APPS "Build the flexrock command (CLI11, fmt)" ON
                       "FLEXROCK_BUILD_IO" OFF)
option(FLEXROCK_INSTALL "Install rules and the CMake package (find_package(flexrock))"
       ${FLEXROCK_MASTER_PROJECT})
option(FLEXROCK_BUILD_TESTS "Build the test suite" ${FLEXROCK_MASTER_PROJECT})
option(FLEXROCK_BUILD_EXAMPLES "Build the example programs" ${FLEXROCK_MASTER_PROJECT})
option(FLEXROCK_BUILD_BENCH "Build the benchmarks (Google Benchmark)" OFF)
option(FLEXROCK_BUILD_VALIDATION "Build the validation driver (docs/validation.md)"
       ${FLEXROCK_MASTER_PROJECT})
option(FLEXROCK_BUILD_PYTHON "Build the Python module (pybind11)" OFF)
option(FLEXROCK_BUILD_FUZZERS "Build the libFuzzer targets in fuzz/ (clang only)" OFF)
option(FLEXROCK_WERROR "Treat compiler warnings as errors" OFF)
set(FLEXROCK_WITH_MPI "AUTO" CACHE STRING
    "MPI for `flexrock spectrum/sweep` across processes: AUTO (if found), ON (required), OFF")
set_property(CACHE FLEXROCK_WITH_MPI PROPERTY STRINGS AUTO ON OFF)
set(FLEXROCK_SANITIZE "" CACHE STRING "Sanitizers for flexrock targets, e.g. address;undefined")
# each fixed size is its own compile of the event loop: half a minute in a release build, five
# under the sanitizers, whose presets keep 0 to 2 (bodies with more modes then run on the
# dynamic-size loop: the same code, with the products not unrolled)
set(FLEXROCK_FIXED_MODES "8" CACHE STRING
    "Largest mode count (0 to 8) with its own fixed-size event loop; more modes use the dynamic size")
