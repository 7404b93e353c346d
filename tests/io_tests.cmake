# SPDX-License-Identifier: BSD-3-Clause
# included from tests/CMakeLists.txt; paths are relative to tests/

# record readers (PEER .AT2, SMC, K-NET, ESM, COSMOS, single-column, time series, combine)
flexrock_add_test(flexrock_io_tests
  SOURCES unit/records_test.cpp unit/agency_records_test.cpp
  LIBS flexrock::io
  LABEL unit)

# synthetic pulses (excitation layer of flexrock::core, no files)
flexrock_add_test(flexrock_excitation_tests
  SOURCES unit/pulses_test.cpp unit/intensity_test.cpp unit/intensity_period_test.cpp
  LABEL unit)

# two horizontal components: record pairs, the azimuth sweep and its envelope, RotD50/RotD100
flexrock_add_test(flexrock_azimuth_tests
  SOURCES unit/azimuths_test.cpp
  LIBS flexrock::io
  LABEL unit)
