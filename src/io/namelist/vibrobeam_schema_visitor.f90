!> Every input variable declared once (CONTRIBUTING.md, "Adding an input variable").
!!
!! A settings type (the &beam group's `beam_settings`, the &time group's `time_settings`,
!! ...) lives in the package that uses it and has one `visit` routine that names each of
!! its variables once, with everything known about it:
!!
!!     call visitor%variable(real_row('beam', 'length', 'm', 1e-9_dp, 1e6_dp, &
!!                                    'length L of the beam'), settings%length)
!!
!! and the component's initial value in the type is the variable's default. Everything
!! done with "every variable" is a visitor walking those calls (`vibrobeam_schema_operations`):
!! the table the file scanner checks a file against, reading the values a file gives,
!! checking each value against its range or choices, listing the resolved input (`--check`,
!! the HDF5 attributes), getting or setting a real by its name (sweeps), and the list of
!! variables `docs/input.md` must document. Only the rules between variables are written
!! by hand, beside the settings they relate.
!!
!! This is the visitor pattern of serialization libraries ("ar & field"), chosen because
!! Fortran has no reflection: a visitor receives the row describing a variable together
!! with the variable itself (intent(inout)), so one declaration serves reading, checking,
!! listing and access without copies of the variable list.
module vibrobeam_schema_visitor
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use vibrobeam_kinds, only: dp
   use vibrobeam_namelist_schema, only: namelist_variable, kind_real, kind_integer, kind_logical, kind_string
   implicit none
   private
   public :: schema_visitor, real_row, integer_row, keyword_row, text_row, logical_row
   public :: unset, is_unset, unset_integer, keyword_length, path_length

   integer, parameter :: keyword_length = 16      !! longest keyword ('hermite', 'dynamics', ...)
   integer, parameter :: path_length = 4096       !! longest file name (&output file, &initial from_file)

   !> Marks a real the user did not give where the default is computed from other inputs
   !! (a row with `optional`): `is_unset` tells it from every given value.
   real(dp), parameter :: unset = -huge(1.0_dp)
   !> The same for an integer variable whose range is non-negative.
   integer, parameter :: unset_integer = -1

   !> Walks the variables of a settings type: `variable` is called once per variable with
   !! its row and the variable itself (a scalar, or the elements of an array variable).
   type, abstract :: schema_visitor
   contains
      procedure(visit_interface), deferred :: visit
      procedure, private, non_overridable :: visit_real, visit_reals, visit_integer, visit_text, visit_texts, &
                                             visit_logical
      generic :: variable => visit_real, visit_reals, visit_integer, visit_text, visit_texts, visit_logical
   end type schema_visitor

   abstract interface
      !> One variable: `row` describes it; exactly one of the value arguments is present,
      !! the one of its kind (reals and keyword/text strings may be arrays: the elements
      !! 1..size of an array variable).
      subroutine visit_interface(self, row, real_value, real_values, integer_value, text_value, text_values, &
                                 logical_value)
         import :: schema_visitor, namelist_variable, dp
         class(schema_visitor), intent(inout) :: self
         type(namelist_variable), intent(in) :: row
         real(dp), intent(inout), optional :: real_value, real_values(:)
         integer, intent(inout), optional :: integer_value
         character(len=*), intent(inout), optional :: text_value, text_values(:)
         logical, intent(inout), optional :: logical_value
      end subroutine visit_interface
   end interface

contains

   subroutine visit_real(self, row, value)
      class(schema_visitor), intent(inout) :: self
      type(namelist_variable), intent(in) :: row
      real(dp), intent(inout) :: value
      call self%visit(row, real_value=value)
   end subroutine visit_real

   subroutine visit_reals(self, row, values)
      class(schema_visitor), intent(inout) :: self
      type(namelist_variable), intent(in) :: row
      real(dp), intent(inout) :: values(:)
      call self%visit(row, real_values=values)
   end subroutine visit_reals

   subroutine visit_integer(self, row, value)
      class(schema_visitor), intent(inout) :: self
      type(namelist_variable), intent(in) :: row
      integer, intent(inout) :: value
      call self%visit(row, integer_value=value)
   end subroutine visit_integer

   subroutine visit_text(self, row, value)
      class(schema_visitor), intent(inout) :: self
      type(namelist_variable), intent(in) :: row
      character(len=*), intent(inout) :: value
      call self%visit(row, text_value=value)
   end subroutine visit_text

   subroutine visit_texts(self, row, values)
      class(schema_visitor), intent(inout) :: self
      type(namelist_variable), intent(in) :: row
      character(len=*), intent(inout) :: values(:)
      call self%visit(row, text_values=values)
   end subroutine visit_texts

   subroutine visit_logical(self, row, value)
      class(schema_visitor), intent(inout) :: self
      type(namelist_variable), intent(in) :: row
      logical, intent(inout) :: value
      call self%visit(row, logical_value=value)
   end subroutine visit_logical

   !> True when `value` is the `unset` marker (a NaN or -Inf is a given value, not unset).
   !! Uses no comparison on a NaN, which traps under -ffpe-trap=invalid.
   elemental logical function is_unset(value)
      real(dp), intent(in) :: value
      if (ieee_is_finite(value)) then
         is_unset = value <= unset   ! finite and <= -huge: the marker itself; -Inf is not unset
      else
         is_unset = .false.
      end if
   end function is_unset

   !> A real variable: hard range [lowest, highest] in `unit` ('' dimensionless); `extent`
   !! > 0 for an array of that many elements; `element`: the element handed over (an array
   !! of settings, 0: none, the row only describes); `optional`: the `unset` marker stands
   !! for a default computed from other inputs (not checked, not listed; for an array, each
   !! element left unset).
   pure function real_row(group, name, unit, lowest, highest, meaning, extent, element, optional) result(row)
      character(len=*), intent(in) :: group, name, unit, meaning
      real(dp), intent(in) :: lowest, highest
      integer, intent(in), optional :: extent, element
      logical, intent(in), optional :: optional
      type(namelist_variable) :: row
      row = namelist_variable(group=group, name=name, kind=kind_real, lowest=lowest, highest=highest, unit=unit, &
                              meaning=meaning)
      if (present(extent)) row%extent = extent
      if (present(element)) row%element = element
      if (present(optional)) row%optional = optional
   end function real_row

   !> An integer variable with hard range [lowest, highest]; `optional`: `unset_integer`
   !! stands for a default computed from other inputs; `extent` and `element` as for
   !! `real_row` (an integer of an array of settings, handed over one element at a time).
   pure function integer_row(group, name, lowest, highest, meaning, optional, extent, element) result(row)
      character(len=*), intent(in) :: group, name, meaning
      integer, intent(in) :: lowest, highest
      logical, intent(in), optional :: optional
      integer, intent(in), optional :: extent, element
      type(namelist_variable) :: row
      row = namelist_variable(group=group, name=name, kind=kind_integer, lowest_integer=lowest, &
                              highest_integer=highest, meaning=meaning)
      if (present(optional)) row%optional = optional
      if (present(extent)) row%extent = extent
      if (present(element)) row%element = element
   end function integer_row

   !> A keyword: one of `choices` ('a|b|c'), at most `max_length` characters, read in lower
   !! case; `extent` and `element` as for `real_row`; `optional`: '' stands for a default
   !! the reader or the user of the value resolves (not checked, not listed).
   pure function keyword_row(group, name, choices, max_length, meaning, extent, element, optional) result(row)
      character(len=*), intent(in) :: group, name, choices, meaning
      integer, intent(in) :: max_length
      integer, intent(in), optional :: extent, element
      logical, intent(in), optional :: optional
      type(namelist_variable) :: row
      row = namelist_variable(group=group, name=name, kind=kind_string, max_length=max_length, choices=choices, &
                              meaning=meaning)
      if (present(extent)) row%extent = extent
      if (present(element)) row%element = element
      if (present(optional)) row%optional = optional
   end function keyword_row

   !> Free text (a file name, a parameter name) of at most `max_length` characters, read as
   !! written; `extent` and `element` as for `real_row`.
   pure function text_row(group, name, max_length, meaning, extent, element) result(row)
      character(len=*), intent(in) :: group, name, meaning
      integer, intent(in) :: max_length
      integer, intent(in), optional :: extent, element
      type(namelist_variable) :: row
      row = namelist_variable(group=group, name=name, kind=kind_string, max_length=max_length, meaning=meaning)
      if (present(extent)) row%extent = extent
      if (present(element)) row%element = element
   end function text_row

   !> A logical (.true. or .false.); `optional`: .false. stands for "not asked for" and is
   !! not listed (a switch added later, so that results without it keep their attributes).
   pure function logical_row(group, name, meaning, optional) result(row)
      character(len=*), intent(in) :: group, name, meaning
      logical, intent(in), optional :: optional
      type(namelist_variable) :: row
      row = namelist_variable(group=group, name=name, kind=kind_logical, meaning=meaning)
      if (present(optional)) row%optional = optional
   end function logical_row
end module vibrobeam_schema_visitor
