! libdbs from Fortran (the module dbs, fortran/dbs.f90): a height-field cloud and a square
! boundary built in arrays, options with a progress callback, the parameterization, its patches
! (indices from 0, as in the C API), and surface evaluations one at a time and many at once.
!
! usage: dbs_fortran_example [RESULT.csv]   (writes the result when a path is given)
module example_progress
  use, intrinsic :: iso_c_binding
  implicit none

  type, bind(C) :: progress_record
    integer(c_int) :: calls = 0
    real(c_double) :: last_fraction = -1.0_c_double
  end type

contains

  !> Progress callback (dbs_progress_fn): records the calls; returning 0 goes on.
  function record_progress(fraction, stage, payload) result(cancel) bind(C)
    real(c_double), value :: fraction
    type(c_ptr), value :: stage
    type(c_ptr), value :: payload
    integer(c_int) :: cancel
    type(progress_record), pointer :: record
    call c_f_pointer(payload, record)
    if (c_associated(stage)) record%calls = record%calls + 1
    record%last_fraction = fraction
    cancel = 0
  end function

end module example_progress

program example
  use, intrinsic :: iso_c_binding
  use dbs
  use example_progress
  implicit none

  integer, parameter :: side_points = 50
  real(c_double), parameter :: pi = 3.14159265358979323846_c_double
  real(c_double), parameter :: bottom(6) = [0d0, 0d0, 0d0, 1d0, 0d0, 0d0]
  real(c_double), parameter :: right(6) = [1d0, 0d0, 0d0, 1d0, 1d0, 0d0]
  real(c_double), parameter :: top(6) = [0d0, 1d0, 0d0, 1d0, 1d0, 0d0]
  real(c_double), parameter :: left(6) = [0d0, 0d0, 0d0, 0d0, 1d0, 0d0]

  type(c_ptr) :: cloud = c_null_ptr, boundary = c_null_ptr, options = c_null_ptr
  type(c_ptr) :: result = c_null_ptr, patches = c_null_ptr
  type(progress_record), target :: progress
  real(c_double), allocatable :: xyz(:), uv(:), distances(:)
  real(c_double) :: x, y, mean, max_distance, accuracy, met, rect(4), point(3)
  real(c_double), target :: normal(3)
  real(c_double) :: points(3, 5), normals(3, 5), su(3, 5), sv(3, 5)
  integer(c_size_t) :: count, i, n_patches, patch_points
  integer(c_int32_t) :: level, is_leaf, nu, nv, iterations
  character(len=512) :: result_path

  count = int(side_points, c_size_t)**2
  allocate(xyz(3 * count), uv(2 * count), distances(count))
  do i = 0, count - 1
    x = (real(mod(i, int(side_points, c_size_t)), c_double) + 0.5d0 + 0.3d0 * sin(7d0 * i)) / side_points
    y = (real(i / side_points, c_double) + 0.5d0 + 0.3d0 * cos(5d0 * i)) / side_points
    xyz(3 * i + 1) = x
    xyz(3 * i + 2) = y
    xyz(3 * i + 3) = 0.2d0 * sin(pi * x) * sin(pi * y)
  end do

  print '(a, a)', 'libdbs ', dbs_f_string(dbs_version_string())
  if (dbs_version_number() /= DBS_VERSION_MAJOR * 10000 + DBS_VERSION_MINOR * 100 + DBS_VERSION_PATCH) &
    error stop 'the loaded libdbs is not the version these bindings describe'

  call check(dbs_cloud_create(xyz, count, cloud), 'dbs_cloud_create')
  call check(dbs_boundary_create(bottom, 2_c_size_t, right, 2_c_size_t, top, 2_c_size_t, left, 2_c_size_t, boundary), &
             'dbs_boundary_create')

  call check(dbs_options_create(options), 'dbs_options_create')
  call check(dbs_options_set_int(options, DBS_OPT_MAX_LEVEL, 2_c_int32_t), 'dbs_options_set_int')
  call check(dbs_options_set_double(options, DBS_OPT_RELATIVE_ACCURACY, 1d-3), 'dbs_options_set_double')
  ! A value out of range is refused with a status and a message naming the option.
  if (dbs_options_set_int(options, DBS_OPT_MAX_LEVEL, 99_c_int32_t) /= DBS_ERR_OUT_OF_RANGE) &
    error stop 'max level 99 was not refused'
  print '(a, a)', 'refused as expected: ', dbs_error_text()
  call check(dbs_options_set_progress(options, c_funloc(record_progress), c_loc(progress)), 'dbs_options_set_progress')

  call check(dbs_parameterize(cloud, boundary, options, result), 'dbs_parameterize')
  if (progress%calls < 1 .or. progress%last_fraction < 1d0 .or. progress%last_fraction > 1d0) &
    error stop 'progress did not end at exactly 1.0'

  call check(dbs_result_uv(result, uv, count), 'dbs_result_uv')
  call check(dbs_result_distances(result, distances, count), 'dbs_result_distances')
  if (any(uv < 0d0) .or. any(uv > 1d0)) error stop 'a parameter lies outside [0,1]'
  call check(dbs_result_stat(result, DBS_STAT_MEAN_DISTANCE, mean), 'dbs_result_stat')
  call check(dbs_result_stat(result, DBS_STAT_MAX_DISTANCE, max_distance), 'dbs_result_stat')
  call check(dbs_result_stat(result, DBS_STAT_ACCURACY, accuracy), 'dbs_result_stat')
  call check(dbs_result_stat(result, DBS_STAT_ACCURACY_MET, met), 'dbs_result_stat')
  print '(i0, a, es10.3, a, es10.3, a, es10.3, a, l1, a)', count, ' points: mean distance', mean, &
    ', max', max_distance, ', target', accuracy, ' (met: ', met > 0.5d0, ')'
  print '(a, i0, a)', 'progress reported ', progress%calls, ' times, ending at 1.0'
  print '(a)', '      x        y        u        v'
  do i = 1, count, count / 5
    print '(4f9.4)', xyz(3 * i - 2), xyz(3 * i - 1), uv(2 * i - 1), uv(2 * i)
  end do

  call check(dbs_result_patches(result, patches), 'dbs_result_patches')
  call check(dbs_patches_count(patches, n_patches), 'dbs_patches_count')
  print '(a)', 'patch level leaf  u0     v0     u1     v1    grid    points  mean distance'
  do i = 0, n_patches - 1
    call check(dbs_patches_level(patches, i, level), 'dbs_patches_level')
    call check(dbs_patches_is_leaf(patches, i, is_leaf), 'dbs_patches_is_leaf')
    call check(dbs_patches_rect(patches, i, rect), 'dbs_patches_rect')
    call check(dbs_patches_grid_size(patches, i, nu, nv), 'dbs_patches_grid_size')
    call check(dbs_patches_stats(patches, i, patch_points, mean, max_distance, iterations), 'dbs_patches_stats')
    print '(i5, i6, i5, 4f7.3, i4, a, i0, i9, es14.3)', i, level, is_leaf, rect, nu, 'x', nv, patch_points, mean
  end do

  ! A nullable output of the C API takes c_loc(x) or c_null_ptr; the module's wrappers take
  ! OPTIONAL arguments instead.
  call check(dbs_result_evaluate(result, 0.5d0, 0.5d0, point, c_loc(normal)), 'dbs_result_evaluate')
  print '(a, 3f9.5, a, 3f9.5)', 'S(0.5,0.5) =', point, '  normal', normal
  if (abs(norm2(normal) - 1d0) > 1d-9) error stop 'the normal at (0.5,0.5) is no unit vector'
  call check(dbs_result_evaluate(result, 0.25d0, 0.75d0, point, c_null_ptr), 'dbs_result_evaluate without a normal')
  print '(a, 3f9.5)', 'S(0.25,0.75) =', point

  ! The first five points' own (u,v), at once, with normals and derivatives: each matches the
  ! evaluation of its pair alone, and the normal is at right angles to both derivatives.
  call check(dbs_result_evaluate_points(result, reshape(uv(1:10), [2, 5]), points, normals, su, sv), &
             'dbs_result_evaluate_points')
  do i = 1, 5
    call check(dbs_result_evaluate_point(result, uv(2 * i - 1), uv(2 * i), point, normal), 'dbs_result_evaluate_point')
    if (any(abs(points(:, i) - point) > 1d-12) .or. any(abs(normals(:, i) - normal) > 1d-12)) &
      error stop 'dbs_result_evaluate_points differs from dbs_result_evaluate_point'
    if (abs(dot_product(normal, su(:, i))) > 1d-9 * norm2(su(:, i)) .or. &
        abs(dot_product(normal, sv(:, i))) > 1d-9 * norm2(sv(:, i))) error stop 'a normal is not normal to dS/du, dS/dv'
  end do
  if (dbs_result_evaluate_points(result, reshape(uv(1:10), [2, 5]), points(:, 1:4)) /= DBS_ERR_INVALID_ARGUMENT) &
    error stop 'dbs_result_evaluate_points took 4 columns for 5 pairs'
  print '(a)', 'dbs_result_evaluate_points: 5 points, normals and derivatives as one at a time'

  if (command_argument_count() >= 1) then
    call get_command_argument(1, result_path)
    call check(dbs_result_save(result, cloud, dbs_c_string(result_path)), 'dbs_result_save')
    print '(a, a)', 'wrote ', trim(result_path)
  end if

  call dbs_result_destroy(result)
  call dbs_options_destroy(options)
  call dbs_boundary_destroy(boundary)
  call dbs_cloud_destroy(cloud)
  deallocate(xyz, uv, distances)

contains

  subroutine check(status, what)
    integer(c_int), intent(in) :: status
    character(len=*), intent(in) :: what
    if (status /= DBS_OK) then
      write (0, '(a, a, a, a, a, a)') 'dbs_fortran_example: ', what, ' failed: ', dbs_error_text(), ' (', &
        dbs_f_string(dbs_status_string(status)) // ')'
      error stop 1
    end if
  end subroutine

end program example
