/* A boundary's own geometry (issue 14, item 7): a loop crossing itself (a bow-tie, a side
 * running across the patch, a side crossing itself) or a side folding back on itself is
 * refused by dbs_boundary_create, _create_tolerant, _load, _load_tolerant and _from_loop with
 * DBS_ERR_DEGENERATE and a message naming the side(s) and where; strongly curved but valid
 * boundaries (half cylinder, 270-degree cylinder, saddle, twisted quadrilateral, closed
 * tube, a narrow notch, noisy sides, the example data and the boundaries found from it) are
 * accepted. The fold shapes of tests/support are accepted in tests/core/test_boundary_shape.cpp. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "capi_support.h"

#define PI 3.14159265358979323846
#define MAX_SIDE 4096

/* A side: up to MAX_SIDE points. */
typedef struct {
  double xyz[3 * MAX_SIDE];
  size_t n;
} side;

/* Appends `per_leg` evenly spaced points from the side's last point to p (the first call
 * puts p itself). */
static void go(side *s, double x, double y, double z, int per_leg) {
  if (s->n == 0) {
    s->xyz[0] = x, s->xyz[1] = y, s->xyz[2] = z;
    s->n = 1;
    return;
  }
  const double *a = s->xyz + 3 * (s->n - 1);
  const double a0 = a[0], a1 = a[1], a2 = a[2];
  for (int k = 1; k <= per_leg; ++k) {
    assert_true(s->n < MAX_SIDE);
    const double t = (double)k / per_leg;
    double *p = s->xyz + 3 * s->n++;
    p[0] = k == per_leg ? x : a0 + t * (x - a0);
    p[1] = k == per_leg ? y : a1 + t * (y - a1);
    p[2] = k == per_leg ? z : a2 + t * (z - a2);
  }
}

/* The four sides of a boundary. */
typedef struct {
  side bottom, right, top, left;
} sides;

/* Straight sides between the corners c00, c10, c01, c11 (corner (u,v)), `per_leg` segments
 * each. */
static void quad(sides *b, const double c00[3], const double c10[3], const double c01[3], const double c11[3], int per_leg) {
  memset(b, 0, sizeof *b);
  go(&b->bottom, c00[0], c00[1], c00[2], 1), go(&b->bottom, c10[0], c10[1], c10[2], per_leg);
  go(&b->right, c10[0], c10[1], c10[2], 1), go(&b->right, c11[0], c11[1], c11[2], per_leg);
  go(&b->top, c01[0], c01[1], c01[2], 1), go(&b->top, c11[0], c11[1], c11[2], per_leg);
  go(&b->left, c00[0], c00[1], c00[2], 1), go(&b->left, c01[0], c01[1], c01[2], per_leg);
}

static int create(const sides *b, dbs_boundary **out) {
  return dbs_boundary_create(b->bottom.xyz, b->bottom.n, b->right.xyz, b->right.n, b->top.xyz, b->top.n, b->left.xyz, b->left.n, out);
}

/* Every coordinate times `factor`. */
static void scale(sides *b, double factor) {
  side *all[4] = {&b->bottom, &b->right, &b->top, &b->left};
  for (int s = 0; s < 4; ++s)
    for (size_t k = 0; k < 3 * all[s]->n; ++k) all[s]->xyz[k] *= factor;
}

/* dbs_boundary_create refuses `b` with DBS_ERR_DEGENERATE, its message holding each of the
 * `count` needles, and leaves *out untouched. */
static void assert_refused(const sides *b, const char *const *needles, int count) {
  dbs_boundary *sentinel = (dbs_boundary *)(uintptr_t)0x1, *out = sentinel;
  const int status = create(b, &out);
  if (status != DBS_ERR_DEGENERATE) print_error("status %d: %s\n", status, dbs_last_error_message());
  assert_int_equal(status, DBS_ERR_DEGENERATE);
  assert_ptr_equal(out, sentinel);
  for (int k = 0; k < count; ++k) {
    if (!strstr(dbs_last_error_message(), needles[k])) print_error("message \"%s\" lacks \"%s\"\n", dbs_last_error_message(), needles[k]);
    assert_non_null(strstr(dbs_last_error_message(), needles[k]));
  }
  assert_int_equal(strncmp(dbs_last_error_message(), "dbs_boundary_create: ", 21), 0);
}

static void assert_accepted(const sides *b, const char *what) {
  dbs_boundary *out = NULL;
  const int status = create(b, &out);
  if (status != DBS_OK) print_error("%s: status %d: %s\n", what, status, dbs_last_error_message());
  assert_int_equal(status, DBS_OK);
  dbs_boundary_destroy(out);
}

/* The unit square with two corners swapped: (1,0) and (1,1) exchanged, so bottom and top
 * cross on the diagonal; the top (corners (0,1) and (1,1)) raised by `lift`. */
static void bow_tie(sides *b, int per_leg, double lift) {
  const double c00[3] = {0, 0, 0}, c10[3] = {1, 1, 0}, c01[3] = {0, 1, lift}, c11[3] = {1, 0, lift};
  quad(b, c00, c10, c01, c11, per_leg);
}

static void bow_tie_refused(void **state) {
  (void)state;
  static sides b;
  const char *needles[] = {"crosses", "side 'bottom'", "side 'top'", "bow-tie", "(0.5, 0.5, 0)"};
  /* Sides of one segment: a proper crossing; even: both diagonals have a point at the
   * centre (they meet at points, not inside segments); odd: they cross inside segments. */
  for (int per_leg = 1; per_leg <= 9; ++per_leg) {
    bow_tie(&b, per_leg, 0.0);
    assert_refused(&b, needles, 5);
  }
  /* Not quite planar: the crossing strands 0.01 apart along the normal (of a size 1.4). */
  bow_tie(&b, 7, 0.01);
  assert_refused(&b, needles, 4);
  /* At both ends of the supported magnitudes. */
  bow_tie(&b, 7, 0.0);
  scale(&b, 1e-100);
  assert_refused(&b, needles, 4);
  bow_tie(&b, 7, 0.0);
  scale(&b, 1e75);
  assert_refused(&b, needles, 4);
}

static void side_across_the_patch_refused(void **state) {
  (void)state;
  static sides b;
  const double c00[3] = {0, 0, 0}, c10[3] = {1, 0, 0}, c01[3] = {0, 1, 0}, c11[3] = {1, 1, 0};
  quad(&b, c00, c10, c01, c11, 10);
  /* The left side runs across the domain, out through the right side and back. */
  memset(&b.left, 0, sizeof b.left);
  go(&b.left, 0, 0, 0, 1), go(&b.left, 1.5, 0.4, 0, 12), go(&b.left, 1.5, 0.6, 0, 3), go(&b.left, 0, 1, 0, 12);
  const char *needles[] = {"crosses", "side 'right'", "side 'left'", "best-fit plane", "(1, 0.266667, 0)"};
  assert_refused(&b, needles, 5);
}

static void side_crossing_itself_refused(void **state) {
  (void)state;
  static sides b;
  const double c00[3] = {0, 0, 0}, c10[3] = {1, 0, 0}, c01[3] = {0, 1, 0}, c11[3] = {1, 1, 0};
  quad(&b, c00, c10, c01, c11, 10);
  /* The bottom makes a loop a third of the square across: right turns only, no fold. */
  memset(&b.bottom, 0, sizeof b.bottom);
  go(&b.bottom, 0, 0, 0, 1), go(&b.bottom, 0.6, 0, 0, 6), go(&b.bottom, 0.6, 0.3, 0, 3), go(&b.bottom, 0.3, 0.3, 0, 3);
  go(&b.bottom, 0.3, -0.2, 0, 5), go(&b.bottom, 1, 0, 0, 7);
  const char *needles[] = {"side 'bottom' crosses itself", "(0.3, 0, 0)"};
  assert_refused(&b, needles, 2);
}

static void side_folding_back_refused(void **state) {
  (void)state;
  static sides b;
  const double c00[3] = {0, 0, 0}, c10[3] = {1, 0, 0}, c01[3] = {0, 1, 0}, c11[3] = {1, 1, 0};
  /* The bottom runs to 0.8, back to 0.3, then on to 1: with 1 and with 20 points a leg. */
  for (int per_leg = 1; per_leg <= 20; per_leg += 19) {
    quad(&b, c00, c10, c01, c11, per_leg);
    memset(&b.bottom, 0, sizeof b.bottom);
    go(&b.bottom, 0, 0, 0, 1), go(&b.bottom, 0.8, 0, 0, per_leg), go(&b.bottom, 0.3, 0, 0, per_leg), go(&b.bottom, 1, 0, 0, per_leg);
    const char *needles[] = {"side 'bottom' folds back on itself", "(0.8, 0, 0)", "180 degrees"};
    assert_refused(&b, needles, 3);
  }
  /* A Z: the top turns back at a slant (169 degrees at 0.8), then forward again (171 degrees
   * at its far end, the sharper tip, named). */
  quad(&b, c00, c10, c01, c11, 4);
  memset(&b.top, 0, sizeof b.top);
  go(&b.top, 0, 1, 0, 1), go(&b.top, 0.8, 1, 0, 4), go(&b.top, 0.3, 1.1, 0, 4), go(&b.top, 1, 1, 0, 4);
  const char *z[] = {"side 'top' folds back on itself at its point 8", "(0.3, 1.1, 0)"};
  assert_refused(&b, z, 2);
  /* A spike: the right side rises 3 times the square's size out of its plane and comes back. */
  quad(&b, c00, c10, c01, c11, 4);
  memset(&b.right, 0, sizeof b.right);
  go(&b.right, 1, 0, 0, 1), go(&b.right, 1, 0.5, 3, 1), go(&b.right, 1, 1, 0, 1);
  const char *spike[] = {"side 'right' folds back on itself at its point 1"};
  assert_refused(&b, spike, 1);
  /* A notch 0.1 wide and 0.4 deep in the bottom: its tip turns by 166 degrees, a spike
   * inwards that counts as folding back (a notch twice as wide is accepted, below). */
  quad(&b, c00, c10, c01, c11, 10);
  memset(&b.bottom, 0, sizeof b.bottom);
  go(&b.bottom, 0, 0, 0, 1), go(&b.bottom, 0.45, 0, 0, 9), go(&b.bottom, 0.5, 0.4, 0, 8), go(&b.bottom, 0.55, 0, 0, 8), go(&b.bottom, 1, 0, 0, 9);
  const char *notch[] = {"side 'bottom' folds back on itself", "(0.5, 0.4, 0)", "165.75 degrees"};
  assert_refused(&b, notch, 3);
}

static void loaded_and_looped_boundaries_refused(void **state) {
  (void)state;
  char path[512];
  temp_file(path, sizeof path, "bow_tie.txt",
            "bottom\n0 0 0\n1 1 0\nright\n1 1 0\n1 0 0\ntop\n0 1 0\n1 0 0\nleft\n0 0 0\n0 1 0\n");
  dbs_boundary *sentinel = (dbs_boundary *)(uintptr_t)0x1, *out = sentinel;
  assert_failure(dbs_boundary_load(path, &out), DBS_ERR_DEGENERATE, "dbs_boundary_load", "crosses");
  assert_non_null(strstr(dbs_last_error_message(), "bow_tie.txt"));
  assert_ptr_equal(out, sentinel);
  double snap = -1.0;
  assert_failure(dbs_boundary_load_tolerant(path, 1e-3, 1, &snap, &out), DBS_ERR_DEGENERATE, "dbs_boundary_load_tolerant", "side 'top'");
  assert_ptr_equal(out, sentinel);
  assert_true(snap == -1.0);

  /* A figure-eight loop cut at four corners in cyclic order. */
  const double eight[] = {0, 0, 0, 1, 1, 0, 1, 2, 0, 0, 2, 0, 1, 1, 0, 1, 0, 0};
  const size_t corners[4] = {0, 2, 3, 5};
  assert_failure(dbs_boundary_from_loop(eight, 6, corners, &out), DBS_ERR_DEGENERATE, "dbs_boundary_from_loop", "crosses");
  assert_ptr_equal(out, sentinel);

  static sides b;
  bow_tie(&b, 3, 0.0);
  assert_failure(dbs_boundary_create_tolerant(b.bottom.xyz, b.bottom.n, b.right.xyz, b.right.n, b.top.xyz, b.top.n, b.left.xyz, b.left.n, 1e-3, 1, &snap, &out),
                 DBS_ERR_DEGENERATE, "dbs_boundary_create_tolerant", "bow-tie");
  assert_ptr_equal(out, sentinel);
}

/* ---- controls: valid boundaries of strongly curved parts ------------------------------- */

/* A cylinder of radius 1 along x, length `length`, over the angles [0, `degrees`]: the lines
 * at both angles are bottom and top, the arcs at both ends left and right. */
static void cylinder(sides *b, double length, double degrees, int arc_points) {
  memset(b, 0, sizeof *b);
  const double a1 = degrees * PI / 180.0;
  go(&b->bottom, 0, 1, 0, 1), go(&b->bottom, length, 1, 0, 8);
  go(&b->top, 0, cos(a1), sin(a1), 1), go(&b->top, length, cos(a1), sin(a1), 8);
  for (int k = 0; k < arc_points; ++k) {
    const double a = a1 * k / (arc_points - 1);
    go(&b->left, 0, cos(a), sin(a), 1);
    go(&b->right, length, cos(a), sin(a), 1);
  }
  /* the arcs end exactly where the lines do */
  memcpy(b->left.xyz + 3 * (b->left.n - 1), b->top.xyz, 3 * sizeof(double));
  memcpy(b->right.xyz + 3 * (b->right.n - 1), b->top.xyz + 3 * (b->top.n - 1), 3 * sizeof(double));
}

static void curved_boundaries_accepted(void **state) {
  (void)state;
  static sides b;
  const double lengths[] = {3.0, 1.0, 0.2};
  const int arcs[] = {4, 9, 200};
  for (int l = 0; l < 3; ++l)
    for (int a = 0; a < 3; ++a) {
      cylinder(&b, lengths[l], 180.0, arcs[a]);
      assert_accepted(&b, "half cylinder");
      cylinder(&b, lengths[l], 270.0, arcs[a]);
      assert_accepted(&b, "270-degree cylinder");
      cylinder(&b, lengths[l], 330.0, arcs[a]);
      assert_accepted(&b, "330-degree cylinder");
    }
  /* The saddle z = x^2 - y^2 over [-1,1]^2. */
  memset(&b, 0, sizeof b);
  for (int k = 0; k <= 50; ++k) {
    const double t = -1.0 + 2.0 * k / 50;
    go(&b.bottom, t, -1, t * t - 1, 1);
    go(&b.top, t, 1, t * t - 1, 1);
    go(&b.left, -1, t, 1 - t * t, 1);
    go(&b.right, 1, t, 1 - t * t, 1);
  }
  assert_accepted(&b, "saddle");
  scale(&b, 1e-100);
  assert_accepted(&b, "saddle x 1e-100");
  scale(&b, 1e175);
  assert_accepted(&b, "saddle x 1e75");
  /* The bow-tie's top lifted by the square's size: a twisted quadrilateral (a ruled
   * saddle), its strands 1 apart where they seem to cross. */
  bow_tie(&b, 7, 1.0);
  assert_accepted(&b, "twisted quadrilateral");
  /* A closed tube: bottom and top full circles, left and right the same seam. */
  memset(&b, 0, sizeof b);
  for (int k = 0; k <= 24; ++k) {
    const double a = 2 * PI * k / 24;
    const double x = k == 24 ? 1 : cos(a), y = k == 24 ? 0 : sin(a);
    go(&b.bottom, x, y, 0, 1);
    go(&b.top, x, y, 3, 1);
  }
  go(&b.right, 1, 0, 0, 1), go(&b.right, 1, 0, 3, 5);
  go(&b.left, 1, 0, 0, 1), go(&b.left, 1, 0, 3, 5);
  assert_accepted(&b, "tube");
  /* A square whose bottom has a notch 0.2 wide and 0.4 deep (its tip turns by 152 degrees). */
  const double c00[3] = {0, 0, 0}, c10[3] = {1, 0, 0}, c01[3] = {0, 1, 0}, c11[3] = {1, 1, 0};
  quad(&b, c00, c10, c01, c11, 10);
  memset(&b.bottom, 0, sizeof b.bottom);
  go(&b.bottom, 0, 0, 0, 1), go(&b.bottom, 0.4, 0, 0, 9), go(&b.bottom, 0.5, 0.4, 0, 8), go(&b.bottom, 0.6, 0, 0, 8), go(&b.bottom, 1, 0, 0, 9);
  assert_accepted(&b, "notch 0.2 wide, 0.4 deep");
  /* Noisy dense sides: every point jittered by up to 0.2 of the spacing, back-steps included. */
  quad(&b, c00, c10, c01, c11, 400);
  side *all[4] = {&b.bottom, &b.right, &b.top, &b.left};
  unsigned state_bits = 12345u;
  for (int s = 0; s < 4; ++s)
    for (size_t k = 1; k + 1 < all[s]->n; ++k)
      for (int c = 0; c < 3; ++c) {
        state_bits = state_bits * 1103515245u + 12345u;
        all[s]->xyz[3 * k + c] += 0.2 / 400 * (((state_bits >> 8) & 0xffff) / 32768.0 - 1.0);
      }
  assert_accepted(&b, "noisy square");
  /* A sparse side with one point stepping back by 1% of its length. */
  quad(&b, c00, c10, c01, c11, 1);
  memset(&b.bottom, 0, sizeof b.bottom);
  go(&b.bottom, 0, 0, 0, 1), go(&b.bottom, 0.5, 0, 0, 1), go(&b.bottom, 0.49, 0.001, 0, 1), go(&b.bottom, 1, 0, 0, 1);
  assert_accepted(&b, "sparse back-step");
}

static void example_boundaries_accepted(void **state) {
  (void)state;
  /* (the CAD export's corners miss by 0.05: it needs a corner tolerance) */
  const char *files[] = {"panel_boundary.txt", "panel_boundary_cad.txt", "shoe_last_boundary.txt"};
  for (int k = 0; k < 3; ++k) {
    char path[512];
    snprintf(path, sizeof path, "%s/%s", DBS_TEST_DATA_DIR, files[k]);
    dbs_boundary *boundary = NULL;
    assert_ok(dbs_boundary_load_tolerant(path, 1e-3, 1, NULL, &boundary));
    dbs_boundary_destroy(boundary);
  }
  const char *clouds[] = {"panel.xyz", "shoe_last.xyz"};
  for (int k = 0; k < 2; ++k) {
    char path[512];
    snprintf(path, sizeof path, "%s/%s", DBS_TEST_DATA_DIR, clouds[k]);
    dbs_cloud *cloud = NULL;
    dbs_boundary *boundary = NULL;
    assert_ok(dbs_cloud_load(path, &cloud));
    assert_ok(dbs_boundary_detect(cloud, NULL, &boundary));
    dbs_boundary_destroy(boundary);
    dbs_cloud_destroy(cloud);
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(bow_tie_refused),
      cmocka_unit_test(side_across_the_patch_refused),
      cmocka_unit_test(side_crossing_itself_refused),
      cmocka_unit_test(side_folding_back_refused),
      cmocka_unit_test(loaded_and_looped_boundaries_refused),
      cmocka_unit_test(curved_boundaries_accepted),
      cmocka_unit_test(example_boundaries_accepted),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
