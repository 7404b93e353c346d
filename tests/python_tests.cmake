# SPDX-License-Identifier: BSD-3-Clause
# included from tests/CMakeLists.txt; the Python package's pytest suite (python/tests), one ctest
# a file so that ctest -j runs them side by side. Needs FLEXROCK_BUILD_PYTHON (on in the release
# preset); under a minute in all with ctest -j2 on two cores.
if(TARGET _flexrock)
  file(GLOB flexrock_pytests CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/python/tests/test_*.py)
  foreach(f ${flexrock_pytests})
    get_filename_component(name ${f} NAME_WE)
    add_test(NAME python_${name}
             COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${FLEXROCK_PYTHON_DIR}
                     FLEXROCK_CLI=$<TARGET_FILE:flexrock> FLEXROCK_SOURCE_DIR=${PROJECT_SOURCE_DIR}
                     MPLBACKEND=Agg PYTHONDONTWRITEBYTECODE=1
                     ${FLEXROCK_PYTHON_EXECUTABLE} -m pytest -q -p no:cacheprovider ${f}
             WORKING_DIRECTORY ${PROJECT_BINARY_DIR})
    set_tests_properties(python_${name} PROPERTIES LABELS python TIMEOUT 300)
  endforeach()
endif()
# the command docs/python.md gives, run by hand from the checkout: no FLEXROCK_CLI, no
# FLEXROCK_SOURCE_DIR, so every test finds the command through conftest's default (build/release)
if(TARGET _flexrock AND PROJECT_BINARY_DIR STREQUAL "${PROJECT_SOURCE_DIR}/build/release")
  add_test(NAME python_by_hand_with_the_defaults
           COMMAND ${CMAKE_COMMAND} -E env --unset=FLEXROCK_CLI --unset=FLEXROCK_SOURCE_DIR
                   PYTHONPATH=${FLEXROCK_PYTHON_DIR} MPLBACKEND=Agg PYTHONDONTWRITEBYTECODE=1
                   ${FLEXROCK_PYTHON_EXECUTABLE} -m pytest -q -p no:cacheprovider
                   python/tests/test_toppling.py
           WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  set_tests_properties(python_by_hand_with_the_defaults PROPERTIES LABELS python TIMEOUT 300)
endif()
