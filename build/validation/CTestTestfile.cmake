# CMake generated Testfile for 
# Source directory: /work/main/validation
# Build directory: /work/main/build/validation
# 
# This file includes the relevant testing commands required for 
# testing this directory and lists subdirectories to be tested as well.
subdirs("three_discs")
