!> What a static solve did and how accurate its answer is (/static attributes;
!! docs/output.md, "Static equilibrium"): the report of both static paths, the double
!! integration of the clamped-free beam (`vibrobeam_static`) and the band Cholesky of every
!! other structure (`vibrobeam_static_band`).
module vibrobeam_static_report
   use vibrobeam_kinds, only: dp
   implicit none
   private
   public :: static_report

   !> What a static solve did and how accurate its answer is (/static attributes).
   type :: static_report
      integer :: iterations = 0          !! held-set solves (each O(J)), or pivots of the band path
      integer :: levels = 0              !! nested subsets of contact points solved (1 on the band path)
      real(dp) :: error_estimate = 0     !! max over the nodes |u - (K^-1 (F + H^T P))_node| (m)
      real(dp) :: error_bound = 0        !! the largest round-off bound it was compared with (m)
      real(dp) :: position_bound = 0     !! the largest bound of a nodal displacement's round-off (m)
      real(dp) :: displacement_scale = 0 !! max |u| over the nodes (m)
      real(dp), allocatable :: unknown_bound(:)   !! (J) derived bound of the round-off of each unknown
      real(dp), allocatable :: reaction_bound(:)  !! (contact points) derived bound of the round-off of each reaction (N)
      !> derived bound of the round-off of the sum of the reactions (N): the moments' errors
      !! telescope in the sum, sum_j P_j = (lambda_0 - lambda_1)/L_1, leaving theirs at the
      !! first span; each slope (lambda_(j-1) - lambda_j)/L_j is computed once and enters two
      !! reactions with opposite signs, so of the rounding of forming the P_j only that of
      !! the first slope (2 eps) and of each final subtraction (eps |P_j|) remains
      real(dp) :: reaction_sum_bound = 0
   end type static_report

end module vibrobeam_static_report
