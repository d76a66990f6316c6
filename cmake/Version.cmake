# pond's version for `pond --version`: the project's (project(VERSION)) and, in a git checkout,
# `git describe`, recomputed at every build (a commit needs no new configure) into
# ${POND_VERSION_DIR}/pond_version.h. Without git, or outside a checkout, the describe part is empty.
find_package(Git QUIET)
set(POND_VERSION_DIR ${CMAKE_BINARY_DIR}/generated)
add_custom_target(pond_version_header
  COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -DVERSION=${PROJECT_VERSION}
          -DGIT_EXECUTABLE=${GIT_EXECUTABLE} -DOUTPUT=${POND_VERSION_DIR}/pond_version.h
          -P ${PROJECT_SOURCE_DIR}/cmake/GitDescribe.cmake
  BYPRODUCTS ${POND_VERSION_DIR}/pond_version.h
  VERBATIM)
