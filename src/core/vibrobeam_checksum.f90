!> A 64-bit cyclic redundancy check (CRC-64 with the polynomial of ECMA-182, in the
!! reflected form with all-ones initial value and final complement, as used by the xz
!! file format; catalogued as CRC-64/XZ, whose check value, the CRC of the nine bytes
!! '123456789', is 0x995DC9BBDF1939FA). A checkpoint carries the CRC of its state
!! (`vibrobeam_checkpoint`), so that a damaged file is refused rather than continued.
!!
!! Why a CRC: it detects every error in an odd number of bits and every burst of at most 64
!! bits (Peterson & Brown, "Cyclic codes for error detection", Proc. IRE 49, 1961), which
!! covers the flipped bit of a disk or a copy; any other damage passes with probability
!! 2^-64. It is not a defence against deliberate change.
!!
!! The data are 64-bit words (a real's bit pattern, an integer) and text, fed byte by byte
!! from the least significant byte of each word, so that the value does not depend on the
!! machine's byte order. Usage: crc = crc64_start(); call crc64_words(crc, words); ...;
!! value = crc64_finish(crc).
module vibrobeam_checksum
   use vibrobeam_kinds, only: int64
   implicit none
   private
   public :: crc64_start, crc64_words, crc64_text, crc64_finish

   !> The reflected ECMA-182 polynomial 0xC96C5795D7870F42.
   integer(int64), parameter :: polynomial = int(z'C96C5795D7870F42', int64)
   integer(int64), parameter :: all_ones = not(0_int64)

contains

   !> The register before any data.
   pure integer(int64) function crc64_start()
      crc64_start = all_ones
   end function crc64_start

   !> The CRC of the data fed into `crc`.
   pure integer(int64) function crc64_finish(crc)
      integer(int64), intent(in) :: crc
      crc64_finish = not(crc)
   end function crc64_finish

   !> Feed the 8 bytes of each word of `words`, least significant byte first.
   pure subroutine crc64_words(crc, words)
      integer(int64), intent(inout) :: crc
      integer(int64), intent(in) :: words(:)
      integer(int64) :: table(0:255)
      integer :: k, b
      table = byte_table()
      do k = 1, size(words)
         do b = 0, 7
            call feed(crc, table, iand(shiftr(words(k), 8*b), 255_int64))
         end do
      end do
   end subroutine crc64_words

   !> Feed the characters of `text`, one byte each.
   pure subroutine crc64_text(crc, text)
      integer(int64), intent(inout) :: crc
      character(len=*), intent(in) :: text
      integer(int64) :: table(0:255)
      integer :: k
      table = byte_table()
      do k = 1, len(text)
         call feed(crc, table, int(iachar(text(k:k)), int64))
      end do
   end subroutine crc64_text

   !> One byte through the register, by the table of `byte_table`.
   pure subroutine feed(crc, table, byte)
      integer(int64), intent(inout) :: crc
      integer(int64), intent(in) :: table(0:255), byte
      crc = ieor(table(int(iand(ieor(crc, byte), 255_int64))), shiftr(crc, 8))
   end subroutine feed

   !> The register's change for each byte value: eight steps of the bitwise division
   !! (shift right; where a 1 falls out, add the polynomial).
   pure function byte_table() result(table)
      integer(int64) :: table(0:255)
      integer(int64) :: r
      integer :: n, bit
      do n = 0, 255
         r = int(n, int64)
         do bit = 1, 8
            if (btest(r, 0)) then
               r = ieor(shiftr(r, 1), polynomial)
            else
               r = shiftr(r, 1)
            end if
         end do
         table(n) = r
      end do
   end function byte_table
end module vibrobeam_checksum
