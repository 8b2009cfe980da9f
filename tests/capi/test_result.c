/* dbs_parameterize, dbs_result_* and dbs_patches_*: a planar cloud whose parameterization is
 * known exactly, every getter, buffer checks, surface evaluation, saving. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "capi_support.h"

#define NX 21
#define NY 11
#define NPOINTS (NX * NY)
#define PER_SIDE 5

struct fixture {
  dbs_cloud *cloud;
  dbs_boundary *boundary;
  dbs_result *result;
};

static int setup(void **state) {
  static struct fixture f;
  f.cloud = plane_cloud(NX, NY);
  f.boundary = plane_boundary(PER_SIDE);
  f.result = parameterize_or_fail(f.cloud, f.boundary, NULL);
  *state = &f;
  return 0;
}

static int teardown(void **state) {
  struct fixture *f = *state;
  dbs_result_destroy(f->result);
  dbs_boundary_destroy(f->boundary);
  dbs_cloud_destroy(f->cloud);
  return 0;
}

static double result_stat(const dbs_result *result, int32_t id) {
  double value = NAN;
  assert_ok(dbs_result_stat(result, id, &value));
  return value;
}

static void uv_is_the_affine_map_of_xy(void **state) {
  struct fixture *f = *state;
  size_t count = 0;
  assert_ok(dbs_result_point_count(f->result, &count));
  assert_int_equal(count, NPOINTS);

  double *xyz = plane_points(NX, NY);
  double uv[2 * NPOINTS], distance[NPOINTS];
  assert_ok(dbs_result_uv(f->result, uv, NPOINTS));
  assert_ok(dbs_result_distances(f->result, distance, NPOINTS));
  double worst_uv = 0, worst_distance = 0;
  for (size_t i = 0; i < NPOINTS; ++i) {
    worst_uv = fmax(worst_uv, fabs(uv[2 * i] - xyz[3 * i] / PLANE_W));
    worst_uv = fmax(worst_uv, fabs(uv[2 * i + 1] - xyz[3 * i + 1] / PLANE_H));
    worst_distance = fmax(worst_distance, fabs(distance[i]));
  }
  free(xyz);
  assert_true(worst_uv < 1e-9);
  assert_true(worst_distance < 1e-9);
}

static void points_name_their_leaf(void **state) {
  struct fixture *f = *state;
  int32_t patch[NPOINTS], level[NPOINTS];
  assert_ok(dbs_result_point_patches(f->result, patch, NPOINTS));
  assert_ok(dbs_result_point_levels(f->result, level, NPOINTS));
  const dbs_patches *all = NULL;
  assert_ok(dbs_result_patches(f->result, &all));
  size_t patches = 0;
  assert_ok(dbs_patches_count(all, &patches));
  for (size_t i = 0; i < NPOINTS; ++i) {
    assert_true(patch[i] >= 0 && (size_t)patch[i] < patches);
    int32_t leaf = -1, patch_level = -1;
    assert_ok(dbs_patches_is_leaf(all, (size_t)patch[i], &leaf));
    assert_ok(dbs_patches_level(all, (size_t)patch[i], &patch_level));
    assert_int_equal(leaf, 1);
    assert_int_equal(level[i], patch_level);
  }
}

static void statistics(void **state) {
  struct fixture *f = *state;
  const double diagonal = sqrt(PLANE_W * PLANE_W + PLANE_H * PLANE_H);
  assert_true(result_stat(f->result, DBS_STAT_MEAN_DISTANCE) < 1e-9);
  assert_true(result_stat(f->result, DBS_STAT_MAX_DISTANCE) < 1e-9);
  assert_true(result_stat(f->result, DBS_STAT_RMS_DISTANCE) < 1e-9);
  assert_true(result_stat(f->result, DBS_STAT_MAX_DISTANCE) >= result_stat(f->result, DBS_STAT_RMS_DISTANCE));
  assert_true(result_stat(f->result, DBS_STAT_RMS_DISTANCE) >= result_stat(f->result, DBS_STAT_MEAN_DISTANCE));
  /* the default target: 1e-3 of the cloud's bounding-box diagonal */
  assert_true(fabs(result_stat(f->result, DBS_STAT_ACCURACY) - 1e-3 * diagonal) < 1e-15);
  assert_true(result_stat(f->result, DBS_STAT_ACCURACY_MET) == 1.0);
  /* a plane needs no subdivision */
  assert_true(result_stat(f->result, DBS_STAT_LEVELS) == 1.0);
  assert_true(result_stat(f->result, DBS_STAT_PATCHES) == 1.0);
  assert_true(result_stat(f->result, DBS_STAT_LEAVES) == 1.0);
  assert_true(result_stat(f->result, DBS_STAT_ITERATIONS) >= 1.0);
  assert_true(result_stat(f->result, DBS_STAT_SECONDS) >= 0.0);
  /* every point's nearest neighbour is 0.1 away (grid spacing along x and y) */
  assert_true(fabs(result_stat(f->result, DBS_STAT_LENGTH_SCALE) - 0.1) < 1e-12);
  {
    /* The stages are timed separately and make up the whole run. */
    const double stages = result_stat(f->result, DBS_STAT_SECONDS_INDEX) + result_stat(f->result, DBS_STAT_SECONDS_EVOLVE) + result_stat(f->result, DBS_STAT_SECONDS_SUBDIVIDE) + result_stat(f->result, DBS_STAT_SECONDS_PARAMETERIZE) + result_stat(f->result, DBS_STAT_SECONDS_FOLDS);
    assert_true(result_stat(f->result, DBS_STAT_SECONDS_FOLDS) > 0.0);
    assert_true(result_stat(f->result, DBS_STAT_SECONDS_EVOLVE) > 0.0);
    assert_true(result_stat(f->result, DBS_STAT_SECONDS_PARAMETERIZE) > 0.0);
    assert_true(stages <= result_stat(f->result, DBS_STAT_SECONDS));
  }

  /* A clean plane: no noise, so the floor leaves the requested target as it is; nothing folds,
   * no two points share a (u,v). */
  assert_true(result_stat(f->result, DBS_STAT_NOISE) < 1e-9);
  assert_true(result_stat(f->result, DBS_STAT_REQUESTED_ACCURACY) == result_stat(f->result, DBS_STAT_ACCURACY));
  assert_true(result_stat(f->result, DBS_STAT_REQUESTED_MET) == result_stat(f->result, DBS_STAT_ACCURACY_MET));
  assert_true(result_stat(f->result, DBS_STAT_FOLDED_SHARE) == 0.0);
  assert_true(result_stat(f->result, DBS_STAT_FOLDED_POINTS) == 0.0);
  assert_true(result_stat(f->result, DBS_STAT_COINCIDENT_POINTS) == 0.0);
  assert_true(result_stat(f->result, DBS_STAT_UNDECIDED_POINTS) <= 0.1 * NPOINTS);
  assert_true(result_stat(f->result, DBS_STAT_JUDGED_POINTS) == NPOINTS); /* a small cloud: every point */
  assert_true(result_stat(f->result, DBS_STAT_REPAIRED_POINTS) == 0);     /* on by default, but a smooth cloud the surface reaches needs none */
  {
    int32_t repaired[NPOINTS];
    assert_ok(dbs_result_repaired(f->result, repaired, NPOINTS));
    for (int i = 0; i < NPOINTS; ++i) assert_int_equal(repaired[i], 0);
    assert_failure(dbs_result_repaired(f->result, repaired, NPOINTS - 1), DBS_ERR_BUFFER_TOO_SMALL, "dbs_result_repaired", "out");
    assert_failure(dbs_result_repaired(NULL, repaired, NPOINTS), DBS_ERR_NULL_ARGUMENT, "dbs_result_repaired", "result");
    assert_failure(dbs_result_repaired(f->result, NULL, NPOINTS), DBS_ERR_NULL_ARGUMENT, "dbs_result_repaired", "out");
  }

  /* The default solver is the linear one: no Ceres iterations, no loss. */
  assert_true(result_stat(f->result, DBS_STAT_SOLVER) == DBS_SOLVER_LINEAR);
  assert_true(result_stat(f->result, DBS_STAT_CERES_ITERATIONS) == 0);
  assert_true(result_stat(f->result, DBS_STAT_LOSS_SCALE) == 0);
  /* a smooth fixture squeezes nothing */
  assert_true(result_stat(f->result, DBS_STAT_COLLAPSED_POINTS) == 0);

  /* The inputs fit each other: the boundary on the cloud's rim, the same size, the domain covered. */
  assert_true(result_stat(f->result, DBS_STAT_BOUNDARY_GAP) <= 2.0);
  assert_true(fabs(result_stat(f->result, DBS_STAT_SCALE_RATIO) - 1.0) < 1e-12);
  assert_true(result_stat(f->result, DBS_STAT_COVERAGE) == 1.0);
  assert_true(result_stat(f->result, DBS_STAT_CLAMPED_POINTS) == 0);
  assert_true(result_stat(f->result, DBS_STAT_FAR_POINTS) == 0);
  /* A smooth fixture's surface turns nowhere against its cloud. */
  assert_true(result_stat(f->result, DBS_STAT_TURNED_POINTS) == 0);
  assert_true(result_stat(f->result, DBS_STAT_TURNED_SHARE) == 0);
  /* The smoothing of turned sheets is off by default. */
  assert_true(result_stat(f->result, DBS_STAT_SMOOTHED_POINTS) == 0);
  /* Nothing pleated: one pass, not the coarse one. */
  assert_true(result_stat(f->result, DBS_STAT_PASSES) == 1);
  assert_true(result_stat(f->result, DBS_STAT_COARSE) == 0);

  double value = -7;
  assert_failure(dbs_result_stat(f->result, -1, &value), DBS_ERR_OUT_OF_RANGE, "dbs_result_stat", "stat -1 is outside its range [0, 40)");
  assert_failure(dbs_result_stat(f->result, 40, &value), DBS_ERR_OUT_OF_RANGE, "dbs_result_stat", "stat 40 ");
  assert_true(value == -7);
}

static void buffers_too_small_are_refused(void **state) {
  struct fixture *f = *state;
  double doubles[2 * NPOINTS];
  int32_t ints[NPOINTS];
  for (size_t i = 0; i < 2 * NPOINTS; ++i) doubles[i] = -7;
  for (size_t i = 0; i < NPOINTS; ++i) ints[i] = -7;
  assert_failure(dbs_result_uv(f->result, doubles, NPOINTS - 1), DBS_ERR_BUFFER_TOO_SMALL, "dbs_result_uv", "holds 230 pairs but 231 are needed");
  assert_failure(dbs_result_distances(f->result, doubles, NPOINTS - 1), DBS_ERR_BUFFER_TOO_SMALL, "dbs_result_distances", "holds 230 values but 231");
  assert_failure(dbs_result_point_patches(f->result, ints, 0), DBS_ERR_BUFFER_TOO_SMALL, "dbs_result_point_patches", "holds 0 values but 231");
  assert_failure(dbs_result_point_levels(f->result, ints, 1), DBS_ERR_BUFFER_TOO_SMALL, "dbs_result_point_levels", "holds 1 values but 231");
  for (size_t i = 0; i < 2 * NPOINTS; ++i) assert_true(doubles[i] == -7);
  for (size_t i = 0; i < NPOINTS; ++i) assert_int_equal(ints[i], -7);
}

static void evaluate_inside_is_the_plane(void **state) {
  struct fixture *f = *state;
  for (int k = 0; k <= 10; ++k) {
    double u = 0.1 * k, v = 0.37 + 0.05 * k;
    double xyz[3], normal[3];
    assert_ok(dbs_result_evaluate(f->result, u, v, xyz, normal));
    assert_true(fabs(xyz[0] - PLANE_W * u) < 1e-9);
    assert_true(fabs(xyz[1] - PLANE_H * v) < 1e-9);
    assert_true(fabs(xyz[2] - PLANE_Z) < 1e-9);
    assert_true(fabs(normal[0]) < 1e-9 && fabs(normal[1]) < 1e-9 && fabs(fabs(normal[2]) - 1.0) < 1e-9);
    double without_normal[3];
    assert_ok(dbs_result_evaluate(f->result, u, v, without_normal, NULL));
    assert_memory_equal(without_normal, xyz, sizeof xyz);
  }
}

static void evaluate_on_the_boundary_is_the_boundary(void **state) {
  struct fixture *f = *state;
  /* each side is the straight segment between its corners, its points evenly spaced */
  for (int k = 0; k <= 16; ++k) {
    double s = k / 16.0, xyz[3];
    const double expected[4][3] = {
        {PLANE_W * s, 0, PLANE_Z}, {PLANE_W, PLANE_H * s, PLANE_Z}, {PLANE_W * s, PLANE_H, PLANE_Z}, {0, PLANE_H * s, PLANE_Z}};
    const double params[4][2] = {{s, 0}, {1, s}, {s, 1}, {0, s}};
    for (int side = 0; side < 4; ++side) {
      assert_ok(dbs_result_evaluate(f->result, params[side][0], params[side][1], xyz, NULL));
      for (int c = 0; c < 3; ++c) assert_true(fabs(xyz[c] - expected[side][c]) < 1e-12 * PLANE_W);
    }
  }
  /* the corners exactly */
  double corner[3];
  assert_ok(dbs_result_evaluate(f->result, 1, 1, corner, NULL));
  assert_true(corner[0] == PLANE_W && corner[1] == PLANE_H && corner[2] == PLANE_Z);
  assert_ok(dbs_result_evaluate(f->result, 0, 0, corner, NULL));
  assert_true(corner[0] == 0 && corner[1] == 0 && corner[2] == PLANE_Z);
}

static void evaluate_outside_the_domain_fails(void **state) {
  struct fixture *f = *state;
  double xyz[3] = {-7, -7, -7}, normal[3] = {-7, -7, -7};
  assert_failure(dbs_result_evaluate(f->result, -0.01, 0.5, xyz, normal), DBS_ERR_OUT_OF_RANGE, "dbs_result_evaluate", "parameter u");
  assert_failure(dbs_result_evaluate(f->result, 0.5, 1.0000001, xyz, normal), DBS_ERR_OUT_OF_RANGE, "dbs_result_evaluate", "parameter v");
  assert_failure(dbs_result_evaluate(f->result, NAN, 0.5, xyz, normal), DBS_ERR_NON_FINITE, "dbs_result_evaluate", "parameter u");
  assert_failure(dbs_result_evaluate(f->result, 0.5, INFINITY, xyz, normal), DBS_ERR_NON_FINITE, "dbs_result_evaluate", "parameter v");
  for (int c = 0; c < 3; ++c) assert_true(xyz[c] == -7 && normal[c] == -7);
}

/* dbs_result_evaluate_many: the same points and normals as dbs_result_evaluate, the plane's
 * derivatives (W, 0, 0) and (0, H, 0), optional outputs, and a refused pair named by its index
 * with nothing written. */
static void evaluate_many_matches_evaluate(void **state) {
  struct fixture *f = *state;
  enum { N = 7 };
  double uv[2 * N], xyz[3 * N], normal[3 * N], su[3 * N], sv[3 * N], alone[3 * N];
  for (int k = 0; k < N; ++k) {
    uv[2 * k] = k / (N - 1.0);
    uv[2 * k + 1] = 0.3 + 0.1 * k;
  }
  assert_ok(dbs_result_evaluate_many(f->result, uv, N, xyz, normal, su, sv));
  assert_ok(dbs_result_evaluate_many(f->result, uv, N, alone, NULL, NULL, NULL));
  assert_memory_equal(alone, xyz, sizeof xyz);
  for (int k = 0; k < N; ++k) {
    double one[3], one_normal[3];
    assert_ok(dbs_result_evaluate(f->result, uv[2 * k], uv[2 * k + 1], one, one_normal));
    assert_memory_equal(one, xyz + 3 * k, sizeof one);
    assert_memory_equal(one_normal, normal + 3 * k, sizeof one_normal);
    assert_true(fabs(su[3 * k] - PLANE_W) < 1e-9 && fabs(su[3 * k + 1]) < 1e-9 && fabs(su[3 * k + 2]) < 1e-9);
    assert_true(fabs(sv[3 * k]) < 1e-9 && fabs(sv[3 * k + 1] - PLANE_H) < 1e-9 && fabs(sv[3 * k + 2]) < 1e-9);
  }
  assert_ok(dbs_result_evaluate_many(f->result, NULL, 0, NULL, NULL, NULL, NULL));
  double untouched[3 * N];
  for (int k = 0; k < 3 * N; ++k) untouched[k] = -7;
  uv[2 * 5 + 1] = 1.5;
  assert_failure(dbs_result_evaluate_many(f->result, uv, N, untouched, NULL, NULL, NULL), DBS_ERR_OUT_OF_RANGE, "dbs_result_evaluate_many", "parameter v of pair 5 = 1.5 is outside [0, 1]");
  uv[2 * 5 + 1] = NAN;
  assert_failure(dbs_result_evaluate_many(f->result, uv, N, untouched, NULL, NULL, NULL), DBS_ERR_NON_FINITE, "dbs_result_evaluate_many", "parameter v of pair 5");
  for (int k = 0; k < 3 * N; ++k) assert_true(untouched[k] == -7);
  assert_failure(dbs_result_evaluate_many(NULL, uv, N, untouched, NULL, NULL, NULL), DBS_ERR_NULL_ARGUMENT, "dbs_result_evaluate_many", "result");
  assert_failure(dbs_result_evaluate_many(f->result, NULL, N, untouched, NULL, NULL, NULL), DBS_ERR_NULL_ARGUMENT, "dbs_result_evaluate_many", "uv");
  assert_failure(dbs_result_evaluate_many(f->result, uv, N, NULL, NULL, NULL, NULL), DBS_ERR_NULL_ARGUMENT, "dbs_result_evaluate_many", "out_xyz");
  assert_failure(dbs_result_evaluate_many(f->result, uv, SIZE_MAX / 2, untouched, NULL, NULL, NULL), DBS_ERR_INVALID_ARGUMENT, "dbs_result_evaluate_many", "more points than any array");
}

static void the_root_patch(void **state) {
  struct fixture *f = *state;
  const dbs_patches *all = NULL, *again = NULL;
  assert_ok(dbs_result_patches(f->result, &all));
  assert_ok(dbs_result_patches(f->result, &again));
  assert_ptr_equal(all, again);
  size_t count = 0;
  assert_ok(dbs_patches_count(all, &count));
  assert_int_equal(count, 1);

  int32_t id = -1, level = -1, leaf = -1, parent = 0, nu = 0, nv = 0, iterations = -1;
  assert_ok(dbs_patches_id(all, 0, &id));
  assert_ok(dbs_patches_level(all, 0, &level));
  assert_ok(dbs_patches_is_leaf(all, 0, &leaf));
  assert_ok(dbs_patches_parent(all, 0, &parent));
  assert_int_equal(id, 0);
  assert_int_equal(level, 0);
  assert_int_equal(leaf, 1);
  assert_int_equal(parent, -1);

  double rect[4];
  assert_ok(dbs_patches_rect(all, 0, rect));
  assert_true(rect[0] == 0 && rect[1] == 0 && rect[2] == 1 && rect[3] == 1);

  assert_ok(dbs_patches_grid_size(all, 0, &nu, &nv));
  assert_true(nu >= 5 && nu <= 11 && nv >= 5 && nv <= 11);
  size_t grid_count = (size_t)nu * (size_t)nv;
  double *grid = malloc(sizeof(double) * 3 * grid_count);
  assert_non_null(grid);
  grid[0] = -7;
  assert_failure(dbs_patches_grid_points(all, 0, grid, grid_count - 1), DBS_ERR_BUFFER_TOO_SMALL, "dbs_patches_grid_points", "points but");
  assert_true(grid[0] == -7);
  assert_ok(dbs_patches_grid_points(all, 0, grid, grid_count));
  /* the grid lies on the plane, u fastest: point (iu, iv) above (W iu/(nu-1), H iv/(nv-1)) */
  for (int iv = 0; iv < nv; ++iv) {
    for (int iu = 0; iu < nu; ++iu) {
      const double *p = grid + 3 * ((size_t)iv * nu + iu);
      assert_true(fabs(p[0] - PLANE_W * iu / (nu - 1)) < 1e-9);
      assert_true(fabs(p[1] - PLANE_H * iv / (nv - 1)) < 1e-9);
      assert_true(fabs(p[2] - PLANE_Z) < 1e-9);
    }
  }
  free(grid);

  for (int32_t side = 0; side < 4; ++side) {
    size_t n = 0;
    assert_ok(dbs_patches_boundary_count(all, 0, side, &n));
    assert_int_equal(n, PER_SIDE);
    double from_patch[3 * PER_SIDE], from_boundary[3 * PER_SIDE];
    assert_ok(dbs_patches_boundary_points(all, 0, side, from_patch, PER_SIDE));
    assert_ok(dbs_boundary_side_points(f->boundary, side, from_boundary, PER_SIDE));
    assert_memory_equal(from_patch, from_boundary, sizeof from_patch);
    assert_failure(dbs_patches_boundary_points(all, 0, side, from_patch, PER_SIDE - 1), DBS_ERR_BUFFER_TOO_SMALL, "dbs_patches_boundary_points", NULL);
  }

  size_t points = 0;
  double mean = -1, max = -1;
  assert_ok(dbs_patches_stats(all, 0, &points, &mean, &max, &iterations));
  assert_int_equal(points, NPOINTS);
  assert_true(mean >= 0 && mean < 1e-9 && max >= mean && max < 1e-9);
  assert_true(iterations >= 1);
  assert_true(iterations == result_stat(f->result, DBS_STAT_ITERATIONS));
  int32_t solver = -1;
  size_t ceres_iterations = 1;
  assert_ok(dbs_patches_solver(all, 0, &solver, &ceres_iterations));
  assert_int_equal(solver, DBS_SOLVER_LINEAR);
  assert_int_equal(ceres_iterations, 0);
}

/* A subdivided result through the C API: the quadtree's links, rectangles and shared sides,
 * and every point's leaf and level. */
static void the_quadtree_of_a_subdivided_result(void **state) {
  (void)state;
  dbs_cloud *cloud = bump_cloud(40, 0.2);
  dbs_boundary *boundary = square_boundary(3);
  dbs_options *options = NULL;
  assert_ok(dbs_options_create(&options));
  assert_ok(dbs_options_set_double(options, DBS_OPT_ACCURACY, 1e-6)); /* out of reach: every patch splits */
  assert_ok(dbs_options_set_int(options, DBS_OPT_MAX_LEVEL, 2));
  assert_ok(dbs_options_set_int(options, DBS_OPT_MAX_GRID, 6));
  dbs_result *result = parameterize_or_fail(cloud, boundary, options);
  assert_true(result_stat(result, DBS_STAT_LEVELS) == 3.0);

  const dbs_patches *all = NULL;
  assert_ok(dbs_result_patches(result, &all));
  size_t count = 0;
  assert_ok(dbs_patches_count(all, &count));
  assert_true(count == result_stat(result, DBS_STAT_PATCHES));
  assert_int_equal(count, 1 + 4 + 16);
  int32_t level[21], parent[21], leaf[21], children[21] = {0};
  double rect[21][4], leaf_area = 0;
  for (size_t i = 0; i < count; ++i) {
    int32_t id = -1;
    assert_ok(dbs_patches_id(all, i, &id));
    assert_int_equal(id, (int32_t)i);
    assert_ok(dbs_patches_level(all, i, &level[i]));
    assert_ok(dbs_patches_parent(all, i, &parent[i]));
    assert_ok(dbs_patches_is_leaf(all, i, &leaf[i]));
    assert_ok(dbs_patches_rect(all, i, rect[i]));
    assert_int_equal(leaf[i], level[i] == 2);
    if (leaf[i]) leaf_area += (rect[i][2] - rect[i][0]) * (rect[i][3] - rect[i][1]);
    if (i == 0) {
      assert_int_equal(parent[i], -1);
      continue;
    }
    /* a child is one quarter of its parent, one level below */
    const int32_t p = parent[i];
    assert_true(p >= 0 && p < (int32_t)i);
    ++children[p];
    assert_int_equal(level[i], level[p] + 1);
    const double half_u = 0.5 * (rect[p][2] - rect[p][0]), half_v = 0.5 * (rect[p][3] - rect[p][1]);
    assert_true(rect[i][2] - rect[i][0] == half_u && rect[i][3] - rect[i][1] == half_v);
    assert_true(rect[i][0] == rect[p][0] || rect[i][0] == rect[p][0] + half_u);
    assert_true(rect[i][1] == rect[p][1] || rect[i][1] == rect[p][1] + half_v);
  }
  for (size_t i = 0; i < count; ++i) assert_int_equal(children[i], leaf[i] ? 0 : 4);
  assert_true(leaf_area == 1.0);

  /* Side by side children share their common side point for point (the projected middle
   * curve), and a patch's grid starts at its boundary's first corner. */
  size_t pairs = 0;
  for (size_t a = 1; a < count; ++a) {
    for (size_t b = 1; b < count; ++b) {
      if (parent[a] != parent[b] || rect[a][2] != rect[b][0] || rect[a][1] != rect[b][1]) continue;
      ++pairs;
      size_t na = 0, nb = 0;
      assert_ok(dbs_patches_boundary_count(all, a, DBS_SIDE_RIGHT, &na));
      assert_ok(dbs_patches_boundary_count(all, b, DBS_SIDE_LEFT, &nb));
      assert_int_equal(na, nb);
      double *right = malloc(sizeof(double) * 3 * na), *left = malloc(sizeof(double) * 3 * nb);
      assert_non_null(right);
      assert_non_null(left);
      assert_ok(dbs_patches_boundary_points(all, a, DBS_SIDE_RIGHT, right, na));
      assert_ok(dbs_patches_boundary_points(all, b, DBS_SIDE_LEFT, left, nb));
      assert_memory_equal(right, left, sizeof(double) * 3 * na);
      free(right);
      free(left);
    }
    int32_t nu = 0, nv = 0;
    assert_ok(dbs_patches_grid_size(all, a, &nu, &nv));
    double *grid = malloc(sizeof(double) * 3 * (size_t)nu * (size_t)nv), corner[3 * 64];
    assert_non_null(grid);
    size_t n = 0;
    assert_ok(dbs_patches_boundary_count(all, a, DBS_SIDE_BOTTOM, &n));
    assert_true(n >= 2 && n <= 64);
    assert_ok(dbs_patches_grid_points(all, a, grid, (size_t)nu * (size_t)nv));
    assert_ok(dbs_patches_boundary_points(all, a, DBS_SIDE_BOTTOM, corner, n));
    for (int c = 0; c < 3; ++c) assert_true(fabs(grid[c] - corner[c]) < 1e-12);
    free(grid);
  }
  assert_int_equal(pairs, 2 * 5); /* two side-by-side pairs in each of the 5 split patches */

  /* every point names a leaf, carries that leaf's level and lies in its rectangle */
  size_t points = 0;
  assert_ok(dbs_result_point_count(result, &points));
  int32_t *patch = malloc(sizeof(int32_t) * points), *point_level = malloc(sizeof(int32_t) * points);
  double *uv = malloc(sizeof(double) * 2 * points);
  assert_true(patch && point_level && uv);
  assert_ok(dbs_result_point_patches(result, patch, points));
  assert_ok(dbs_result_point_levels(result, point_level, points));
  assert_ok(dbs_result_uv(result, uv, points));
  size_t per_leaf[21] = {0};
  for (size_t k = 0; k < points; ++k) {
    const int32_t id = patch[k];
    assert_true(id >= 0 && id < (int32_t)count && leaf[id]);
    assert_int_equal(point_level[k], level[id]);
    assert_true(uv[2 * k] >= rect[id][0] && uv[2 * k] <= rect[id][2] && uv[2 * k + 1] >= rect[id][1] && uv[2 * k + 1] <= rect[id][3]);
    ++per_leaf[id];
  }
  size_t used = 0;
  for (size_t i = 0; i < count; ++i) used += per_leaf[i] > 0;
  assert_int_equal(used, 16); /* 1600 points on 16 leaves: each gets some */
  free(patch);
  free(point_level);
  free(uv);
  dbs_result_destroy(result);
  dbs_options_destroy(options);
  dbs_boundary_destroy(boundary);
  dbs_cloud_destroy(cloud);
}

static void patch_indices_and_sides_are_checked(void **state) {
  struct fixture *f = *state;
  const dbs_patches *all = NULL;
  assert_ok(dbs_result_patches(f->result, &all));
  int32_t value = -7, nu = -7, nv = -7;
  double rect[4] = {-7, -7, -7, -7}, xyz[3 * PER_SIDE], mean = -7, max = -7;
  size_t n = 7;
  const char *range = "patch index 1 is outside its range [0, 1)";
  assert_failure(dbs_patches_id(all, 1, &value), DBS_ERR_OUT_OF_RANGE, "dbs_patches_id", range);
  assert_failure(dbs_patches_level(all, 1, &value), DBS_ERR_OUT_OF_RANGE, "dbs_patches_level", range);
  assert_failure(dbs_patches_is_leaf(all, 1, &value), DBS_ERR_OUT_OF_RANGE, "dbs_patches_is_leaf", range);
  assert_failure(dbs_patches_parent(all, 1, &value), DBS_ERR_OUT_OF_RANGE, "dbs_patches_parent", range);
  assert_failure(dbs_patches_rect(all, 1, rect), DBS_ERR_OUT_OF_RANGE, "dbs_patches_rect", range);
  assert_failure(dbs_patches_grid_size(all, 1, &nu, &nv), DBS_ERR_OUT_OF_RANGE, "dbs_patches_grid_size", range);
  assert_failure(dbs_patches_grid_points(all, 1, xyz, PER_SIDE), DBS_ERR_OUT_OF_RANGE, "dbs_patches_grid_points", range);
  assert_failure(dbs_patches_boundary_count(all, 1, 0, &n), DBS_ERR_OUT_OF_RANGE, "dbs_patches_boundary_count", range);
  assert_failure(dbs_patches_boundary_points(all, 1, 0, xyz, PER_SIDE), DBS_ERR_OUT_OF_RANGE, "dbs_patches_boundary_points", range);
  /* a size_t index is printed as the number it is, not as -1 */
  char huge[64];
  snprintf(huge, sizeof huge, "patch index %zu is outside", (size_t)-1);
  assert_failure(dbs_patches_stats(all, (size_t)-1, &n, &mean, &max, &value), DBS_ERR_OUT_OF_RANGE, "dbs_patches_stats", huge);
  assert_failure(dbs_patches_boundary_count(all, 0, 4, &n), DBS_ERR_OUT_OF_RANGE, "dbs_patches_boundary_count", "side 4 is outside its range [0, 4)");
  assert_failure(dbs_patches_boundary_points(all, 0, -1, xyz, PER_SIDE), DBS_ERR_OUT_OF_RANGE, "dbs_patches_boundary_points", "side -1 ");
  assert_int_equal(value, -7);
  assert_true(nu == -7 && nv == -7 && n == 7 && mean == -7 && max == -7);
  for (int c = 0; c < 4; ++c) assert_true(rect[c] == -7);
}

/* The lines of `text`, each NUL-terminated in place; returns the count (at most `max`). */
static size_t split_lines(char *text, char **lines, size_t max) {
  size_t count = 0;
  for (char *line = strtok(text, "\n"); line && count < max; line = strtok(NULL, "\n")) lines[count++] = line;
  return count;
}

static void save_csv(void **state) {
  struct fixture *f = *state;
  char path[512];
  temp_path(path, sizeof path, "result.csv");
  assert_ok(dbs_result_save(f->result, f->cloud, path));

  char *text = read_all(path, NULL);
  char *lines[NPOINTS + 2];
  assert_int_equal(split_lines(text, lines, NPOINTS + 2), NPOINTS + 1);
  assert_string_equal(lines[0], "index,u,v,distance,patch,level");
  double uv[2 * NPOINTS];
  assert_ok(dbs_result_uv(f->result, uv, NPOINTS));
  for (size_t i = 0; i < NPOINTS; ++i) {
    long index = -1, patch = -1, level = -1;
    double u, v, distance;
    assert_int_equal(sscanf(lines[i + 1], "%ld,%lf,%lf,%lf,%ld,%ld", &index, &u, &v, &distance, &patch, &level), 6);
    assert_int_equal(index, (long)i);
    assert_true(fabs(u - uv[2 * i]) < 1e-12 && fabs(v - uv[2 * i + 1]) < 1e-12);
    assert_true(fabs(distance) < 1e-9);
    assert_int_equal(patch, 0);
    assert_int_equal(level, 0);
  }
  free(text);
}

/* The saved points read back as a cloud: the same count and bounding box. */
static void assert_reloads_as_the_cloud(const char *path, double tolerance) {
  if (!reads_with_draco(path)) return;
  dbs_cloud *back = NULL;
  assert_ok(dbs_cloud_load(path, &back));
  size_t count = 0;
  assert_ok(dbs_cloud_count(back, &count));
  assert_int_equal(count, NPOINTS);
  double min[3], max[3];
  assert_ok(dbs_cloud_bounds(back, min, max));
  const double expected_min[3] = {0, 0, PLANE_Z}, expected_max[3] = {PLANE_W, PLANE_H, PLANE_Z};
  for (int c = 0; c < 3; ++c) {
    assert_true(fabs(min[c] - expected_min[c]) <= tolerance);
    assert_true(fabs(max[c] - expected_max[c]) <= tolerance);
  }
  dbs_cloud_destroy(back);
}

static void save_ply_and_drc(void **state) {
  struct fixture *f = *state;
  char path[512];
  temp_path(path, sizeof path, "result.ply");
  assert_ok(dbs_result_save(f->result, f->cloud, path));
  char *text = read_all(path, NULL); /* the header is text; the binary body follows "end_header" */
  assert_memory_equal(text, "ply\n", 4);
  assert_non_null(strstr(text, "format binary_little_endian 1.0"));
  assert_non_null(strstr(text, "element vertex 231"));
  assert_non_null(strstr(text, "property double x"));
  assert_non_null(strstr(text, "property double u"));
  assert_non_null(strstr(text, "property double v"));
  assert_non_null(strstr(text, "property double distance"));
  assert_non_null(strstr(text, "property int patch"));
  free(text);
  assert_reloads_as_the_cloud(path, 1e-6);

  temp_path(path, sizeof path, "result.drc");
  if (!has_draco()) {
    assert_failure(dbs_result_save(f->result, f->cloud, path), DBS_ERR_UNSUPPORTED, "dbs_result_save", "built without Draco");
    return;
  }
  assert_ok(dbs_result_save(f->result, f->cloud, path));
  assert_reloads_as_the_cloud(path, 1e-3 * PLANE_W);
}

static void save_failures(void **state) {
  struct fixture *f = *state;
  char path[512];
  assert_failure(dbs_result_save(f->result, f->cloud, "/nonexistent-directory/result.csv"), DBS_ERR_IO, "dbs_result_save", "/nonexistent-directory/result.csv");
  temp_path(path, sizeof path, "result.unknown");
  assert_failure(dbs_result_save(f->result, f->cloud, path), DBS_ERR_UNSUPPORTED, "dbs_result_save", NULL);
  dbs_cloud *other = plane_cloud(3, 3);
  temp_path(path, sizeof path, "mismatch.csv");
  assert_failure(dbs_result_save(f->result, other, path), DBS_ERR_INVALID_ARGUMENT, "dbs_result_save", NULL);
  dbs_cloud_destroy(other);
}

static void parameterize_rejects_coincident_points(void **state) {
  (void)state;
  const double xyz[9] = {1, 0.5, PLANE_Z, 1, 0.5, PLANE_Z, 1, 0.5, PLANE_Z};
  dbs_cloud *cloud = NULL;
  assert_ok(dbs_cloud_create(xyz, 3, &cloud));
  dbs_boundary *boundary = plane_boundary(2);
  dbs_result *result = (dbs_result *)0x1;
  assert_failure(dbs_parameterize(cloud, boundary, NULL, &result), DBS_ERR_DEGENERATE, "dbs_parameterize", "distinct points");
  assert_ptr_equal(result, (dbs_result *)0x1);
  dbs_boundary_destroy(boundary);
  dbs_cloud_destroy(cloud);
}

static void null_options_are_the_defaults(void **state) {
  struct fixture *f = *state;
  dbs_options *options = NULL;
  assert_ok(dbs_options_create(&options));
  dbs_result *with_defaults = parameterize_or_fail(f->cloud, f->boundary, options);
  double uv_null[2 * NPOINTS], uv_defaults[2 * NPOINTS];
  assert_ok(dbs_result_uv(f->result, uv_null, NPOINTS));
  assert_ok(dbs_result_uv(with_defaults, uv_defaults, NPOINTS));
  assert_memory_equal(uv_null, uv_defaults, sizeof uv_null);
  dbs_result_destroy(with_defaults);
  dbs_options_destroy(options);
}

static void destroy_accepts_null(void **state) {
  (void)state;
  dbs_result_destroy(NULL);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(uv_is_the_affine_map_of_xy),
      cmocka_unit_test(evaluate_many_matches_evaluate),
      cmocka_unit_test(points_name_their_leaf),
      cmocka_unit_test(statistics),
      cmocka_unit_test(buffers_too_small_are_refused),
      cmocka_unit_test(evaluate_inside_is_the_plane),
      cmocka_unit_test(evaluate_on_the_boundary_is_the_boundary),
      cmocka_unit_test(evaluate_outside_the_domain_fails),
      cmocka_unit_test(the_root_patch),
      cmocka_unit_test(the_quadtree_of_a_subdivided_result),
      cmocka_unit_test(patch_indices_and_sides_are_checked),
      cmocka_unit_test(save_csv),
      cmocka_unit_test(save_ply_and_drc),
      cmocka_unit_test(save_failures),
      cmocka_unit_test(parameterize_rejects_coincident_points),
      cmocka_unit_test(null_options_are_the_defaults),
      cmocka_unit_test(destroy_accepts_null),
  };
  return cmocka_run_group_tests(tests, setup, teardown);
}
