// The repair's fill (harmonic_fill.hpp) on the tallest finger of the fingers shape: every
// other point keeps its true (u,v), the finger's wall and tip are filled from them. The
// harmonic fill crushes the tip (collapsed reference triangles); the stretch balance spreads
// it and keeps it unfolded. A region that is not crushed (a patch of the flat plate) is left
// exactly as the harmonic fill put it.
#include <algorithm>
#include <cmath>
#include <vector>

#include "cloud_index.hpp"
#include "fold_shapes.hpp"
#include "harmonic_fill.hpp"
#include "result.hpp"

// cmocka last: its fail() macro would hide dbs::fail.
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
extern "C" {
#include <cmocka.h>
}

namespace {

using dbs::Vec3;

struct Setup {
  dbs_folds::FoldShape shape = dbs_folds::fold_shape("fingers");
  std::vector<Vec3> points;
  dbs::Result result;
  dbs::FillRows rows;

  /// The points for which `inside(point)` holds become rows (12 nearest points, inverse-distance
  /// weights, as the repair builds them), placed at `start` and filled harmonically.
  template <class Inside>
  Setup(Inside inside, double start_u, double start_v) {
    for (std::size_t k = 0; k < shape.count(); ++k) points.emplace_back(shape.xyz[3 * k], shape.xyz[3 * k + 1], shape.xyz[3 * k + 2]);
    result.u.resize(points.size());
    result.v.resize(points.size());
    for (std::size_t k = 0; k < points.size(); ++k) {
      result.u[k] = shape.uv_true[2 * k];
      result.v[k] = shape.uv_true[2 * k + 1];
    }
    const dbs::CloudIndex index(points);
    for (std::size_t k = 0; k < points.size(); ++k) {
      if (!inside(points[k])) continue;
      std::vector<std::size_t> ids, near;
      std::vector<double> d2, w;
      index.knn(points[k], 13, ids, d2);
      double sum = 0.0;
      for (std::size_t m = 0; m < ids.size(); ++m) {
        if (ids[m] == k) continue;
        near.push_back(ids[m]);
        w.push_back(1.0 / std::sqrt(d2[m]));
        sum += w.back();
      }
      for (double& x : w) x /= sum;
      rows.ids.push_back(k);
      rows.neighbours.push_back(near);
      rows.weights.push_back(w);
      result.u[k] = start_u;
      result.v[k] = start_v;
    }
    dbs::fill_sweeps(result, rows, dbs::kFillSweeps);
  }

  std::vector<double> uv() const {
    std::vector<double> out;
    for (std::size_t k = 0; k < points.size(); ++k) out.push_back(result.u[k]), out.push_back(result.v[k]);
    return out;
  }
};

// The tallest finger stands at (0.6, 0.72) on the 1.2 x 1 plate, 0.29 tall, radius 0.03.
bool finger_wall(const Vec3& p) { return std::hypot(p.x() - 0.6, p.y() - 0.72) < 0.04 && p.z() > 0.02; }

void stretch_balance_spreads_a_crushed_finger(void**) {
  Setup s(finger_wall, 0.5, 0.72);
  assert_true(s.rows.ids.size() > 60);
  const dbs_folds::FoldCount harmonic = dbs_folds::fold_share(s.uv(), s.shape.triangles);
  const dbs::CloudIndex index(s.points);
  const std::size_t changed = dbs::balance_stretch(s.result, s.points, index, s.rows, 2);
  const dbs_folds::FoldCount balanced = dbs_folds::fold_share(s.uv(), s.shape.triangles);
  std::printf("finger: harmonic %zu folded (%zu collapsed), balanced %zu (%zu), %zu rows\n", harmonic.folded, harmonic.collapsed, balanced.folded, balanced.collapsed,
              s.rows.ids.size());
  assert_int_equal(changed, s.rows.ids.size());
  assert_true(harmonic.collapsed >= 20);
  assert_true(4 * balanced.folded <= harmonic.folded);
  // Every row stays inside the (u,v) disk of the finger's fixed surroundings (a convex
  // combination of them).
  std::vector<char> row(s.points.size(), 0);
  for (std::size_t i : s.rows.ids) row[i] = 1;
  double rim = 0.0;
  for (const auto& near : s.rows.neighbours)
    for (std::size_t m : near)
      if (!row[m]) rim = std::max(rim, std::hypot(s.result.u[m] - 0.5, s.result.v[m] - 0.72));
  for (std::size_t i : s.rows.ids) assert_true(std::hypot(s.result.u[i] - 0.5, s.result.v[i] - 0.72) < rim);
}

void a_region_that_is_not_crushed_stays(void**) {
  Setup s([](const Vec3& p) { return std::hypot(p.x() - 0.3, p.y() - 0.8) < 0.06; }, 0.25, 0.8);
  assert_true(s.rows.ids.size() > 20);
  const std::vector<double> before = s.uv();
  const dbs::CloudIndex index(s.points);
  assert_int_equal(dbs::balance_stretch(s.result, s.points, index, s.rows, 2), 0);
  assert_true(s.uv() == before);
}

void the_balance_does_not_depend_on_threads(void**) {
  Setup a(finger_wall, 0.5, 0.72), b(finger_wall, 0.5, 0.72);
  const dbs::CloudIndex index(a.points);
  dbs::balance_stretch(a.result, a.points, index, a.rows, 1);
  dbs::balance_stretch(b.result, b.points, index, b.rows, 3);
  assert_true(a.uv() == b.uv());
}

}  // namespace

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(stretch_balance_spreads_a_crushed_finger),
      cmocka_unit_test(a_region_that_is_not_crushed_stays),
      cmocka_unit_test(the_balance_does_not_depend_on_threads),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
