# The data railsim ships, staged into <build>/share/railsim (so programs in the
# build tree find it as the installed ones find <prefix>/share/railsim) and
# installed there. Layout of the data folder (core/data_dir.hpp):
#   profiles/   wheel and rail profiles (the source folder profiles/)
#   plots/      the chart script (results/plots/render_chart.py)
#   vehicles/   vehicle files and contact tables (vehicles/)
#   tracks/     track files (tracks/*.yaml)
#   scenarios/  scenarios (scenarios/*.yaml; they name ../vehicles/, ../tracks/)
#   railsim-data.txt  marker naming the version
set(RAILSIM_DATA_BUILD_DIR ${CMAKE_BINARY_DIR}/share/railsim)
set(RAILSIM_DATA_INSTALL_DIR ${CMAKE_INSTALL_DATADIR}/railsim)

# folder in the data folder -> files (relative to the source root)
set(_railsim_data_sets
  "profiles|profiles|*"
  "plots|results/plots|*.py"
  "vehicles|vehicles|*"
  "tracks|tracks|*.yaml"
  "scenarios|scenarios|*.yaml")

set(_railsim_staged)
set(RAILSIM_DATA_FILES)  # absolute source paths, for the install rules
foreach(set_spec ${_railsim_data_sets})
  string(REPLACE "|" ";" parts "${set_spec}")
  list(GET parts 0 dest)
  list(GET parts 1 src)
  list(GET parts 2 pattern)
  file(GLOB_RECURSE files CONFIGURE_DEPENDS RELATIVE ${CMAKE_SOURCE_DIR}/${src} ${CMAKE_SOURCE_DIR}/${src}/${pattern})
  foreach(f ${files})
    set(out ${RAILSIM_DATA_BUILD_DIR}/${dest}/${f})
    add_custom_command(OUTPUT ${out}
      COMMAND ${CMAKE_COMMAND} -E copy_if_different ${CMAKE_SOURCE_DIR}/${src}/${f} ${out}
      DEPENDS ${CMAKE_SOURCE_DIR}/${src}/${f}
      COMMENT "" VERBATIM)
    list(APPEND _railsim_staged ${out})
    get_filename_component(sub ${f} DIRECTORY)
    install(FILES ${CMAKE_SOURCE_DIR}/${src}/${f} DESTINATION ${RAILSIM_DATA_INSTALL_DIR}/${dest}/${sub}
            COMPONENT runtime)
  endforeach()
endforeach()

set(_railsim_marker_text "railsim ${PROJECT_VERSION} data folder (profiles, plots, vehicles, tracks, scenarios)\n")
file(WRITE ${CMAKE_BINARY_DIR}/railsim-data.txt.in "${_railsim_marker_text}")
configure_file(${CMAKE_BINARY_DIR}/railsim-data.txt.in ${RAILSIM_DATA_BUILD_DIR}/railsim-data.txt COPYONLY)
install(FILES ${RAILSIM_DATA_BUILD_DIR}/railsim-data.txt DESTINATION ${RAILSIM_DATA_INSTALL_DIR} COMPONENT runtime)

add_custom_target(railsim_data ALL DEPENDS ${_railsim_staged})
