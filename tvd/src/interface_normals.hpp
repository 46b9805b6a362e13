//! @file Interface normals of the cut cells for the contact fluxes.
#pragma once
#include <vector>

#include "hvi/common/snapshot.hpp"
#include "hvi/tvd/markers.hpp"

namespace hvi::tvd::detail {

//! normal[c] = unit length-weighted mean normal of the marker segments inside cell c, pointing
//! out of the cell's owner, zero where no segment passes or the normals cancel. Unlike the
//! normals of MarkerSet::rasterize, segments lying on the domain boundary (a body's side along
//! a wall or an r-z line along the axis) are left out: there they are no interface, and in the
//! corner cells they would tilt the normal of a real interface (striker/shield at the axis) by
//! 45 degrees. Pieces outside the grid are skipped. `length` is scratch of grid.cells() values.
void interfaceNormals(const MarkerSet& markers, const GridSpec& grid, const std::vector<int>& owner,
                      std::vector<Vec2>& normal, std::vector<double>& length);

}  // namespace hvi::tvd::detail
