/* Generates the example clouds and boundaries of data/ (see data/README.md).
 *
 *   cc -O2 -o /tmp/mk data/make_example_data.c -lm && /tmp/mk data
 *
 * Deterministic: its own 64-bit LCG with a fixed seed, so the files are reproducible. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const double kPi = 3.14159265358979323846;

static unsigned long long rng_state = 20240611ULL;

/* uniform in [0,1) from the top 53 bits of the LCG (Knuth's MMIX constants) */
static double uniform(void) {
  rng_state = rng_state * 6364136223846793005ULL + 1442695040888963407ULL;
  return (double)(rng_state >> 11) * (1.0 / 9007199254740992.0);
}

/* standard normal (Box-Muller) */
static double gaussian(void) {
  double a = uniform();
  const double b = uniform();
  if (a < 1e-300) a = 1e-300;
  return sqrt(-2.0 * log(a)) * cos(2.0 * kPi * b);
}

typedef void (*surface_fn)(double u, double v, double p[3]);

/* Stand-in for the side surface of a shoe last, u along the length (heel at u=0, toe at
 * u=1), v from the sole edge (v=0) up to the top (v=1): a strip bowed in plan view,
 * whose cross-section curves inward towards the top, lower at the toe, bent up at the
 * toe (toe spring), with a train of sharp welt ridges over the forepart (u > 0.7, 3 units
 * high, 15 units apart) that one base surface cannot follow. */
static void shoe_last(double u, double v, double p[3]) {
  const double spring = u > 0.65 ? (u - 0.65) / 0.35 : 0.0;
  const double height = 101.0 - 50.0 * u * u;                      /* section height */
  const double bow = 14.0 * (1.0 - (2.0 * u - 1.0) * (2.0 * u - 1.0)); /* plan-view bow */
  const double ridge = u > 0.7 ? 3.0 * pow(sin(kPi * (u - 0.7) / 0.06), 2.0) * (0.3 + 0.7 * v) : 0.0;
  p[0] = 246.0 * u - 6.0 * sin(kPi * v) * spring;
  p[1] = bow + 34.0 * sin(0.5 * kPi * v) * (1.0 - 0.35 * v) + ridge;
  p[2] = height * v + 28.0 * spring * spring;
}

/* A gently curved 100 x 50 panel. */
static void panel(double u, double v, double p[3]) {
  const double x = 100.0 * u, y = 50.0 * v;
  p[0] = x;
  p[1] = y;
  p[2] = 6.0 * sin(kPi * u) + 2.0 * (v - 0.5) * (v - 0.5) + 1.5 * u * v;
}

static FILE* open_out(const char* dir, const char* name) {
  char path[1024];
  FILE* f;
  snprintf(path, sizeof path, "%s/%s", dir, name);
  f = fopen(path, "w");
  if (!f) {
    perror(path);
    exit(1);
  }
  return f;
}

static void write_cloud(const char* dir, const char* name, surface_fn s, int count, double noise, const char* what) {
  FILE* f = open_out(dir, name);
  int i, k;
  fprintf(f, "# %s: %d points, noise sigma %g per coordinate (make_example_data.c)\n", what, count, noise);
  for (i = 0; i < count; ++i) {
    double p[3];
    const double u = uniform(), v = uniform();
    s(u, v, p);
    for (k = 0; k < 3; ++k) p[k] += noise * gaussian();
    fprintf(f, "%.4f %.4f %.4f\n", p[0], p[1], p[2]);
  }
  fclose(f);
}

/* The four sides sampled from the surface's border, corners shared exactly (FORMATS.md). */
static void write_boundary(const char* dir, const char* name, surface_fn s, int samples, const char* what) {
  static const char* kNames[4] = {"bottom", "right", "top", "left"};
  FILE* f = open_out(dir, name);
  int side, i;
  fprintf(f, "# boundary of %s, %d points per side (make_example_data.c)\n", what, samples);
  for (side = 0; side < 4; ++side) {
    fprintf(f, "%s\n", kNames[side]);
    for (i = 0; i < samples; ++i) {
      const double t = (double)i / (samples - 1);
      double p[3];
      switch (side) {
        case 0: s(t, 0.0, p); break;
        case 1: s(1.0, t, p); break;
        case 2: s(t, 1.0, p); break;
        default: s(0.0, t, p); break;
      }
      fprintf(f, "%.6f %.6f %.6f\n", p[0], p[1], p[2]);
    }
  }
  fclose(f);
}

int main(int argc, char** argv) {
  const char* dir = argc > 1 ? argv[1] : ".";
  write_cloud(dir, "shoe_last.xyz", shoe_last, 20000, 0.05, "shoe-last stand-in side surface");
  write_boundary(dir, "shoe_last_boundary.txt", shoe_last, 50, "the shoe-last stand-in");
  write_cloud(dir, "panel.xyz", panel, 2000, 0.02, "gently curved 100 x 50 panel");
  write_boundary(dir, "panel_boundary.txt", panel, 21, "the 100 x 50 panel");
  return 0;
}
