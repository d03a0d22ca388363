!> The checkpoint's CRC-64 (vibrobeam_checksum, vibrobeam_checkpoint's record_checksum)
!! against independent facts:
!! - the published check value of CRC-64/XZ, the CRC of the nine bytes '123456789':
!!   0x995DC9BBDF1939FA (the catalogue of parametrised CRC algorithms, reveng.sourceforge.io,
!!   and the xz file format specification, which fixes the algorithm); fed as text, and as
!!   one 64-bit word holding '12345678' (least significant byte first) followed by '9', which
!!   checks the byte order of words;
!! - a CRC detects every single-bit error (the polynomial has more than one term): each of
!!   the 64 bits of each value of a small state, flipped, changes record_checksum, and so
!!   do a changed item name and a changed type of the same bits.
!! Exact comparisons: a CRC is integer arithmetic, with no tolerance to derive.
program test_checksum
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_checksum, only: crc64_start, crc64_words, crc64_text, crc64_finish
   use vibrobeam_checkpoint, only: record_checksum
   use vibrobeam_state_record, only: state_record
   use vibrobeam_test_support, only: test_counter
   implicit none
   type(test_counter) :: t
   type(state_record) :: record, changed
   integer(int64), parameter :: check_value = int(z'995DC9BBDF1939FA', int64)
   integer(int64) :: crc, word, reference, unchanged
   real(dp) :: values(3)
   integer :: k, bit, missed

   crc = crc64_start()
   call crc64_text(crc, '123456789')
   call t%check_true('CRC-64/XZ of ''123456789'' (text) is 0x995DC9BBDF1939FA', crc64_finish(crc) == check_value)

   word = 0
   do k = 8, 1, -1
      word = ior(shiftl(word, 8), int(iachar('12345678'(k:k)), int64))
   end do
   crc = crc64_start()
   call crc64_words(crc, [word])
   call crc64_text(crc, '9')
   call t%check_true('CRC-64/XZ of ''123456789'' (a word and a byte) is 0x995DC9BBDF1939FA', &
                     crc64_finish(crc) == check_value)

   crc = crc64_start()
   call t%check_true('CRC-64/XZ of no data is 0', crc64_finish(crc) == 0_int64)

   ! a small state, as a checkpoint holds it
   values = [1.0_dp, -2.5e-3_dp, 3.0e8_dp]
   call record%put_reals('stepper.u', values)
   call record%put_int64s('stepper.steps', [5000_int64])
   reference = record_checksum(record)
   missed = 0
   do k = 1, size(values)
      do bit = 0, 63
         changed = record
         changed%items(1)%reals(k) = transfer(ieor(transfer(values(k), 1_int64), shiftl(1_int64, bit)), 1.0_dp)
         if (record_checksum(changed) == reference) missed = missed + 1
      end do
   end do
   do bit = 0, 63
      changed = record
      changed%items(2)%int64s(1) = ieor(5000_int64, shiftl(1_int64, bit))
      if (record_checksum(changed) == reference) missed = missed + 1
   end do
   call t%check_true('every one of the 256 single-bit flips of the state changes its checksum', missed == 0)
   changed = record
   changed%items(1)%name = 'stepper.v'
   call t%check_true('a renamed item changes the checksum', record_checksum(changed) /= reference)
   call changed%clear()
   call changed%put_int64s('stepper.u', transfer(values, 1_int64, size(values)))
   call changed%put_int64s('stepper.steps', [5000_int64])
   call t%check_true('the same bits as integers instead of reals change the checksum', &
                     record_checksum(changed) /= reference)
   unchanged = record_checksum(record)
   call t%check_true('the checksum of the same state is the same', unchanged == reference)
   call t%finish('test_checksum')
end program test_checksum
