# readelf for the checks run as scripts (cmake -P): include() it, then readelf_or_pass().

# Ends the calling script, a pass with nothing checked, where readelf is not installed;
# sets READELF otherwise. A macro, so that its return() leaves the caller.
macro(readelf_or_pass)
  find_program(READELF readelf)
  if(NOT READELF)
    message(STATUS "readelf not found: nothing to check")
    return()
  endif()
endmacro()

# Sets OUT to what `readelf FLAGS... FILE` prints; fails (naming the first flag) when it fails.
function(readelf_output out file)
  execute_process(COMMAND "${READELF}" ${ARGN} "${file}" OUTPUT_VARIABLE text
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    list(GET ARGN 0 flag)
    message(FATAL_ERROR "readelf ${flag} ${file} failed")
  endif()
  set(${out} "${text}" PARENT_SCOPE)
endfunction()
