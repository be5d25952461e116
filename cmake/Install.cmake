# `cmake --install build --prefix P`: the library (shared, versioned, and static), its public
# headers, the gembem command, pkg-config and CMake package files, the Python package and the demo,
# in Debian's layout (GNUInstallDirs; docs/install.md). Also what CPack packs into the .deb
# (cmake/Package.cmake).
include(CMakePackageConfigHelpers)

install(TARGETS gembem_shared EXPORT gembemTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS gembem ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS gembem_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/gembem DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.h")

# pkg-config: the shared library by default; `pkg-config --static` adds what libgembem.a needs.
set(GB_PC_REQUIRES_PRIVATE "libfyaml lapacke openblas qhull_r")
set(GB_PC_LIBS_PRIVATE "-lumfpack -lcholmod ${OpenMP_C_FLAGS} -lgmsh -lpthread -lm")
if(GB_HAVE_PETSC)
  # PETSc's library by name, not Requires.private PETSc: Debian's PETSc.pc asks a static link for
  # -lhdf5 and others that its packages name differently.
  list(JOIN PETSC_LDFLAGS " " petsc_ldflags)
  string(APPEND GB_PC_LIBS_PRIVATE " ${petsc_ldflags}")
  string(APPEND GB_PC_REQUIRES_PRIVATE " ompi-c")
endif()
file(RELATIVE_PATH GB_PC_TO_PREFIX /p/${CMAKE_INSTALL_LIBDIR}/pkgconfig /p/)
string(REGEX REPLACE "/$" "" GB_PC_TO_PREFIX "${GB_PC_TO_PREFIX}")
configure_file(${CMAKE_CURRENT_LIST_DIR}/gembem.pc.in ${PROJECT_BINARY_DIR}/gembem.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/gembem.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

# CMake: find_package(gembem) gives the imported target gembem::gembem (the shared library, which
# carries its own dependencies: nothing for the caller to find).
set(GB_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/gembem)
install(EXPORT gembemTargets NAMESPACE gembem:: DESTINATION ${GB_CMAKE_DIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/gembemConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/gembemConfig.cmake INSTALL_DESTINATION ${GB_CMAKE_DIR})
# 0.x: a minor release may change the API, so only the same major.minor is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/gembemConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/gembemConfig.cmake ${PROJECT_BINARY_DIR}/gembemConfigVersion.cmake
        DESTINATION ${GB_CMAKE_DIR})

# The Python package, where Debian's python3 looks for packages of /usr (lib/python3/dist-packages),
# with _paths.py telling it where the command and the library are relative to itself (so that the
# installed tree may be moved, or unpacked from the .deb anywhere).
set(GB_PYTHON_INSTALL_DIR lib/python3/dist-packages CACHE STRING
    "Where the Python package is installed, relative to the prefix")
install(DIRECTORY ${PROJECT_SOURCE_DIR}/python/gembem DESTINATION ${GB_PYTHON_INSTALL_DIR}
        PATTERN __pycache__ EXCLUDE)
file(RELATIVE_PATH GB_PY_TO_BIN /p/${GB_PYTHON_INSTALL_DIR}/gembem /p/${CMAKE_INSTALL_BINDIR})
file(RELATIVE_PATH GB_PY_TO_LIB /p/${GB_PYTHON_INSTALL_DIR}/gembem /p/${CMAKE_INSTALL_LIBDIR})
configure_file(${CMAKE_CURRENT_LIST_DIR}/_paths.py.in ${PROJECT_BINARY_DIR}/python/_paths.py @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/python/_paths.py DESTINATION ${GB_PYTHON_INSTALL_DIR}/gembem)

# The demo (examples/demo) and the meshes its scenes name (../../meshes from there).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/demo DESTINATION ${CMAKE_INSTALL_DATADIR}/gembem/examples)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/meshes DESTINATION ${CMAKE_INSTALL_DATADIR}/gembem)

# A prefix whose Python directory /usr/bin/python3 does not search: /usr/local gets a .pth file in
# the directory it does search there; any other prefix is told what to add to PYTHONPATH.
execute_process(COMMAND ${GB_PYTHON} -c "import sys; print('%d.%d' % sys.version_info[:2])"
                OUTPUT_VARIABLE GB_PYTHON_VERSION OUTPUT_STRIP_TRAILING_WHITESPACE)
configure_file(${CMAKE_CURRENT_LIST_DIR}/InstallPython.cmake.in ${PROJECT_BINARY_DIR}/InstallPython.cmake @ONLY)
install(SCRIPT ${PROJECT_BINARY_DIR}/InstallPython.cmake)
