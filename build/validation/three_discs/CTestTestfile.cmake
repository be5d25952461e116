# CMake generated Testfile for 
# Source directory: /work/main/validation/three_discs
# Build directory: /work/main/build/validation/three_discs
# 
# This file includes the relevant testing commands required for 
# testing this directory and lists subdirectories to be tested as well.
