# SPDX-License-Identifier: BSD-3-Clause
# included from tests/CMakeLists.txt; paths are relative to tests/

# studies (flexrock::study, io/study_files): spectra, sweeps, fragility fits, the thread pool
flexrock_add_test(flexrock_study_tests
  SOURCES unit/study_spectrum_test.cpp unit/study_sweep_test.cpp unit/study_fragility_test.cpp
          unit/study_files_test.cpp unit/journal_test.cpp unit/study_sliding_test.cpp
          unit/study_uncertain_test.cpp unit/study_session_test.cpp unit/study_messages_test.cpp
          unit/study_names_test.cpp unit/fragility_session_test.cpp
          unit/fragility_partial_test.cpp
  LIBS flexrock::study flexrock::io
  LABEL unit)

if(TARGET flexrock)
  # the commands: outputs, thread-count independence, errors; resume after SIGINT, SIGTERM and
  # SIGKILL, damaged journals, a second writer
  foreach(script study_spectrum study_spectrum_resume study_sweep_resume study_fragility
                 study_intensity study_shards spectrum_units sweep_pairs)
    add_test(NAME cli_${script}
             COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/${script}.sh $<TARGET_FILE:flexrock>
                     ${PROJECT_SOURCE_DIR})
    set_tests_properties(cli_${script} PROPERTIES LABELS cli TIMEOUT 300)
  endforeach()
  # record suites; with MPI, also 2 processes against threads
  set(flexrock_suite_mpi "")
  if(FLEXROCK_HAVE_MPI AND MPIEXEC_EXECUTABLE)
    set(flexrock_suite_mpi ${MPIEXEC_EXECUTABLE})
  endif()
  add_test(NAME cli_study_suite
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/study_suite.sh $<TARGET_FILE:flexrock>
                   ${PROJECT_SOURCE_DIR} ${flexrock_suite_mpi})
  set_tests_properties(cli_study_suite PROPERTIES LABELS cli TIMEOUT 300)
  # uncertain parameters: the same file for 1 and 2 threads, 2 MPI processes, a kill and a resume
  add_test(NAME cli_study_uncertain
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/study_uncertain.sh $<TARGET_FILE:flexrock>
                   ${PROJECT_SOURCE_DIR} ${flexrock_suite_mpi})
  set_tests_properties(cli_study_uncertain PROPERTIES LABELS cli TIMEOUT 300)
  # flexrock plot needs the build's Python package: only where it is built
  if(FLEXROCK_BUILD_PYTHON)
    set_tests_properties(cli_study_intensity PROPERTIES ENVIRONMENT "FLEXROCK_TEST_PLOT=1")
  endif()
  # the fit against scipy.optimize (Debian's python3-scipy, only for /usr/bin/python3)
  execute_process(COMMAND /usr/bin/python3 -c "import scipy.optimize, numpy"
                  RESULT_VARIABLE flexrock_no_scipy OUTPUT_QUIET ERROR_QUIET)
  if(flexrock_no_scipy EQUAL 0)
    add_test(NAME cli_study_fragility_scipy
             COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/unit/study_fragility_reference.py
                     $<TARGET_FILE:flexrock>)
    set_tests_properties(cli_study_fragility_scipy PROPERTIES LABELS cli)
    # multiple-stripe and truncated-IDA fits against known parameters and scipy.optimize
    add_test(NAME cli_study_fragility_msa_scipy
             COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/unit/study_fragility_msa_reference.py
                     $<TARGET_FILE:flexrock>)
    set_tests_properties(cli_study_fragility_msa_scipy PROPERTIES LABELS cli)
    # several damage states at once against data of known fragilities (numpy)
    add_test(NAME cli_study_fragility_states
             COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/unit/study_fragility_states.py
                     $<TARGET_FILE:flexrock>)
    set_tests_properties(cli_study_fragility_states PROPERTIES LABELS cli)
    if(FLEXROCK_BUILD_PYTHON)
      set_tests_properties(cli_study_fragility_states PROPERTIES ENVIRONMENT "FLEXROCK_TEST_PLOT=1")
    endif()
  endif()
  # two MPI processes write the same file as threads do
  if(FLEXROCK_HAVE_MPI AND MPIEXEC_EXECUTABLE)
    add_test(NAME cli_study_mpi
             COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/study_mpi.sh $<TARGET_FILE:flexrock>
                     ${PROJECT_SOURCE_DIR} ${MPIEXEC_EXECUTABLE})
    set_tests_properties(cli_study_mpi PROPERTIES LABELS cli TIMEOUT 300)
  endif()
endif()

# the hand estimates of a qualification against the engine and their closed forms
flexrock_add_test(flexrock_hand_estimates_tests
  SOURCES unit/hand_estimates_test.cpp
  LIBS flexrock::study
  LABEL unit)

# qualifications: files refused with file, line and key, the report's numbers against the runs,
# a stopped qualification resumed
flexrock_add_test(flexrock_qualify_tests
  SOURCES unit/qualify_test.cpp
  LIBS flexrock::study flexrock::io
  LABEL unit)
if(TARGET flexrock)
  # flexrock qualify on the shipped cabinet (small suite): verdict, hashes, same bytes again,
  # bad files; with the Python package, the HTML and PDF too
  add_test(NAME cli_qualify
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/qualify.sh $<TARGET_FILE:flexrock>
                   ${PROJECT_SOURCE_DIR})
  set_tests_properties(cli_qualify PROPERTIES LABELS cli TIMEOUT 300)
  if(FLEXROCK_BUILD_PYTHON)
    set_tests_properties(cli_qualify PROPERTIES ENVIRONMENT "FLEXROCK_TEST_PLOT=1")
  endif()
endif()
