!> Unit test of the rules that turn obstacles into contact points (`build_contact_points`,
!! docs/input.md "How obstacles become constraints"), for the two cases the documentation
!! must state exactly:
!! 1. a punctual obstacle midway between two nodes acts on the node x_i with
!!    i = nint(x/h), Fortran's rounding half away from zero: the node farther from the
!!    clamp when x/h is exactly i + 1/2 in binary (L = 1, N = 4, x = 0.375: node 0.5); a
!!    midpoint written in decimal is often not exactly midway in binary, and then goes to
!!    the node its binary value is nearer (N = 10: x = 0.15 -> 0.1, 0.25 -> 0.3, 0.35 -> 0.3);
!! 2. a longitudinal obstacle that covers no node acts at the node nearest its middle, at
!!    the level of its end nearest that node (its level held constant beyond its ends):
!!    N = 4, [0.30, 0.40] at levels -1, -2 mm acts at x = 0.25 at -1 mm; [0.55, 0.70] at
!!    -3, -4 mm acts at x = 0.75 at -4 mm.
!! Positions and levels are compared exactly: they are copied, not computed.
program test_contact_points
   use vibrobeam_kinds, only: dp
   use vibrobeam_scene, only: scene_type, obstacle_type
   use vibrobeam_model, only: beam_model, build_model
   use vibrobeam_contact_set, only: contact_set
   use vibrobeam_obstacles, only: build_contact_points
   use vibrobeam_test_support, only: test_counter
   implicit none
   type(test_counter) :: t
   call punctual(4, 0.375_dp, 0.5_dp)
   call punctual(10, 0.15_dp, 0.1_dp)
   call punctual(10, 0.25_dp, 0.3_dp)
   call punctual(10, 0.35_dp, 0.3_dp)
   call short(0.30_dp, 0.40_dp, -1e-3_dp, -2e-3_dp, 0.25_dp, -1e-3_dp)
   call short(0.55_dp, 0.70_dp, -3e-3_dp, -4e-3_dp, 0.75_dp, -4e-3_dp)
   call t%finish('test_contact_points')
contains
   subroutine punctual(elements, x, node_x)
      integer, intent(in) :: elements
      real(dp), intent(in) :: x, node_x
      type(contact_set) :: contacts
      character(len=80) :: label
      write (label, '(a,i0,a,f5.3)') 'N = ', elements, ', punctual obstacle at x = ', x
      contacts = contacts_of(elements, obstacle_type('below', x, x, -1e-3_dp, -1e-3_dp))
      call t%check_true(trim(label)//': one contact point', contacts%count == 1)
      if (contacts%count /= 1) return
      call t%check_true(trim(label)//': acts at the documented node', &
                        abs(contacts%x(1) - node_x) < 1e-12_dp, 'acts at x = '//real_text(contacts%x(1)))
   end subroutine punctual

   subroutine short(x_from, x_to, level_from, level_to, node_x, level)
      real(dp), intent(in) :: x_from, x_to, level_from, level_to, node_x, level
      type(contact_set) :: contacts
      character(len=80) :: label
      write (label, '(a,f4.2,a,f4.2,a)') 'N = 4, obstacle [', x_from, ', ', x_to, ']'
      contacts = contacts_of(4, obstacle_type('below', x_from, x_to, level_from, level_to))
      call t%check_true(trim(label)//': one contact point', contacts%count == 1)
      if (contacts%count /= 1) return
      call t%check_true(trim(label)//': acts at the node nearest its middle', &
                        abs(contacts%x(1) - node_x) < 1e-12_dp, 'acts at x = '//real_text(contacts%x(1)))
      call t%check_true(trim(label)//': at the level of its nearest end', abs(contacts%lower(1) - level) <= 0, &
                        'level '//real_text(contacts%lower(1)))
   end subroutine short

   function contacts_of(elements, obstacle) result(contacts)
      integer, intent(in) :: elements
      type(obstacle_type), intent(in) :: obstacle
      type(contact_set) :: contacts
      type(scene_type) :: scene
      type(beam_model) :: model
      character(len=:), allocatable :: warnings
      character(len=256) :: errmsg
      integer :: stat
      scene%obstacles = [obstacle]
      call build_model('hermite', elements, 1.0_dp, 1.0_dp, 1.0_dp, model, stat, errmsg)
      warnings = ''
      call build_contact_points(scene%obstacles, model, contacts, warnings, stat, errmsg)
      if (stat /= 0) error stop 'build_contact_points failed'
   end function contacts_of

   function real_text(x) result(text)
      real(dp), intent(in) :: x
      character(len=24) :: text
      write (text, '(es24.16)') x
   end function real_text
end program test_contact_points
