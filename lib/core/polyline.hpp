// A polyline parameterized by normalized arc length s in [0,1].
#pragma once

#include <utility>
#include <vector>

#include "geometry.hpp"

namespace dbs {

class Polyline {
 public:
  Polyline() = default;
  /// Requires >= 2 points; throws Error(Degenerate) when the total length is zero.
  explicit Polyline(std::vector<Vec3> points);

  const std::vector<Vec3>& points() const { return points_; }
  std::size_t size() const { return points_.size(); }
  double length() const { return cumulative_.empty() ? 0.0 : cumulative_.back(); }
  const Vec3& front() const { return points_.front(); }
  const Vec3& back() const { return points_.back(); }

  /// Point at arc-length fraction s (clamped to [0,1]); exact at s = 0, s = 1 and at vertices.
  Vec3 at(double s) const;
  /// Unit tangent at s (of the segment containing s).
  Vec3 tangent(double s) const;
  /// at(s), and in d_ds its derivative length() * tangent(s), from one segment search.
  Vec3 at(double s, Vec3& d_ds) const;
  /// The two halves at arc-length fraction s; the split point ends the first and starts
  /// the second (it is a vertex of both, exactly).
  std::pair<Polyline, Polyline> split(double s) const;
  /// Nearest point of the polyline to q; out_s receives its arc-length fraction.
  Vec3 nearest(const Vec3& q, double* out_s = nullptr) const;
  /// Copy with the first / last vertex replaced (used to make corners coincide exactly).
  Polyline with_ends(const Vec3& first, const Vec3& last) const;

  /// Finding the segment of s in O(1): bucket b holds the first vertex whose cumulative
  /// length exceeds b / buckets of the total (one bucket per segment), so a few steps from
  /// there find it (the result is that of a binary search; this lookup is on the path of
  /// every surface evaluation).
  struct Lookup {
    double buckets_per_length = 0.0;
    std::vector<std::size_t> bucket_first;
  };

 private:
  std::vector<Vec3> points_;
  std::vector<double> cumulative_;  // arc length up to each vertex
  Lookup lookup_;
  std::vector<Vec3> derivative_;  // per segment: the d/ds at(s, d_ds) gives on it
};

}  // namespace dbs
