!> The state of a run that a checkpoint holds (docs/output.md, "Checkpoint and restart"),
!! as a list of named arrays: 64-bit reals (bit patterns kept exactly) and 64-bit
!! integers (step counts, flags). The stepper and the recorder each put their state into a
!! record (`save_state`) and take it back (`restore_state`); `vibrobeam_checkpoint` writes
!! a record to HDF5 and reads it back. Names are 'owner.quantity' ('stepper.u',
!! 'recorder.contact_time'); an item keeps its size for a whole run, so that the
!! checkpoint datasets can be created once.
module vibrobeam_state_record
   use vibrobeam_status, only: stat_failure
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_text, only: integer_text
   implicit none
   private
   public :: state_record, state_item

   integer, parameter :: name_length = 64

   type :: state_item
      character(len=name_length) :: name = ''
      logical :: integers = .false.
      real(dp), allocatable :: reals(:)
      integer(int64), allocatable :: int64s(:)
   end type state_item

   type :: state_record
      integer :: count = 0
      type(state_item), allocatable :: items(:)
   contains
      procedure :: clear
      procedure :: put_reals
      procedure :: put_real
      procedure :: put_int64s
      procedure :: put_int64
      procedure :: put_logicals
      procedure :: find
      procedure :: get_reals
      procedure :: get_real
      procedure :: get_int64s
      procedure :: get_int64
      procedure :: get_logicals
      procedure :: add_item
   end type state_record

contains

   !> Forget every item.
   subroutine clear(self)
      class(state_record), intent(inout) :: self
      self%count = 0
      if (allocated(self%items)) deallocate (self%items)
   end subroutine clear

   !> Append `item` (replacing an item of the same name).
   subroutine add_item(self, item)
      class(state_record), intent(inout) :: self
      type(state_item), intent(in) :: item
      type(state_item), allocatable :: bigger(:)
      integer :: k
      k = self%find(item%name)
      if (k > 0) then
         self%items(k) = item
         return
      end if
      if (.not. allocated(self%items)) allocate (self%items(16))
      if (self%count == size(self%items)) then
         allocate (bigger(2*self%count))
         bigger(1:self%count) = self%items(1:self%count)
         call move_alloc(bigger, self%items)
      end if
      self%count = self%count + 1
      self%items(self%count) = item
   end subroutine add_item

   subroutine put_reals(self, name, values)
      class(state_record), intent(inout) :: self
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: values(:)
      type(state_item) :: item
      item%name = name
      item%integers = .false.
      allocate (item%reals, source=values)
      call self%add_item(item)
   end subroutine put_reals

   subroutine put_real(self, name, value)
      class(state_record), intent(inout) :: self
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: value
      call self%put_reals(name, [value])
   end subroutine put_real

   subroutine put_int64s(self, name, values)
      class(state_record), intent(inout) :: self
      character(len=*), intent(in) :: name
      integer(int64), intent(in) :: values(:)
      type(state_item) :: item
      item%name = name
      item%integers = .true.
      allocate (item%int64s, source=values)
      call self%add_item(item)
   end subroutine put_int64s

   subroutine put_int64(self, name, value)
      class(state_record), intent(inout) :: self
      character(len=*), intent(in) :: name
      integer(int64), intent(in) :: value
      call self%put_int64s(name, [value])
   end subroutine put_int64

   !> Logicals as 0/1 integers.
   subroutine put_logicals(self, name, values)
      class(state_record), intent(inout) :: self
      character(len=*), intent(in) :: name
      logical, intent(in) :: values(:)
      call self%put_int64s(name, merge(1_int64, 0_int64, values))
   end subroutine put_logicals

   !> Index of the item `name`, 0 when absent.
   pure integer function find(self, name)
      class(state_record), intent(in) :: self
      character(len=*), intent(in) :: name
      integer :: k
      find = 0
      do k = 1, self%count
         if (self%items(k)%name == name) then
            find = k
            return
         end if
      end do
   end function find

   !> The real item `name`, which must hold size(values) values.
   subroutine get_reals(self, name, values, stat, errmsg)
      class(state_record), intent(in) :: self
      character(len=*), intent(in) :: name
      real(dp), intent(out) :: values(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: k
      call locate(self, name, .false., size(values), k, stat, errmsg)
      if (stat == 0) values = self%items(k)%reals
   end subroutine get_reals

   subroutine get_real(self, name, value, stat, errmsg)
      class(state_record), intent(in) :: self
      character(len=*), intent(in) :: name
      real(dp), intent(out) :: value
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: values(1)
      call self%get_reals(name, values, stat, errmsg)
      value = values(1)
   end subroutine get_real

   subroutine get_int64s(self, name, values, stat, errmsg)
      class(state_record), intent(in) :: self
      character(len=*), intent(in) :: name
      integer(int64), intent(out) :: values(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: k
      call locate(self, name, .true., size(values), k, stat, errmsg)
      if (stat == 0) values = self%items(k)%int64s
   end subroutine get_int64s

   subroutine get_int64(self, name, value, stat, errmsg)
      class(state_record), intent(in) :: self
      character(len=*), intent(in) :: name
      integer(int64), intent(out) :: value
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(int64) :: values(1)
      call self%get_int64s(name, values, stat, errmsg)
      value = values(1)
   end subroutine get_int64

   subroutine get_logicals(self, name, values, stat, errmsg)
      class(state_record), intent(in) :: self
      character(len=*), intent(in) :: name
      logical, intent(out) :: values(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(int64) :: numbers(size(values))
      call self%get_int64s(name, numbers, stat, errmsg)
      values = numbers /= 0
   end subroutine get_logicals

   !> Find `name` and check its type and size.
   subroutine locate(self, name, integers, expected, k, stat, errmsg)
      type(state_record), intent(in) :: self
      character(len=*), intent(in) :: name
      logical, intent(in) :: integers
      integer, intent(in) :: expected
      integer, intent(out) :: k, stat
      character(len=*), intent(out) :: errmsg
      integer :: found
      stat = 0
      errmsg = ''
      k = self%find(name)
      if (k == 0) then
         stat = stat_failure
         errmsg = 'the checkpoint has no ''' // trim(name) // ''''
         return
      end if
      if (self%items(k)%integers .neqv. integers) then
         stat = stat_failure
         errmsg = 'the checkpoint''s ''' // trim(name) // ''' has the wrong type'
         return
      end if
      if (integers) then
         found = size(self%items(k)%int64s)
      else
         found = size(self%items(k)%reals)
      end if
      if (found /= expected) then
         stat = stat_failure
         errmsg = 'the checkpoint''s ''' // trim(name) // ''' holds ' // integer_text(found) // &
                  ' values, expected ' // integer_text(expected)
      end if
   end subroutine locate
end module vibrobeam_state_record
