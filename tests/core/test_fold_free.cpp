// The fold-free method on the hard shapes of tests/support/fold_shapes (issue 10), with the
// default options: folded reference triangles (their signed (u,v) area negative or collapsed
// below 1e-3 of the median), the result surface's distance to the noise-free truth, the
// noise estimate and the noise floor, levels, and the library's own reference-free fold
// measure. The reference triangles are used only here, never by the library.
//
// Two groups:
// - what holds: the noisy saddle (sigma = 0.5% of the diagonal) folds nothing and its
//   surface stays on the truth; the noise does not change the rippled field's level count;
//   the noise estimate is calibrated; the floor is what keeps a noisy cloud from being
//   chased; the reference-free measure reports no folds where there are none.
// - what does not hold yet (the issue asks 0 folds on every shape): the overhanging,
//   steep and pointed shapes still fold a few percent. Their bounds are today's figures
//   (dbs-bench-folds, README) with a small margin, so a regression fails; tightening them
//   is the open part of the fold-free work. This group is labelled "slow" (about half a
//   minute) and left out of the sanitizer run.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "boundary.hpp"
#include "fold_measure.hpp"
#include "fold_repair.hpp"
#include "fold_shapes.hpp"
#include "meshless_reference.hpp"
#include "parameterize.hpp"
#include "point_cloud.hpp"
#include "turned_sheets.hpp"

#include "core_test_support.hpp"

namespace {

using dbs::Vec3;
using dbs_folds::FoldShape;

std::vector<Vec3> points_of(const std::vector<double>& xyz, double scale = 1.0) {
  std::vector<Vec3> p;
  for (std::size_t i = 0; i + 2 < xyz.size(); i += 3) p.emplace_back(scale * xyz[i], scale * xyz[i + 1], scale * xyz[i + 2]);
  return p;
}

struct Run {
  dbs::Result result;
  dbs_folds::FoldCount folds;
  double to_truth = 0.0;  // mean |S(u_i, v_i) - noise-free surface|
  std::size_t turned_truth = 0;  // points where the surface's Su x Sv points against the noise-free normal
};

Run run(const FoldShape& shape, dbs::Options options = {}, double scale = 1.0) {
  const dbs::Boundary boundary(points_of(shape.bottom, scale), points_of(shape.right, scale), points_of(shape.top, scale), points_of(shape.left, scale));
  // These shapes are the input checks' controls (input_checks.hpp): overhangs, a 270-degree
  // cap, protrusions and creases are no mistake, so no run here warns.
  std::vector<std::string> warnings;
  options.warning = [&warnings](const char* message) { warnings.emplace_back(message); };
  Run r{dbs::parameterize(dbs::PointCloud(points_of(shape.xyz, scale)), boundary, options), {}, 0.0};
  for (const std::string& w : warnings) std::printf("%s: unexpected warning: %s\n", shape.name.c_str(), w.c_str());
  assert_true(warnings.empty());
  assert_int_equal(r.result.far_points, 0);
  std::vector<double> uv, on_surface;
  for (std::size_t i = 0; i < r.result.u.size(); ++i) {
    uv.push_back(r.result.u[i]);
    uv.push_back(r.result.v[i]);
    const Vec3 s = r.result.evaluate(r.result.u[i], r.result.v[i]) / scale;
    on_surface.insert(on_surface.end(), {s.x(), s.y(), s.z()});
    const dbs_folds::Point3 truth = dbs_folds::surface_normal(shape.surface, shape.uv_true[2 * i], shape.uv_true[2 * i + 1]);
    Vec3 su, sv;
    r.result.derivatives(r.result.u[i], r.result.v[i], su, sv);
    const bool reached = !dbs::beyond_repair_reach(r.result, i);  // turned sheets are judged on the surface only
    if (reached && Vec3(truth[0], truth[1], truth[2]) != Vec3::Zero() && !(su.cross(sv).dot(Vec3(truth[0], truth[1], truth[2])) > 0.0)) ++r.turned_truth;
  }
  r.folds = dbs_folds::fold_share(uv, shape.triangles);
  r.to_truth = dbs_folds::mean_distance_to_surface(shape, on_surface);
  std::printf("%-13s levels %d patches %3zu folds %4zu (%5.2f%%) mean %.3g to truth %.3g target %.3g (requested %.3g) noise %.3g measure %.2f%% (%zu/%zu undecided)\n",
              shape.name.c_str(), r.result.levels, r.result.patches.size(), r.folds.folded, 100.0 * r.folds.share, r.result.mean_distance, r.to_truth,
              r.result.accuracy, r.result.requested_accuracy, r.result.noise, 100.0 * r.result.folded_share, r.result.undecided_points, r.result.judged_points);
  std::printf("%-13s collapsed %zu of the undecided; turned %zu (%.2f%%), against the truth %zu\n", shape.name.c_str(), r.result.collapsed_points, r.result.turned_points,
              100.0 * r.result.turned_share, r.turned_truth);
  return r;
}

void noisy_saddle_stays_on_the_truth_and_folds_nothing(void**) {
  const FoldShape shape = dbs_folds::saddle(dbs_folds::kSaddleNoise);
  const Run r = run(shape);
  assert_int_equal(r.folds.folded, 0);
  assert_true(r.to_truth < shape.noise_sigma / 3.0);
  // Its surface turns nowhere, by the truth and by the library's own measure.
  assert_int_equal(r.turned_truth, 0);
  assert_int_equal(r.result.turned_points, 0);
  // The estimate is calibrated (within 30% of the true sigma) and raised the target to the
  // floor 1.25 sigma sqrt(2/pi); a single patch then fits.
  std::printf("noisy saddle: sigma %.4g, estimated %.4g\n", shape.noise_sigma, r.result.noise);
  assert_true(std::abs(r.result.noise - shape.noise_sigma) <= 0.3 * shape.noise_sigma);
  assert_true(std::abs(r.result.accuracy - 1.25 * r.result.noise * std::sqrt(2.0 / M_PI)) <= 1e-12 * r.result.accuracy);
  assert_true(r.result.accuracy > r.result.requested_accuracy);
  assert_true(r.result.accuracy_met);
  assert_false(r.result.requested_accuracy_met);  // 1e-3 of the diagonal is below what the noise allows
  assert_int_equal(r.result.levels, 1);
  assert_true(r.result.folded_share <= 0.001);
}

void without_the_floor_the_noise_is_chased(void**) {
  const FoldShape shape = dbs_folds::saddle(dbs_folds::kSaddleNoise);
  dbs::Options options;
  options.noise_floor = 0;
  options.max_level = 2;
  const Run r = run(shape, options);
  assert_true(r.result.accuracy == r.result.requested_accuracy);
  assert_int_equal(r.result.levels, 3);  // every patch subdivides to the last level
  assert_false(r.result.accuracy_met);
}

void repair_leaves_a_noisy_cloud_alone(void**) {
  // The noise floor gates the repair: no noisy point is taken for one the surface missed.
  dbs::Options options;
  options.repair = 1;
  const Run r = run(dbs_folds::saddle(dbs_folds::kSaddleNoise), options);
  assert_int_equal(r.result.repaired_points, 0);
  assert_int_equal(r.folds.folded, 0);
}

void gross_outliers_left_alone(double offset) {
  // 2% of the saddle's points, drawn at random, moved `offset` times its diagonal along z: far
  // from the surface, but each alone, so the repair neither moves them nor fits the surface
  // through them: the result is the one without the repair, bit for bit. At 0.3 x the
  // diagonal the outliers of one side are nearer to each other than to the surface (their 12
  // nearest points are all outliers), yet they form no sheet: they are about 7 times the
  // cloud's spacing apart.
  FoldShape shape = dbs_folds::saddle();
  std::uint64_t state = 12345;
  std::vector<std::size_t> moved;
  for (std::size_t k = 0; k < shape.count(); ++k) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    if ((state >> 33) % 50 != 0) continue;
    shape.xyz[3 * k + 2] += ((state >> 20) & 1) ? offset * shape.diagonal : -offset * shape.diagonal;
    moved.push_back(k);
  }
  dbs::Options off;
  off.repair = 0;
  const Run on = run(shape), plain = run(shape, off);
  // They are far, as the repair sees it: beyond 10x the target and one spacing.
  assert_true(moved.size() > 40);
  for (std::size_t k : moved) assert_true(plain.result.distance[k] > 10.0 * plain.result.accuracy && plain.result.distance[k] > plain.result.length_scale);
  assert_int_equal(on.result.repaired_points, 0);
  assert_true(on.result.u == plain.result.u && on.result.v == plain.result.v && on.result.distance == plain.result.distance);
}

void repair_leaves_gross_outliers_alone(void**) {
  gross_outliers_left_alone(0.05);
  gross_outliers_left_alone(0.3);
}

void repair_sets_a_scrambled_region_right(void**) {
  // The clean saddle's result, then the (u,v) of the 60 points nearest its middle point
  // shuffled among them (a region whose points a surface pleated below its grid's scale
  // would scatter): the fold measure finds no local map there (scrambled or folded, never
  // fine), and the repair fills those points from the ones around, so that no reference
  // triangle folds again; the points around keep their (u,v) bit for bit.
  const FoldShape shape = dbs_folds::saddle();
  dbs::Options off;
  off.repair = 0;
  Run r = run(shape, off);
  assert_int_equal(r.folds.folded, 0);
  const std::vector<Vec3> points = points_of(shape.xyz);
  const std::size_t middle = shape.grid_a / 2 + shape.grid_a * (shape.grid_b / 2);
  std::vector<std::size_t> region(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) region[i] = i;
  std::sort(region.begin(), region.end(), [&](std::size_t a, std::size_t b) { return (points[a] - points[middle]).norm() < (points[b] - points[middle]).norm(); });
  region.resize(60);
  dbs::Result& result = r.result;
  const std::vector<double> u0 = result.u, v0 = result.v;
  std::uint64_t state = 99;
  for (std::size_t k = region.size() - 1; k > 0; --k) {  // Fisher-Yates with a fixed LCG
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    const std::size_t j = static_cast<std::size_t>((state >> 33) % (k + 1));
    std::swap(result.u[region[k]], result.u[region[j]]);
    std::swap(result.v[region[k]], result.v[region[j]]);
  }
  for (std::size_t i : region) result.distance[i] = (result.evaluate(result.u[i], result.v[i]) - points[i]).norm();
  auto folded = [&] {
    std::vector<double> uv;
    for (std::size_t i = 0; i < points.size(); ++i) uv.insert(uv.end(), {result.u[i], result.v[i]});
    return dbs_folds::fold_share(uv, shape.triangles).folded;
  };
  const std::size_t scrambled_folds = folded();
  const dbs::FoldMeasure measure = dbs::measure_folds(points, result.u, result.v, result.noise, 1);
  std::size_t doubtful = 0, fine = 0;
  for (std::size_t i : region) {
    doubtful += measure.state[i] == dbs::kFoldScrambled || measure.state[i] == dbs::kFolded;
    fine += measure.state[i] == dbs::kFoldOk;
  }
  std::printf("scrambled region: %zu points, %zu reference folds, %zu judged scrambled or folded, %zu fine\n", region.size(), scrambled_folds, doubtful, fine);
  assert_true(scrambled_folds >= region.size() / 2);
  assert_true(doubtful >= region.size() * 3 / 4);
  const dbs::Repair repair = dbs::repair_folds(result, points, dbs::doubtful_points(result, points, {}, measure.state, 1), 1);
  std::printf("scrambled region: %zu points repaired, %zu reference folds after\n", repair.repaired, folded());
  assert_int_equal(folded(), 0);
  assert_true(repair.repaired >= region.size() * 3 / 4);
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (result.repaired[i]) continue;
    const bool inside = std::find(region.begin(), region.end(), i) != region.end();
    if (!inside) assert_true(result.u[i] == u0[i] && result.v[i] == v0[i]);
  }
}

void clean_saddle_has_no_noise(void**) {
  const Run r = run(dbs_folds::saddle());
  assert_int_equal(r.folds.folded, 0);
  assert_true(r.result.noise < 0.1 * r.result.requested_accuracy);
  assert_true(r.result.accuracy == r.result.requested_accuracy);
  assert_int_equal(r.result.folded_points, 0);
  assert_int_equal(r.result.collapsed_points, 0);
  assert_int_equal(r.turned_truth, 0);
  assert_int_equal(r.result.turned_points, 0);
}

void noise_does_not_change_the_level_count(void**) {
  const Run clean = run(dbs_folds::rippled());
  const Run noisy = run(dbs_folds::rippled(dbs_folds::kRippledNoise));
  assert_true(clean.result.levels >= 2);
  assert_int_equal(noisy.result.levels, clean.result.levels);
  assert_int_equal(clean.folds.folded, 0);
  assert_int_equal(noisy.folds.folded, 0);
  assert_int_equal(clean.result.folded_points, 0);
  assert_true(noisy.result.folded_share <= 0.001);
}

void hard_shapes_stay_within_their_bounds(void**) {
  // Folded reference triangles and mean distance with the default options (the repair on,
  // since 0.4): a little above today's figures, mushroom 0.01% / 0.0040, tall dome 0.12% /
  // 0.0103, fingers 0.09% / 0.0036, open box 0.15% / 0.00084, cone 0% / 0.00068, sphere cap
  // 0.05% / 0.0032. Before the warm-up grid and the seams' departure guard: 0.03% / 0.0051,
  // 0.12% / 0.0115, 0.14% / 0.0036, 0.18% / 0.0007, 0.19% / 0.00083, 0.06% / 0.0031; before
  // the wide reaches of the repair 0.06%, 0.13%, 0.26%, 0.18%, 0.26%, 0.06%. Without the
  // repair (the default of 0.3) they were 7.23% / 0.0208, 8.24% / 0.0183, 3.62% / 0.0080,
  // 0.18% / 0.0021, 0.77% / 0.0014, 0.10% / 0.0033; before the guard, the seam correction and
  // the seam-aware assignment (0.2): 9.65%, 7.37%, 4.08%, 0.21%, 1.27%, 2.30%. The repair is on
  // by default because it keeps or lowers both figures on every shape: checked here against a
  // run without it.
  //
  // Points on a turned sheet (on the surface, its Su x Sv at their (u,v) against the
  // noise-free normal; DBS_STAT_TURNED_*), today at 4,096 points 1.06% / 2.31% / 2.90% / 0.44%
  // / 0.22% / 0 by the truth and 1.13% / 2.34% / 2.33% / 0.25% / 0.24% / 0 by the library's
  // own measure (which has no normal for a few points, e.g. round the fingers' tips): bounded
  // like the folds, and the library's count must agree with the truth's within a quarter and
  // ten points.
  const struct {
    const char* name;
    double max_share, max_mean, max_turned;
  } bounds[] = {{"mushroom", 0.0005, 0.0045, 0.02}, {"tall-dome", 0.002, 0.0115, 0.03}, {"fingers", 0.0015, 0.004, 0.035},
                {"open-box", 0.002, 0.001, 0.007}, {"cone", 0.0005, 0.0008, 0.005}, {"sphere-cap", 0.001, 0.0034, 0.001}};
  dbs::Options without;
  without.repair = 0;
  for (const auto& b : bounds) {
    const FoldShape shape = dbs_folds::fold_shape(b.name);
    const Run r = run(shape);
    // The mushroom's and the dome's roots end 24 and 25 times above the target, but the median
    // distance of their points is 0.17 and 0.06 times it: only the feature stands off the
    // surface, and the root is not evolved again from other starts (evolve.hpp), which both
    // did and then dropped; nor is the fingers' (6.9 and 0.04 times). The others end within
    // the restart's 5 times the target (the open box 4.3).
    assert_int_equal(r.result.patches.at(0).restarts, 0);
    assert_true(r.folds.share <= b.max_share);
    assert_true(r.result.mean_distance <= b.max_mean);
    assert_true(r.result.turned_share <= b.max_turned);
    const double gap = std::abs(static_cast<double>(r.result.turned_points) - static_cast<double>(r.turned_truth));
    assert_true(gap <= 0.25 * static_cast<double>(r.turned_truth) + 10.0);
    const Run plain = run(shape, without);
    assert_true(r.folds.folded <= plain.folds.folded);
    assert_true(r.result.mean_distance <= plain.result.mean_distance);
    // The reference-free measure never reports more than the reference folds (it misses
    // collapses, which keep their orientation) and is at most 0.1% on the creased box.
    if (std::string(b.name) == "open-box") assert_true(r.result.folded_share <= 0.001);
    // Where most of the reference folds are collapses (points piled up on walls the surfaces
    // did not climb), the measure counts collapsed points instead of reporting a clean result
    // (0.3 showed 0 folded on the fingers): without the repair 83 on the dome, 32 on the fingers.
    if (std::string(b.name) == "tall-dome" || std::string(b.name) == "fingers") assert_true(plain.result.collapsed_points >= 16);
  }
}

void sphere_cap_against_the_meshless_reference(void**) {
  // 270, 300 and 330 degrees of a sphere, open only at a small rim: no failure; the issue asks for
  // no more folds than a meshless method (k = 12 inverse-distance weights, one solve) on the
  // same points. At 1, 1.25, 1.5 and 2 times the points. 270 degrees: at the three denser
  // ones the root surface did not wrap the sphere and a seam node shot 46 h off the cloud,
  // folding 3-17% (before the warm-up grid and the seams' departure guard); now 4, 11, 9 and 6
  // folded triangles against the meshless 5, 10, 12 and 7. 300 degrees: 0.7-5.8% with the
  // warm-up grid alone (the root's grids crossed over the rim: mean distance 0.17-0.28), now
  // 6, 14, 9 and 9 against 8, 12, 11 and 13, since the root restarts from a 3 x 3 grid. One
  // or two more than the meshless method at 1.25 times the points: slivers on the diagonals
  // near the corners, where the small rim's corners pinch the map (one patch folds the same).
  // 330 degrees (a head open only at its neck): no warm-up wrapped it (mean distance
  // 0.15-0.17 after the repair had filled nearly every point, 0.17-9.9% folded); since the
  // root starts from the meshless seed there, 7, 17, 11 and 12 against 8, 17, 16 and 14 (13
  // at 1.5 times the points before the repaired regions were untangled).
  // Asserted: at most 0.25% at every density (the meshless method folds up to 0.20%), and no
  // more than the meshless method over the four together.
  for (const char* name : {"sphere-cap", "sphere-cap-300", "sphere-cap-330"}) {
    std::size_t ours = 0, theirs = 0;
    for (double density : {1.0, 1.25, 1.5, 2.0}) {
      const FoldShape shape = dbs_folds::fold_shape(name, density);
      const Run r = run(shape);
      const dbs_folds::MeshlessReference meshless = dbs_folds::meshless_reference(shape);
      const dbs_folds::FoldCount reference = dbs_folds::fold_share(meshless.uv, shape.triangles);
      std::printf("%s x%.2f (%zu points): libdbs %zu folds (%.2f%%, %d levels, mean distance %.3g), meshless %zu (%.2f%%)\n", name, density, shape.count(), r.folds.folded,
                  100.0 * r.folds.share, r.result.levels, r.result.mean_distance, reference.folded, 100.0 * reference.share);
      assert_true(reference.share <= 0.0025);  // the meshless method: 0.04-0.20%
      assert_true(r.folds.share <= 0.0025);
      assert_true(r.result.mean_distance <= 0.004);  // wrapped: the target is 0.0033-0.0034
      ours += r.folds.folded;
      theirs += reference.folded;
    }
    assert_true(ours <= theirs);
  }
}

void noisy_caps_are_wrapped(void**) {
  // The closed caps as a scanner sees them, with noise along the normal (sigma 0.25% and
  // 0.5% of the diagonal, the noise floor raising the target 2.5 and 4.7 times): the root
  // must still wrap the cloud. Two ways it did not:
  // - 330 degrees, sigma 0.5%, 8,281 points: the meshless seed's border test fitted its plane
  //   to 12 points near the rim, which the noise tilts, and refused the seed (mean distance
  //   0.153 against a target of 0.0165, 234 folded reference triangles; seeded: 0.0158, 14);
  // - 300 degrees, sigma 0.25%, 10,201 points: the root ended 6.1 times above the raised
  //   target, its median 1.4 times (0.0525 and 0.0121 against 0.0086), and was not restarted
  //   at 10 times (0.0179 and 250 folds; restarted at 5 times: 0.0083 and 13).
  const struct {
    const char* name;
    double density, noise;
  } cases[] = {{"sphere-cap-330", 2.0, 0.005}, {"sphere-cap-300", 2.5, 0.0025}};
  for (const auto& c : cases) {
    const FoldShape shape = dbs_folds::fold_shape(c.name, c.density, c.noise);
    const Run r = run(shape);
    std::printf("%s x%.1f, sigma %.2f%% of the diagonal: mean distance %.3g (target %.3g), %zu folds (%.2f%%), %d restarts\n", c.name, c.density, 100.0 * c.noise,
                r.result.mean_distance, r.result.accuracy, r.folds.folded, 100.0 * r.folds.share, r.result.patches.at(0).restarts);
    assert_true(r.result.accuracy > 2.0 * r.result.requested_accuracy);
    assert_true(r.result.patches.at(0).restarts >= 1);
    assert_true(r.result.mean_distance <= 1.25 * r.result.accuracy);
    assert_true(r.folds.share <= 0.0025);  // as the clean caps (the meshless method: 0.34% and 0.07% here)
  }
  // The 270-degree cap, sigma 0.25%, 10,201 points: nothing is far and the measure doubts no
  // point but the torn ones, which only the wide reaches take; they start from the unrepaired
  // result (before, torn points alone started no repair): mean distance 0.00801 -> 0.00722,
  // 14 -> 15 folded reference triangles.
  const FoldShape cap = dbs_folds::fold_shape("sphere-cap", 2.5, 0.0025);
  const Run r = run(cap);
  std::printf("%s x2.5: %zu repaired points, mean distance %.3g, %zu folds\n", cap.name.c_str(), r.result.repaired_points, r.result.mean_distance, r.folds.folded);
  assert_true(r.result.repaired_points > 0);
  assert_true(r.result.mean_distance < 0.0075);
  assert_true(r.folds.share <= 0.0025);
}

void repair_on_the_hard_shapes(void**) {
  // The last-resort repair on the two shapes whose points the surfaces reach least: 7.70% and
  // 8.90% folded without it.
  dbs::Options options;
  options.repair = 1;
  for (const char* name : {"mushroom", "tall-dome"}) {
    const FoldShape shape = dbs_folds::fold_shape(name);
    const Run r = run(shape, options);
    std::printf("%s repaired %zu points\n", name, r.result.repaired_points);
    assert_true(r.folds.share <= 0.005);
    assert_true(r.result.repaired_points > 0);
    // Every point carries the distance of the (refitted) surface at its (u,v); repaired
    // points are flagged and belong to the leaf there.
    std::size_t flagged = 0;
    const std::vector<Vec3> points = points_of(shape.xyz);
    for (std::size_t i = 0; i < points.size(); ++i) {
      assert_true(std::abs((r.result.evaluate(r.result.u[i], r.result.v[i]) - points[i]).norm() - r.result.distance[i]) <= 1e-9);
      if (!r.result.repaired[i]) continue;
      ++flagged;
      assert_int_equal(r.result.patch[i], r.result.leaf_at(r.result.u[i], r.result.v[i]));
    }
    assert_int_equal(flagged, r.result.repaired_points);
  }
}

void repair_at_scan_density(void**) {
  // The two hardest shapes at 2.5 times the points (about 10,000, the size of the scans the
  // fold-free work is judged on), where the surfaces come close to more of the cloud but
  // pleat between leaves and scatter the points of steep walls in (u,v). Today: mushroom
  // 0.27% folded (0.49% before the repaired regions were untangled, 0.45% before the warm-up
  // grid and the seams' departure guard, 0.67% before the wide reaches, 4.32% without the
  // repair), tall dome 0.46% (1.14%, 1.33%, 1.55%, 5.28%); the
  // repair must keep at least half of them off and not raise the mean distance above the one
  // without it. The fingers, whose tips the harmonic fill crushed (2.25%), are at 0.05%
  // (0.10% before the warm-up grid, 0.58% with the narrow reach alone).
  const struct {
    const char* name;
    double max_share;
  } bounds[] = {{"mushroom", 0.0035}, {"tall-dome", 0.006}, {"fingers", 0.001}};
  dbs::Options without;
  without.repair = 0;
  for (const auto& b : bounds) {
    const FoldShape shape = dbs_folds::fold_shape(b.name, 2.5);
    const Run r = run(shape), plain = run(shape, without);
    assert_true(shape.count() > 10000);
    assert_true(r.folds.share <= b.max_share);
    assert_true(2 * r.folds.folded <= plain.folds.folded);
    assert_true(r.result.mean_distance <= plain.result.mean_distance);
  }
}

/// Every point's parameters, distance, leaf and level, and every patch's figures, bit for bit.
bool same_for_every_thread_count(const dbs::Result& a, const dbs::Result& b) {
  if (!(a.u == b.u && a.v == b.v && a.distance == b.distance && a.patch == b.patch && a.level == b.level)) return false;
  if (a.folded_points != b.folded_points || a.patches.size() != b.patches.size()) return false;
  for (std::size_t k = 0; k < a.patches.size(); ++k) {
    const dbs::Patch &p = a.patches[k], &q = b.patches[k];
    if (!(p.mean_distance == q.mean_distance && p.max_distance == q.max_distance && p.error == q.error && p.accurate == q.accurate && p.subcloud == q.subcloud)) return false;
  }
  return a.mean_distance == b.mean_distance;
}

/// The mushroom's 76 leaves are projected several at once on more than one thread, their
/// feet merged in leaf order (a point two leaves hold keeps the foot one thread gives it).
void many_leaves_are_the_same_for_every_thread_count(void**) {
  const FoldShape shape = dbs_folds::fold_shape("mushroom");
  dbs::Options one, two, three;
  one.threads = 1;
  two.threads = 2;
  three.threads = 3;
  const Run a = run(shape, one), b = run(shape, two), c = run(shape, three);
  std::size_t leaves = 0;
  for (const dbs::Patch& p : a.result.patches) leaves += p.is_leaf() ? 1 : 0;
  std::printf("mushroom: %zu patches, %zu leaves\n", a.result.patches.size(), leaves);
  assert_true(leaves >= 50);
  assert_true(same_for_every_thread_count(a.result, b.result));
  assert_true(same_for_every_thread_count(a.result, c.result));
}

void hard_shape_is_scale_and_thread_invariant(void**) {
  const FoldShape shape = dbs_folds::cone();
  dbs::Options one, two;
  one.threads = 1;
  two.threads = 2;
  one.max_level = two.max_level = 2;
  const Run a = run(shape, one), b = run(shape, two), scaled = run(shape, one, 1000.0);
  assert_true(same_for_every_thread_count(a.result, b.result));
  double worst = 0.0;
  for (std::size_t i = 0; i < a.result.u.size(); ++i) worst = std::max({worst, std::abs(a.result.u[i] - scaled.result.u[i]), std::abs(a.result.v[i] - scaled.result.v[i])});
  std::printf("cone: (u,v) of the cloud x1000 differ by %.3g\n", worst);
  // Not the 1e-9 of the smooth clouds (test_recursive): on these shapes the iterations of the
  // evolution amplify rounding; 0.2 already differed by 3e-6 on the clean saddle with a
  // single patch and by 5e-8 here. The guard's decisions are the same at both scales (the
  // same nodes damped), and the (u,v) differ by 9e-5 since the guard leaves cells alone that
  // already fail its test before the move (7e-7 when it judged them too, at 0.64% instead of
  // 0.10% folds on the sphere cap).
  assert_true(worst <= 2e-4);
  // The 330-degree cap, whose root restarts and starts from the meshless seed: the same bits
  // with 1 and 2 threads.
  const FoldShape closed = dbs_folds::fold_shape("sphere-cap-330");
  const Run c1 = run(closed, one), c2 = run(closed, two);
  assert_true(c1.result.u == c2.result.u && c1.result.v == c2.result.v && c1.result.distance == c2.result.distance);
  assert_true(c1.result.mean_distance < 0.01);  // the seed was taken (0.15 without it)
  // Most of the cap lies far from the first root surface (its median distance 0.71-0.77, 220
  // times the target): both restarts are tried, the 3 x 3 warm-up and the seed.
  assert_int_equal(c1.result.patches.at(0).restarts, 2);
}

}  // namespace

void far_points_leave_the_turned_count_alone(void**) {
  // With points far outside the body, the fold measure judges a list of the others (the
  // driver's path with judged indices): the tall dome's points on turned sheets are the same
  // as without them, point for point in (u,v).
  const FoldShape shape = dbs_folds::fold_shape("tall-dome");
  const dbs::Boundary boundary(points_of(shape.bottom), points_of(shape.right), points_of(shape.top), points_of(shape.left));
  std::vector<Vec3> points = points_of(shape.xyz);
  const dbs::Result plain = dbs::parameterize(dbs::PointCloud(points), boundary, dbs::Options());
  for (double x : {1e6, -2e6, 3e6}) points.emplace_back(x, 0.5, 0.1);
  dbs::Options options;
  options.warning = [](const char*) {};
  const dbs::Result with_far = dbs::parameterize(dbs::PointCloud(points), boundary, options);
  assert_int_equal(with_far.far_points, 3);
  for (std::size_t i = 0; i < plain.u.size(); ++i) assert_true(with_far.u[i] == plain.u[i] && with_far.v[i] == plain.v[i]);
  assert_true(plain.turned_points > 50);
  assert_int_equal(with_far.turned_points, plain.turned_points);
  assert_true(with_far.turned_share == plain.turned_share);
  const std::vector<std::int32_t> flags = with_far.point_flags(), plain_flags = plain.point_flags();
  std::size_t flagged = 0;
  for (std::size_t i = 0; i < plain.u.size(); ++i) {
    assert_int_equal(flags[i] & dbs::kPointTurned, plain_flags[i] & dbs::kPointTurned);
    flagged += (flags[i] & dbs::kPointTurned) != 0;
  }
  assert_int_equal(flagged, plain.turned_points);
  for (std::size_t i = plain.u.size(); i < flags.size(); ++i) assert_int_equal(flags[i], dbs::kPointFar);  // far points are not judged
}

int main(int argc, char** argv) {
  // "--quick": the group that holds, for the sanitizer build.
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const struct CMUnitTest always[] = {
      cmocka_unit_test(noisy_saddle_stays_on_the_truth_and_folds_nothing),
      cmocka_unit_test(without_the_floor_the_noise_is_chased),
      cmocka_unit_test(clean_saddle_has_no_noise),
      cmocka_unit_test(repair_leaves_a_noisy_cloud_alone),
      cmocka_unit_test(repair_leaves_gross_outliers_alone),
      cmocka_unit_test(repair_sets_a_scrambled_region_right),
      cmocka_unit_test(noise_does_not_change_the_level_count),
  };
  const struct CMUnitTest slow[] = {
      cmocka_unit_test(hard_shapes_stay_within_their_bounds),
      cmocka_unit_test(repair_on_the_hard_shapes),
      cmocka_unit_test(repair_at_scan_density),
      cmocka_unit_test(sphere_cap_against_the_meshless_reference),
      cmocka_unit_test(noisy_caps_are_wrapped),
      cmocka_unit_test(hard_shape_is_scale_and_thread_invariant),
      cmocka_unit_test(many_leaves_are_the_same_for_every_thread_count),
      cmocka_unit_test(far_points_leave_the_turned_count_alone),
  };
  int failed = cmocka_run_group_tests_name("fold_free", always, nullptr, nullptr);
  if (!quick) failed += cmocka_run_group_tests_name("fold_free_hard_shapes", slow, nullptr, nullptr);
  return failed;
}
