!> The CRC-64 of the random signals of a scene's &forces (every point of a coherent field)
!! at its first 2^15 time steps (docs/method.md, "Random signals"): printed as one
!! hexadecimal line, for random_signal_bits.sh to compare between runs on 1 and 2 threads,
!! on the reference BLAS and OpenBLAS, and between builds. The signals are evaluated twice
!! at once on two OpenMP threads (each its own copy) and a third time from step
!! 2^14 + 1234 on, as a continued run would: all three must give the same bits (exit 1
!! otherwise).
!!
!! usage: random_signal_digest SCENE.nml
program random_signal_digest
   use vibrobeam_kinds, only: dp, int64, output_unit, error_unit
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem
   use vibrobeam_random_signal, only: random_signal
   use vibrobeam_checksum, only: crc64_start, crc64_words, crc64_finish
   use vibrobeam_test_support, only: read_test_scene, prepare_test_scene, same_bits
   implicit none
   integer, parameter :: steps = 2**15, restart = 2**14 + 1234
   type(scene_type) :: scene
   type(run_problem) :: prepared
   type(random_signal), allocatable :: signals(:, :)
   type(random_signal) :: continued
   real(dp), allocatable :: values(:), again(:)
   integer(int64) :: crc(2)
   character(len=4096) :: path
   integer :: i, j, n
   logical :: same
   call get_command_argument(1, path)
   scene = read_test_scene(trim(path))
   call prepare_test_scene(scene, prepared)
   allocate (signals(size(scene%forces%load), 2))
   do i = 1, size(scene%forces%load)
      signals(i, :) = prepared%loads%forces%random_of(i)
   end do
   crc = [crc64_start(), crc64_start()]
   !$omp parallel do num_threads(2) private(i, n, values)
   do j = 1, 2
      do i = 1, size(signals, 1)
         if (signals(i, j)%taps == 0) cycle   ! not a random load
         allocate (values(signals(i, j)%channels))
         do n = 0, steps - 1
            call signals(i, j)%values(n*scene%time%dt, values)
            call crc64_words(crc(j), transfer(values, 0_int64, size(values)))
         end do
         deallocate (values)
      end do
   end do
   !$omp end parallel do
   crc = [crc64_finish(crc(1)), crc64_finish(crc(2))]
   same = .true.
   do i = 1, size(signals, 1)
      if (signals(i, 1)%taps == 0) cycle
      continued = prepared%loads%forces%random_of(i)
      allocate (values(continued%channels), again(continued%channels))
      do n = restart, steps - 1
         call continued%values(n*scene%time%dt, again)
         call signals(i, 1)%values(n*scene%time%dt, values)
         same = same .and. all(same_bits(again, values))
      end do
      deallocate (values, again)
   end do
   write (output_unit, '(a,z16.16)') 'random signals of &forces at 2^15 steps: CRC-64 ', crc(1)
   if (crc(1) /= crc(2)) then
      write (error_unit, '(a)') 'FAIL the two threads computed different signals'
      error stop 1
   end if
   if (.not. same) then
      write (error_unit, '(a)') 'FAIL a continued evaluation gave another signal'
      error stop 1
   end if
end program random_signal_digest
