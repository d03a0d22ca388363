!> Obstacle profiles (&obstacles profile(i), issue 18 item 9; docs/input.md "&obstacles"):
!! 1. a linear profile against a closed-form static contact (strip_profile.nml): the strip
!!    rests with its tip on the inclined line u = -8e-3 x/L over [L/2, L] and touches it
!!    nowhere else; the reaction is the propped cantilever's with the tip displacement
!!    prescribed, R = 3 EI (|q| L^4/(8 EI) - g)/L^3, g = 8e-3 m, exact at the nodes for both
!!    bases (test_static_closed_forms.f90, item 2). Tolerance: the solver's derived bound of
!!    the reaction (`static_report`), gamma_12 of the closed form's terms, and the level's
!!    own rounding in the table's interpolation (gamma_3 g) times the tip stiffness 3EI/L^3.
!! 2. a constant profile equals the flat obstacle bitwise: the contact points' bounds and
!!    the compliant stops' levels of the same obstacles, given by level_from and by a
!!    profile of that level (a rigid longitudinal 'below', a rigid punctual 'above', a
!!    compliant longitudinal one).
!! It fails when the profile is ignored (the levels are then level_from's, 0: the
!! reaction is the stop at 0 instead of -8 mm).
!! usage: test_obstacle_profile SCENE_DIR
program test_obstacle_profile
   use vibrobeam_kinds, only: dp
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem
   use vibrobeam_model, only: nodal_displacement
   use vibrobeam_static, only: solve_static, static_report
   use vibrobeam_roundoff_bounds, only: gamma_n
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene, same_bits
   implicit none
   type(test_counter) :: t
   character(len=512) :: dir
   character(len=*), parameter :: flat_file = 'test_obstacle_profile_flat.dat'
   integer :: unit
   call get_command_argument(1, dir)
   call inclined_line('hermite')
   call inclined_line('bspline')
   call constant_profile()
   open (newunit=unit, file=flat_file)
   close (unit, status='delete')
   call t%finish('test_obstacle_profile')
contains
   !> Item 1 of the module comment on `basis`.
   subroutine inclined_line(basis)
      character(len=*), intent(in) :: basis
      real(dp), parameter :: g = 8e-3_dp
      type(scene_type) :: scene
      type(run_problem) :: prepared
      type(static_report) :: report
      real(dp), allocatable :: u(:), reaction(:), w(:)
      real(dp) :: p, length, ei, exact
      integer :: iterations, stat
      character(len=512) :: errmsg
      scene = read_test_scene(trim(dir)//'/strip_profile.nml')
      scene%mesh%basis = basis
      call prepare_test_scene(scene, prepared)
      allocate (u(prepared%model%unknowns), reaction(prepared%contacts%count))
      call solve_static(prepared%model, prepared%contacts, prepared%loads%at(0.0_dp), u, reaction, iterations, stat, &
                        errmsg, report=report)
      call t%check_true(basis//': the static solve succeeds', stat == 0, trim(errmsg))
      call t%check_true(basis//': the obstacle acts at the 51 nodes of [L/2, L]', prepared%contacts%count == 51)
      if (stat /= 0 .or. prepared%contacts%count /= 51) return
      p = -scene%load%distributed
      length = scene%beam%length
      ei = scene%beam%ei()
      exact = 3*ei*(p*length**4/(8*ei) - g)/length**3
      call t%check_close(basis//': tip reaction 3 EI (|q| L^4/(8 EI) - g)/L^3 on the profile''s level', &
                         abs(reaction(51) - exact), 0.0_dp, 1.0_dp, report%reaction_bound(51) + &
                         gamma_n(12)*3*ei*(p*length**4/(8*ei) + g)/length**3 + gamma_n(3)*g*3*ei/length**3)
      call t%check_true(basis//': no other node touches the line', .not. any(abs(reaction(1:50)) > 0))
      w = nodal_displacement(prepared%model, u)
      call t%check_close(basis//': the tip rests on the profile at -g', abs(w(size(w)) + g), 0.0_dp, 1.0_dp, &
                         nodal_bound(prepared, report, size(w)) + gamma_n(3)*g)
   end subroutine inclined_line

   !> The derived round-off bound of the displacement at node `node` (1..N+1).
   real(dp) function nodal_bound(prepared, report, node)
      type(run_problem), intent(in) :: prepared
      type(static_report), intent(in) :: report
      integer, intent(in) :: node
      real(dp) :: bound(prepared%model%elements + 1)
      bound = nodal_displacement(prepared%model, report%unknown_bound)   ! B-spline rows: non-negative weights
      nodal_bound = bound(node)
   end function nodal_bound

   !> Item 2 of the module comment.
   subroutine constant_profile()
      type(scene_type) :: flat, profiled
      type(run_problem) :: a, b
      integer :: unit, k
      flat = read_test_scene(trim(dir)//'/strip_profile.nml')
      deallocate (flat%obstacles)
      allocate (flat%obstacles(3))
      flat%obstacles(1)%side = 'below'
      flat%obstacles(1)%x_from = 0.1_dp
      flat%obstacles(1)%x_to = 0.3_dp
      flat%obstacles(2)%side = 'above'
      flat%obstacles(2)%x_from = 0.45_dp
      flat%obstacles(2)%x_to = 0.45_dp
      flat%obstacles(3)%side = 'below'
      flat%obstacles(3)%x_from = 0.2_dp
      flat%obstacles(3)%x_to = 0.45_dp
      flat%obstacles(3)%stiffness = 1e4_dp
      flat%obstacles%level_from = [-0.3e-3_dp, 0.7e-3_dp, -0.1e-3_dp]
      flat%obstacles%level_to = flat%obstacles%level_from
      flat%analysis%kind = 'dynamics'
      flat%initial%displacement = 'zero'
      call prepare_test_scene(flat, a)
      profiled = flat
      do k = 1, 3
         write (profiled%obstacles(k)%profile, '(a,i0,a)') flat_file(1:len(flat_file) - 4)//'_', k, '.dat'
         open (newunit=unit, file=trim(profiled%obstacles(k)%profile), status='replace')
         write (unit, '(a)') '# a flat surface'
         write (unit, '(2es26.17e3)') 0.0_dp, flat%obstacles(k)%level_from, 0.2_dp, flat%obstacles(k)%level_from, &
            0.45_dp, flat%obstacles(k)%level_from
         close (unit)
         profiled%obstacles(k)%level_from = 5.0_dp   ! must not matter
         profiled%obstacles(k)%level_to = -5.0_dp
      end do
      call prepare_test_scene(profiled, b)
      do k = 1, 3
         open (newunit=unit, file=trim(profiled%obstacles(k)%profile))
         close (unit, status='delete')
      end do
      call t%check_true('constant profiles: the same contact points', a%contacts%count == b%contacts%count .and. &
                        all(a%contacts%node == b%contacts%node))
      if (a%contacts%count /= b%contacts%count) return
      call t%check_true('constant profiles: the flat obstacles'' bounds bitwise', &
                        all(same_bits(a%contacts%lower, b%contacts%lower)) .and. &
                        all(same_bits(a%contacts%upper, b%contacts%upper)))
      call t%check_true('constant profile: the compliant stop''s levels bitwise', &
                        a%contacts%springs%count == b%contacts%springs%count .and. &
                        all(same_bits(a%contacts%springs%level, b%contacts%springs%level)))
   end subroutine constant_profile

end program test_obstacle_profile
