!> The parameter of a continuation of periodic orbits (&periodic parameter, step,
!! parameter_min, parameter_max; docs/input.md, "&periodic"; docs/method.md,
!! "Continuation of periodic orbits"): resolved as a sweep resolves its parameter (the same
!! `resolve_axis`, so every input a sweep may vary can be continued in, and nothing else),
!! and the rules between these variables and the scene.
module vibrobeam_continuation_axis
   use vibrobeam_status, only: stat_failure
   use vibrobeam_kinds, only: dp
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_scene, only: scene_type
   use vibrobeam_schema_visitor, only: is_unset
   use vibrobeam_scene_values, only: real_input, set_real_input
   use vibrobeam_periodic_settings, only: forcing_frequency
   use vibrobeam_sweep_axis, only: sweep_axis, resolve_name, check_range
   use vibrobeam_namelist_schema, only: namelist_variable
   implicit none
   private
   public :: resolve_continuation, continues, branch_points

contains

   !> The scene asks for a continuation: kind = 'periodic' with &periodic parameter given.
   pure logical function continues(scene)
      type(scene_type), intent(in) :: scene
      continues = scene%analysis%kind == 'periodic' .and. len_trim(scene%periodic%parameter) > 0
   end function continues

   !> The most points of the branch --check counts on: &periodic max_points; on a backbone
   !! bounded in its step's direction, no more than its first step's whole range takes,
   !! ceiling(|bound - tip_amplitude|/|step|) + 1 (a step never shorter than the first but
   !! after a corrector fails).
   integer function branch_points(scene)
      type(scene_type), intent(in) :: scene
      real(dp) :: bound
      branch_points = scene%periodic%max_points
      if (.not. scene%periodic%autonomous .or. is_unset(scene%periodic%tip_amplitude) .or. &
          .not. abs(scene%periodic%step) > 0) return
      bound = merge(scene%periodic%parameter_max, scene%periodic%parameter_min, scene%periodic%step > 0)
      if (is_unset(bound)) return
      if (abs(bound - scene%periodic%tip_amplitude)/abs(scene%periodic%step) < branch_points) &
         branch_points = min(branch_points, ceiling(abs(bound - scene%periodic%tip_amplitude)/abs(scene%periodic%step)) + 1)
   end function branch_points

   !> `axis`: the continuation's parameter (group, name, element, unit) and `start`, its
   !! value in the scene, where the branch begins. stat = stat_failure with a message
   !! naming &periodic, the variable, its value and what is allowed when: the parameter
   !! is not a sweepable real input; step = 0; parameter_min > parameter_max; the start or
   !! a bound is outside the input's range; the start is outside [parameter_min,
   !! parameter_max]; an obstacle is rigid (the period map is not smooth there,
   !! docs/method.md); the model is reduced (its basis would change with the parameter).
   !! The backbone of an autonomous orbit (&periodic autonomous) has its own parameter and
   !! rules (`resolve_backbone`).
   subroutine resolve_continuation(scene, axis, start, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(sweep_axis), intent(out) :: axis
      real(dp), intent(out) :: start
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=*), parameter :: group = '&periodic '
      character(len=:), allocatable :: label
      type(namelist_variable) :: variable
      type(scene_type) :: shifted
      character(len=:), allocatable :: problem
      real(dp) :: omega
      logical :: found
      integer :: i
      start = 0
      stat = stat_failure
      associate (periodic => scene%periodic)
         axis%parameter = periodic%parameter
         if (.not. (abs(periodic%step) > 0)) then
            errmsg = group//'step = '//real_text(periodic%step)//' is not allowed with parameter = '''// &
                     trim(periodic%parameter)//''': give the first continuation step, non-zero, in the parameter''s '// &
                     'unit (its sign is the direction)'
            return
         end if
         if (.not. is_unset(periodic%parameter_min) .and. .not. is_unset(periodic%parameter_max)) then
            if (periodic%parameter_min > periodic%parameter_max) then
               errmsg = group//'parameter_min = '//real_text(periodic%parameter_min)//' is above parameter_max = '// &
                        real_text(periodic%parameter_max)//': the bounds must satisfy parameter_min <= parameter_max'
               return
            end if
         end if
         if (periodic%autonomous) then
            call resolve_backbone()
            return
         end if
         do i = 1, size(scene%obstacles)
            if (scene%obstacles(i)%stiffness > 0) cycle
            errmsg = group//'parameter = '''//trim(periodic%parameter)//''' with a rigid obstacle (&obstacles '// &
                     'stiffness('//integer_text(i)//') = 0): continuation needs a smooth period map, compliant '// &
                     'stops (stiffness > 0) or none (docs/method.md, "Continuation of periodic orbits")'
            return
         end do
         if (scene%mesh%reduction /= 'none') then
            errmsg = group//'parameter = '''//trim(periodic%parameter)//''' with &mesh reduction = '''// &
                     trim(scene%mesh%reduction)//''': continuation steps the full model only, for now (''none'')'
            return
         end if
         label = group//'parameter = '''//trim(periodic%parameter)//''''
         call resolve_name(axis, label, scene, variable, stat, errmsg)
         if (stat /= 0) return
         call real_input(scene, axis%group, axis%name, axis%index, start, found)
         ! the start and the bounds inside the input's range
         axis%values = [start]
         call check_range(axis, variable, label, stat, errmsg)
         if (stat /= 0) return
         if (.not. is_unset(periodic%parameter_min)) then
            axis%values = [periodic%parameter_min]
            call check_range(axis, variable, group//'parameter_min', stat, errmsg)
            if (stat /= 0) return
         end if
         if (.not. is_unset(periodic%parameter_max)) then
            axis%values = [periodic%parameter_max]
            call check_range(axis, variable, group//'parameter_max', stat, errmsg)
            if (stat /= 0) return
         end if
         call start_inside()
         if (stat /= 0) return
         stat = stat_failure
         ! one forcing frequency along the branch (two harmonic loads of one frequency part
         ! when the parameter moves one of them)
         shifted = scene
         call set_real_input(shifted, axis%group, axis%name, axis%index, start + periodic%step, found)
         call forcing_frequency(shifted%load, omega, problem)
         if (len(problem) > 0) then
            errmsg = label//' moves one of the harmonic loads alone: at '//real_text(start + periodic%step)// &
                     ' the scene '//problem//'; continue in a scene with one harmonic load'
            return
         end if
      end associate
      stat = 0
      errmsg = ''
   contains
      !> The start inside [parameter_min, parameter_max] (stat 0), else stat_failure and why.
      subroutine start_inside()
         stat = stat_failure
      if (.not. is_unset(scene%periodic%parameter_min)) then
         if (start < scene%periodic%parameter_min) then
            errmsg = group//'parameter_min = '//real_text(scene%periodic%parameter_min)//' is above the start, '// &
                     trim(axis%parameter)//' = '//real_text(start)//': the branch starts at the scene''s value, '// &
                     'inside [parameter_min, parameter_max]'
            return
         end if
      end if
      if (.not. is_unset(scene%periodic%parameter_max)) then
         if (start > scene%periodic%parameter_max) then
            errmsg = group//'parameter_max = '//real_text(scene%periodic%parameter_max)//' is below the start, '// &
                     trim(axis%parameter)//' = '//real_text(start)//': the branch starts at the scene''s value, '// &
                     'inside [parameter_min, parameter_max]'
            return
         end if
      end if
         stat = 0
      end subroutine start_inside

      !> The backbone of an autonomous orbit (&periodic autonomous; docs/method.md, "The
      !! backbone"): its parameter is the orbit's tip amplitude, which the rules allow alone
      !! (`vibrobeam_scene_rules`), its start &periodic tip_amplitude, which must be given
      !! and not 0 (the rest state), and a step towards 0 needs the bound on that side
      !! between 0 and the start: the backbone ends at the rest state, where the period is
      !! undetermined. Rigid stops and a reduced model are taken as by one autonomous orbit
      !! (the parameter changes neither the model nor its basis).
      subroutine resolve_backbone()
         character(len=:), allocatable :: bound_name
         real(dp) :: bound
         axis%parameter = 'periodic.tip_amplitude'
         axis%group = 'periodic'
         axis%name = 'tip_amplitude'
         axis%index = 1
         axis%unit = 'm'
         stat = stat_failure
         if (is_unset(scene%periodic%tip_amplitude)) then
            errmsg = group//'parameter = ''periodic.tip_amplitude'' needs &periodic tip_amplitude (m), where the '// &
                     'backbone starts (not 0)'
            return
         end if
         start = scene%periodic%tip_amplitude
         if (.not. abs(start) > 0) then
            errmsg = group//'tip_amplitude = 0 is not allowed with parameter = ''periodic.tip_amplitude'': that is '// &
                     'the rest state, whose period is undetermined; start the backbone at an amplitude of either sign'
            return
         end if
         call start_inside()
         if (stat /= 0) return
         if (scene%periodic%step*start < 0) then
            stat = stat_failure
            bound_name = merge('parameter_min', 'parameter_max', start > 0)
            bound = merge(scene%periodic%parameter_min, scene%periodic%parameter_max, start > 0)
            if (is_unset(bound)) then
               errmsg = group//'step = '//real_text(scene%periodic%step)//' heads the backbone from tip_amplitude = '// &
                        real_text(start)//' m towards the rest state (0), where it ends: give '//bound_name// &
                        ' between 0 and the start'
               return
            end if
            if (.not. bound*start > 0) then
               errmsg = group//bound_name//' = '//real_text(bound)//' is not between 0 and the start, '// &
                        'tip_amplitude = '//real_text(start)//' m: the backbone ends at the rest state (0), where '// &
                        'the period is undetermined'
               return
            end if
         end if
         stat = 0
         errmsg = ''
      end subroutine resolve_backbone
   end subroutine resolve_continuation
end module vibrobeam_continuation_axis
