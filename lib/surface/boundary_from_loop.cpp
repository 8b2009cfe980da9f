#include "boundary_from_loop.hpp"

#include <algorithm>
#include <string>

#include "error.hpp"

namespace dbs {

namespace {

std::string corner_list(const std::array<std::size_t, 4>& corners) {
  return std::to_string(corners[0]) + ", " + std::to_string(corners[1]) + ", " + std::to_string(corners[2]) + ", " + std::to_string(corners[3]);
}

}  // namespace

Boundary boundary_from_loop(std::vector<Vec3> loop, std::array<std::size_t, 4> corners) {
  if (loop.size() >= 2 && loop.front() == loop.back()) {
    loop.pop_back();
    for (std::size_t& c : corners)
      if (c == loop.size()) c = 0;  // the repeated point is the first one
  }
  const std::size_t n = loop.size();
  if (n < 4) fail(ErrorCode::InvalidArgument, "the loop has " + std::to_string(n) + " distinct end points; at least 4 are needed, one per corner");
  for (std::size_t i = 0; i < n; ++i)
    if (!is_finite(loop[i])) fail(ErrorCode::NonFinite, "loop point " + std::to_string(i) + " has a non-finite coordinate");
  for (int k = 0; k < 4; ++k) {
    if (corners[k] >= n) fail(ErrorCode::OutOfRange, "corner " + std::to_string(k) + " is index " + std::to_string(corners[k]) + ", not one of the loop's " + std::to_string(n) + " points");
    for (int j = 0; j < k; ++j)
      if (corners[j] == corners[k]) fail(ErrorCode::InvalidArgument, "corners " + std::to_string(j) + " and " + std::to_string(k) + " are the same loop point " + std::to_string(corners[k]));
  }
  // Steps from a to b going forward along the loop.
  auto ahead = [n](std::size_t a, std::size_t b) { return (b + n - a) % n; };
  const bool forward = ahead(corners[0], corners[1]) < ahead(corners[0], corners[2]) && ahead(corners[0], corners[2]) < ahead(corners[0], corners[3]);
  const bool backward = ahead(corners[1], corners[0]) < ahead(corners[2], corners[0]) && ahead(corners[2], corners[0]) < ahead(corners[3], corners[0]);
  if (!forward && !backward)
    fail(ErrorCode::InvalidArgument, "the corners (loop points " + corner_list(corners) + ") are not in cyclic order along the loop in either direction: the bottom, right, top and left would cross");
  // The loop's points from a to b inclusive, in the direction the corners go.
  auto arc = [&](std::size_t a, std::size_t b) {
    std::vector<Vec3> points;
    const std::size_t steps = forward ? ahead(a, b) : ahead(b, a);
    for (std::size_t s = 0, i = a; s <= steps; ++s, i = forward ? (i + 1) % n : (i + n - 1) % n) points.push_back(loop[i]);
    return points;
  };
  std::vector<Vec3> top = arc(corners[2], corners[3]), left = arc(corners[3], corners[0]);
  std::reverse(top.begin(), top.end());
  std::reverse(left.begin(), left.end());
  return Boundary(arc(corners[0], corners[1]), arc(corners[1], corners[2]), std::move(top), std::move(left));
}

}  // namespace dbs
