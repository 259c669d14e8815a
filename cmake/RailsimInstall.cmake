# Install rules, package configuration, man page and CPack.
#
#   cmake --install build/release --prefix PREFIX
# puts
#   PREFIX/bin/railsim                          the program
#   PREFIX/lib/librailsim_*.a                   the libraries
#   PREFIX/include/railsim/<folder>/*.hpp       their headers (#include <railsim/contact/registry.hpp>)
#   PREFIX/lib/cmake/railsim/                   railsimConfig.cmake: find_package(railsim), railsim::railsim
#   PREFIX/lib/python3/dist-packages/railsim/   the Python module (RAILSIM_PYTHON_INSTALL_DIR)
#   PREFIX/share/railsim/                       the data (cmake/RailsimData.cmake)
#   PREFIX/share/man/man1/railsim.1             the man page (help2man)
#   PREFIX/share/doc/railsim/                   LICENSE, README.md
# Components: "runtime" (program, Python module, data, man page, licence) and
# "dev" (libraries, headers, CMake package); cpack -G DEB makes one package each.
include(CMakePackageConfigHelpers)

set(RAILSIM_CMAKE_INSTALL_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/railsim)

# --- program -----------------------------------------------------------------
install(TARGETS railsim RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)

# --- libraries and the package configuration ---------------------------------
set(_railsim_libs railsim_core railsim_config railsim_results railsim_contact railsim_track railsim_engine
    railsim_analysis)
foreach(lib ${_railsim_libs})
  string(REPLACE "railsim_" "" short ${lib})
  set_target_properties(${lib} PROPERTIES EXPORT_NAME ${short})
endforeach()
# railsim::railsim: everything (the analyses link the rest).
add_library(railsim_all INTERFACE)
target_link_libraries(railsim_all INTERFACE railsim_analysis)
set_target_properties(railsim_all PROPERTIES EXPORT_NAME railsim)
install(TARGETS railsim_root_include railsim_all ${_railsim_libs} EXPORT railsimTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT dev
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT dev)
install(EXPORT railsimTargets NAMESPACE railsim:: DESTINATION ${RAILSIM_CMAKE_INSTALL_DIR} COMPONENT dev)
set(RAILSIM_HAVE_MPI_EXPORT ${MPI_CXX_FOUND})
configure_package_config_file(${CMAKE_SOURCE_DIR}/cmake/railsimConfig.cmake.in
  ${CMAKE_BINARY_DIR}/railsimConfig.cmake INSTALL_DESTINATION ${RAILSIM_CMAKE_INSTALL_DIR}
  PATH_VARS RAILSIM_DATA_INSTALL_DIR)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/railsimConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/railsimConfig.cmake ${CMAKE_BINARY_DIR}/railsimConfigVersion.cmake
              ${CMAKE_SOURCE_DIR}/cmake/FindFFTW3.cmake
        DESTINATION ${RAILSIM_CMAKE_INSTALL_DIR} COMPONENT dev)

# --- headers: include/railsim/<folder>/, including each other as <railsim/...> -
set(RAILSIM_HEADER_STAGE ${CMAKE_BINARY_DIR}/install-headers)
add_custom_target(railsim_install_headers ALL
  COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${CMAKE_SOURCE_DIR} -DGENERATED_DIR=${RAILSIM_GENERATED_DIR}
          -DSTAGE_DIR=${RAILSIM_HEADER_STAGE}/railsim -P ${CMAKE_SOURCE_DIR}/cmake/RailsimStageHeaders.cmake
  COMMENT "Staging the installed headers (include/railsim/...)" VERBATIM)
install(DIRECTORY ${RAILSIM_HEADER_STAGE}/railsim DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT dev)

# --- man page ----------------------------------------------------------------
if(RAILSIM_BUILD_MANPAGE)
  find_program(HELP2MAN_PROGRAM help2man)
  if(NOT HELP2MAN_PROGRAM)
    message(FATAL_ERROR "help2man not found: install it (Debian package help2man, scripts/setup.sh does) "
                        "or configure with -DRAILSIM_BUILD_MANPAGE=OFF")
  endif()
  add_custom_command(OUTPUT ${CMAKE_BINARY_DIR}/railsim.1
    COMMAND ${HELP2MAN_PROGRAM} --no-info --no-discard-stderr
            --name "railway vehicle dynamics with pluggable wheel-rail contact"
            --include ${CMAKE_SOURCE_DIR}/cmake/railsim.h2m
            --output ${CMAKE_BINARY_DIR}/railsim.1 $<TARGET_FILE:railsim>
    DEPENDS railsim ${CMAKE_SOURCE_DIR}/cmake/railsim.h2m
    COMMENT "Making the man page railsim.1 (help2man)" VERBATIM)
  add_custom_target(railsim_manpage ALL DEPENDS ${CMAKE_BINARY_DIR}/railsim.1)
  install(FILES ${CMAKE_BINARY_DIR}/railsim.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 COMPONENT runtime)
endif()

install(FILES ${CMAKE_SOURCE_DIR}/LICENSE ${CMAKE_SOURCE_DIR}/README.md
        DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT runtime)

# --- CPack: cpack -G DEB (in the build folder) --------------------------------
set(CPACK_PACKAGE_NAME railsim)
set(CPACK_PACKAGE_VENDOR "railsim developers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_RESOURCE_FILE_LICENSE ${CMAKE_SOURCE_DIR}/LICENSE)
set(CPACK_RESOURCE_FILE_README ${CMAKE_SOURCE_DIR}/README.md)
set(CPACK_GENERATOR DEB)
set(CPACK_COMPONENTS_ALL runtime dev)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "railsim developers <railsim@users.noreply.github.com>")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "${PROJECT_HOMEPAGE_URL}")
set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME railsim)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_DEPENDS "python3, python3-numpy, python3-matplotlib")
set(CPACK_COMPONENT_RUNTIME_DESCRIPTION "railsim program, Python module, data and man page")
set(CPACK_DEBIAN_DEV_PACKAGE_NAME railsim-dev)
set(CPACK_DEBIAN_DEV_PACKAGE_SECTION libdevel)
set(_railsim_dev_depends "railsim (= ${PROJECT_VERSION}), libeigen3-dev, libsundials-dev, libboost-dev, libyaml-cpp-dev, libspdlog-dev, libfftw3-dev, nlohmann-json3-dev, pkg-config")
if(MPI_CXX_FOUND)
  string(APPEND _railsim_dev_depends ", libopenmpi-dev")
endif()
set(CPACK_DEBIAN_DEV_PACKAGE_DEPENDS "${_railsim_dev_depends}")
set(CPACK_COMPONENT_DEV_DESCRIPTION "railsim static libraries, headers and CMake package (find_package(railsim))")
include(CPack)
