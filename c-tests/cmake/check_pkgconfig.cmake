# Compiles SOURCE with the flags of `pkg-config topomesh` (PKG_CONFIG_PATH=PC_DIR) into OUT
# and runs it, in one of three MODEs:
#   dynamic  --cflags --libs, run with LIB_DIR on LD_LIBRARY_PATH;
#   rpath    --cflags --libs plus -Wl,-rpath,<libdir from the .pc file>, run with no
#            LD_LIBRARY_PATH: what the README says for a prefix outside the system folders;
#   static   -static and --static --cflags --libs: a fully static executable (no dynamic
#            section at all), so libtopomesh.a and Libs.private must be enough.
set(ENV{PKG_CONFIG_PATH} "${PC_DIR}")
execute_process(COMMAND "${PKG_CONFIG}" --modversion topomesh
                OUTPUT_VARIABLE v OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR NOT v STREQUAL VERSION)
  message(FATAL_ERROR "pkg-config --modversion topomesh gave '${v}' (rc ${rc}), expected ${VERSION}")
endif()
set(query --cflags --libs)
set(extra "")
if(MODE STREQUAL "static")
  set(query --static --cflags --libs)
  set(extra -static)
endif()
execute_process(COMMAND "${PKG_CONFIG}" ${query} topomesh
                OUTPUT_VARIABLE flags OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pkg-config ${query} topomesh failed")
endif()
if(MODE STREQUAL "rpath")
  execute_process(COMMAND "${PKG_CONFIG}" --variable=libdir topomesh
                  OUTPUT_VARIABLE libdir OUTPUT_STRIP_TRAILING_WHITESPACE)
  set(extra "-Wl,-rpath,${libdir}")
endif()
message(STATUS "pkg-config flags (${MODE}): ${flags} ${extra}")
separate_arguments(flag_list UNIX_COMMAND "${flags}")
execute_process(COMMAND "${CC}" -std=c11 -Wall -Werror "${SOURCE}" -o "${OUT}" ${extra} ${flag_list}
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "compiling with pkg-config flags (${MODE}) failed:\n${err}")
endif()
if(MODE STREQUAL "dynamic")
  set(ENV{LD_LIBRARY_PATH} "${LIB_DIR}")
else()
  unset(ENV{LD_LIBRARY_PATH})
endif()
execute_process(COMMAND "${OUT}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${OUT} failed (${rc}): ${out}${err}")
endif()
message(STATUS "${out}")
if(MODE STREQUAL "static")
  find_program(READELF readelf)
  if(READELF)
    execute_process(COMMAND "${READELF}" -d "${OUT}" OUTPUT_VARIABLE dyn ERROR_VARIABLE dyn)
    if(NOT dyn MATCHES "no dynamic section")
      message(FATAL_ERROR "${OUT} is not fully static:\n${dyn}")
    endif()
  endif()
endif()
