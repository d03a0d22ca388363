# CMake generated Testfile for 
# Source directory: /work/wt/issue10-solver/verification/benchmark
# Build directory: /work/wt/issue10-solver/build-debug/verification/benchmark
# 
# This file includes the relevant testing commands required for 
# testing this directory and lists subdirectories to be tested as well.
