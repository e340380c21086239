# Fails when the executable EXE depends on libtopomesh.so at run time.
include("${CMAKE_CURRENT_LIST_DIR}/readelf.cmake")
readelf_or_pass()
readelf_output(out "${EXE}" -d)
if(out MATCHES "libtopomesh")
  message(FATAL_ERROR "${EXE} links libtopomesh dynamically:\n${out}")
endif()
message(STATUS "${EXE}: no dynamic dependency on libtopomesh")
