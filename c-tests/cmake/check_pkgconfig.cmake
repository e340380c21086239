# Compiles SOURCE with `pkg-config --cflags --libs topomesh` (PKG_CONFIG_PATH=PC_DIR) and
# runs it with LIB_DIR on the library path.
set(ENV{PKG_CONFIG_PATH} "${PC_DIR}")
execute_process(COMMAND "${PKG_CONFIG}" --modversion topomesh
                OUTPUT_VARIABLE v OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR NOT v STREQUAL VERSION)
  message(FATAL_ERROR "pkg-config --modversion topomesh gave '${v}' (rc ${rc}), expected ${VERSION}")
endif()
execute_process(COMMAND "${PKG_CONFIG}" --cflags --libs topomesh
                OUTPUT_VARIABLE flags OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pkg-config --cflags --libs topomesh failed")
endif()
message(STATUS "pkg-config flags: ${flags}")
separate_arguments(flag_list UNIX_COMMAND "${flags}")
execute_process(COMMAND "${CC}" -std=c11 -Wall -Werror "${SOURCE}" -o "${OUT}" ${flag_list}
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "compiling with pkg-config flags failed:\n${err}")
endif()
set(ENV{LD_LIBRARY_PATH} "${LIB_DIR}")
execute_process(COMMAND "${OUT}" RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${OUT} failed (${rc}): ${out}")
endif()
message(STATUS "${out}")
