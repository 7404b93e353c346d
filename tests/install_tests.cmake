# SPDX-License-Identifier: BSD-3-Clause
# included from tests/CMakeLists.txt: installs as a user would make them (label "install").
#  install_consumer: `cmake --install` of this build, then tests/consumer built against it with
#                    find_package(flexrock) (about a minute: one small C++ project)
#  install_pip:      `pip install .` into a fresh venv with the system site packages, packaging
#                    this build's module and command (FLEXROCK_BUILD_DIR: no second build)
#  install_pip_interpreter: the same through scripts/pip-install.sh with a python3 first on PATH
#                    that cannot build (no wheel, no numpy), and setup.py's message for it
if(FLEXROCK_INSTALL AND TARGET flexrock)
  # a sanitized build installs an instrumented library: its consumer must link the same runtime
  set(_consumer_flags "")
  if(FLEXROCK_SANITIZE)
    string(REPLACE ";" "," _consumer_flags "${FLEXROCK_SANITIZE}")
    set(_consumer_flags "-fsanitize=${_consumer_flags}")
  endif()
  add_test(NAME install_consumer
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/install/consumer.sh ${PROJECT_BINARY_DIR}
                   ${PROJECT_SOURCE_DIR} "${_consumer_flags}")
  set_tests_properties(install_consumer PROPERTIES LABELS install TIMEOUT 600)
endif()
if(TARGET _flexrock AND TARGET flexrock)
  add_test(NAME install_pip
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/install/pip.sh ${PROJECT_SOURCE_DIR}
                   ${PROJECT_BINARY_DIR})
  add_test(NAME install_pip_interpreter
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/install/pip_interpreter.sh ${PROJECT_SOURCE_DIR}
                   ${PROJECT_BINARY_DIR})
  # both bring the build's two targets up to date: one build tool in the directory at a time
  set_tests_properties(install_pip install_pip_interpreter PROPERTIES LABELS install TIMEOUT 600
                       RESOURCE_LOCK flexrock_build_dir)
endif()
