# SPDX-License-Identifier: BSD-3-Clause
# included from tests/CMakeLists.txt; paths are relative to tests/

# case files (toml++) and outputs (CSV, summary JSON): flexrock::io
find_package(nlohmann_json 3.9 REQUIRED)
flexrock_add_test(flexrock_case_file_tests
  SOURCES unit/case_file_test.cpp unit/outputs_test.cpp unit/fe_modal_files_test.cpp
          unit/solver_keys_test.cpp
  LIBS flexrock::io nlohmann_json::nlohmann_json
  LABEL unit)

# the `flexrock` command: exit codes, messages, columns, no partial outputs, the four examples
if(TARGET flexrock)
  foreach(script usage bad_input run_outcomes real_inputs io_safety keys_reference record_formats
                 assumption_breaks compliant_step_cost friction_tie azimuths verb_help restraints
                 support_input body_of_revolution configurations)
    add_test(NAME cli_${script}
             COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/${script}.sh $<TARGET_FILE:flexrock>
                     ${PROJECT_SOURCE_DIR})
    set_tests_properties(cli_${script} PROPERTIES LABELS cli)
  endforeach()
  # the quickstart's figure: drawn with the package's Python files only (python_tests builds them)
  if(TARGET _flexrock)
    add_test(NAME cli_plot_without_module
             COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/plot_without_module.sh
                     $<TARGET_FILE:flexrock> ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR})
    set_tests_properties(cli_plot_without_module PROPERTIES LABELS cli)
  endif()
  foreach(example museum_statue flexible_tank asymmetric_cabinet slender_column statue_on_platform)
    add_test(NAME cli_example_${example}
             COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/examples.sh $<TARGET_FILE:flexrock>
                     ${PROJECT_SOURCE_DIR} ${example})
    set_tests_properties(cli_example_${example} PROPERTIES LABELS cli)
  endforeach()
endif()
