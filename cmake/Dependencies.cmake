# Debian 12 packages (tools/setup.sh installs them); see shared/design/DEPENDENCIES.md.
find_package(PkgConfig REQUIRED)
pkg_check_modules(FYAML REQUIRED IMPORTED_TARGET libfyaml)
pkg_check_modules(OPENBLAS REQUIRED IMPORTED_TARGET openblas)
pkg_check_modules(LAPACKE REQUIRED IMPORTED_TARGET lapacke)
# qhull's reentrant C library: the Delaunay triangulation of grain centres (src/measure).
pkg_check_modules(QHULL REQUIRED IMPORTED_TARGET qhull_r)

# SuiteSparse has neither pkg-config nor a CMake config on Debian 12.
find_path(SUITESPARSE_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse REQUIRED)
find_library(CHOLMOD_LIBRARY cholmod REQUIRED)
find_library(UMFPACK_LIBRARY umfpack REQUIRED)
add_library(gb_suitesparse INTERFACE)
target_include_directories(gb_suitesparse INTERFACE ${SUITESPARSE_INCLUDE_DIR})
target_link_libraries(gb_suitesparse INTERFACE ${UMFPACK_LIBRARY} ${CHOLMOD_LIBRARY})
# CHOLMOD runs OpenMP loops (libgomp); src/solver/linear_cholmod.c serialises them (factorise).
find_package(OpenMP REQUIRED COMPONENTS C)
target_link_libraries(gb_suitesparse INTERFACE OpenMP::OpenMP_C)

# gmsh: gmshc.h and -lgmsh, no pkg-config.
find_path(GMSH_INCLUDE_DIR gmshc.h REQUIRED)
find_library(GMSH_LIBRARY gmsh REQUIRED)
add_library(gb_gmsh INTERFACE)
target_include_directories(gb_gmsh INTERFACE ${GMSH_INCLUDE_DIR})
target_link_libraries(gb_gmsh INTERFACE ${GMSH_LIBRARY})

# Debian's python3 with matplotlib, for figures (not the python3 first on PATH).
set(GB_PYTHON /usr/bin/python3 CACHE FILEPATH "Python with matplotlib, for figures")

# PETSc (optional, libpetsc-real-dev; tools/setup.sh --with-petsc): the distributed linear solver of
# solver.linear: petsc (src/solver/linear_petsc.c). AUTO builds it when the pkg-config file is found.
set(GB_WITH_PETSC AUTO CACHE STRING "Build the PETSc linear solver: AUTO, ON or OFF")
set_property(CACHE GB_WITH_PETSC PROPERTY STRINGS AUTO ON OFF)
set(GB_HAVE_PETSC OFF)
if(NOT GB_WITH_PETSC STREQUAL "OFF")
  if(GB_WITH_PETSC STREQUAL "ON")
    pkg_check_modules(PETSC REQUIRED IMPORTED_TARGET PETSc)
  else()
    pkg_check_modules(PETSC QUIET IMPORTED_TARGET PETSc)
  endif()
  if(PETSC_FOUND)
    find_package(MPI COMPONENTS C)
    if(MPI_C_FOUND)
      set(GB_HAVE_PETSC ON)
    elseif(GB_WITH_PETSC STREQUAL "ON")
      message(FATAL_ERROR "GB_WITH_PETSC=ON: PETSc found but not MPI's C library (libopenmpi-dev)")
    endif()
  endif()
endif()
message(STATUS "PETSc linear solver (solver.linear: petsc): ${GB_HAVE_PETSC}")
