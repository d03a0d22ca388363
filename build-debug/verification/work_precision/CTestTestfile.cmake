# CMake generated Testfile for 
# Source directory: /work/wt/issue10-solver/verification/work_precision
# Build directory: /work/wt/issue10-solver/build-debug/verification/work_precision
# 
# This file includes the relevant testing commands required for 
# testing this directory and lists subdirectories to be tested as well.
add_test([=[long.work_precision_free]=] "/work/wt/issue10-solver/build-debug/verification/work_precision/work_precision" "free" "/work/wt/issue10-solver/verification/dynamics/free_flight.nml" "/work/wt/issue10-solver/build-debug/verification/work_precision/work" "--check")
set_tests_properties([=[long.work_precision_free]=] PROPERTIES  LABELS "long" TIMEOUT "1800" _BACKTRACE_TRIPLES "/work/wt/issue10-solver/verification/work_precision/CMakeLists.txt;14;add_test;/work/wt/issue10-solver/verification/work_precision/CMakeLists.txt;0;")
add_test([=[long.work_precision_impacts]=] "/work/wt/issue10-solver/build-debug/verification/work_precision/work_precision" "impacts" "/work/wt/issue10-solver/inputs/looseness_tip_stops.nml" "/work/wt/issue10-solver/build-debug/verification/work_precision/work" "--check")
set_tests_properties([=[long.work_precision_impacts]=] PROPERTIES  LABELS "long" TIMEOUT "1800" _BACKTRACE_TRIPLES "/work/wt/issue10-solver/verification/work_precision/CMakeLists.txt;16;add_test;/work/wt/issue10-solver/verification/work_precision/CMakeLists.txt;0;")
