// The four corners of a closed outline loop (outline.hpp), where it turns most.
//
// A loop point's turning is the signed angle between the chords to the loop points
// kCornerWindow of the perimeter before and after it, in the surface's tangent plane there
// (so a half cylinder's curved ends, straight along the surface, do not turn), counted
// positive towards the inside. The corners are the four largest maxima at least 5% of the
// perimeter apart (twice the chord length: a side may be short, as the ends of the example
// shoe last, a strip ten times longer than wide). A round outline, whose fourth turning is
// below kRoundTurning, takes
// instead the loop points nearest to the corners of its minimum-area bounding rectangle in the
// plane of its principal axes (an ellipse: the rectangle of its axes). Ties go to the lower
// loop index, so the choice is deterministic.
#pragma once
#include <array>
#include <cstddef>

#include "outline.hpp"

namespace dbs {

constexpr double kCornerWindow = 0.025;      ///< chord length of the turning, fraction of the perimeter
constexpr double kCornerSeparation = 0.05;   ///< corners at least this fraction of the perimeter apart (two window lengths)
constexpr double kRoundTurning = 0.5235987755982988;  ///< 30 degrees

/// Indices into loop.points of its four corners, in increasing order. Throws
/// Error(Degenerate) when the loop has fewer than 8 points or four distinct corners cannot
/// be found.
std::array<std::size_t, 4> outline_corners(const OutlineLoop& loop);

}  // namespace dbs
