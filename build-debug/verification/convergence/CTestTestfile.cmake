# CMake generated Testfile for 
# Source directory: /work/wt/issue10-solver/verification/convergence
# Build directory: /work/wt/issue10-solver/build-debug/verification/convergence
# 
# This file includes the relevant testing commands required for 
# testing this directory and lists subdirectories to be tested as well.
add_test([=[verification.first_contact_episode_convergence]=] "/work/wt/issue10-solver/build-debug/verification/convergence/test_first_episode" "/work/wt/issue10-solver/inputs/looseness_tip_stops.nml")
set_tests_properties([=[verification.first_contact_episode_convergence]=] PROPERTIES  LABELS "verification" _BACKTRACE_TRIPLES "/work/wt/issue10-solver/verification/convergence/CMakeLists.txt;17;add_test;/work/wt/issue10-solver/verification/convergence/CMakeLists.txt;0;")
