// The shape checks of a boundary (lib/surface/boundary_shape): every analytic fold shape of
// tests/support (the 270-degree sphere cap, the mushroom, the open box, ...) is accepted at
// every magnitude supported; a curl of a side is tolerated below kCurlLength of the loop and
// refused above it; crossings farther apart than kCrossingGap along the normal are accepted.
// The refusals through the C API are in tests/capi/test_boundary_shape.c.
#include <cmath>
#include <string>
#include <vector>

#include "boundary.hpp"
#include "boundary_shape.hpp"
#include "fold_shapes.hpp"

#include "core_test_support.hpp"

using dbs::Boundary;
using dbs::ErrorCode;
using dbs::Vec3;
using Points = std::vector<Vec3>;

namespace {

Points to_points(const std::vector<double>& xyz, double scale) {
  Points out;
  for (std::size_t k = 0; k + 2 < xyz.size(); k += 3) out.emplace_back(scale * xyz[k], scale * xyz[k + 1], scale * xyz[k + 2]);
  return out;
}

void fold_shapes_accepted(void**) {
  for (const std::string& name : dbs_folds::fold_shape_names()) {
    const dbs_folds::FoldShape shape = dbs_folds::fold_shape(name);
    for (double scale : {1.0, 1e-100, 1e75}) {
      try {
        const Boundary b(to_points(shape.bottom, scale), to_points(shape.right, scale), to_points(shape.top, scale), to_points(shape.left, scale));
        assert_true(b.size() > 0.0);
      } catch (const dbs::Error& e) {
        fail_msg("%s x %g refused: %s", name.c_str(), scale, e.what());
      }
    }
  }
}

// The unit square whose bottom ties a knot: out to (0.5 + r, 0), up and round a square of
// side r, crossing itself at (0.5, 0).
Boundary square_with_curl(double r) {
  const Points bottom = {Vec3(0, 0, 0), Vec3(0.5 + r, 0, 0), Vec3(0.5 + r, r, 0), Vec3(0.5, r, 0), Vec3(0.5, -r, 0), Vec3(1, 0, 0)};
  return Boundary(bottom, {Vec3(1, 0, 0), Vec3(1, 1, 0)}, {Vec3(0, 1, 0), Vec3(1, 1, 0)}, {Vec3(0, 0, 0), Vec3(0, 1, 0)});
}

void small_curls_tolerated(void**) {
  // The loop is about 4 long; the curl closed at the crossing is 4 r long (3 r of square
  // and r down to the crossing). The small one is also well below the fold check's window
  // (a curl about as wide as that window turns back within it: a fold).
  const double loop_length = 4.0;
  const double small = 0.1 * dbs::kCurlLength * loop_length / 4.0, large = 2.0 * dbs::kCurlLength * loop_length / 4.0;
  assert_true(square_with_curl(small).size() > 1.0);
  core_test::expect_error([&] { square_with_curl(large); }, ErrorCode::Degenerate, {"side 'bottom' crosses itself", "(0.5, 0, 0)"});
}

// The bow-tie (bottom and top crossing on the diagonal) with the top raised by `lift`.
Boundary lifted_bow_tie(double lift) {
  return Boundary({Vec3(0, 0, 0), Vec3(1, 1, 0)}, {Vec3(1, 1, 0), Vec3(1, 0, lift)}, {Vec3(0, 1, lift), Vec3(1, 0, lift)},
                  {Vec3(0, 0, 0), Vec3(0, 1, lift)});
}

void crossing_gap_decides(void**) {
  // The size is sqrt(2 + lift^2) (about 1.414): strands half kCrossingGap of it apart
  // cross, strands twice it apart pass each other.
  const double size = std::sqrt(2.0);
  core_test::expect_error([&] { lifted_bow_tie(0.5 * dbs::kCrossingGap * size); }, ErrorCode::Degenerate, {"bow-tie"});
  assert_true(lifted_bow_tie(2.0 * dbs::kCrossingGap * size).size() > 1.0);
}

void polyline_sides_not_checked(void**) {
  // Children of a subdivision are made from already-checked sides (and projected middle
  // curves): only the corners and the area are checked there, not the shape.
  const dbs::Polyline bottom({Vec3(0, 0, 0), Vec3(0.8, 0, 0), Vec3(0.3, 0, 0.2), Vec3(1, 0, 0)});
  const Boundary b(bottom, dbs::Polyline({Vec3(1, 0, 0), Vec3(1, 1, 0)}), dbs::Polyline({Vec3(0, 1, 0), Vec3(1, 1, 0)}),
                   dbs::Polyline({Vec3(0, 0, 0), Vec3(0, 1, 0)}));
  assert_true(b.size() > 1.0);
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(fold_shapes_accepted),
      cmocka_unit_test(small_curls_tolerated),
      cmocka_unit_test(crossing_gap_decides),
      cmocka_unit_test(polyline_sides_not_checked),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
