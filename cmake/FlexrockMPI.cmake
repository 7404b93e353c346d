# SPDX-License-Identifier: BSD-3-Clause
# FLEXROCK_WITH_MPI: AUTO uses MPI when find_package finds it, ON requires it, OFF never uses it.
# Sets FLEXROCK_HAVE_MPI (a cache entry, so that tests/ sees it) and, with it, the imported
# target MPI::MPI_CXX in the including directory.
set(_flexrock_have_mpi OFF)
string(TOUPPER "${FLEXROCK_WITH_MPI}" _flexrock_mpi)
if(_flexrock_mpi STREQUAL "ON")
  find_package(MPI REQUIRED COMPONENTS CXX)
  set(_flexrock_have_mpi ON)
elseif(_flexrock_mpi STREQUAL "AUTO" OR _flexrock_mpi STREQUAL "")
  find_package(MPI QUIET COMPONENTS CXX)
  if(MPI_CXX_FOUND)
    set(_flexrock_have_mpi ON)
  endif()
elseif(NOT _flexrock_mpi STREQUAL "OFF")
  message(FATAL_ERROR "FLEXROCK_WITH_MPI must be AUTO, ON or OFF, got '${FLEXROCK_WITH_MPI}'")
endif()
set(FLEXROCK_HAVE_MPI ${_flexrock_have_mpi} CACHE INTERNAL "flexrock is built with MPI")
if(FLEXROCK_HAVE_MPI)
  message(STATUS "flexrock: MPI ${MPI_CXX_VERSION} for studies across processes")
else()
  message(STATUS "flexrock: no MPI (FLEXROCK_WITH_MPI=${FLEXROCK_WITH_MPI}); studies use threads")
endif()
