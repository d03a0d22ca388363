!> The contact statistics of a contact target (a contact point, an obstacle, the beam)
!! and the force statistics of the compliant stops at a contact point, from the sums and
!! extremes `vibrobeam_statistics` accumulates over a window or one of its blocks
!! (docs/statistics.md, "At each contact point, each obstacle and the beam" and "Force of the
!! compliant stops").
module vibrobeam_contact_fill
   use vibrobeam_kinds, only: dp
   implicit none
   private
   public :: fill, fill_force
   public :: f_force, f_force_square, f_steps, f_episodes, f_episode_steps, per_force, x_force, x_episode_steps, &
             per_force_extreme

   !> Sum quantities of the compliant stops' force per contact point: sum |f|, sum f^2,
   !! steps with f /= 0, compliant episodes, their steps; extremes: |f|, episode steps.
   integer, parameter :: f_force = 1, f_force_square = 2, f_steps = 3, f_episodes = 4, f_episode_steps = 5, &
                         per_force = 5, x_force = 1, x_episode_steps = 2, per_force_extreme = 2

contains

   !> The contact statistics from sums over `samples` steps lasting `duration` (s).
   pure subroutine fill(values, at, impacts, episodes, impulse, impulse_square, largest, contact_steps, force, &
                        samples, duration)
      real(dp), intent(inout) :: values(:)
      integer, intent(in) :: at(7)
      real(dp), intent(in) :: impacts, episodes, impulse, impulse_square, largest, contact_steps, force, samples, &
                              duration
      values(at(1)) = impacts/duration
      values(at(2)) = episodes/duration
      values(at(3:5)) = 0
      if (episodes > 0) then
         values(at(3)) = impulse/episodes
         values(at(4)) = largest
         values(at(5)) = sqrt(impulse_square/episodes)
      end if
      values(at(6)) = contact_steps/samples
      values(at(7)) = force/duration
   end subroutine fill

   !> The force statistics from the force sums and extremes over `samples` steps of dt.
   pure subroutine fill_force(values, at, sums, extremes, samples, dt)
      real(dp), intent(inout) :: values(:)
      integer, intent(in) :: at(7)
      real(dp), intent(in) :: sums(per_force), extremes(per_force_extreme), samples, dt
      values(at) = 0
      values(at(1)) = max(0.0_dp, extremes(x_force))
      values(at(2)) = sums(f_force)/samples
      if (sums(f_steps) > 0) then
         values(at(3)) = sums(f_force)/sums(f_steps)
         values(at(4)) = sqrt(sums(f_force_square)/sums(f_steps))
      end if
      values(at(5)) = sums(f_steps)/samples
      if (sums(f_episodes) > 0) then
         values(at(6)) = sums(f_episode_steps)*dt/sums(f_episodes)
         values(at(7)) = extremes(x_episode_steps)*dt
      end if
   end subroutine fill_force
end module vibrobeam_contact_fill
