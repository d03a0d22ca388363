!> The discrete constraints of a scene (theory §2, "Discrete constraints" K_h): contact
!! points c with bounds lower(c) <= H_c U <= upper(c), each row H_c at most four unknowns,
!! and the compliant stops acting at them. What the contact numerics work on; which
!! obstacles give which points is `vibrobeam_obstacles`' job (`build_contact_points`).
module vibrobeam_contact_set
   use vibrobeam_kinds, only: dp
   use vibrobeam_compliant_law, only: spring_set
   implicit none
   private
   public :: contact_set, contact_value, no_bound

   real(dp), parameter :: no_bound = huge(1.0_dp)   !! |bound| of a side with no obstacle

   !> The contact points of a scene, ordered by node.
   type :: contact_set
      integer :: count = 0
      integer, allocatable :: node(:)        !! node index i (1..N), x_c = x_i
      real(dp), allocatable :: x(:)          !! position (m)
      real(dp), allocatable :: lower(:)      !! g1(x_c) (m), -no_bound if no obstacle below
      real(dp), allocatable :: upper(:)      !! g2(x_c) (m), +no_bound if no obstacle above
      integer, allocatable :: dofs(:,:)      !! (4, count) unknowns of row H_c (0 = none)
      real(dp), allocatable :: weights(:,:)  !! (4, count) coefficients of row H_c
      type(spring_set) :: springs            !! the compliant stops (none: rigid obstacles only)
      !> (count) the obstacle (index in &obstacles) that gives `lower`, `upper`; on a side
      !! with springs only, its first spring's obstacle; 0: none. An impulse (or a
      !! compliant episode) upwards comes from the lower one, downwards from the upper one.
      integer, allocatable :: lower_obstacle(:), upper_obstacle(:)
   end type contact_set

contains

   !> H_c U: the displacement of the beam at contact point c (m).
   pure function contact_value(contacts, c, u) result(value)
      type(contact_set), intent(in) :: contacts
      integer, intent(in) :: c
      real(dp), intent(in) :: u(:)
      real(dp) :: value
      integer :: a
      value = 0
      do a = 1, 4
         if (contacts%dofs(a, c) /= 0) value = value + contacts%weights(a, c)*u(contacts%dofs(a, c))
      end do
   end function contact_value
end module vibrobeam_contact_set
