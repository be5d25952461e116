# CMake generated Testfile for 
# Source directory: /work/main/tests/unit
# Build directory: /work/main/build/tests/unit
# 
# This file includes the relevant testing commands required for 
# testing this directory and lists subdirectories to be tested as well.
add_test([=[test_yaml_read]=] "/work/main/build/tests/unit/test_yaml_read")
set_tests_properties([=[test_yaml_read]=] PROPERTIES  WORKING_DIRECTORY "/work/main" _BACKTRACE_TRIPLES "/work/main/tests/CMakeLists.txt;6;add_test;/work/main/tests/unit/CMakeLists.txt;1;gb_add_test;/work/main/tests/unit/CMakeLists.txt;0;")
