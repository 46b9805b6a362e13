//! @file Whether two body shapes overlap (touching is not overlapping).
#pragma once
#include "hvi/cases/scene.hpp"

namespace hvi::cases::detail {

//! Signed depth of p in s: positive inside (distance to the boundary), negative outside.
double depth(const Shape& s, Vec2 p);

//! True if the interiors of a and b share a region deeper than `tol` (cm). Exact for disks and
//! rectangles; with a polygon, by vertex depths and 128 x 128 samples of the common bounding
//! box, which can miss an overlap thinner than 1/128 of that box.
bool overlaps(const Shape& a, const Shape& b, double tol);

}  // namespace hvi::cases::detail
