# Remove fortran modules provided by this target.
FILE(REMOVE
  "modules/vibrobeam_band.mod"
  "modules/VIBROBEAM_BAND.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_band.mod.stamp"

  "modules/vibrobeam_bspline.mod"
  "modules/VIBROBEAM_BSPLINE.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_bspline.mod.stamp"

  "modules/vibrobeam_cantilever_exact.mod"
  "modules/VIBROBEAM_CANTILEVER_EXACT.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_cantilever_exact.mod.stamp"

  "modules/vibrobeam_contact_newton.mod"
  "modules/VIBROBEAM_CONTACT_NEWTON.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_contact_newton.mod.stamp"

  "modules/vibrobeam_contact_pivoting.mod"
  "modules/VIBROBEAM_CONTACT_PIVOTING.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_contact_pivoting.mod.stamp"

  "modules/vibrobeam_contact_points.mod"
  "modules/VIBROBEAM_CONTACT_POINTS.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_contact_points.mod.stamp"

  "modules/vibrobeam_contact_solver.mod"
  "modules/VIBROBEAM_CONTACT_SOLVER.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_contact_solver.mod.stamp"

  "modules/vibrobeam_contact_system.mod"
  "modules/VIBROBEAM_CONTACT_SYSTEM.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_contact_system.mod.stamp"

  "modules/vibrobeam_dynamics.mod"
  "modules/VIBROBEAM_DYNAMICS.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_dynamics.mod.stamp"

  "modules/vibrobeam_filesystem.mod"
  "modules/VIBROBEAM_FILESYSTEM.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_filesystem.mod.stamp"

  "modules/vibrobeam_hdf5.mod"
  "modules/VIBROBEAM_HDF5.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_hdf5.mod.stamp"

  "modules/vibrobeam_hermite.mod"
  "modules/VIBROBEAM_HERMITE.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_hermite.mod.stamp"

  "modules/vibrobeam_initial_state.mod"
  "modules/VIBROBEAM_INITIAL_STATE.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_initial_state.mod.stamp"

  "modules/vibrobeam_input.mod"
  "modules/VIBROBEAM_INPUT.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_input.mod.stamp"

  "modules/vibrobeam_kinds.mod"
  "modules/VIBROBEAM_KINDS.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_kinds.mod.stamp"

  "modules/vibrobeam_lcp.mod"
  "modules/VIBROBEAM_LCP.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_lcp.mod.stamp"

  "modules/vibrobeam_loads.mod"
  "modules/VIBROBEAM_LOADS.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_loads.mod.stamp"

  "modules/vibrobeam_model.mod"
  "modules/VIBROBEAM_MODEL.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_model.mod.stamp"

  "modules/vibrobeam_modes.mod"
  "modules/VIBROBEAM_MODES.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_modes.mod.stamp"

  "modules/vibrobeam_position_stepper.mod"
  "modules/VIBROBEAM_POSITION_STEPPER.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_position_stepper.mod.stamp"

  "modules/vibrobeam_recorder.mod"
  "modules/VIBROBEAM_RECORDER.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_recorder.mod.stamp"

  "modules/vibrobeam_results.mod"
  "modules/VIBROBEAM_RESULTS.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_results.mod.stamp"

  "modules/vibrobeam_saddle_band.mod"
  "modules/VIBROBEAM_SADDLE_BAND.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_saddle_band.mod.stamp"

  "modules/vibrobeam_scene.mod"
  "modules/VIBROBEAM_SCENE.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_scene.mod.stamp"

  "modules/vibrobeam_setup.mod"
  "modules/VIBROBEAM_SETUP.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_setup.mod.stamp"

  "modules/vibrobeam_spectrum.mod"
  "modules/VIBROBEAM_SPECTRUM.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_spectrum.mod.stamp"

  "modules/vibrobeam_static.mod"
  "modules/VIBROBEAM_STATIC.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_static.mod.stamp"

  "modules/vibrobeam_status.mod"
  "modules/VIBROBEAM_STATUS.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_status.mod.stamp"

  "modules/vibrobeam_stepper.mod"
  "modules/VIBROBEAM_STEPPER.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_stepper.mod.stamp"

  "modules/vibrobeam_text.mod"
  "modules/VIBROBEAM_TEXT.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_text.mod.stamp"

  "modules/vibrobeam_velocity_stepper.mod"
  "modules/VIBROBEAM_VELOCITY_STEPPER.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_velocity_stepper.mod.stamp"

  "modules/vibrobeam_version.mod"
  "modules/VIBROBEAM_VERSION.mod"
  "CMakeFiles/vibrobeam_lib.dir/vibrobeam_version.mod.stamp"
  )
