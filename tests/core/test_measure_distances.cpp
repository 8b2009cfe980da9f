// The measurement of a growing grid (evolve.hpp, measure_distances): with a bound to stop
// above, a measurement whose error stays below the bound gives the very figures and feet of one
// without it; one whose error is above it stops early with a lower bound that is itself above
// the bound, leaves most feet untouched, and gives the same bits for every thread count.
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "analytic_clouds.hpp"
#include "base_surface.hpp"
#include "evolve.hpp"
#include "surface_projection.hpp"

// cmocka last (its fail() macro would hide dbs::fail), with C linkage (its header does
// not declare it).
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
extern "C" {
#include <cmocka.h>
}

using namespace dbs;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// The flat unit square (the Coons patch of its four straight sides).
BaseSurface flat_square() { return BaseSurface(dbs_test::boundary_of([](double x, double y) { return Vec3(x, y, 0.0); }, 9)); }

/// 3,600 random points of a bump over the unit square: they lie off the flat square by up
/// to 0.1 (mean about 0.04).
std::vector<Vec3> bump_cloud() { return dbs_test::random_points([](double x, double y) { return Vec3(x, y, 0.1 * std::sin(M_PI * x) * std::sin(M_PI * y)); }, 3600, 5); }

PointList all_of(const std::vector<Vec3>& pts) {
  PointList indices(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) indices[i] = static_cast<std::uint32_t>(i);
  return indices;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

struct Measured {
  double mean = 0.0, max = 0.0, loss = 0.0;
  bool stopped = false;
  std::vector<Vec2> feet;
};

Measured measure(const SurfaceProjector& projector, const std::vector<Vec3>& pts, int threads, double stop_above, LossKind loss = LossKind::None) {
  Measured m;
  m.feet.assign(pts.size(), Vec2(std::nan(""), std::nan("")));
  measure_distances(projector, pts, all_of(pts), 1, threads, m.mean, m.max, loss, 0.02, loss == LossKind::None ? nullptr : &m.loss, nullptr, &m.feet, 1, stop_above,
                    &m.stopped);
  return m;
}

bool same_feet(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k)
    for (int c = 0; c < 2; ++c)
      if (!(same_bits(a[k][c], b[k][c]) || (std::isnan(a[k][c]) && std::isnan(b[k][c])))) return false;
  return true;
}

void a_bound_above_the_error_changes_nothing(void**) {
  const std::vector<Vec3> pts = bump_cloud();
  const BaseSurface surface = flat_square();
  const SurfaceProjector projector(surface, FootPrecision::Measure);
  const Measured whole = measure(projector, pts, 1, kInf);
  assert_false(whole.stopped);
  assert_true(whole.mean > 0.03 && whole.mean < 0.05);
  // The bound just above the mean: every point is measured, the figures are the same bits.
  const Measured bounded = measure(projector, pts, 1, whole.mean * 1.0001);
  assert_false(bounded.stopped);
  assert_true(same_bits(bounded.mean, whole.mean));
  assert_true(same_bits(bounded.max, whole.max));
  assert_true(same_feet(bounded.feet, whole.feet));
}

void a_bound_below_the_error_stops_early(void**) {
  const std::vector<Vec3> pts = bump_cloud();
  const BaseSurface surface = flat_square();
  const SurfaceProjector projector(surface, FootPrecision::Measure);
  const Measured whole = measure(projector, pts, 1, kInf);
  const double bound = 0.25 * whole.mean;
  const Measured stopped = measure(projector, pts, 1, bound);
  assert_true(stopped.stopped);
  // A lower bound of the mean, and above the bound: the caller's decision is the same.
  assert_true(stopped.mean > bound);
  assert_true(stopped.mean <= whole.mean);
  assert_true(stopped.max <= whole.max);
  // Stopped after the first round or two: most points were not measured, their feet unset.
  std::size_t unmeasured = 0;
  for (const Vec2& f : stopped.feet) unmeasured += std::isnan(f.x()) ? 1 : 0;
  assert_true(unmeasured >= pts.size() / 2);
  // Every measured foot is the one the whole measurement found.
  for (std::size_t k = 0; k < pts.size(); ++k)
    if (!std::isnan(stopped.feet[k].x())) assert_true(same_bits(stopped.feet[k].x(), whole.feet[k].x()) && same_bits(stopped.feet[k].y(), whole.feet[k].y()));
}

/// Whatever the bound, the measurement decides as the whole one does: it stops only when the
/// whole sample's mean is above the bound, and a stopped one reports a mean above it (so the
/// caller's test `error <= target` never accepts a measurement that stopped), down to bounds
/// an ulp or two from the whole mean.
void the_decision_is_that_of_the_whole_measurement(void**) {
  const std::vector<Vec3> pts = bump_cloud();
  const BaseSurface surface = flat_square();
  const SurfaceProjector projector(surface, FootPrecision::Measure);
  const Measured whole = measure(projector, pts, 1, kInf);
  std::vector<double> bounds;
  for (double f : {0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 0.9, 0.99, 0.999999, 1.0, 1.000001, 1.5}) bounds.push_back(f * whole.mean);
  double below = whole.mean, above = whole.mean;
  for (int k = 0; k < 3; ++k) {
    below = std::nextafter(below, 0.0);
    above = std::nextafter(above, kInf);
    bounds.push_back(below);
    bounds.push_back(above);
  }
  std::size_t stops = 0;
  for (double bound : bounds) {
    const Measured m = measure(projector, pts, 1, bound);
    if (m.stopped) {
      ++stops;
      assert_true(m.mean > bound);
    } else {
      assert_true(same_bits(m.mean, whole.mean));
    }
    assert_true((m.mean > bound) == (whole.mean > bound));
  }
  assert_true(stops >= 3);  // the low bounds stop early
}

void the_robust_error_stops_on_the_loss(void**) {
  const std::vector<Vec3> pts = bump_cloud();
  const BaseSurface surface = flat_square();
  const SurfaceProjector projector(surface, FootPrecision::Measure);
  const Measured whole = measure(projector, pts, 1, kInf, LossKind::Huber);
  assert_true(whole.loss > 0.0);
  // The loss's mean decides: a bound above it (though below the plain mean, if that is larger)
  // measures everything; a bound well below it stops.
  const Measured above = measure(projector, pts, 1, whole.loss * 1.0001, LossKind::Huber);
  assert_false(above.stopped);
  assert_true(same_bits(above.loss, whole.loss) && same_bits(above.mean, whole.mean));
  const Measured below = measure(projector, pts, 1, 0.25 * whole.loss, LossKind::Huber);
  assert_true(below.stopped);
  assert_true(below.loss > 0.25 * whole.loss && below.loss <= whole.loss);
}

void an_early_stop_is_the_same_for_every_thread_count(void**) {
  const std::vector<Vec3> pts = bump_cloud();
  const BaseSurface surface = flat_square();
  const SurfaceProjector projector(surface, FootPrecision::Measure);
  const Measured one = measure(projector, pts, 1, 0.01);
  assert_true(one.stopped);
  for (int threads : {2, 3, 8}) {
    const Measured many = measure(projector, pts, threads, 0.01);
    assert_true(many.stopped);
    assert_true(same_bits(many.mean, one.mean) && same_bits(many.max, one.max));
    assert_true(same_feet(many.feet, one.feet));
  }
}

}  // namespace

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(a_bound_above_the_error_changes_nothing),
      cmocka_unit_test(a_bound_below_the_error_stops_early),
      cmocka_unit_test(the_decision_is_that_of_the_whole_measurement),
      cmocka_unit_test(the_robust_error_stops_on_the_loss),
      cmocka_unit_test(an_early_stop_is_the_same_for_every_thread_count),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
