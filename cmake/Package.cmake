# `cpack -G DEB` (in the build directory): a Debian package of what cmake/Install.cmake installs,
# under /usr. The libraries it links come from dpkg-shlibdeps (SuiteSparse, OpenBLAS/LAPACK,
# LAPACKE, gmsh, libfyaml, qhull, OpenMP; PETSc and Open MPI when built with them); the Python
# package's are listed. Configure with -DCMAKE_INSTALL_PREFIX=/usr for Debian's multiarch LIBDIR
# (lib/x86_64-linux-gnu); otherwise the package's libraries are in /usr/lib, which works as well.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME gembem)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR gembem)
set(CPACK_PACKAGE_CONTACT "gembem maintainers <gembem@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "quasi-static mechanics of granular materials (granular element method, BEM host)")
set(CPACK_PACKAGE_DESCRIPTION "gembem runs Kishino's granular element method on discs in a box or in the cavity
of an elastic body solved by boundary elements: the C library (shared and static, headers,
pkg-config, CMake package), the gembem command, the Python package and the demo.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3, python3-numpy, python3-yaml, python3-matplotlib")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "snakemake, paraview")
include(CPack)
