!> The wear indicators at the supports (issue 21; docs/statistics.md, "Wear at the
!! supports") against closed forms, on the run of verification/dynamics/wear_sliding.nml
!! (a tube pressed at its tip onto a flat stop by a constant force F at an angle a from
!! its normal, above the friction angle; run by run_case.sh, read here):
!! - the force acts at the contact node and the planes do not couple, so the wall takes
!!   exactly the force's normal component in every step: mean and RMS normal force
!!   F cos a, contact and sliding fractions 1, no impact;
!! - while sliding, friction takes mu P_n |v_t| in every step (the same tangential
!!   velocity, t.(V^{n+1} + V^n)/2 with theta = 1/2), so the normal work rate times mu
!!   and the window's length equals /energy/dissipated_friction at its end;
!! - the wear volume rate is K times the work rate.
!! Tolerances: each impulse is the LCP solution of one contact, exact to a few eps of it;
!! sums over n = 500 steps: 1e-12 relative (n eps x 9); the fractions count whole steps.
program check_support_wear
   use vibrobeam_kinds, only: dp, output_unit, pi
   use vibrobeam_hdf5_file_reads, only: read_real_1d
   use vibrobeam_test_support, only: test_counter
   implicit none
   type(test_counter) :: t
   character(len=*), parameter :: file = 'wear_sliding.h5'
   real(dp), parameter :: force = 10, angle = 20*pi/180, mu = 0.3_dp, coefficient = 1e-14_dp, window = 0.005_dp
   real(dp), allocatable :: work(:), work_error(:), mean(:), rms(:), contact(:), sliding(:), impacts(:), volume(:)
   real(dp), allocatable :: friction(:)
   integer :: stat
   character(len=512) :: errmsg
   call read('/wear/work_rate', work)
   call read('/wear/work_rate_error', work_error)
   call read('/wear/mean_force', mean)
   call read('/wear/rms_force', rms)
   call read('/wear/contact_fraction', contact)
   call read('/wear/sliding_fraction', sliding)
   call read('/wear/impact_rate', impacts)
   call read('/wear/wear_volume_rate', volume)
   call read('/energy/dissipated_friction', friction)
   write (output_unit, '(a,es12.5,a,es10.3,a,2es14.6,a,2f8.4,a,es10.3)') 'work rate ', work(1), ' +- ', work_error(1), &
      ' W; mean and RMS force ', mean(1), rms(1), ' N; contact and sliding fractions ', contact(1), sliding(1), &
      '; impacts/s ', impacts(1)
   call t%check_true('the work rate is positive, its standard error finite', work(1) > 0 .and. work_error(1) >= 0 .and. &
                     work_error(1) < huge(1.0_dp))
   call t%check_close('mean normal force = F cos a', mean(1), force*cos(angle), 1e-12_dp)
   call t%check_close('RMS normal force = F cos a', rms(1), force*cos(angle), 1e-12_dp)
   call t%check_close('contact fraction 1', contact(1), 1.0_dp, 1e-12_dp)
   call t%check_close('sliding fraction 1', sliding(1), 1.0_dp, 1e-12_dp)
   call t%check_close('no impact', impacts(1), 0.0_dp, 1.0_dp, 1e-12_dp)
   call t%check_close('mu T x work rate = the energy friction took', mu*window*work(1), friction(size(friction)), &
                      1e-12_dp)
   call t%check_close('wear volume rate = K x work rate', volume(1), coefficient*work(1), 1e-15_dp)
   call t%finish('check_support_wear')
contains
   subroutine read(path, values)
      character(len=*), intent(in) :: path
      real(dp), allocatable, intent(out) :: values(:)
      call read_real_1d(file, path, values, stat, errmsg)
      if (stat /= 0) then
         write (output_unit, '(a)') 'FAIL reading '//path//': '//trim(errmsg)
         error stop 1
      end if
   end subroutine read
end program check_support_wear
