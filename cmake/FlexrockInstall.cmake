# SPDX-License-Identifier: BSD-3-Clause
# cmake --install: headers, the libraries (flexrock::core, flexrock::study, flexrock::io), the
# `flexrock` command, and the CMake package that find_package(flexrock) reads. Each library has
# its own export set, so that flexrockConfig.cmake loads (and looks for the dependencies of) only
# the components a consumer asks for: flexrock::core needs Eigen and Boost only.
include(CMakePackageConfigHelpers)
set(FLEXROCK_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/flexrock
    CACHE STRING "Where the flexrock CMake package is installed, relative to the prefix")

install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/flexrock ${PROJECT_BINARY_DIR}/include/flexrock
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT devel FILES_MATCHING PATTERN "*.hpp")

set(flexrock_components core study)
if(FLEXROCK_BUILD_IO)
  list(APPEND flexrock_components io)
endif()
foreach(component ${flexrock_components})
  install(TARGETS flexrock_${component} EXPORT flexrock-${component}-targets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT devel
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT runtime
          RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime
          INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(EXPORT flexrock-${component}-targets NAMESPACE flexrock::
          FILE flexrock-${component}-targets.cmake DESTINATION ${FLEXROCK_INSTALL_CMAKEDIR}
          COMPONENT devel)
endforeach()

if(TARGET flexrock)
  install(TARGETS flexrock RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
endif()
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/CITATION.cff
        DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/flexrock COMPONENT devel)

set(FLEXROCK_INSTALLED_COMPONENTS ${flexrock_components})
if(NOT DEFINED FLEXROCK_IO_LINKS_TOMLPLUSPLUS)
  set(FLEXROCK_IO_LINKS_TOMLPLUSPLUS OFF)
endif()
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/flexrockConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/cmake/flexrockConfig.cmake
                              INSTALL_DESTINATION ${FLEXROCK_INSTALL_CMAKEDIR})
# 0.x releases may break the API in any minor version (semver): only the same 0.MINOR matches
if(PROJECT_VERSION_MAJOR EQUAL 0)
  set(flexrock_compatibility SameMinorVersion)
else()
  set(flexrock_compatibility SameMajorVersion)
endif()
write_basic_package_version_file(${PROJECT_BINARY_DIR}/cmake/flexrockConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY ${flexrock_compatibility})
install(FILES ${PROJECT_BINARY_DIR}/cmake/flexrockConfig.cmake
              ${PROJECT_BINARY_DIR}/cmake/flexrockConfigVersion.cmake
        DESTINATION ${FLEXROCK_INSTALL_CMAKEDIR} COMPONENT devel)
