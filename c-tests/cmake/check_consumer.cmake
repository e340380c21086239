# Configures, builds and runs the consumer project (CONSUMER_DIR) against the installed
# package (topomesh_DIR) in BUILD_DIR, asking for COMPONENTS (a ;-list, passed with | in
# place of ;). With EXPECT_ERROR set, the configure step must fail and its output contain
# EXPECT_ERROR (the name of the missing component). EXES (a |-list) names the programs to
# run, by default those of c-tests/cmake/consumer.
string(REPLACE "|" ";" components "${COMPONENTS}")
file(REMOVE_RECURSE "${BUILD_DIR}")
execute_process(
  COMMAND "${CMAKE_COMMAND}" -S "${CONSUMER_DIR}" -B "${BUILD_DIR}" -G "${GENERATOR}"
          "-Dtopomesh_DIR=${topomesh_DIR}" "-DTOPOMESH_COMPONENTS=${components}"
          "-DCMAKE_C_COMPILER=${C_COMPILER}" "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(DEFINED EXPECT_ERROR)
  if(rc EQUAL 0)
    message(FATAL_ERROR "configuring with COMPONENTS ${components} succeeded; expected a failure")
  endif()
  if(NOT "${out}${err}" MATCHES "${EXPECT_ERROR}")
    message(FATAL_ERROR "the failure does not name '${EXPECT_ERROR}':\n${out}${err}")
  endif()
  message(STATUS "configure failed as expected, naming '${EXPECT_ERROR}':\n${err}")
  return()
endif()
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "configuring the consumer failed:\n${out}${err}")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" --build "${BUILD_DIR}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "building the consumer failed:\n${out}${err}")
endif()
# Run from the build tree: the shared one finds libtopomesh by the build RPATH CMake sets
# for the non-system prefix, with no LD_LIBRARY_PATH.
unset(ENV{LD_LIBRARY_PATH})
set(want_consumer_shared "consumer: 4 vertices 5 edges 1 curves, sum of x\\+y 4")
set(want_consumer_static "${want_consumer_shared}")
set(want_consumer_c "consumer_c: [0-9.]+, 5 edges")
set(want_consumer_eigen "consumer_eigen: V 4x3, F 2x3, laplacian 4x4 with 14 entries")
if(NOT DEFINED EXES)
  set(EXES "consumer_shared|consumer_static|consumer_c")
endif()
string(REPLACE "|" ";" EXES "${EXES}")
foreach(exe IN LISTS EXES)
  execute_process(COMMAND "${BUILD_DIR}/${exe}" RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "${want_${exe}}")
    message(FATAL_ERROR "${exe} failed (${rc}): ${out}${err}")
  endif()
  message(STATUS "${out}")
endforeach()
find_program(READELF readelf)
list(FIND EXES consumer_static static_index)
if(READELF AND static_index GREATER -1)
  execute_process(COMMAND "${READELF}" -d "${BUILD_DIR}/consumer_static" OUTPUT_VARIABLE out)
  if(out MATCHES "libtopomesh")
    message(FATAL_ERROR "consumer_static links libtopomesh dynamically:\n${out}")
  endif()
endif()
