//! @file Polygon checks for scene bodies: simplicity, orientation, segment tests.
#pragma once
#include <string>

#include "hvi/cases/scene.hpp"

namespace hvi::cases::detail {

//! Reorders clockwise vertices to counter-clockwise. False, with the reason, if the polygon has a
//! repeated vertex, crossing or touching non-adjacent edges, or zero area.
bool makeSimpleCounterClockwise(Polygon& poly, std::string& why);

//! Whether segments [a, b] and [c, d] share a point (touching counts).
bool segmentsIntersect(Vec2 a, Vec2 b, Vec2 c, Vec2 d);
//! Distance from p to the segment [a, b].
double distanceToSegment(Vec2 p, Vec2 a, Vec2 b);

}  // namespace hvi::cases::detail
