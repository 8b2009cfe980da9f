! The Fortran 2008 module of libdbs: `use dbs`.
!
! dbs_capi.inc (generated from dbs.h by scripts/generate_bindings.py) declares every constant and
! one bind(C) interface per function of dbs.h: statuses are integer(c_int), ids integer(c_int32_t),
! counts integer(c_size_t), values real(c_double), handles type(c_ptr) (`value` when passed in,
! intent(out) when the function creates one), points flat arrays x0 y0 z0 x1 ... Indices (points,
! patches, sides, holes, pairs) start at 0 as in the C API. Arguments the C API allows to be NULL
! are type(c_ptr): c_loc(x) or c_null_ptr.
!
! Written here: strings both ways (dbs_c_string, dbs_f_string, dbs_error_text) and evaluations
! with OPTIONAL outputs (dbs_result_evaluate_point, dbs_result_evaluate_points).
module dbs
  use, intrinsic :: iso_c_binding
  implicit none

  include 'dbs_capi.inc'

contains

  !> A Fortran string as a NUL-terminated C string (trailing blanks dropped), for paths.
  function dbs_c_string(text) result(c_text)
    character(len=*), intent(in) :: text
    character(kind=c_char, len=len_trim(text) + 1) :: c_text
    c_text = trim(text) // c_null_char
  end function dbs_c_string

  !> Copies a C string (dbs_version_string, dbs_status_string, dbs_last_error_message, the
  !> stage of a progress callback, a warning) into a Fortran string; "" for c_null_ptr.
  function dbs_f_string(c_text) result(text)
    type(c_ptr), intent(in) :: c_text
    character(len=:), allocatable :: text
    character(kind=c_char), pointer :: chars(:)
    integer(c_size_t) :: n, i
    interface
      function c_strlen(s) bind(C, name="strlen")
        import :: c_ptr, c_size_t
        type(c_ptr), value :: s
        integer(c_size_t) :: c_strlen
      end function c_strlen
    end interface
    if (.not. c_associated(c_text)) then
      text = ""
      return
    end if
    n = c_strlen(c_text)
    call c_f_pointer(c_text, chars, [n])
    allocate(character(len=n) :: text)
    do i = 1, n
      text(i:i) = chars(i)
    end do
  end function dbs_f_string

  !> The message of the last failed call on this thread.
  function dbs_error_text() result(text)
    character(len=:), allocatable :: text
    text = dbs_f_string(dbs_last_error_message())
  end function dbs_error_text

  !> dbs_result_evaluate with the normal optional: the point S(u,v) into xyz and, when present,
  !> the unit normal into normal. Returns the C status.
  function dbs_result_evaluate_point(result, u, v, xyz, normal) result(status)
    type(c_ptr), intent(in) :: result
    real(c_double), intent(in) :: u, v
    real(c_double), intent(out) :: xyz(3)
    real(c_double), intent(out), optional, target :: normal(3)
    integer(c_int) :: status
    if (present(normal)) then
      status = dbs_result_evaluate(result, u, v, xyz, c_loc(normal))
    else
      status = dbs_result_evaluate(result, u, v, xyz, c_null_ptr)
    end if
  end function dbs_result_evaluate_point

  !> dbs_result_evaluate_many over the columns of uv(2, n): the points into xyz(3, n) and, when
  !> present, the unit normals and the derivatives dS/du, dS/dv into normal, su, sv (3, n each).
  !> Arrays of other shapes are refused here, before the C call, with DBS_ERR_INVALID_ARGUMENT
  !> (dbs_error_text then tells nothing about it) and nothing written.
  function dbs_result_evaluate_points(result, uv, xyz, normal, su, sv) result(status)
    type(c_ptr), intent(in) :: result
    real(c_double), intent(in) :: uv(:, :)
    real(c_double), intent(out), contiguous :: xyz(:, :)
    real(c_double), intent(out), optional, contiguous, target :: normal(:, :), su(:, :), sv(:, :)
    integer(c_int) :: status
    type(c_ptr) :: normal_address, su_address, sv_address
    integer(c_size_t) :: n
    n = size(uv, 2, c_size_t)
    normal_address = c_null_ptr
    su_address = c_null_ptr
    sv_address = c_null_ptr
    status = DBS_ERR_INVALID_ARGUMENT
    if (size(uv, 1) /= 2 .or. .not. fits(xyz)) return
    if (present(normal)) then
      if (.not. fits(normal)) return
      if (n > 0) normal_address = c_loc(normal)
    end if
    if (present(su)) then
      if (.not. fits(su)) return
      if (n > 0) su_address = c_loc(su)
    end if
    if (present(sv)) then
      if (.not. fits(sv)) return
      if (n > 0) sv_address = c_loc(sv)
    end if
    status = dbs_result_evaluate_many(result, uv, n, xyz, normal_address, su_address, sv_address)
  contains
    logical function fits(values)
      real(c_double), intent(in) :: values(:, :)
      fits = size(values, 1) == 3 .and. size(values, 2, c_size_t) == n
    end function fits
  end function dbs_result_evaluate_points

end module dbs
