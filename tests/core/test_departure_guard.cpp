// The departure guard of the curve projection (departure_guard.hpp): a node sitting on the
// cloud whose ray meets a dense clump far off the sheet is held on the sheet, and its
// neighbours stay there too; a node approaching the cloud or lying over a hole is never held;
// fixed nodes stay exactly put; sizes that do not match are refused.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "cloud_index.hpp"
#include "curve_projection.hpp"
#include "departure_guard.hpp"
#include "core_test_support.hpp"  // last of the dbs headers

using namespace dbs;

namespace {

constexpr double kGamma = 0.5;

/// A jittered grid of pitch 1 over [0,40] x [0,20] in z = 0, without the points with
/// hole_from < x < hole_to, and `clump` points within 0.05 of (20, 10, 8): an off-sheet
/// clump on the vertical ray of the node at x = 20.
std::vector<Vec3> sheet_with_clump(int clump, double hole_from = 1e9, double hole_to = -1e9) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3), tiny(-0.05, 0.05);
  std::vector<Vec3> pts;
  for (int j = 0; j <= 20; ++j)
    for (int i = 0; i <= 40; ++i) {
      const double x = i + jitter(rng), y = j + jitter(rng);
      if (!(x > hole_from && x < hole_to)) pts.emplace_back(x, y, 0.0);
    }
  for (int k = 0; k < clump; ++k) pts.emplace_back(20.0 + tiny(rng), 10.0 + tiny(rng), 8.0 + tiny(rng));
  return pts;
}

/// Nodes along y = 10 at x = 0, 1, ..., 40 at height z(x), projected vertically.
CurveProjectionInput line_at(double (*z)(double)) {
  CurveProjectionInput in;
  for (int i = 0; i <= 40; ++i) {
    in.nodes.emplace_back(i, 10.0, z(i));
    in.directions.emplace_back(0.0, 0.0, 1.0);
  }
  return in;
}

double on_sheet(double) { return 0.0; }

double largest_height(const CurveProjectionInput& in, const std::vector<double>& t) {
  double worst = 0.0;
  for (std::size_t k = 0; k < t.size(); ++k) worst = std::max(worst, std::abs(in.nodes[k].z() + t[k] * in.directions[k].z()));
  return worst;
}

void clump_on_a_ray_does_not_pull_the_curve_off_the_sheet(void**) {
  const std::vector<Vec3> pts = sheet_with_clump(400);
  const CloudIndex index(pts);
  const DirectedProjector projector(index, cloud_spacing(index));
  const double h = projector.length_scale();
  CurveProjectionInput plain = line_at(on_sheet), guarded = plain;
  const double unguarded = largest_height(plain, project_curve(projector, plain, kGamma));
  std::size_t held = 0;
  const std::vector<double> t = solve_curve_near(projector, guarded, kGamma, RefinementSettings(), nullptr, &held);
  const double kept = largest_height(guarded, t);
  std::printf("clump 8 units above the sheet: the plain projection lifts the curve %.2f h, the guarded one %.3f h (%zu node(s) held)\n", unguarded / h, kept / h, held);
  assert_true(unguarded > 3.0 * h);  // the failure the guard is for
  assert_true(kept < 0.5 * h);
  assert_true(held >= 1 && held <= 7);  // the clump's node and neighbours its pull reaches
  // The held nodes are fixed: offset 0 exactly, and listed in input.fixed.
  assert_true(guarded.fixed.size() == held);
  for (std::size_t f : guarded.fixed) assert_true(t[f] == 0.0);
}

double lifted(double x) { return x == 0.0 || x == 40.0 ? 0.0 : 6.0; }

void approaching_and_bridging_nodes_are_not_held(void**) {
  // Every interior node 6 units above the sheet, which has a hole 8 units wide under the
  // middle: all nodes come nearer the cloud, those over the hole follow their neighbours.
  const std::vector<Vec3> pts = sheet_with_clump(0, 16.0, 24.0);
  const CloudIndex index(pts);
  const DirectedProjector projector(index, cloud_spacing(index));
  CurveProjectionInput in = line_at(lifted);
  const std::vector<double> plain = project_curve(projector, in, kGamma);
  std::size_t held = 0;
  const std::vector<double> t = solve_curve_near(projector, in, kGamma, RefinementSettings(), nullptr, &held);
  assert_int_equal(held, 0);
  assert_true(in.fixed.empty());
  assert_true(t == plain);
  assert_true(largest_height(in, t) < 0.5 * projector.length_scale());
}

void departure_is_judged_against_the_tolerance(void**) {
  const std::vector<Vec3> pts = sheet_with_clump(0);
  const CloudIndex index(pts);
  const DirectedProjector projector(index, 1.0);
  CurveProjectionInput in = line_at(on_sheet);
  std::vector<double> offsets(in.nodes.size(), 0.0);
  offsets[5] = 0.9;    // leaves the sheet by less than the tolerance
  offsets[10] = 1.5;   // by more
  offsets[40] = 30.0;  // an end: never held (ends are fixed)
  in.fixed.push_back(20);
  offsets[20] = 5.0;   // already fixed: not listed again
  assert_int_equal(hold_departing_nodes(projector, in, offsets, 1.0), 1);
  assert_int_equal(in.fixed.size(), 2);
  assert_int_equal(in.fixed.back(), 10);
  // Sizes that do not match the nodes are refused, the input untouched.
  offsets.pop_back();
  assert_true(core_test::throws(ErrorCode::InvalidArgument, [&] { hold_departing_nodes(projector, in, offsets, 1.0); }));
  offsets.push_back(0.0);
  in.fixed.push_back(in.nodes.size());
  assert_true(core_test::throws(ErrorCode::OutOfRange, [&] { hold_departing_nodes(projector, in, offsets, 1.0); }));
  assert_int_equal(in.fixed.size(), 3);
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(clump_on_a_ray_does_not_pull_the_curve_off_the_sheet),
      cmocka_unit_test(approaching_and_bridging_nodes_are_not_held),
      cmocka_unit_test(departure_is_judged_against_the_tolerance),
  };
  return cmocka_run_group_tests_name("departure_guard", tests, nullptr, nullptr);
}
