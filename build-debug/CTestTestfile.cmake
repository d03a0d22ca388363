# CMake generated Testfile for 
# Source directory: /work/wt/issue10-solver
# Build directory: /work/wt/issue10-solver/build-debug
# 
# This file includes the relevant testing commands required for 
# testing this directory and lists subdirectories to be tested as well.
subdirs("verification")
