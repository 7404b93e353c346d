# SPDX-License-Identifier: BSD-3-Clause
# included from tests/CMakeLists.txt; paths are relative to tests/
# Hardening: random soak of the engine, adversarial inputs, fuzz regressions, reproducibility and
# interrupted runs (docs/reliability.md).

# random soak: a short fixed-seed run here (FLEXROCK_SOAK_RUNS cases); the long one is
#   build/release/tests/flexrock_soak --runs 100000 --threads 2
find_package(Threads REQUIRED)
add_executable(flexrock_soak soak/soak.cpp)
target_include_directories(flexrock_soak PRIVATE ${PROJECT_SOURCE_DIR}/tests)
target_link_libraries(flexrock_soak PRIVATE flexrock::core flexrock_warnings Threads::Threads)
flexrock_apply_sanitizers(flexrock_soak)
set(FLEXROCK_SOAK_RUNS 2000 CACHE STRING "Cases of the soak test in ctest (the long soak: 100000)")
set(_soak_runs ${FLEXROCK_SOAK_RUNS})
if(FLEXROCK_SANITIZE)
  # sanitized builds run ~10x slower: fewer cases, the same generator
  math(EXPR _soak_runs "${FLEXROCK_SOAK_RUNS} / 10")
endif()
add_test(NAME soak_short COMMAND flexrock_soak --runs ${_soak_runs} --threads 2)
set_tests_properties(soak_short PROPERTIES LABELS soak TIMEOUT 300)
# a harsh case whose balance misses the bound at the default tolerances (2.85 x; within it at
# rtol 1e-12): the soak must show that the run flagged it itself (energy_unbalanced)
if(NOT FLEXROCK_SANITIZE)
  add_test(NAME soak_shows_the_runs_energy_flag
           COMMAND flexrock_soak --coupled --seed 20261129 --only 4935)
  set_tests_properties(soak_shows_the_runs_energy_flag PROPERTIES LABELS soak TIMEOUT 300
                       PASS_REGULAR_EXPRESSION "x the bound; flagged by the run \\(energy_unbalanced\\)")
endif()

# adversarial inputs (empty records, huge dt, 10^7 samples, 100 g, 1e-9 m edges, stiff modes,
# singular modal mass, endless chatter): a hang fails on the TIMEOUT
add_executable(flexrock_adversarial_tests unit/adversarial_inputs_test.cpp)
target_include_directories(flexrock_adversarial_tests PRIVATE ${PROJECT_SOURCE_DIR}/tests)
target_link_libraries(flexrock_adversarial_tests PRIVATE flexrock::io flexrock::core GTest::gtest
                                                         GTest::gtest_main flexrock_warnings)
flexrock_apply_sanitizers(flexrock_adversarial_tests)
gtest_discover_tests(flexrock_adversarial_tests PROPERTIES LABELS unit TIMEOUT 120
                     DISCOVERY_TIMEOUT 60)

# the fuzz targets' logic replayed on fuzz/corpus/ and fuzz/regressions/ (any compiler)
flexrock_add_test(flexrock_fuzz_regression_tests
  SOURCES unit/fuzz_regression_test.cpp ${PROJECT_SOURCE_DIR}/fuzz/fuzz_inputs.cpp
  LIBS flexrock::io
  LABEL unit)
target_include_directories(flexrock_fuzz_regression_tests PRIVATE ${PROJECT_SOURCE_DIR}/fuzz)

# the command line: interrupted runs leave complete files or none; the same input gives the same
# bytes (across runs and thread counts)
if(TARGET flexrock)
  foreach(script interrupt reproducible)
    add_test(NAME cli_${script}
             COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/${script}.sh $<TARGET_FILE:flexrock>
                     ${PROJECT_SOURCE_DIR})
    set_tests_properties(cli_${script} PROPERTIES LABELS cli TIMEOUT 300)
  endforeach()
endif()

# files that are not what they seem (FIFOs, devices, symbolic-link loops, over-long names,
# outputs that are inputs): refused without blocking, a hang fails on the TIMEOUT
add_executable(flexrock_io_hazard_tests unit/io_hazards_test.cpp)
target_include_directories(flexrock_io_hazard_tests PRIVATE ${PROJECT_SOURCE_DIR}/tests)
target_link_libraries(flexrock_io_hazard_tests PRIVATE flexrock::io flexrock::core GTest::gtest
                                                       GTest::gtest_main flexrock_warnings)
flexrock_apply_sanitizers(flexrock_io_hazard_tests)
gtest_discover_tests(flexrock_io_hazard_tests PROPERTIES LABELS unit TIMEOUT 60
                     DISCOVERY_TIMEOUT 60)

# files planted or forged by someone else (links at temporaries and journals, binary and
# oversized inputs, a hand-edited sweep CSV) and solver values past their physical range
add_executable(flexrock_hostile_files_tests unit/hostile_files_test.cpp)
target_include_directories(flexrock_hostile_files_tests PRIVATE ${PROJECT_SOURCE_DIR}/tests)
target_link_libraries(flexrock_hostile_files_tests PRIVATE flexrock::io flexrock::core
                                                           GTest::gtest GTest::gtest_main
                                                           flexrock_warnings)
flexrock_apply_sanitizers(flexrock_hostile_files_tests)
gtest_discover_tests(flexrock_hostile_files_tests PROPERTIES LABELS unit TIMEOUT 60
                     DISCOVERY_TIMEOUT 60)
if(TARGET flexrock)
  add_test(NAME cli_hostile_files
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/hostile_files.sh $<TARGET_FILE:flexrock>
                   ${PROJECT_SOURCE_DIR})
  set_tests_properties(cli_hostile_files PROPERTIES LABELS cli TIMEOUT 300)
endif()
