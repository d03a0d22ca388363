!> The two bending planes of a beam (docs/method.md, "Two bending planes and tube-support
!! contact"): a state of `planes` x J unknowns stacked plane by plane (y in 1:J, z in
!! J+1:2J), and the shares of a load or an initial field given in y and turned by a
!! `direction` angle towards z.
module vibrobeam_planes
   use vibrobeam_kinds, only: dp, pi
   implicit none
   private
   public :: direction_shares, spread_planes

contains

   !> (cos a, sin a) of a direction a in degrees from y towards z, exact at the multiples
   !! of 90 degrees (0, 90, 180, 270 and their negatives give 0 and +-1 exactly, so a load
   !! along y or z has no share at all in the other plane; cos(pi/2) in floating point is
   !! 6e-17, not 0).
   pure function direction_shares(degrees) result(shares)
      real(dp), intent(in) :: degrees
      real(dp) :: shares(2), turned
      integer :: quarter
      turned = modulo(degrees, 360.0_dp)
      if (abs(turned - 90*anint(turned/90)) > 0) then
         shares = [cos(turned*pi/180), sin(turned*pi/180)]
         return
      end if
      quarter = modulo(nint(turned/90), 4)
      select case (quarter)
      case (0)
         shares = [1.0_dp, 0.0_dp]
      case (1)
         shares = [0.0_dp, 1.0_dp]
      case (2)
         shares = [-1.0_dp, 0.0_dp]
      case default
         shares = [0.0_dp, -1.0_dp]
      end select
   end function direction_shares

   !> A field given in the y plane, f(1:J), turned towards z: f(1:J) = c f(1:J),
   !! f(J+1:2J) = s f(1:J) with (c, s) = `shares`; f has 2J values. (1, 0) leaves y as
   !! it is (no product) and z exactly 0.
   pure subroutine spread_planes(shares, f)
      real(dp), intent(in) :: shares(2)
      real(dp), intent(inout) :: f(:)
      integer :: j
      j = size(f)/2
      f(j + 1:) = shares(2)*f(1:j)
      if (abs(shares(1) - 1) > 0) f(1:j) = shares(1)*f(1:j)
   end subroutine spread_planes
end module vibrobeam_planes
