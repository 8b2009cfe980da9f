// A four-sided boundary cut from one closed polyline (an outline traced around a scan, a CAD
// loop) at four of its points, the corners (0,0), (1,0), (1,1), (0,1) in that order.
#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include "boundary.hpp"

namespace dbs {

/// `loop`: a closed polyline, its first point not repeated at the end (a last point equal
/// to the first, bit for bit, is dropped, and a corner on it is the first point). `corners`: four distinct indices into it, in
/// cyclic order along the loop in either direction. The bottom runs from loop[corners[0]] to
/// loop[corners[1]] along the loop (the way that passes no other corner), the right from
/// corners[1] to corners[2], the top from corners[3] to corners[2] and the left from
/// corners[0] to corners[3]; the loop's own direction does not matter (the same loop reversed,
/// its corner indices following it, gives the same boundary bit for bit), and rotating the
/// corner list rotates the domain. Every side holds the loop's own points, its ends the
/// corner points themselves, so the corners coincide exactly.
/// Throws Error: InvalidArgument (fewer than 4 points, corners repeated or not in cyclic
/// order), OutOfRange (a corner index beyond the loop), NonFinite, and what the Boundary
/// constructor throws (a side of zero length, no area).
Boundary boundary_from_loop(std::vector<Vec3> loop, std::array<std::size_t, 4> corners);

}  // namespace dbs
