// The connectivity-free fold measure: nothing folds on fold-free parameterizations (smooth,
// strongly curved, noisy, creased, globally mirrored), a flipped patch is found, coincident
// (u,v) are counted exactly, and the verdicts do not depend on scale or thread count.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "analytic_clouds.hpp"
#include "cloud_index.hpp"
#include "error.hpp"
#include "fold_measure.hpp"

// cmocka last: its fail() macro would hide dbs::fail.
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
extern "C" {
#include <cmocka.h>
}

using namespace dbs;
using namespace dbs_test;

namespace {

/// A cloud with its parameters.
struct Sample {
  std::vector<Vec3> points;
  std::vector<double> u, v;
};

/// `count` random points of s over [0,1]^2, parameters (u,v) = the surface's own (a,b).
Sample sample(const Surface& s, std::size_t count, unsigned seed) {
  Sample out;
  std::vector<Vec2> ab;
  out.points = random_points(s, count, seed, &ab);
  for (const Vec2& p : ab) out.u.push_back(p.x()), out.v.push_back(p.y());
  return out;
}

/// Moves every point along the surface normal of s by a Gaussian of deviation sigma.
void add_normal_noise(Sample& c, const Surface& s, double sigma, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gauss(0.0, sigma);
  const double h = 1e-6;
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    const double a = c.u[i], b = c.v[i];
    const Vec3 su = s(a + h, b) - s(a - h, b), sv = s(a, b + h) - s(a, b - h);
    c.points[i] += gauss(rng) * su.cross(sv).normalized();
  }
}

double diagonal(const std::vector<Vec3>& pts) { return bounds_of(pts).diagonal(); }

double share(std::size_t part, std::size_t whole) { return static_cast<double>(part) / static_cast<double>(whole); }

void no_folds_on_clean_height_field(void**) {
  const Sample c = sample(height_field(), 4000, 11);
  const FoldMeasure m = measure_folds(c.points, c.u, c.v, 0.0, 2);
  assert_int_equal(m.points, 4000);
  assert_int_equal(m.state.size(), 4000);
  assert_int_equal(m.folded, 0);
  assert_true(m.folded_share == 0.0);
  assert_true(share(m.undecided, m.points) < 0.01);
  assert_int_equal(m.coincident, 0);
  assert_int_equal(m.collapsed, 0);
  assert_int_equal(m.torn, 0);
}

void squeezed_band_is_collapsed_not_folded(void**) {
  // A band across a clean height field (0.4 < v < 0.6) squeezed onto the line v = 0.5, as
  // points a surface never reached pile up: its orientation cannot be told, so nothing is
  // folded, but the band's inner points are counted collapsed and nothing away from it is.
  Sample c = sample(height_field(), 4000, 11);
  for (double& v : c.v)
    if (v > 0.4 && v < 0.6) v = 0.5 + 1e-5 * (v - 0.5);
  const FoldMeasure m = measure_folds(c.points, c.u, c.v, 0.0, 2);
  const double h = cloud_spacing(CloudIndex(c.points));
  std::size_t band = 0, band_collapsed = 0;
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    const double v = c.points[i].y();  // the height field's y is its parameter b
    if (std::abs(v - 0.5) < 0.1 - 3.0 * h && c.points[i].x() > 3.0 * h && c.points[i].x() < 1.0 - 3.0 * h) {
      ++band;
      band_collapsed += m.state[i] == kFoldCollapsed;
    } else if (std::abs(v - 0.5) > 0.1 + 3.0 * h) {
      assert_true(m.state[i] != kFoldCollapsed);
    }
  }
  assert_true(band > 400);
  assert_true(band_collapsed >= 0.9 * band);
  assert_int_equal(m.folded, 0);
  assert_true(m.collapsed >= band_collapsed);
}

void no_folds_on_curved_surfaces(void**) {
  // A half cylinder of radius 0.3 and length 1, and a dome 5 times taller than its width.
  const Surface half_cylinder = [](double a, double b) { return Vec3(0.3 * std::cos(M_PI * a), b, 0.3 * std::sin(M_PI * a)); };
  const Surface bump = [](double a, double b) {
    const double r2 = (a - 0.5) * (a - 0.5) + (b - 0.5) * (b - 0.5);
    return Vec3(a, b, 0.6 * std::exp(-r2 / (0.12 * 0.12)));
  };
  for (const Surface& s : {half_cylinder, bump}) {
    const Sample c = sample(s, 4000, 12);
    const FoldMeasure m = measure_folds(c.points, c.u, c.v, 0.0, 2);
    assert_int_equal(m.folded, 0);
    assert_true(share(m.undecided, m.points) < 0.02);
    assert_int_equal(m.torn, 0);
  }
}

void noisy_height_field_folds_at_most_a_thousandth(void**) {
  const Surface s = height_field();
  Sample c = sample(s, 4000, 13);
  const double sigma = 0.005 * diagonal(c.points);
  add_normal_noise(c, s, sigma, 14);
  const FoldMeasure m = measure_folds(c.points, c.u, c.v, sigma, 2);
  assert_true(m.folded_share <= 1e-3);
  // Border neighbourhoods, one-sided and as thick as they are wide, are widened rather than
  // given up.
  assert_true(share(m.undecided, m.points) < 0.01);
}

void creased_box_folds_at_most_a_thousandth(void**) {
  // An open box: floor [0,1]^2 and four walls of height 0.5, points uniform by area. (u,v)
  // maps the floor onto [1/4,3/4]^2 and each wall onto the ring between that square and
  // [0,1]^2 (L-infinity rings by height), one-to-one.
  const double height = 0.5;
  std::mt19937_64 rng(15);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Sample c;
  for (int i = 0; i < 4000; ++i) {
    const double face = unit(rng) * (1.0 + 4.0 * height), s = unit(rng), t = unit(rng);
    Vec3 p;
    if (face < 1.0) {
      p = Vec3(s, t, 0.0);
    } else {
      const int wall = std::min(3, static_cast<int>((face - 1.0) / height));
      const double z = t * height;
      p = wall == 0 ? Vec3(s, 0, z) : wall == 1 ? Vec3(1, s, z) : wall == 2 ? Vec3(s, 1, z) : Vec3(0, s, z);
    }
    const double grow = 0.5 * (1.0 + p.z() / height);
    c.points.push_back(p);
    c.u.push_back(0.5 + (p.x() - 0.5) * grow);
    c.v.push_back(0.5 + (p.y() - 0.5) * grow);
  }
  const FoldMeasure m = measure_folds(c.points, c.u, c.v, 0.0, 2);
  assert_true(m.folded_share <= 1e-3);
  assert_true(share(m.undecided, m.points) < 0.02);
  assert_int_equal(m.torn, 0);
}

void thin_flap_folds_nothing(void**) {
  // A sheet turned back on itself (two unit squares `gap` apart joined by a half cylinder),
  // u along the sheet: the normals must follow the turn, not cross the gap.
  std::mt19937_64 rng(24);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double gap = 6.0 * 0.5 / std::sqrt(2000.0);  // about 6 spacings of 4000 points on 2 units of area
  const double radius = 0.5 * gap, arc = M_PI * radius, length = 2.0 + arc;
  Sample c;
  for (int i = 0; i < 4000; ++i) {
    const double s = unit(rng) * length, y = unit(rng);
    Vec3 p;
    if (s < 1.0) {
      p = Vec3(1.0 - s, y, 0.0);
    } else if (s < 1.0 + arc) {
      const double a = (s - 1.0) / radius;
      p = Vec3(-radius * std::sin(a), y, radius - radius * std::cos(a));
    } else {
      p = Vec3(s - 1.0 - arc, y, gap);
    }
    c.points.push_back(p);
    c.u.push_back(s / length);
    c.v.push_back(y);
  }
  const FoldMeasure m = measure_folds(c.points, c.u, c.v, 0.0, 2);
  assert_true(m.folded_share <= 1e-3);
  assert_true(share(m.undecided, m.points) < 0.02);
  // The two sides of the flap are far apart in (u,v) but never graph neighbours: no tear.
  assert_int_equal(m.torn, 0);
}

void thrown_points_are_torn(void**) {
  // The points of a small disk of the height field (radius 0.12 about the domain's centre)
  // thrown 0.25 along u, as a leaf that passed them at a distance gives them feet elsewhere
  // in the domain: among themselves their map is sound, and the measure's local maps leave
  // the torn neighbours out, so the disk is neither folded nor undecided. The points on both
  // sides of its rim see each other thrown off: they are torn (34 inside the disk, 41 outside
  // it), and nothing away from the rim is.
  Sample c = sample(height_field(), 4000, 25);
  const double h = cloud_spacing(CloudIndex(c.points)), radius = 0.12;
  std::vector<double> centre_distance;
  for (std::size_t i = 0; i < c.u.size(); ++i) {
    centre_distance.push_back(std::hypot(c.u[i] - 0.5, c.v[i] - 0.5));
    if (centre_distance.back() < radius) c.u[i] += 0.25;
  }
  const FoldMeasure m = measure_folds(c.points, c.u, c.v, 0.0, 2);
  // The tear runs along the disk's rim: points within 3 spacings h of it, on either side.
  std::size_t disk = 0, rim = 0, rim_torn = 0, away_torn = 0;
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    const double d = centre_distance[i];
    disk += d < radius;
    if (std::abs(d - radius) < 3.0 * h) {
      ++rim;
      rim_torn += m.state[i] == kFoldTorn;
    } else {
      away_torn += m.state[i] == kFoldTorn;
    }
  }
  std::printf("spacing %.3g; thrown disk: %zu points, %zu within 3 spacings of its rim, %zu of them torn; %zu torn away from it\n", h, disk, rim, rim_torn, away_torn);
  assert_true(disk > 20);
  assert_true(rim_torn >= 0.35 * static_cast<double>(rim));  // 75 of 160
  assert_int_equal(away_torn, 0);
  assert_int_equal(m.torn, rim_torn);
  assert_int_equal(m.folded, 0);
  // The torn points count as decided and sound in the measure's figures.
  assert_true(share(m.undecided, m.points) < 0.02);
}

void closed_sheet_is_not_torn_across_the_boundary(void**) {
  // A whole cylinder cut along one generator: u = angle / 2 pi, v = height. Points on either
  // side of the cut are neighbours in 3D and a whole domain apart in (u,v), both at the
  // domain's border: a cut the boundary makes, not a tear.
  const Surface cylinder = [](double a, double b) { return Vec3(0.3 * std::cos(2.0 * M_PI * a), 0.3 * std::sin(2.0 * M_PI * a), b); };
  const Sample c = sample(cylinder, 4000, 26);
  const FoldMeasure m = measure_folds(c.points, c.u, c.v, 0.0, 2);
  assert_int_equal(m.torn, 0);
  assert_int_equal(m.folded, 0);
}

/// The height field with u mirrored (u -> 1-u) inside the disk of radius 0.2 about the
/// domain's centre.
struct Flipped {
  Sample c;
  std::vector<double> centre_distance;
};

Flipped flipped_patch() {
  Flipped f{sample(height_field(), 4000, 16), {}};
  for (std::size_t i = 0; i < f.c.u.size(); ++i) {
    const double d = std::hypot(f.c.u[i] - 0.5, f.c.v[i] - 0.5);
    f.centre_distance.push_back(d);
    if (d < 0.2) f.c.u[i] = 1.0 - f.c.u[i];
  }
  return f;
}

void flipped_patch_is_flagged(void**) {
  const Flipped f = flipped_patch();
  const FoldMeasure m = measure_folds(f.c.points, f.c.u, f.c.v, 0.0, 2);
  const CloudIndex index(f.c.points);
  const double h = cloud_spacing(index);
  std::size_t inner = 0, inner_folded = 0, outer = 0, outer_folded = 0;
  for (std::size_t i = 0; i < f.c.points.size(); ++i) {
    const double d = f.centre_distance[i];
    if (d < 0.2 - 2.0 * h) {
      ++inner;
      inner_folded += m.state[i] == kFolded;
    } else if (d > 0.2 + 2.0 * h) {
      ++outer;
      outer_folded += m.state[i] == kFolded;
    }
  }
  assert_true(inner > 300);
  assert_true(inner_folded >= 0.9 * inner);
  assert_int_equal(outer_folded, 0);
  assert_true(m.folded >= inner_folded);
  // Only points of the flipped disk or its rim fold.
  for (std::size_t i = 0; i < f.c.points.size(); ++i)
    if (m.state[i] == kFolded) assert_true(f.centre_distance[i] < 0.2 + 2.0 * h);
}

void global_mirror_folds_nothing(void**) {
  Sample c = sample(height_field(), 4000, 17);
  for (double& u : c.u) u = 1.0 - u;
  const FoldMeasure m = measure_folds(c.points, c.u, c.v, 0.0, 2);
  assert_int_equal(m.folded, 0);
  // The flipped patch mirrored as a whole: the disk is now the majority's sign, the rest folds.
  Flipped f = flipped_patch();
  for (double& u : f.c.u) u = 1.0 - u;
  const FoldMeasure mf = measure_folds(f.c.points, f.c.u, f.c.v, 0.0, 2);
  const FoldMeasure plain = measure_folds(f.c.points, flipped_patch().c.u, f.c.v, 0.0, 2);
  assert_true(mf.state == plain.state);
}

void scrambled_parameters_are_undecided(void**) {
  // Random (u,v): no neighbourhood is mapped by a linear map, so nothing is judged.
  Sample c = sample(height_field(), 4000, 22);
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (std::size_t i = 0; i < c.u.size(); ++i) c.u[i] = unit(rng), c.v[i] = unit(rng);
  const FoldMeasure m = measure_folds(c.points, c.u, c.v, 0.0, 2);
  assert_true(share(m.undecided, m.points) > 0.99);
  assert_true(m.folded <= m.points - m.undecided);
  // Most of them because no linear map explains their neighbours' (u,v): scrambled, the
  // verdict the repair acts on (a fine map has none).
  const std::size_t scrambled = static_cast<std::size_t>(std::count(m.state.begin(), m.state.end(), kFoldScrambled));
  assert_true(share(scrambled, m.points) > 0.5);
  const Sample fine = sample(height_field(), 4000, 22);
  const FoldMeasure f = measure_folds(fine.points, fine.u, fine.v, 0.0, 2);
  assert_int_equal(std::count(f.state.begin(), f.state.end(), kFoldScrambled), 0);
}

void verdicts_spread_to_the_nearest_judged_point(void**) {
  // A 40 x 40 grid, every third point judged with a made-up verdict by its index: each point
  // takes the verdict of the nearest judged one (checked by brute force), for any thread count.
  std::vector<Vec3> points;
  for (int j = 0; j < 40; ++j)
    for (int i = 0; i < 40; ++i) points.emplace_back(i * 0.1 + 0.003 * ((i * 7 + j * 3) % 5), j * 0.1, 0.01 * ((i + j) % 3));
  std::vector<std::size_t> judged;
  std::vector<std::int8_t> verdict;
  const std::int8_t kinds[] = {kFoldOk, kFolded, kFoldUndecided, kFoldCollapsed, kFoldScrambled};
  for (std::size_t i = 0; i < points.size(); i += 3) {
    judged.push_back(i);
    verdict.push_back(kinds[(i / 3) % 5]);
  }
  const std::vector<std::int8_t> one = spread_verdicts(points, judged, verdict, 1), two = spread_verdicts(points, judged, verdict, 2);
  assert_true(one == two);
  assert_int_equal(one.size(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::size_t best = 0;
    for (std::size_t k = 1; k < judged.size(); ++k)
      if ((points[judged[k]] - points[i]).squaredNorm() < (points[judged[best]] - points[i]).squaredNorm()) best = k;
    assert_int_equal(one[i], verdict[best]);
  }
  // Mismatched sizes and an index beyond the cloud are refused.
  for (int bad = 0; bad < 2; ++bad) {
    bool threw = false;
    try {
      if (bad == 0) spread_verdicts(points, judged, std::vector<std::int8_t>(verdict.begin(), verdict.end() - 1), 1);
      else spread_verdicts(points, {0, points.size()}, {kFoldOk, kFoldOk}, 1);
    } catch (const Error& e) {
      threw = e.code() == ErrorCode::InvalidArgument;
    }
    assert_true(threw);
  }
}

void coincident_count_is_exact(void**) {
  Sample c = sample(height_field(), 4000, 18);
  // 10 pairs with identical (u,v), one triple, one pair 1e-13 apart (counted), one pair 1e-11
  // apart (not counted), one exact duplicate point.
  for (std::size_t k = 0; k < 10; ++k) c.u[100 + k] = c.u[k], c.v[100 + k] = c.v[k];
  c.u[201] = c.u[200], c.v[201] = c.v[200], c.u[202] = c.u[200], c.v[202] = c.v[200];
  c.u[301] = c.u[300] + 1e-13, c.v[301] = c.v[300] - 1e-13;
  c.u[401] = c.u[400] + 1e-11, c.v[401] = c.v[400];
  c.points.push_back(c.points[500]), c.u.push_back(c.u[500]), c.v.push_back(c.v[500]);
  const std::size_t expected = 20 + 3 + 2 + 2;
  assert_int_equal(count_coincident(c.u, c.v), expected);
  const FoldMeasure m = measure_folds(c.points, c.u, c.v, 0.0, 2);
  assert_int_equal(m.coincident, expected);
  // Many points on one line u = 0 (as on a patch side) with distinct v: none coincide.
  std::vector<double> u(5000, 0.0), v(5000);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = static_cast<double>(i) / 5000.0;
  assert_int_equal(count_coincident(u, v), 0);
  v[4999] = v[0];
  assert_int_equal(count_coincident(u, v), 2);
}

void invariant_to_scale(void**) {
  const Surface s = height_field();
  for (int noisy = 0; noisy < 2; ++noisy) {
    Flipped f = flipped_patch();
    const double sigma = noisy ? 0.005 * diagonal(f.c.points) : 0.0;
    if (noisy) add_normal_noise(f.c, s, sigma, 19);
    std::vector<Vec3> scaled;
    for (const Vec3& p : f.c.points) scaled.push_back(move_and_scale(p, 1000.0));
    const FoldMeasure a = measure_folds(f.c.points, f.c.u, f.c.v, sigma, 2);
    const FoldMeasure b = measure_folds(scaled, f.c.u, f.c.v, 1000.0 * sigma, 2);
    assert_true(a.folded > 0);
    assert_true(a.state == b.state);
    assert_int_equal(a.folded, b.folded);
    assert_int_equal(a.undecided, b.undecided);
  }
}

void invariant_to_threads(void**) {
  Flipped f = flipped_patch();
  add_normal_noise(f.c, height_field(), 0.002, 20);
  const FoldMeasure one = measure_folds(f.c.points, f.c.u, f.c.v, 0.002, 1);
  const FoldMeasure three = measure_folds(f.c.points, f.c.u, f.c.v, 0.002, 3);
  assert_true(one.folded > 0);
  assert_true(one.state == three.state);
  assert_int_equal(one.folded, three.folded);
  assert_int_equal(one.undecided, three.undecided);
  assert_true(one.folded_share == three.folded_share);
}

void same(const FoldMeasure& a, const FoldMeasure& b) {
  assert_true(a.state == b.state);
  assert_int_equal(a.folded, b.folded);
  assert_int_equal(a.undecided, b.undecided);
  assert_int_equal(a.collapsed, b.collapsed);
  assert_int_equal(a.coincident, b.coincident);
  assert_true(a.folded_share == b.folded_share);
}

void kept_neighbourhoods_judge_as_a_fresh_measure(void**) {
  // One FoldNeighbourhoods judging several parameterizations of the same points, as the repair
  // does, in an order where the later ones reuse neighbourhoods (and wider retries, at the
  // cloud's border) found for the earlier: every verdict is that of a fresh measure_folds.
  for (int noisy = 0; noisy < 2; ++noisy) {
    Flipped f = flipped_patch();
    const double sigma = noisy ? 0.002 : 0.0;
    if (noisy) add_normal_noise(f.c, height_field(), sigma, 22);
    const std::vector<double> plain_u = f.c.u;
    std::vector<double> mirrored_u = f.c.u, scrambled_u = f.c.u;
    for (double& u : mirrored_u) u = 1.0 - u;
    std::mt19937_64 rng(23);
    std::shuffle(scrambled_u.begin(), scrambled_u.begin() + 400, rng);
    FoldNeighbourhoods kept(f.c.points, sigma);
    assert_int_equal(kept.size(), f.c.points.size());
    std::size_t folded = 0;
    for (const std::vector<double>* u : std::initializer_list<const std::vector<double>*>{&plain_u, &mirrored_u, &scrambled_u, &plain_u}) {
      const FoldMeasure fresh = measure_folds(f.c.points, *u, f.c.v, sigma, 2);
      same(kept.judge(*u, f.c.v, 2), fresh);
      same(kept.judge(*u, f.c.v, 1), fresh);
      folded += fresh.folded;
    }
    assert_true(folded > 0);
  }
  // A cloud judged scaled (1e30 across) and a tiny one, through the kept neighbourhoods too.
  Flipped f = flipped_patch();
  for (double factor : {1e30, 1e-30}) {
    std::vector<Vec3> scaled;
    for (const Vec3& p : f.c.points) scaled.push_back(p * factor);
    FoldNeighbourhoods kept(scaled, 0.0);
    same(kept.judge(f.c.u, f.c.v, 2), measure_folds(f.c.points, f.c.u, f.c.v, 0.0, 2));
  }
  // Bad parameters are refused by judge as by measure_folds, and the object stays usable.
  FoldNeighbourhoods kept(f.c.points, 0.0);
  std::vector<double> bad_v = f.c.v, short_v(f.c.v.begin(), f.c.v.end() - 1);
  bad_v[3] = NAN;
  for (const std::vector<double>* v : {&bad_v, &short_v}) {
    int code = -1;
    try {
      kept.judge(f.c.u, *v, 2);
    } catch (const Error& e) {
      code = static_cast<int>(e.code());
    }
    assert_int_equal(code, static_cast<int>(v == &bad_v ? ErrorCode::NonFinite : ErrorCode::InvalidArgument));
  }
  same(kept.judge(f.c.u, f.c.v, 2), measure_folds(f.c.points, f.c.u, f.c.v, 0.0, 2));
  int code = -1;
  try {
    FoldNeighbourhoods negative(f.c.points, -1.0);
  } catch (const Error& e) {
    code = static_cast<int>(e.code());
  }
  assert_int_equal(code, static_cast<int>(ErrorCode::InvalidArgument));
}

int error_code(const std::vector<Vec3>& p, const std::vector<double>& u, const std::vector<double>& v, double sigma) {
  try {
    measure_folds(p, u, v, sigma, 1);
  } catch (const Error& e) {
    return static_cast<int>(e.code());
  }
  return -1;
}

void bad_input_is_refused(void**) {
  Sample c = sample(height_field(), 100, 21);
  const int invalid = static_cast<int>(ErrorCode::InvalidArgument), nonfinite = static_cast<int>(ErrorCode::NonFinite);
  std::vector<double> short_u(c.u.begin(), c.u.end() - 1);
  assert_int_equal(error_code(c.points, short_u, c.v, 0.0), invalid);
  assert_int_equal(error_code(c.points, c.u, short_u, 0.0), invalid);
  assert_int_equal(error_code(c.points, c.u, c.v, -1.0), invalid);
  assert_int_equal(error_code(c.points, c.u, c.v, NAN), nonfinite);
  assert_int_equal(error_code(c.points, c.u, c.v, INFINITY), nonfinite);
  Sample bad = c;
  bad.points[7].y() = NAN;
  assert_int_equal(error_code(bad.points, bad.u, bad.v, 0.0), nonfinite);
  bad = c;
  bad.v[9] = INFINITY;
  assert_int_equal(error_code(bad.points, bad.u, bad.v, 0.0), nonfinite);
  bool threw = false;
  try {
    count_coincident(c.u, short_u);
  } catch (const Error& e) {
    threw = e.code() == ErrorCode::InvalidArgument;
  }
  assert_true(threw);
}

void tiny_inputs_are_undecided(void**) {
  const FoldMeasure empty = measure_folds({}, {}, {}, 0.0, 2);
  assert_int_equal(empty.points, 0);
  assert_int_equal(empty.undecided, 0);
  assert_true(empty.folded_share == 0.0);
  const std::vector<Vec3> three = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  const FoldMeasure m3 = measure_folds(three, {0, 1, 0}, {0, 0, 1}, 0.0, 2);
  assert_int_equal(m3.undecided, 3);
  assert_int_equal(m3.folded, 0);
  const std::vector<Vec3> same(50, Vec3(1, 2, 3));
  const FoldMeasure ms = measure_folds(same, std::vector<double>(50, 0.5), std::vector<double>(50, 0.5), 0.0, 2);
  assert_int_equal(ms.undecided, 50);
  assert_int_equal(ms.coincident, 50);
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(no_folds_on_clean_height_field),
      cmocka_unit_test(no_folds_on_curved_surfaces),
      cmocka_unit_test(noisy_height_field_folds_at_most_a_thousandth),
      cmocka_unit_test(creased_box_folds_at_most_a_thousandth),
      cmocka_unit_test(thin_flap_folds_nothing),
      cmocka_unit_test(thrown_points_are_torn),
      cmocka_unit_test(closed_sheet_is_not_torn_across_the_boundary),
      cmocka_unit_test(flipped_patch_is_flagged),
      cmocka_unit_test(squeezed_band_is_collapsed_not_folded),
      cmocka_unit_test(global_mirror_folds_nothing),
      cmocka_unit_test(scrambled_parameters_are_undecided),
      cmocka_unit_test(verdicts_spread_to_the_nearest_judged_point),
      cmocka_unit_test(coincident_count_is_exact),
      cmocka_unit_test(invariant_to_scale),
      cmocka_unit_test(invariant_to_threads),
      cmocka_unit_test(kept_neighbourhoods_judge_as_a_fresh_measure),
      cmocka_unit_test(bad_input_is_refused),
      cmocka_unit_test(tiny_inputs_are_undecided),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
