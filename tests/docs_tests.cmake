# SPDX-License-Identifier: BSD-3-Clause
# included from tests/CMakeLists.txt: the API reference builds without a warning (label "docs").
#  api_docs: scripts/api-docs.sh on this build: Doxygen over the public headers, Sphinx over the
#            Python package (a broken header comment or docstring fails it). Skipped (77) where
#            doxygen or python3-sphinx is missing; scripts/test.sh installs them.
if(TARGET _flexrock)
  add_test(NAME api_docs
           COMMAND bash -c "command -v doxygen >/dev/null && /usr/bin/python3 -c 'import sphinx' 2>/dev/null || { echo 'doxygen or python3-sphinx missing: scripts/install-deps.sh --docs'; exit 77; }; d=$(mktemp -d) && trap 'rm -rf \"$d\"' EXIT && FLEXROCK_API_BUILD=${PROJECT_BINARY_DIR} ${PROJECT_SOURCE_DIR}/scripts/api-docs.sh \"$d\""
           WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  set_tests_properties(api_docs PROPERTIES LABELS docs TIMEOUT 300 SKIP_RETURN_CODE 77)
endif()
