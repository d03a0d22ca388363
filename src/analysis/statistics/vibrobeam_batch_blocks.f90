!> Accumulators over a statistics window split into equal blocks for batch means
!! (docs/statistics.md, "Sub-windows and standard errors"), with memory that does not
!! grow with the window.
!!
!! The window's samples (one per time step, offsets j = 0, 1, 2, ...) are grouped into
!! blocks of L samples, L a power of two: block b holds the offsets bL .. (b+1)L - 1. L
!! starts at 1; when `max_blocks` = 16 blocks are complete, neighbours are merged
!! pairwise into 8 blocks of 2L. At any time, L is therefore the largest power of two
!! such that the samples so far fill at least `min_blocks` = 8 blocks (or 1 before
!! there are 16 samples), and there are between 8 and 15 complete blocks plus one
!! partial block of fewer than L samples. This depends only on the number of samples, not
!! on where the window will end: a run continued from a checkpoint reaches exactly the
!! state of the uninterrupted run (the sums are merged in the same order).
!!
!! Three kinds of quantity, each indexed by the caller:
!! - sums: values added into a block (`add`), e.g. u, u^2, a count of impacts;
!! - extremes: the smallest and largest value seen in a block (`extreme`);
!! - levels: running values (energy sums) recorded at the start of every block and read
!!   at the end (`level_change`), so a block's change is level(end) - level(start).
!! A value may be added to an earlier block than the current one (`block_of(offset)`):
!! a contact episode is counted in the block where it opened, when it closes.
module vibrobeam_batch_blocks
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_state_record, only: state_record
   implicit none
   private
   public :: block_accumulator, min_blocks, max_blocks, block_length_of, standard_error

   integer, parameter :: min_blocks = 8    !! complete blocks at least (once 8 samples exist)
   integer, parameter :: max_blocks = 16   !! complete blocks that trigger a merge

   type :: block_accumulator
      integer(int64) :: block_steps = 1      !! L
      integer :: complete = 0                !! complete blocks (0..max_blocks-1)
      integer(int64) :: samples = 0          !! samples so far
      !> (quantities, 0:max_blocks): blocks 0..complete-1 complete, block `complete` partial
      real(dp), allocatable :: sums(:, :), lows(:, :), highs(:, :)
      real(dp), allocatable :: levels(:, :)  !! (level quantities, 0:max_blocks) at each block's start
   contains
      procedure :: init
      procedure :: add
      procedure :: extreme
      procedure :: block_of
      procedure :: close_sample
      procedure :: completes_block
      procedure :: total
      procedure :: lowest
      procedure :: highest
      procedure :: save_state
      procedure :: restore_state
   end type block_accumulator

contains

   !> The block length L of a window of `samples` samples: the largest power of two with
   !! floor(samples/L) >= min_blocks (1 when samples < 2 min_blocks).
   pure function block_length_of(samples) result(length)
      integer(int64), intent(in) :: samples
      integer(int64) :: length
      length = 1
      do while (samples/(2*length) >= min_blocks)
         length = 2*length
      end do
   end function block_length_of

   !> sqrt(sum_b (x_b - mean)^2 / (c (c - 1))): the standard error of the mean of c batch
   !! values x_b (0 when c < 2).
   pure function standard_error(batch_values) result(error)
      real(dp), intent(in) :: batch_values(:)
      real(dp) :: error, mean
      integer :: c
      c = size(batch_values)
      error = 0
      if (c < 2) return
      mean = sum(batch_values)/c
      error = sqrt(sum((batch_values - mean)**2)/(real(c, dp)*(c - 1)))
   end function standard_error

   !> Start empty with room for `sums`, `extremes` and `levels` quantities; `start_levels`
   !! are the levels at the window's start.
   subroutine init(self, sums, extremes, start_levels)
      class(block_accumulator), intent(inout) :: self
      integer, intent(in) :: sums, extremes
      real(dp), intent(in) :: start_levels(:)
      self%block_steps = 1
      self%complete = 0
      self%samples = 0
      if (allocated(self%sums)) deallocate (self%sums, self%lows, self%highs, self%levels)
      allocate (self%sums(sums, 0:max_blocks), source=0.0_dp)
      allocate (self%lows(extremes, 0:max_blocks), source=huge(1.0_dp))
      allocate (self%highs(extremes, 0:max_blocks), source=-huge(1.0_dp))
      allocate (self%levels(size(start_levels), 0:max_blocks), source=0.0_dp)
      self%levels(:, 0) = start_levels
   end subroutine init

   !> Block of the sample at `offset` (0-based, < samples + 1): offset/L.
   pure integer function block_of(self, offset)
      class(block_accumulator), intent(in) :: self
      integer(int64), intent(in) :: offset
      block_of = int(offset/self%block_steps)
   end function block_of

   !> Add `value` to sum quantity `q` of `block` (default: the current, partial block).
   subroutine add(self, q, value, block)
      class(block_accumulator), intent(inout) :: self
      integer, intent(in) :: q
      real(dp), intent(in) :: value
      integer, intent(in), optional :: block
      integer :: b
      b = chosen_block(self, block)
      self%sums(q, b) = self%sums(q, b) + value
   end subroutine add

   !> `block` when given, else the current (partial) block.
   pure integer function chosen_block(self, block)
      type(block_accumulator), intent(in) :: self
      integer, intent(in), optional :: block
      chosen_block = self%complete
      if (present(block)) chosen_block = block
   end function chosen_block

   !> Let extreme quantity `q` of `block` (default: the current one) see `value`.
   subroutine extreme(self, q, value, block)
      class(block_accumulator), intent(inout) :: self
      integer, intent(in) :: q
      real(dp), intent(in) :: value
      integer, intent(in), optional :: block
      integer :: b
      b = chosen_block(self, block)
      self%lows(q, b) = min(self%lows(q, b), value)
      self%highs(q, b) = max(self%highs(q, b), value)
   end subroutine extreme

   !> True when closing the current sample completes its block (the caller then gives
   !! the levels to `close_sample`).
   pure logical function completes_block(self)
      class(block_accumulator), intent(in) :: self
      completes_block = self%samples + 1 - self%complete*self%block_steps >= self%block_steps
   end function completes_block

   !> The current sample is complete; `levels_now` are the levels after it, needed only
   !! when it `completes_block`. Completes the partial block when it holds L samples (its
   !! end levels start the next one) and merges pairs of blocks when `max_blocks` are
   !! complete.
   subroutine close_sample(self, levels_now)
      class(block_accumulator), intent(inout) :: self
      real(dp), intent(in), optional :: levels_now(:)
      integer :: b
      self%samples = self%samples + 1
      if (self%samples - self%complete*self%block_steps < self%block_steps) return
      self%complete = self%complete + 1
      if (present(levels_now)) self%levels(:, self%complete) = levels_now
      if (self%complete < max_blocks) return
      do b = 0, max_blocks/2 - 1
         self%sums(:, b) = self%sums(:, 2*b) + self%sums(:, 2*b + 1)
         self%lows(:, b) = min(self%lows(:, 2*b), self%lows(:, 2*b + 1))
         self%highs(:, b) = max(self%highs(:, 2*b), self%highs(:, 2*b + 1))
         self%levels(:, b) = self%levels(:, 2*b)
      end do
      ! the new partial block (empty) starts where block max_blocks - 1 ended
      self%levels(:, max_blocks/2) = self%levels(:, max_blocks)
      self%sums(:, max_blocks/2:) = 0
      self%lows(:, max_blocks/2:) = huge(1.0_dp)
      self%highs(:, max_blocks/2:) = -huge(1.0_dp)
      self%levels(:, max_blocks/2 + 1:) = 0
      self%complete = max_blocks/2
      self%block_steps = 2*self%block_steps
   end subroutine close_sample

   !> Sum quantity `q` over the whole window (every block, the partial one included), the
   !! blocks added in order.
   pure real(dp) function total(self, q)
      class(block_accumulator), intent(in) :: self
      integer, intent(in) :: q
      integer :: b
      total = 0
      do b = 0, self%complete
         total = total + self%sums(q, b)
      end do
   end function total

   pure real(dp) function lowest(self, q)
      class(block_accumulator), intent(in) :: self
      integer, intent(in) :: q
      lowest = minval(self%lows(q, 0:self%complete))
   end function lowest

   pure real(dp) function highest(self, q)
      class(block_accumulator), intent(in) :: self
      integer, intent(in) :: q
      highest = maxval(self%highs(q, 0:self%complete))
   end function highest

   !> Put the state into `record` under names starting with `prefix`.
   subroutine save_state(self, record, prefix)
      class(block_accumulator), intent(in) :: self
      type(state_record), intent(inout) :: record
      character(len=*), intent(in) :: prefix
      call record%put_int64s(prefix//'.counts', [self%block_steps, int(self%complete, int64), self%samples])
      call record%put_reals(prefix//'.sums', reshape(self%sums, [size(self%sums)]))
      call record%put_reals(prefix//'.lows', reshape(self%lows, [size(self%lows)]))
      call record%put_reals(prefix//'.highs', reshape(self%highs, [size(self%highs)]))
      call record%put_reals(prefix//'.levels', reshape(self%levels, [size(self%levels)]))
   end subroutine save_state

   !> Take back what `save_state` put (the accumulator is `init`ed with the same sizes).
   subroutine restore_state(self, record, prefix, stat, errmsg)
      class(block_accumulator), intent(inout) :: self
      type(state_record), intent(in) :: record
      character(len=*), intent(in) :: prefix
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(int64) :: counts(3)
      real(dp), allocatable :: flat(:)
      call record%get_int64s(prefix//'.counts', counts, stat, errmsg)
      if (stat /= 0) return
      self%block_steps = counts(1)
      self%complete = int(counts(2))
      self%samples = counts(3)
      call take(prefix//'.sums', self%sums)
      if (stat == 0) call take(prefix//'.lows', self%lows)
      if (stat == 0) call take(prefix//'.highs', self%highs)
      if (stat == 0) call take(prefix//'.levels', self%levels)
   contains
      subroutine take(name, values)
         character(len=*), intent(in) :: name
         real(dp), intent(inout) :: values(:, 0:)
         allocate (flat(size(values)))
         call record%get_reals(name, flat, stat, errmsg)
         if (stat == 0) values = reshape(flat, shape(values))
         deallocate (flat)
      end subroutine take
   end subroutine restore_state
end module vibrobeam_batch_blocks
