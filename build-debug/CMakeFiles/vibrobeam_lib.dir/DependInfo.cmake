
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  "Fortran"
  )
# The set of files for implicit dependencies of each language:
set(CMAKE_DEPENDS_CHECK_Fortran
  "/work/wt/issue10-solver/build-debug/generated/vibrobeam_version.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/generated/vibrobeam_version.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_band.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_band.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_bspline.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_bspline.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_cantilever_exact.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_cantilever_exact.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_contact_newton.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_contact_newton.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_contact_pivoting.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_contact_pivoting.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_contact_points.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_contact_points.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_contact_solver.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_contact_solver.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_contact_system.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_contact_system.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_dynamics.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_dynamics.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_filesystem.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_filesystem.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_hdf5.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_hdf5.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_hermite.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_hermite.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_initial_state.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_initial_state.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_input.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_input.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_kinds.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_kinds.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_lcp.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_lcp.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_loads.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_loads.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_model.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_model.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_modes.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_modes.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_position_stepper.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_position_stepper.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_recorder.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_recorder.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_results.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_results.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_saddle_band.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_saddle_band.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_scene.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_scene.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_setup.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_setup.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_spectrum.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_spectrum.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_static.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_static.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_status.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_status.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_stepper.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_stepper.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_text.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_text.f90.o"
  "/work/wt/issue10-solver/src/vibrobeam_velocity_stepper.f90" "/work/wt/issue10-solver/build-debug/CMakeFiles/vibrobeam_lib.dir/src/vibrobeam_velocity_stepper.f90.o"
  )
set(CMAKE_Fortran_COMPILER_ID "GNU")
set(CMAKE_Fortran_SUBMODULE_SEP "@")
set(CMAKE_Fortran_SUBMODULE_EXT ".smod")

# The include file search paths:
set(CMAKE_Fortran_TARGET_INCLUDE_PATH
  "/usr/include/hdf5/serial"
  "modules"
  "/usr/include"
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "/work/wt/issue10-solver/build-debug/modules")
