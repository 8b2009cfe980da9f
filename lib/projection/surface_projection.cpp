#include "surface_projection.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <mutex>
#include <string>

#include "error.hpp"
#include "grid_nearest.hpp"

namespace dbs {

namespace {

constexpr int kMaxIterations = 50;
constexpr int kMaxHalvings = 40;
/// The iteration stops once the parameters are estimated to be this close to the foot
/// (FootPrecision::Parameters, FootPrecision::Distance).
constexpr double kConvergedParameters = 1e-12;
constexpr double kConvergedDistance = 1e-7;
/// FootPrecision::Measure: a mean distance to compare with an accuracy target. Distances
/// within 3e-7 of the exact ones on a surface 2.9 across (core_test_surface_projection).
constexpr double kConvergedMeasure = 1e-5;
/// A step turning back on a halved one is at most this fraction of it (settle_on_crease);
/// for the exact feet, a crease coordinate's step after a halved one, either way
/// (settle_coordinate_on_crease).
constexpr double kCreaseShrink = 0.25;
/// FootPrecision::Parameters: after this many steps a coordinate turning back on a halved
/// step is settled on its crease (see settle_coordinate_on_crease).
constexpr int kLateSettling = 8;
/// FootPrecision::Measure: Gauss-Newton steps shrinking slower than this give way to
/// Newton's (see descend).
constexpr double kSlowRate = 0.25;
/// FootPrecision::Parameters: after a full Gauss-Newton step no longer than kFreezeNear,
/// where Gauss-Newton's rate is at least kFreezeRate, the curvature term of Newton's Hessian
/// is evaluated once and kept for the rest of the descent (see freeze_curvature).
constexpr double kFreezeNear = 1e-2;
constexpr double kFreezeRate = 0.005;
/// Steps in (u,v) shorter than this are taken without a line search (see take_step).
constexpr double kNearFoot = 1e-6;
/// Growth of |S - q|^2 that counts as rounding for a step near the foot, in units of
/// epsilon |S - q| (|S| + |q|) (the rounding error of S - q, times 2 |S - q|, with margin).
constexpr double kRoundingGrowth = 16.0;
/// The residual S - q counts as leaving the patch through a side when the cosine of its
/// angle with the inward tangent is below -kOutwardCosine; smaller angles are rounding.
constexpr double kOutwardCosine = 1e-9;
/// sample_cover()'s margin over half the longest cell diagonal.
constexpr double kCoverMargin = 1.5;

double clamp_unit(double x) { return std::min(1.0, std::max(0.0, x)); }

double distance_to_segment(const Vec3& q, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0.0 ? clamp_unit((q - a).dot(ab) / length2) : 0.0;
  return (q - (a + t * ab)).norm();
}

/// Gauss-Newton converges linearly near the foot, with a rate r estimated from two
/// successive step lengths; the distance left to the foot is then about step r / (1 - r).
bool converged(double step, double previous, double tolerance) {
  if (step <= tolerance) return true;
  if (!std::isfinite(previous)) return false;
  const double rate = step / previous;
  return rate < 0.5 && step * rate / (1.0 - rate) <= tolerance;
}

/// True when coordinate c of x sits on a bound of [0,1] and the gradient g_c = S_c.(S - q)
/// points out of the domain there (descent would leave the patch).
bool pushes_out(double x, double g, double tangent_norm, double residual_norm) {
  const double scale = kOutwardCosine * tangent_norm * residual_norm;
  return (x <= 0.0 && g > scale) || (x >= 1.0 && g < -scale);
}

/// A 2 x 2 symmetric matrix: the model's Hessian in (u,v).
struct Hessian {
  double uu, uv, vv;
};

/// Gauss-Newton's Hessian J^T J of |S - q|^2 / 2 at s.
Hessian gauss_newton_hessian(const SurfacePoint& s) { return {s.du.squaredNorm(), s.du.dot(s.dv), s.dv.squaredNorm()}; }

struct Iterate {
  Vec2 x;
  SurfacePoint s;
  double f;  // |S - q|^2
};

}  // namespace

struct SurfaceProjector::Impl {
  const BaseSurface& surface;
  double tolerance;
  bool settle_creases;  // FootPrecision::Distance and Measure
  bool newton_when_slow;  // FootPrecision::Measure
  int samples;
  /// Arc length of a side between two consecutive samples on it.
  std::array<double, 4> side_step;

  Impl(const BaseSurface& s, double t, bool settle, bool newton, int n) : surface(s), tolerance(t), settle_creases(settle), newton_when_slow(newton), samples(n) {
    for (int side = 0; side < 4; ++side) side_step[side] = surface.boundary().side(static_cast<Side>(side)).length() / (samples - 1);
  }

  /// The samples x samples surface samples (u fastest) and their search tree, made on first
  /// use: a descent from a start given (project_from) that stays inside needs neither, and
  /// a growing grid's error sample mostly starts from its feet on the previous surface.
  const std::vector<Vec3>& grid() const {
    std::call_once(built, [&] {
      grid_ = surface.sample(samples, samples).points;
      index_ = std::make_unique<GridNearest>(grid_, samples, samples);
    });
    return grid_;
  }
  const GridNearest& index() const {
    grid();
    return *index_;
  }

  /// The samples of the four sides alone (bottom, right, top, left; each `samples` long,
  /// along u or v), made on first use: the same bits as the grid's border (there the surface
  /// is the boundary's own point), at a 64th of the cost of the grid and without its tree. A
  /// descent that leaves the patch needs only these.
  const std::array<std::vector<Vec3>, 4>& sides() const {
    std::call_once(sided, [&] {
      const int last = samples - 1;
      for (int side = 0; side < 4; ++side) {
        sides_[side].resize(static_cast<std::size_t>(samples));
        for (int k = 0; k < samples; ++k) {
          const double s = static_cast<double>(k) / last;
          switch (static_cast<Side>(side)) {
            case Side::Bottom: sides_[side][k] = surface.eval(s, 0.0); break;
            case Side::Right: sides_[side][k] = surface.eval(1.0, s); break;
            case Side::Top: sides_[side][k] = surface.eval(s, 1.0); break;
            case Side::Left: sides_[side][k] = surface.eval(0.0, s); break;
          }
        }
      }
    });
    return sides_;
  }

  /// SurfaceProjector::sample_cover(). Inside a cell of a flat grid every point lies within
  /// half the cell's longer diagonal of a corner; a cubic spline over at most a quarter of
  /// the samples' sites bulges inside a cell by a small fraction of that (kCoverMargin).
  double cover() const {
    std::call_once(covered, [&] {
      if (4 * surface.displacement_sites() > samples) {
        cover_ = std::numeric_limits<double>::infinity();
        return;
      }
      const std::vector<Vec3>& g = grid();
      double longest = 0.0;
      for (int j = 0; j + 1 < samples; ++j)
        for (int i = 0; i + 1 < samples; ++i) {
          const std::size_t k = static_cast<std::size_t>(j) * samples + i;
          longest = std::max({longest, (g[k] - g[k + samples + 1]).norm(), (g[k + 1] - g[k + samples]).norm()});
        }
      cover_ = kCoverMargin * (0.5 * longest + 2.0 * boundary_wiggle(g));
    });
    return cover_;
  }

  /// The farthest a vertex of a side's polyline lies from the chord between the two samples
  /// of that side around it.
  double boundary_wiggle(const std::vector<Vec3>& g) const {
    const int last = samples - 1;
    double farthest = 0.0;
    for (int side = 0; side < 4; ++side) {
      const Polyline& curve = surface.boundary().side(static_cast<Side>(side));
      auto sample = [&](int k) -> const Vec3& {
        switch (static_cast<Side>(side)) {
          case Side::Bottom: return g[static_cast<std::size_t>(k)];
          case Side::Right: return g[static_cast<std::size_t>(k) * samples + last];
          case Side::Top: return g[static_cast<std::size_t>(last) * samples + k];
          default: return g[static_cast<std::size_t>(k) * samples];
        }
      };
      double walked = 0.0;
      const std::vector<Vec3>& pts = curve.points();
      for (std::size_t i = 0; i < pts.size(); ++i) {
        if (i > 0) walked += (pts[i] - pts[i - 1]).norm();
        const double s = std::min(1.0, walked / curve.length()) * last;
        const int below = std::min(last, static_cast<int>(s));
        const int above = std::min(last, below + 1);
        farthest = std::max(farthest, distance_to_segment(pts[i], sample(below), sample(above)));
      }
    }
    return farthest;
  }

  /// eval_derivs at every sample (u fastest), made by prepare(); empty until then.
  std::vector<SurfacePoint> tabulated;

  /// The parameters of sample k.
  Vec2 sample_parameters(std::size_t k) const {
    return Vec2(static_cast<double>(k % samples) / (samples - 1), static_cast<double>(k / samples) / (samples - 1));
  }

 private:
  mutable std::once_flag built;
  mutable std::vector<Vec3> grid_;
  mutable std::unique_ptr<GridNearest> index_;
  mutable std::once_flag sided;
  mutable std::array<std::vector<Vec3>, 4> sides_;
  mutable std::once_flag covered;
  mutable double cover_ = 0.0;

 public:

  static Vec2 gradient(const Vec3& q, const Iterate& it) {
    const Vec3 r = it.s.p - q;
    return Vec2(it.s.du.dot(r), it.s.dv.dot(r));
  }

  static std::array<bool, 2> held_coordinates(const Iterate& it, const Vec2& g) {
    const double r_norm = std::sqrt(it.f);
    return {{pushes_out(it.x.x(), g.x(), it.s.du.norm(), r_norm), pushes_out(it.x.y(), g.y(), it.s.dv.norm(), r_norm)}};
  }

  Iterate at(const Vec3& q, const Vec2& x) const {
    Iterate it{x, surface.eval_derivs(x.x(), x.y()), 0.0};
    it.f = (it.s.p - q).squaredNorm();
    return it;
  }

  /// Moves `it` by `step` (clamped to the domain), halved until the distance does not grow;
  /// returns the length of the step taken before clamping (the full step's when none was
  /// halved), 0 when no such step moves it. Near the foot (`trusted`) the step is taken as it
  /// is unless |S - q|^2 grows by more than its rounding error: the decrease a tiny step
  /// brings is below that resolution, so a strict line search would stall there (and would
  /// stall differently for a moved and scaled copy of the same input); a step capped on a
  /// crease (`halve_trusted`) is short by construction, so it is halved there too. With
  /// `settle_creases`, halving stops below the tolerance: a step that short moves the foot
  /// by less than the precision asked.
  double take_step(const Vec3& q, Iterate& it, Vec2 step, bool trusted, bool halve_trusted = false) const {
    const double rounding = kRoundingGrowth * std::numeric_limits<double>::epsilon() * std::sqrt(it.f) * (q.norm() + it.s.p.norm());
    for (int halving = 0; halving < kMaxHalvings; ++halving, step *= 0.5) {
      if (settle_creases && halving > 0 && step.norm() <= tolerance) return 0.0;
      const Vec2 x(clamp_unit(it.x.x() + step.x()), clamp_unit(it.x.y() + step.y()));
      if (x == it.x) return 0.0;
      // A halved trial is judged on the point alone (S without its derivatives, the same
      // bits as eval_derivs' point): on a crease most of them are refused.
      Iterate trial;
      if (halving == 0) trial = at(q, x);
      const double f = halving == 0 ? trial.f : (surface.eval(x.x(), x.y()) - q).squaredNorm();
      if (f <= it.f || (trusted && f <= it.f + rounding)) {
        it = halving == 0 ? trial : at(q, x);
        return step.norm();
      }
      if (trusted && !halve_trusted) return 0.0;
    }
    return 0.0;
  }

  /// A foot on a crease: the Gauss-Newton step on either side points across it, a full
  /// step increases the distance and is halved, and the iterate jumps to about the same
  /// distance from the crease on the other side, again and again. A step turning back on a
  /// halved one (`last`) is therefore shortened to kCreaseShrink of it: the foot lies
  /// between the last two iterates, and the iterate closes in on the crease at a linear rate.
  static void settle_on_crease(Vec2& step, const Vec2& last, bool halved) {
    if (!halved || !(step.dot(last) < 0.0)) return;
    const double cap = kCreaseShrink * last.norm(), length = step.norm();
    if (length > cap) step *= cap / length;
  }

  /// Where a descent is: the iterations made, the length of the last step taken and the
  /// step itself (before clamping), whether it was halved, and the crease coordinates.
  struct Descent {
    int iteration = 0;
    double previous = std::numeric_limits<double>::infinity();
    Vec2 last = Vec2::Zero();
    bool halved = false;
    /// Per coordinate: a step of it turned back on a halved one (a crease along it).
    std::array<bool, 2> crease{{false, false}};
    /// r . S'' at one iterate (see freeze_curvature), added to Gauss-Newton's Hessian by
    /// the curved steps.
    Hessian curvature{0.0, 0.0, 0.0};
  };

  /// settle_on_crease for the exact feet (FootPrecision::Parameters), one coordinate at a
  /// time. A crease of the Coons patch of polylines runs along a u or a v line (a vertex of
  /// a side's polyline). A coordinate whose step turns back on a halved one is marked as a
  /// crease coordinate; from the kLateSettling-th step on, after any halved step, its step
  /// is capped at kCreaseShrink of its last one, whichever way it points. The foot then
  /// closes in on the crease whether it swings across it or approaches it from one side
  /// (where each full step crosses it and is halved, and the other coordinate moved only by
  /// the same halved fraction), and slides along the crease in the other coordinate to the
  /// least distance there. Early steps are left alone: a descent that crosses a crease once
  /// on its way is not on it. Feet swinging across a crease ran into the iteration limit
  /// (1,610 of the 15,413 leaf feet of a 10,201-point overhanging cap, 1.9 million halved
  /// trials). Returns whether a step was capped.
  static bool settle_coordinate_on_crease(Vec2& step, Descent& d) {
    bool capped = false;
    if (!d.halved) return capped;
    for (int c = 0; c < 2; ++c) {
      if (step[c] * d.last[c] < 0.0) d.crease[c] = true;
      if (!d.crease[c] || d.iteration < kLateSettling) continue;
      const double cap = kCreaseShrink * std::abs(d.last[c]);
      if (std::abs(step[c]) > cap) step[c] = std::copysign(cap, step[c]), capped = true;
    }
    return capped;
  }

  /// Gauss-Newton's Hessian plus a curvature term r . S'' (Newton's Hessian) where the sum
  /// stays positive definite, so that the step still descends; else Gauss-Newton's.
  static Hessian with_curvature(const Hessian& gauss_newton, const Hessian& curvature) {
    const Hessian h{gauss_newton.uu + curvature.uu, gauss_newton.uv + curvature.uv, gauss_newton.vv + curvature.vv};
    return h.uu > 0.0 && h.vv > 0.0 && h.uu * h.vv - h.uv * h.uv > 1e-14 * h.uu * h.vv ? h : gauss_newton;
  }

  /// r . S'' with r = S - q at `it`, from the second derivatives there.
  static Hessian curvature_term(const Vec3& q, const Iterate& it, const SecondDerivatives& s) {
    const Vec3 r = it.s.p - q;
    return {r.dot(s.uu), r.dot(s.uv), r.dot(s.vv)};
  }

  /// The exact feet converge at Gauss-Newton's linear rate, about the distance times the
  /// curvature (on the rippled field 0.005-0.1: about 5 steps a foot to reach 1e-12 in the
  /// parameters, where a flat surface takes 3). Near the foot the curvature term
  /// C = r . S'' of Newton's Hessian hardly changes: evaluated once there and kept, it makes
  /// the rate about the distance still to go times the change of the curvature. Only where
  /// Gauss-Newton's rate is slow enough to pay for one evaluation: after a later step the
  /// ratio of the last two; after the first, which has none before it, the curvature along
  /// the step s from the gradients at both ends (g' - g = (J^T J + C) s) over J^T J along s.
  /// And only after a full step (a halved or capped one is on a crease, where the second
  /// derivatives jump). On the rippled field at 1M points, 1 thread: 27.23e9 instructions
  /// against 28.67e9 (surface evaluations 7.31 -> 5.83 million, 0.76 million second
  /// derivatives); the smooth field's 11.00e9 -> 11.16e9 (the test costs more than the
  /// 11,000 feet it freezes save). Tried and not kept, on the rippled field: deciding by
  /// the ratio of two steps alone (from the second step on: 1M 27.87e9, the smooth field
  /// 11.02e9); the term estimated from the gradients alone (Powell's symmetric secant
  /// update, no evaluation: fewer steps saved, more halvings; 28.21e9); from second
  /// derivatives tabulated at the samples, from the first step on (100,000 points: 8.69e9
  /// against 8.51e9 here, 8.66e9 without); frozen only nearer the foot (within 3-4 steps
  /// predicted at the rate: 8.67e9 and up). True when it froze the term in `d`, after the
  /// full (`full`) step from `from` (gradient `from_gradient`) to `it`.
  bool freeze_curvature(const Vec3& q, const Iterate& it, Descent& d, const Vec2& from, const Vec2& from_gradient, bool full) const {
    if (!full) return false;
    const Vec2 s = it.x - from;
    const double s2 = s.squaredNorm();
    if (!(s2 > 0.0) || s2 > kFreezeNear * kFreezeNear) return false;
    if (d.iteration > 0) {
      if (!(std::sqrt(s2) >= kFreezeRate * d.previous)) return false;
    } else {
      const Hessian a = gauss_newton_hessian(it.s);
      const double along = a.uu * s.x() * s.x() + 2.0 * a.uv * s.x() * s.y() + a.vv * s.y() * s.y();
      const double curved = s.dot(gradient(q, it) - from_gradient) - along;
      if (!(std::abs(curved) >= kFreezeRate * along)) return false;
    }
    d.curvature = curvature_term(q, it, surface.second_derivatives(it.x.x(), it.x.y()));
    return true;
  }

  /// Newton's Hessian of |S - q|^2 / 2 at the iterate (see with_curvature): one evaluation
  /// of the second derivatives.
  Hessian newton_hessian(const Vec3& q, const Iterate& it) const {
    return with_curvature(gauss_newton_hessian(it.s), curvature_term(q, it, surface.second_derivatives(it.x.x(), it.x.y())));
  }

  /// Gauss-Newton on |S(u,v) - q|^2 over [0,1]^2 with an active set: a coordinate on a bound
  /// whose gradient points outward is held there and the other one moves alone. Each step
  /// is clamped to the domain and halved until the distance decreases. With
  /// newton_when_slow, Gauss-Newton's rate (about the distance times the curvature) is
  /// watched: for a point as far off as the surface's radius of curvature (another sheet of
  /// a folded cloud) it nears 1, and such a foot ran into the iteration limit with its
  /// distance still falling; it goes on with Newton's steps, which converge in a few.
  Iterate descend(const Vec3& q, Iterate it, std::array<bool, 2>& held) const {
    Descent d;
    switch (iterate<Steps::GaussNewton>(q, it, held, d)) {
      case Turn::ToNewton: iterate<Steps::Newton>(q, it, held, d); break;
      case Turn::ToCurved: iterate<Steps::Curved>(q, it, held, d); break;
      case Turn::Done: break;
    }
    held = held_coordinates(it, gradient(q, it));
    return it;
  }

  /// The Hessian of descend()'s steps: Gauss-Newton's; Newton's at every iterate; or
  /// Gauss-Newton's plus the curvature term frozen at one iterate (see freeze_curvature).
  enum class Steps { GaussNewton, Newton, Curved };
  /// How a loop of steps ends: converged (or out of steps), or turning from Gauss-Newton's
  /// to one of the other kinds.
  enum class Turn { Done, ToNewton, ToCurved };

  /// descend()'s steps of one kind (a loop of each: the Gauss-Newton loop of every foot
  /// carries nothing of the others).
  template <Steps kSteps>
  Turn iterate(const Vec3& q, Iterate& it, std::array<bool, 2>& held, Descent& d) const {
    for (; d.iteration < kMaxIterations; ++d.iteration) {
      const Vec2 g = gradient(q, it);
      held = held_coordinates(it, g);
      const Hessian h = kSteps == Steps::Newton ? newton_hessian(q, it) : kSteps == Steps::Curved ? with_curvature(gauss_newton_hessian(it.s), d.curvature) : gauss_newton_hessian(it.s);
      const double huu = h.uu, hvv = h.vv, huv = h.uv;
      Vec2 step = Vec2::Zero();
      if (!held[0] && !held[1]) {
        const double det = huu * hvv - huv * huv;
        // A degenerate Jacobian (collapsed corner) falls back to a scaled gradient step.
        if (det > 1e-14 * huu * hvv)
          step = Vec2(-(hvv * g.x() - huv * g.y()) / det, -(huu * g.y() - huv * g.x()) / det);
        else if (huu + hvv > 0.0)
          step = -g / (huu + hvv);
      } else if (!held[0] && huu > 0.0) {
        step.x() = -g.x() / huu;
      } else if (!held[1] && hvv > 0.0) {
        step.y() = -g.y() / hvv;
      }
      // A capped step is short by construction, not because the foot is near: refused, it
      // is halved (see take_step).
      bool capped = false;
      if (settle_creases)
        settle_on_crease(step, d.last, d.halved);
      else
        capped = settle_coordinate_on_crease(step, d);
      const double length = step.norm();
      const Vec2 from = it.x;
      const double taken = length > 0.0 ? take_step(q, it, step, length <= kNearFoot, capped) : 0.0;
      if (!(taken > 0.0)) return Turn::Done;
      // With settle_creases converged by the step taken (a halved step is the progress made).
      const double progress = settle_creases ? taken : length;
      if (converged(progress, d.previous, tolerance)) return Turn::Done;
      const bool gauss_newton = kSteps == Steps::GaussNewton;
      const bool slow = gauss_newton && newton_when_slow && progress >= kSlowRate * d.previous;
      const bool curve = gauss_newton && !settle_creases && freeze_curvature(q, it, d, from, g, taken == length && !capped);
      // The rate of the next step is judged against the step taken, not the one proposed:
      // after a step halved across a crease, the next proposal is measured against what
      // moved the iterate (the exact feet converge by their proposals, whose lengths
      // estimate the distance left).
      d.previous = taken;
      d.halved = taken < length;
      d.last = step * (taken / length);
      if (slow || curve) {
        ++d.iteration;
        return slow ? Turn::ToNewton : Turn::ToCurved;
      }
    }
    return Turn::Done;
  }

  /// Local minimum of |S - q| along one side, from that side's nearest sample.
  Iterate along_side(const Vec3& q, Side side, int sample) const {
    const double s = static_cast<double>(sample) / (samples - 1);
    Vec2 x;
    switch (side) {
      case Side::Bottom: x = Vec2(s, 0.0); break;
      case Side::Right: x = Vec2(1.0, s); break;
      case Side::Top: x = Vec2(s, 1.0); break;
      case Side::Left: x = Vec2(0.0, s); break;
    }
    const bool along_u = side == Side::Bottom || side == Side::Top;
    Iterate it = at(q, x);
    double previous = std::numeric_limits<double>::infinity();
    for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
      const Vec3& tangent = along_u ? it.s.du : it.s.dv;
      const double h = tangent.squaredNorm();
      if (!(h > 0.0)) break;
      const double step = -tangent.dot(it.s.p - q) / h, length = std::abs(step);
      const double taken = length > 0.0 ? take_step(q, it, along_u ? Vec2(step, 0.0) : Vec2(0.0, step), length <= kNearFoot) : 0.0;
      if (!(taken > 0.0)) break;
      const double progress = settle_creases ? taken : length;
      if (converged(progress, previous, tolerance)) break;
      previous = progress;
    }
    return it;
  }

  /// Nearest point of the four sides: each side starts from its nearest sample; a side whose
  /// samples are all farther than the best foot found plus half a sample step cannot win.
  Iterate nearest_on_boundary(const Vec3& q) const {
    const std::array<std::vector<Vec3>, 4>& side_samples = sides();
    auto sample_point = [&](Side side, int k) -> const Vec3& { return side_samples[static_cast<int>(side)][static_cast<std::size_t>(k)]; };
    std::array<std::pair<double, int>, 4> nearest_sample;
    for (int side = 0; side < 4; ++side) {
      nearest_sample[side] = {std::numeric_limits<double>::infinity(), 0};
      for (int k = 0; k < samples; ++k) {
        const double d = (sample_point(static_cast<Side>(side), k) - q).norm();
        if (d < nearest_sample[side].first) nearest_sample[side] = {d, k};
      }
    }
    std::array<int, 4> order{{0, 1, 2, 3}};
    std::sort(order.begin(), order.end(), [&](int a, int b) { return nearest_sample[a].first < nearest_sample[b].first || (nearest_sample[a].first == nearest_sample[b].first && a < b); });
    Iterate best;
    best.f = std::numeric_limits<double>::infinity();
    for (int side : order) {
      if (nearest_sample[side].first - 0.5 * side_step[side] >= std::sqrt(best.f)) continue;
      const Iterate it = along_side(q, static_cast<Side>(side), nearest_sample[side].second);
      if (it.f < best.f) best = it;
    }
    return best;
  }

  /// The descent from `start`, then the nearest boundary point where it leaves the patch.
  Foot foot_from(const Vec3& q, const Iterate& start) const {
    std::array<bool, 2> held{{false, false}};
    Iterate it = descend(q, start, held);
    Foot foot;
    foot.inside = !held[0] && !held[1];
    if (!foot.inside) it = nearest_on_boundary(q);
    foot.u = it.x.x();
    foot.v = it.x.y();
    foot.point = it.s.p;
    foot.distance = std::sqrt(it.f);
    return foot;
  }
};

SurfaceProjector::SurfaceProjector(const BaseSurface& surface, FootPrecision precision, int samples) {
  if (samples < 2) fail(ErrorCode::InvalidArgument, "SurfaceProjector: samples = " + std::to_string(samples) + ", at least 2 needed");
  impl_ = std::make_unique<Impl>(surface, precision == FootPrecision::Parameters ? kConvergedParameters : precision == FootPrecision::Measure ? kConvergedMeasure : kConvergedDistance, precision != FootPrecision::Parameters,
                                 precision == FootPrecision::Measure, samples);
}

SurfaceProjector::~SurfaceProjector() = default;

double SurfaceProjector::sample_distance(const Vec3& q) const { return nearest_sample(q).distance; }

double SurfaceProjector::sample_cover() const { return impl_->cover(); }

SurfaceProjector::Sample SurfaceProjector::nearest_sample(const Vec3& q) const {
  if (!is_finite(q)) fail(ErrorCode::NonFinite, "SurfaceProjector::nearest_sample: the point is not finite");
  const std::size_t k = impl_->index().nearest(q);
  return {k, (impl_->grid()[k] - q).norm()};
}

SurfaceProjector::Sample SurfaceProjector::sample_near(const Vec3& q, const Vec2& guess, int max_steps) const {
  if (!is_finite(q)) fail(ErrorCode::NonFinite, "SurfaceProjector::sample_near: the point is not finite");
  const Impl& m = *impl_;
  const std::vector<Vec3>& grid = m.grid();
  const int n = m.samples;
  auto cell = [n](double x) { return std::isfinite(x) ? static_cast<int>(std::lround(std::clamp(x, 0.0, 1.0) * (n - 1))) : 0; };
  int i = cell(guess.x()), j = cell(guess.y());
  auto distance2 = [&](int a, int b) { return (grid[static_cast<std::size_t>(b) * n + a] - q).squaredNorm(); };
  double best = distance2(i, j);
  for (int step = 0; step < max_steps; ++step) {
    int bi = i, bj = j;
    for (int b = std::max(0, j - 1); b <= std::min(n - 1, j + 1); ++b)
      for (int a = std::max(0, i - 1); a <= std::min(n - 1, i + 1); ++a) {
        const double d2 = distance2(a, b);
        if (d2 < best) best = d2, bi = a, bj = b;
      }
    if (bi == i && bj == j) break;
    i = bi, j = bj;
  }
  return {static_cast<std::size_t>(j) * n + i, std::sqrt(best)};
}

Foot SurfaceProjector::project(const Vec3& q) const {
  if (!is_finite(q)) fail(ErrorCode::NonFinite, "SurfaceProjector::project: the point is not finite");
  return project(q, Sample{impl_->index().nearest(q), 0.0});
}

Foot SurfaceProjector::project(const Vec3& q, const Sample& nearest) const {
  if (!is_finite(q)) fail(ErrorCode::NonFinite, "SurfaceProjector::project: the point is not finite");
  const Impl& m = *impl_;
  if (nearest.index >= m.grid().size()) fail(ErrorCode::OutOfRange, "SurfaceProjector::project: sample " + std::to_string(nearest.index) + " does not exist");
  const std::size_t k = nearest.index;
  if (m.tabulated.empty()) return project_from(q, m.sample_parameters(k));
  // The start's evaluation from the table: the same bits as m.at(q, start).
  Iterate start{m.sample_parameters(k), m.tabulated[k], 0.0};
  start.f = (start.s.p - q).squaredNorm();
  return m.foot_from(q, start);
}

void SurfaceProjector::prepare(std::size_t projections) {
  Impl& m = *impl_;
  const std::size_t count = static_cast<std::size_t>(m.samples) * static_cast<std::size_t>(m.samples);
  if (projections <= count || !m.tabulated.empty()) return;
  m.tabulated.resize(count);
  for (std::size_t k = 0; k < count; ++k) {
    const Vec2 x = m.sample_parameters(k);
    m.tabulated[k] = m.surface.eval_derivs(x.x(), x.y());
  }
}

Foot SurfaceProjector::project_from(const Vec3& q, const Vec2& start) const {
  if (!is_finite(q)) fail(ErrorCode::NonFinite, "SurfaceProjector::project_from: the point is not finite");
  if (!(start.x() >= 0.0 && start.x() <= 1.0 && start.y() >= 0.0 && start.y() <= 1.0)) fail(ErrorCode::OutOfRange, "SurfaceProjector::project_from: the start is outside [0,1]^2");
  return impl_->foot_from(q, impl_->at(q, start));
}

}  // namespace dbs
