# SPDX-License-Identifier: BSD-3-Clause
flexrock_add_test(flexrock_model_tests SOURCES unit/body_test.cpp unit/impact_test.cpp unit/sin_cos_test.cpp
                  unit/flight_test.cpp unit/sliding_test.cpp unit/taken_rigid_test.cpp LABEL unit)
flexrock_add_test(flexrock_friction_tie_tests SOURCES unit/friction_tie_test.cpp LABEL unit)
flexrock_add_test(flexrock_support_tests SOURCES unit/support_test.cpp LABEL unit)
flexrock_add_test(flexrock_integrate_tests SOURCES unit/dopri5_test.cpp unit/dop853_test.cpp
                  unit/rosenbrock4_test.cpp LABEL unit)
flexrock_add_test(flexrock_rigid_validation_tests SOURCES validation/rigid_block_test.cpp LABEL validation)
flexrock_add_test(flexrock_flexible_validation_tests SOURCES validation/flexible_body_test.cpp LABEL validation)

# the machine-checked derivation writes the reference values the C++ equations are compared with
find_package(nlohmann_json REQUIRED)
find_package(Python3 COMPONENTS Interpreter)
set(FLEXROCK_SYMPY_PYTHON /usr/bin/python3 CACHE FILEPATH "Python with sympy (Debian python3-sympy)")
add_test(NAME derive_sympy_reference
         COMMAND ${FLEXROCK_SYMPY_PYTHON} ${PROJECT_SOURCE_DIR}/tools/derive/derive.py
                 --out ${PROJECT_BINARY_DIR}/sympy_reference.json)
set_tests_properties(derive_sympy_reference PROPERTIES FIXTURES_SETUP sympy_reference
                     LABELS unit TIMEOUT 600)
add_executable(flexrock_sympy_tests unit/sympy_reference_test.cpp)
target_link_libraries(flexrock_sympy_tests PRIVATE flexrock::core nlohmann_json::nlohmann_json
                      GTest::gtest GTest::gtest_main flexrock_warnings)
target_compile_definitions(flexrock_sympy_tests PRIVATE FLEXROCK_BINARY_DIR="${PROJECT_BINARY_DIR}")
flexrock_apply_sanitizers(flexrock_sympy_tests)
gtest_discover_tests(flexrock_sympy_tests PROPERTIES LABELS unit FIXTURES_REQUIRED sympy_reference)
# the support's impact map against the same derivation (tools/derive/support.py)
add_executable(flexrock_support_reference_tests unit/support_reference_test.cpp)
target_link_libraries(flexrock_support_reference_tests PRIVATE flexrock::core nlohmann_json::nlohmann_json
                      GTest::gtest GTest::gtest_main flexrock_warnings)
target_compile_definitions(flexrock_support_reference_tests PRIVATE FLEXROCK_BINARY_DIR="${PROJECT_BINARY_DIR}")
flexrock_apply_sanitizers(flexrock_support_reference_tests)
gtest_discover_tests(flexrock_support_reference_tests PROPERTIES LABELS unit FIXTURES_REQUIRED sympy_reference)
# the reset maps of contact/ against the same derivation, and the laws' own properties
add_executable(flexrock_contact_maps_tests unit/contact_maps_test.cpp)
target_link_libraries(flexrock_contact_maps_tests PRIVATE flexrock::core nlohmann_json::nlohmann_json
                      GTest::gtest GTest::gtest_main flexrock_warnings)
target_compile_definitions(flexrock_contact_maps_tests PRIVATE
                           FLEXROCK_BINARY_DIR="${PROJECT_BINARY_DIR}")
flexrock_apply_sanitizers(flexrock_contact_maps_tests)
gtest_discover_tests(flexrock_contact_maps_tests PROPERTIES LABELS unit
                     FIXTURES_REQUIRED sympy_reference)
flexrock_add_test(flexrock_sim_tests SOURCES unit/simulate_test.cpp LABEL unit)
# the 3D engine of a body of revolution against the derivation, the planar engine, conservation
add_executable(flexrock_axisymmetric_tests unit/axisymmetric_test.cpp)
target_link_libraries(flexrock_axisymmetric_tests PRIVATE flexrock::core nlohmann_json::nlohmann_json
                      GTest::gtest GTest::gtest_main flexrock_warnings)
target_compile_definitions(flexrock_axisymmetric_tests PRIVATE
                           FLEXROCK_BINARY_DIR="${PROJECT_BINARY_DIR}")
flexrock_apply_sanitizers(flexrock_axisymmetric_tests)
gtest_discover_tests(flexrock_axisymmetric_tests PROPERTIES LABELS unit
                     FIXTURES_REQUIRED sympy_reference)
# the run says where the sticking contact breaks (pivot_tension, tensile_landing), with magnitudes
flexrock_add_test(flexrock_assumption_breaks_tests SOURCES unit/assumption_breaks_test.cpp LABEL unit)
flexrock_add_test(flexrock_impact_law_tests SOURCES unit/impact_law_test.cpp LABEL unit)
flexrock_add_test(flexrock_compliant_tests SOURCES unit/compliant_test.cpp LABEL unit)
flexrock_add_test(flexrock_compliant_corners_tests SOURCES unit/compliant_corners_test.cpp LABEL unit)
flexrock_add_test(flexrock_compliant_energy_tests SOURCES unit/compliant_energy_test.cpp LABEL unit)
# also the audit of the compliant contact's loss (src/sim)
target_include_directories(flexrock_compliant_energy_tests PRIVATE ${PROJECT_SOURCE_DIR}/src)
flexrock_add_test(flexrock_step_cost_tests SOURCES unit/step_cost_test.cpp LABEL unit)
flexrock_add_test(flexrock_compliant_step_cost_tests SOURCES unit/compliant_step_cost_test.cpp
                  LABEL unit)
# the compliant contact's linearization (src/sim)
target_include_directories(flexrock_compliant_step_cost_tests PRIVATE ${PROJECT_SOURCE_DIR}/src)
flexrock_add_test(flexrock_stiff_rocking_tests SOURCES unit/stiff_rocking_test.cpp LABEL unit)
flexrock_add_test(flexrock_step_extremes_tests SOURCES unit/step_extremes_test.cpp
                  LIBS flexrock::io LABEL unit)
# replaces global operator new to count allocations: its own executable
flexrock_add_test(flexrock_allocation_tests SOURCES unit/no_allocation_test.cpp LABEL unit)
flexrock_add_test(flexrock_excitation_motion_tests SOURCES unit/ground_motion_test.cpp
                  unit/peak_acceleration_test.cpp LABEL unit)
flexrock_add_test(flexrock_contact_propagation_tests SOURCES unit/contact_propagation_test.cpp LABEL unit)
# also the closed-form exponential of a mode (src/sim)
target_include_directories(flexrock_contact_propagation_tests PRIVATE ${PROJECT_SOURCE_DIR}/src)
# the rigid body's rocking series: also one step of the internal stepper (src/sim)
flexrock_add_test(flexrock_rocking_series_tests SOURCES unit/rocking_series_test.cpp LABEL unit)
flexrock_add_test(flexrock_free_rocking_arc_tests SOURCES unit/free_rocking_arc_test.cpp LABEL unit)
target_include_directories(flexrock_free_rocking_arc_tests PRIVATE ${PROJECT_SOURCE_DIR}/src)
target_include_directories(flexrock_rocking_series_tests PRIVATE ${PROJECT_SOURCE_DIR}/src)
flexrock_add_test(flexrock_series_guards_tests SOURCES unit/series_guards_test.cpp LABEL unit)
target_include_directories(flexrock_series_guards_tests PRIVATE ${PROJECT_SOURCE_DIR}/src)
# every transition of the contact automaton fires (its table, src/sim/automaton.hpp)
flexrock_add_test(flexrock_automaton_transitions_tests SOURCES unit/automaton_transitions_test.cpp
                  LABEL unit)
target_include_directories(flexrock_automaton_transitions_tests PRIVATE ${PROJECT_SOURCE_DIR}/src)
# restraints (tendons, anchors) against tools/derive/restraints.py's closed forms
flexrock_add_test(flexrock_restraints_tests SOURCES unit/restraints_test.cpp LABEL unit)
target_link_libraries(flexrock_restraints_tests PRIVATE nlohmann_json::nlohmann_json)
# rocking frames and stacked blocks (theory §25): against the derivation's numbers and brute force
add_executable(flexrock_assemblies_tests unit/assemblies_test.cpp)
target_link_libraries(flexrock_assemblies_tests PRIVATE flexrock::core flexrock::io
                      nlohmann_json::nlohmann_json GTest::gtest GTest::gtest_main flexrock_warnings)
target_compile_definitions(flexrock_assemblies_tests PRIVATE
                           FLEXROCK_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
                           FLEXROCK_BINARY_DIR="${PROJECT_BINARY_DIR}")
flexrock_apply_sanitizers(flexrock_assemblies_tests)
gtest_discover_tests(flexrock_assemblies_tests PROPERTIES LABELS unit
                     FIXTURES_REQUIRED sympy_reference DISCOVERY_TIMEOUT 60)
