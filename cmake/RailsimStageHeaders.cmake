cmake_policy(SET CMP0057 NEW)
# Build-time script (cmake -P): copies railsim's headers into STAGE_DIR with
# their project includes rewritten from "folder/file.hpp" to
# <railsim/folder/file.hpp>, so installed headers need only PREFIX/include on
# the include path and no name of theirs (core/errors.hpp, ...) can collide
# with another package's. Files are rewritten only when their content changes.
set(_folders core config results contact track engine)
set(_regex "#include \"((core|config|results|contact|track|engine)/[^\"]+)\"")
file(GLOB_RECURSE _headers RELATIVE ${SOURCE_DIR} ${SOURCE_DIR}/core/*.hpp ${SOURCE_DIR}/config/*.hpp
     ${SOURCE_DIR}/results/*.hpp ${SOURCE_DIR}/contact/*.hpp ${SOURCE_DIR}/track/*.hpp ${SOURCE_DIR}/engine/*.hpp)
file(GLOB_RECURSE _generated RELATIVE ${GENERATED_DIR} ${GENERATED_DIR}/*.hpp)
set(_wanted)
foreach(pair IN LISTS _headers _generated)
  list(APPEND _wanted ${STAGE_DIR}/${pair})
endforeach()
foreach(h ${_headers} ${_generated})
  if(EXISTS ${SOURCE_DIR}/${h})
    file(READ ${SOURCE_DIR}/${h} text)
  else()
    file(READ ${GENERATED_DIR}/${h} text)
  endif()
  string(REGEX REPLACE "${_regex}" "#include <railsim/\\1>" text "${text}")
  set(out ${STAGE_DIR}/${h})
  set(old "")
  if(EXISTS ${out})
    file(READ ${out} old)
  endif()
  if(NOT old STREQUAL text)
    file(WRITE ${out} "${text}")
  endif()
endforeach()
# Headers removed from the sources leave the stage too.
file(GLOB_RECURSE _staged ${STAGE_DIR}/*.hpp)
foreach(s ${_staged})
  if(NOT s IN_LIST _wanted)
    file(REMOVE ${s})
  endif()
endforeach()
