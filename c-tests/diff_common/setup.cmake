# The common setup of the differential test folders (diff_surface, diff_volume), after
# their project(). Standing alone (cmake -S c-tests/diff_...), a folder finds the package
# and enables testing here; under c-tests/CMakeLists.txt both are done. The mesh cache lives
# outside the repository (TOPOMESH_MESH_DIR, by default ~/.cache/topomesh/meshes, made by
# scripts/fetch-meshes.sh and scripts/fetch-tets.sh). Sets TOPOMESH_MESH_DIR and
# TOPOMESH_DIFF_FLAGS: -O2 (the benchmarks' flags; no -march=native) and NDEBUG, so that the
# peers run without their debug checks, like topomesh's release build.
if(CMAKE_SOURCE_DIR STREQUAL CMAKE_CURRENT_SOURCE_DIR)
  find_package(topomesh CONFIG REQUIRED)
  enable_testing()
endif()
if(DEFINED ENV{TOPOMESH_MESH_DIR})
  set(_mesh_dir_default "$ENV{TOPOMESH_MESH_DIR}")
else()
  set(_mesh_dir_default "$ENV{HOME}/.cache/topomesh/meshes")
endif()
set(TOPOMESH_MESH_DIR "${_mesh_dir_default}" CACHE PATH
    "Mesh cache (scripts/fetch-meshes.sh, scripts/fetch-tets.sh)")
set(TOPOMESH_DIFF_FLAGS -O2 -DNDEBUG)
find_package(CGAL REQUIRED)
