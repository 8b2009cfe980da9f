#include "fold_repair.hpp"

#include <algorithm>
#include <cmath>

#include "cloud_index.hpp"
#include "error.hpp"
#include "fold_measure.hpp"
#include "harmonic_fill.hpp"
#include "leaf_refit.hpp"
#include "parallel.hpp"
#include "untangle.hpp"

namespace dbs {

namespace {

Vec2 clamp_unit(const Vec2& x) { return x.cwiseMax(0.0).cwiseMin(1.0); }

/// Gauss-Newton towards the orthogonal foot of q on the result surface (the leaf at each
/// (u,v), derivatives by central differences), within `radius` of `start` and inside [0,1]^2;
/// a step is kept only when it brings the surface closer.
Vec2 step_towards_foot(const Result& result, const Vec3& q, const Vec2& start, double radius) {
  if (!(radius > 0.0)) return start;
  auto trust = [&](Vec2 x) {
    Vec2 d = x - start;
    const double length = d.norm();
    if (length > radius) d *= radius / length;
    return clamp_unit(start + d);
  };
  auto surface = [&](const Vec2& x) { return result.evaluate(x.x(), x.y()); };
  Vec2 x = start;
  double best = (surface(x) - q).norm();
  const double eps = 1e-3 * radius;
  for (int it = 0; it < 8; ++it) {
    const Vec2 u0 = trust(Vec2(x.x() - eps, x.y())), u1 = trust(Vec2(x.x() + eps, x.y()));
    const Vec2 v0 = trust(Vec2(x.x(), x.y() - eps)), v1 = trust(Vec2(x.x(), x.y() + eps));
    if (!(u1.x() > u0.x()) || !(v1.y() > v0.y())) break;
    const Vec3 su = (surface(u1) - surface(u0)) / (u1.x() - u0.x());
    const Vec3 sv = (surface(v1) - surface(v0)) / (v1.y() - v0.y());
    const Vec3 r = q - surface(x);
    const double a = su.dot(su), b = su.dot(sv), c = sv.dot(sv), det = a * c - b * b;
    if (!(det > 0.0)) break;
    const double gu = su.dot(r), gv = sv.dot(r);
    const Vec2 next = trust(x + Vec2((c * gu - b * gv) / det, (a * gv - b * gu) / det));
    const double d = (surface(next) - q).norm();
    if (!(d < best)) break;
    best = d;
    x = next;
  }
  return x;
}

/// Whether far point i (at `distance` from its surface) stands alone, a gross outlier rather
/// than a sheet the surfaces missed: within r = max(distance / 2, kIsolationSpacings h) of
/// it, a sheet of the cloud's spacing h holds about 0.785 (r / h)^2 points; an outlier holds
/// few (the surface it sticks out of is `distance` away, fellow outliers are sparse). It is
/// isolated when fewer than kIsolationShare of those (at least 3, at most 64) lie within r.
bool isolated(const CloudIndex& index, const std::vector<Vec3>& points, std::size_t i, double distance, double h) {
  const double r = std::max(0.5 * distance, kIsolationSpacings * h);
  const double expected = 0.785 * (r / h) * (r / h);
  const std::size_t needed = static_cast<std::size_t>(std::clamp(std::ceil(kIsolationShare * expected), 3.0, 64.0));
  std::vector<std::size_t> ids;
  std::vector<double> d2;
  index.knn(points[i], needed + 1, ids, d2);  // the point itself comes first
  return d2.size() < needed + 1 || d2.back() > r * r;
}

/// Whether far point i lies in a sheet the surfaces missed, however sparsely sampled, rather
/// than standing alone: at least half of its kRepairNeighbours nearest points are far too,
/// and all of them lie within kSheetSpacings spacings h (a sheet a few times sparser than the
/// cloud, such as a mushroom's cap, passes; the sparse layer that a few percent of gross
/// outliers form on each side of a surface, tens of times sparser, does not).
bool in_missed_sheet(const CloudIndex& index, const std::vector<Vec3>& points, std::size_t i, const std::vector<char>& far, double h) {
  std::vector<std::size_t> ids;
  std::vector<double> d2;
  index.knn(points[i], kRepairNeighbours + 1, ids, d2);
  if (d2.empty() || d2.back() > (kSheetSpacings * h) * (kSheetSpacings * h)) return false;
  std::size_t others = 0, count = 0;
  for (std::size_t m : ids) {
    if (m == i) continue;
    ++count;
    others += far[m] ? 1 : 0;
  }
  return count > 0 && 2 * others >= count;
}

/// The trust radius of point i's step towards its foot: kRepairTrust times the mean (u,v)
/// distance to its nearest points in 3D (`neighbours`), so that a step cannot carry it past
/// them (0 without neighbours).
double trust_radius(const Result& result, std::size_t i, const std::vector<std::size_t>& neighbours) {
  if (neighbours.empty()) return 0.0;
  const Vec2 at(result.u[i], result.v[i]);
  double spread = 0.0;
  for (std::size_t m : neighbours) spread += (Vec2(result.u[m], result.v[m]) - at).norm();
  return kRepairTrust * spread / static_cast<double>(neighbours.size());
}

/// Whether points[i] lies at the border of the cloud: the centroid of its kRepairNeighbours
/// nearest points is offset from it by more than kBorderOffset times their mean distance (a
/// point inside a sheet has neighbours all around). A fill from one side would pull it inwards.
bool at_cloud_border(const CloudIndex& index, const std::vector<Vec3>& points, std::size_t i) {
  std::vector<std::size_t> ids;
  std::vector<double> d2;
  index.knn(points[i], kRepairNeighbours + 1, ids, d2);
  Vec3 offset = Vec3::Zero();
  double spread = 0.0;
  for (std::size_t m : ids) {
    offset += points[m] - points[i];
    spread += (points[m] - points[i]).norm();
  }
  return offset.norm() > kBorderOffset * spread;
}

/// A wide reach of the repair (RepairReach): the suspect points and the far ones, widened by
/// `rings` rings of candidates (a candidate joins when one of its kRepairNeighbours nearest
/// points is taken or far), the cloud's border included. 1 for a point to repair (far points
/// are repaired anyway).
std::vector<char> widened(const CloudIndex& index, const std::vector<Vec3>& points, const std::vector<std::size_t>& candidates, const std::vector<char>& suspect,
                          const std::vector<char>& far, int rings, int threads) {
  std::vector<std::vector<std::size_t>> near(candidates.size());
  parallel_for(candidates.size(), threads, [&](std::size_t c) {
    std::vector<double> d2;
    index.knn(points[candidates[c]], kRepairNeighbours + 1, near[c], d2);
  });
  // Far candidates are taken too: on a sampled cloud every point takes the flag of its nearest
  // judged point, and one whose nearest judged point is far must not stay fixed amid the fill.
  std::vector<char> taken = suspect;
  for (std::size_t i : candidates) taken[i] = taken[i] || far[i];
  for (int ring = 0; ring < rings; ++ring) {
    const std::vector<char> before = taken;
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      const std::size_t i = candidates[c];
      if (before[i]) continue;
      taken[i] = std::any_of(near[c].begin(), near[c].end(), [&](std::size_t m) { return before[m] != 0; }) ? 1 : 0;
    }
  }
  return taken;
}

/// Whether a verdict leaves a point alone in `reach`: sound, or torn in the narrow reach (torn
/// points go to the wide reaches only, which the driver keeps only where they leave fewer
/// doubts at no higher mean distance).
bool sound_in(std::int8_t state, RepairReach reach) { return state == kFoldOk || (state == kFoldTorn && reach.wide_rings == 0); }

/// The suspect points among `candidates` (see doubtful_points), `state` and `far` indexed
/// like `points` (entries of other points unused), the ring of their kRepairNeighbours
/// nearest points in `index` included: 1 for a point to repair.
std::vector<char> suspect_points(const CloudIndex& index, const std::vector<Vec3>& points, const std::vector<std::size_t>& candidates, const std::vector<std::int8_t>& state,
                                 const std::vector<char>& far, int threads, RepairReach reach) {
  const std::size_t n = points.size();
  auto sound = [&](std::size_t i) { return sound_in(state[i], reach); };
  std::vector<char> doubtful(n, 0), suspect(n, 0);
  for (std::size_t i : candidates) doubtful[i] = far[i] || !sound(i);
  parallel_for(candidates.size(), threads, [&](std::size_t c) {
    const std::size_t i = candidates[c];
    if (far[i] || sound(i)) return;
    if (state[i] == kFolded || state[i] == kFoldCollapsed || state[i] == kFoldTorn) {
      suspect[i] = 1;
      return;
    }
    // Undecided: repaired where no linear map explains its neighbours' (u,v) (scrambled), or
    // inside a region of doubtful points (a sign not significant there is one the fill can
    // set right), never at the cloud's border (where a fill from one side pulls it inwards);
    // a sign not significant in a region that is otherwise sound is left as it is.
    std::vector<std::size_t> ids;
    std::vector<double> d2;
    index.knn(points[i], kRepairNeighbours + 1, ids, d2);
    std::size_t others = 0;
    for (std::size_t m : ids) others += (m != i && doubtful[m]) ? 1 : 0;
    if (state[i] != kFoldScrambled && static_cast<double>(others) < kSuspectClusterShare * static_cast<double>(ids.size() - 1)) return;
    suspect[i] = at_cloud_border(index, points, i) ? 0 : 1;
  });
  if (reach.wide_rings > 0) return widened(index, points, candidates, suspect, far, reach.wide_rings, threads);
  // One ring more: the fill's fixed points around a doubtful region are then sound ones, not
  // its own disturbed edge (the cloud's border stays out, as above).
  std::vector<std::vector<std::size_t>> ring(candidates.size());
  parallel_for(candidates.size(), threads, [&](std::size_t c) {
    const std::size_t i = candidates[c];
    if (!suspect[i]) return;
    std::vector<double> d2;
    index.knn(points[i], kRepairNeighbours + 1, ring[c], d2);
    ring[c].erase(std::remove_if(ring[c].begin(), ring[c].end(), [&](std::size_t m) { return suspect[m] || far[m] || at_cloud_border(index, points, m); }), ring[c].end());
  });
  std::vector<char> taken = suspect;
  for (const std::vector<std::size_t>& around : ring)
    for (std::size_t m : around) taken[m] = 1;
  return taken;
}

/// Per point: 1 when farther from its surface than the repair's "far" (in the body, inside the boundary).
std::vector<char> far_from_surface(const Result& result) {
  const std::size_t n = result.distance.size();
  std::vector<char> far(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    // A point outside the boundary (clamped onto the domain's edge) is far from the surface
    // because the boundary does not reach it, not because a surface missed it: a fill would
    // only pull it inside the domain.
    const bool outside = result.left_out(i) || (i < result.clamped.size() && result.clamped[i]);
    far[i] = !outside && beyond_repair_reach(result, i);
  }
  return far;
}

/// Points neither repaired nor data of a refit: those far outside the body or cropped
/// (Result::left_out), and far points that stand alone (gross outliers, see isolated).
std::vector<char> left_out_or_isolated(const Result& result, const std::vector<Vec3>& points, const CloudIndex& index, const std::vector<char>& is_far, int threads) {
  std::vector<char> outlier(points.size(), 0);
  parallel_for(points.size(), threads, [&](std::size_t i) {
    if (result.left_out(i)) outlier[i] = 1;
    else if (is_far[i]) outlier[i] = isolated(index, points, i, result.distance[i], result.length_scale) && !in_missed_sheet(index, points, i, is_far, result.length_scale) ? 1 : 0;
  });
  return outlier;
}

}  // namespace

std::vector<char> doubtful_points(const Result& result, const std::vector<Vec3>& points, const std::vector<std::size_t>& judged, const std::vector<std::int8_t>& state, int threads, WorkMeter* meter,
                                  RepairReach reach) {
  const std::size_t n = points.size();
  std::vector<char> none(n, 0);
  if (std::all_of(state.begin(), state.end(), [&](std::int8_t s) { return sound_in(s, reach); })) return none;
  const std::vector<char> far = far_from_surface(result);
  if (judged.empty()) {
    if (state.size() != n) fail(ErrorCode::InvalidArgument, "doubtful_points: " + std::to_string(state.size()) + " verdicts for " + std::to_string(n) + " points");
    std::vector<std::size_t> all(n);
    for (std::size_t i = 0; i < n; ++i) all[i] = i;
    return suspect_points(CloudIndex(points), points, all, state, far, threads, reach);
  }
  if (state.size() != judged.size()) fail(ErrorCode::InvalidArgument, "doubtful_points: " + std::to_string(state.size()) + " verdicts for " + std::to_string(judged.size()) + " judged points");
  // The suspects of the judged points among themselves (the sparser cloud the verdicts are
  // of), then each point takes the flag of its nearest judged point.
  std::vector<std::int8_t> global(n, kFoldOk);
  for (std::size_t k = 0; k < judged.size(); ++k) global[judged[k]] = state[k];
  const std::vector<char> suspect = suspect_points(CloudIndex(points, judged), points, judged, global, far, threads, reach);
  std::vector<std::int8_t> flags(judged.size());
  bool any = false;
  for (std::size_t k = 0; k < judged.size(); ++k) {
    flags[k] = suspect[judged[k]];
    any = any || flags[k] != 0;
  }
  if (!any) return none;
  const std::vector<std::int8_t> spread = spread_verdicts(points, judged, flags, threads, meter);
  std::vector<char> out(n, 0);
  for (std::size_t i = 0; i < n; ++i) out[i] = spread[i] != 0 && !result.left_out(i);
  return out;
}

int max_wide_rings(std::size_t points, bool noisy) {
  if (noisy) return kMaxWideRings;
  const double across = std::sqrt(static_cast<double>(points)) / kPointsAcrossPerRing;
  return std::max(kMaxWideRings, static_cast<int>(std::floor(across + 0.5)));
}

bool beyond_repair_reach(const Result& result, std::size_t i) {
  const double d = result.distance[i];
  return d > kRepairFactor * result.accuracy && d > kRepairSpacings * result.length_scale;
}

std::vector<char> refit_outliers(const Result& result, const std::vector<Vec3>& points, const CloudIndex& index, int threads) {
  return left_out_or_isolated(result, points, index, far_from_surface(result), threads);
}

bool repair_has_work(const Result& result, const std::vector<char>& suspect) {
  if (std::find(suspect.begin(), suspect.end(), 1) != suspect.end()) return true;
  const std::vector<char> far = far_from_surface(result);
  return std::find(far.begin(), far.end(), 1) != far.end();
}

Repair repair_folds(Result& result, const std::vector<Vec3>& points, const std::vector<char>& suspect, int threads) {
  const std::size_t n = points.size();
  result.repaired.assign(n, 0);
  if (!suspect.empty() && suspect.size() != n) fail(ErrorCode::InvalidArgument, "repair_folds: " + std::to_string(suspect.size()) + " suspect flags for " + std::to_string(n) + " points");
  // Points far outside the cloud's body, and cropped ones, are neither repaired nor fitted (nor data of a fit).
  auto outside = [&](std::size_t i) { return result.left_out(i); };
  const std::vector<char> is_far = far_from_surface(result);
  auto taken = [&](std::size_t i) { return is_far[i] || (!suspect.empty() && suspect[i]); };
  bool any = false;
  for (std::size_t i = 0; i < n && !any; ++i) any = taken(i) && !outside(i);
  if (!any) return {};
  const CloudIndex index(points);
  std::vector<std::size_t> far;
  for (std::size_t i = 0; i < n; ++i)
    if (taken(i) && !outside(i)) far.push_back(i);
  if (far.empty() || far.size() == n) return {};  // nothing to repair, or nothing to repair from

  // Gross outliers are left where they are and out of the refit: a harmonic fill would give
  // them the (u,v) of the surface under them anyway, and a fit through them would pull the
  // surface off the clean points.
  const std::vector<char> outlier = left_out_or_isolated(result, points, index, is_far, threads);
  far.erase(std::remove_if(far.begin(), far.end(), [&](std::size_t i) { return outlier[i] != 0; }), far.end());
  if (far.empty()) return {};

  std::vector<Placement> before(far.size());
  for (std::size_t f = 0; f < far.size(); ++f) before[f] = Placement::of(result, far[f]);

  // Each far point's neighbours and their normalized inverse-distance weights.
  FillRows fill;
  fill.ids = far;
  fill.neighbours.resize(far.size());
  fill.weights.resize(far.size());
  std::vector<std::vector<std::size_t>>& neighbours = fill.neighbours;
  parallel_for(far.size(), threads, [&](std::size_t f) {
    std::vector<std::size_t> ids;
    std::vector<double> d2;
    index.knn(points[far[f]], kRepairNeighbours + 1, ids, d2);
    double sum = 0.0;
    for (std::size_t m = 0; m < ids.size(); ++m) {
      if (ids[m] == far[f] || !(d2[m] > 0.0)) continue;
      neighbours[f].push_back(ids[m]);
      fill.weights[f].push_back(1.0 / std::sqrt(d2[m]));
      sum += fill.weights[f].back();
    }
    for (double& w : fill.weights[f]) w /= sum;
  });
  fill_sweeps(result, fill, kFillSweeps);
  balance_stretch(result, points, index, fill, threads);
  // Towards the foot, within a fraction of the spread of the neighbours' (u,v).
  std::vector<Vec2> moved(far.size());
  parallel_for(far.size(), threads, [&](std::size_t f) {
    moved[f] = step_towards_foot(result, points[far[f]], Vec2(result.u[far[f]], result.v[far[f]]), trust_radius(result, far[f], neighbours[f]));
  });
  std::size_t repaired = 0;
  for (std::size_t f = 0; f < far.size(); ++f) {
    if (neighbours[f].empty()) continue;  // all its neighbours coincide with it: nothing to repair from
    const std::size_t i = far[f];
    ++repaired;
    place_on_leaf(result, points, i, moved[f]);
    result.repaired[i] = 1;
  }
  if (repaired == 0) return {};
  Repair out;
  out.refitted = refit_marked_leaves(result, points, outlier, result.repaired, threads);
  // A repaired point whose leaf kept its surface (its refit would have moved the surface
  // away from most of the leaf's points) goes back to its foot: without the refit the fill
  // only moves it off the surface.
  const std::vector<char> refitted = patch_flags(result, out.refitted);
  for (std::size_t f = 0; f < far.size(); ++f) {
    const std::size_t i = far[f];
    if (!result.repaired[i]) continue;
    if (refitted[static_cast<std::size_t>(result.leaf_at(result.u[i], result.v[i]))]) {
      ++out.repaired;
      continue;
    }
    result.repaired[i] = 0;
    put_back(result, points, i, before[f], refitted);
  }
  return out;
}

Repair untangle_repaired(Result& result, const std::vector<Vec3>& points, int threads) {
  const std::size_t n = points.size();
  if (result.repaired.size() != n) return {};
  std::vector<std::size_t> repaired;
  for (std::size_t i = 0; i < n; ++i)
    if (result.repaired[i]) repaired.push_back(i);
  if (repaired.empty()) return {};
  const CloudIndex index(points);
  const std::vector<char> outlier = left_out_or_isolated(result, points, index, far_from_surface(result), threads);
  // The repaired points and the ring of their nearest points; never a point clamped onto the
  // domain's edge (the boundary does not reach it, see far_from_surface).
  std::vector<std::vector<std::size_t>> rings(repaired.size());
  parallel_for(repaired.size(), threads, [&](std::size_t k) {
    std::vector<double> d2;
    index.knn(points[repaired[k]], kRepairNeighbours + 1, rings[k], d2);
  });
  auto clamped = [&](std::size_t i) { return i < result.clamped.size() && result.clamped[i]; };
  std::vector<char> candidate(n, 0);
  for (const std::vector<std::size_t>& ring : rings)
    for (std::size_t m : ring) candidate[m] = !outlier[m] && !clamped(m);
  rings = {};
  std::vector<std::size_t> before_ids;  // the candidates, in increasing index order
  std::vector<Placement> before;
  for (std::size_t i = 0; i < n; ++i)
    if (candidate[i]) {
      before_ids.push_back(i);
      before.push_back(Placement::of(result, i));
    }
  const std::vector<std::size_t> moved = untangle(result, points, index, candidate, threads);
  if (moved.empty()) return {};
  std::vector<char> marked(n, 0);
  for (std::size_t i : moved) {
    marked[i] = 1;
    place_on_leaf(result, points, i, Vec2(result.u[i], result.v[i]));
  }
  Repair out;
  out.refitted = refit_marked_leaves(result, points, outlier, marked, threads);
  // A moved point whose leaf kept its surface (its refit would have moved the surface away
  // from most of the leaf's points) goes back: only a refit brings the surface to it.
  const std::vector<char> refitted = patch_flags(result, out.refitted);
  for (std::size_t i : moved) {
    if (refitted[static_cast<std::size_t>(result.leaf_at(result.u[i], result.v[i]))]) {
      ++out.repaired;
      if (!result.repaired[i]) ++result.repaired_points;
      result.repaired[i] = 1;
      continue;
    }
    const std::size_t k = static_cast<std::size_t>(std::lower_bound(before_ids.begin(), before_ids.end(), i) - before_ids.begin());
    put_back(result, points, i, before[k], refitted);
  }
  return out;
}

}  // namespace dbs
