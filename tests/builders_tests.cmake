# SPDX-License-Identifier: BSD-3-Clause
# included from tests/CMakeLists.txt; paths are relative to tests/

# builders of body parameters (rigid, lumped model, oscillator on slab, cantilever)
flexrock_add_test(flexrock_builders_tests SOURCES unit/builders_test.cpp LABEL unit)
