# Tests by module: every ctest is named <module>_<what> and carries <module> as a
# label, so `ctest -L bem` runs the boundary element module's tests. <module> is a folder of src/ or
# one of the project's other parts below. A test may carry more labels (the modules it also runs,
# set where it is added: set_property(TEST name APPEND PROPERTY LABELS cli)).
set(GB_TEST_MODULES
    bem cli contact core gem hybrid io measure pack run scene solver   # src/<module>
    validation demo python study fuzz tools docs install)          # validation/, the demo, python/, studies/, fuzz/, tools/, the README, the installed files

# A test of one C program test_x.c (the executable test_x), run with the arguments that follow in
# the repository's root. It sees the public API only (include/gembem/), as the tools and
# validation programs do.
function(gb_add_test name source)
  get_filename_component(exe ${source} NAME_WE)
  add_executable(${exe} ${source})
  target_include_directories(${exe} PRIVATE ${PROJECT_SOURCE_DIR}/tests)
  target_link_libraries(${exe} PRIVATE gembem)
  add_test(NAME ${name} COMMAND ${exe} ${ARGN} WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
endfunction()

# A white-box unit test of a module's internals (its private headers in src/<module>/): the
# contact law of one pair, a grain's stiffness, the BEM's quadrature, a YAML reader.
function(gb_add_module_test name source)
  gb_add_test(${name} ${source} ${ARGN})
  get_filename_component(exe ${source} NAME_WE)
  target_include_directories(${exe} PRIVATE ${PROJECT_SOURCE_DIR}/src ${PROJECT_BINARY_DIR}/src) # core/config.h: generated
endfunction()

# Called at the end of every CMakeLists.txt that adds tests: checks the names of this directory's
# tests and labels each with its module.
function(gb_label_tests)
  get_property(tests DIRECTORY PROPERTY TESTS)
  foreach(t IN LISTS tests)
    string(REGEX MATCH "^[a-z0-9]+" module "${t}")
    if(NOT t MATCHES "^[a-z0-9]+_." OR NOT module IN_LIST GB_TEST_MODULES)
      message(FATAL_ERROR "ctest '${t}': a test is named <module>_<what>, <module> one of: ${GB_TEST_MODULES}")
    endif()
    set_property(TEST ${t} APPEND PROPERTY LABELS ${module})
    set_property(GLOBAL APPEND PROPERTY GB_LABELLED_TESTS ${t})
  endforeach()
endfunction()

# Called once, after every add_subdirectory: a directory that added tests and did not call
# gb_label_tests() stops the configuration (no test without a module label).
function(gb_check_tests_labelled dir)
  get_property(tests DIRECTORY ${dir} PROPERTY TESTS)
  get_property(labelled GLOBAL PROPERTY GB_LABELLED_TESTS)
  foreach(t IN LISTS tests)
    if(NOT t IN_LIST labelled)
      message(FATAL_ERROR "ctest '${t}' (${dir}): not labelled; call gb_label_tests() at the end of its CMakeLists.txt")
    endif()
  endforeach()
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(d IN LISTS subdirs)
    gb_check_tests_labelled(${d})
  endforeach()
endfunction()
