//! @file Marker lines (front tracking) of the Eulerian TVD solver: construction, advection,
//! redistribution and exact rasterisation into a cell-ownership (configuration) array.
#pragma once
#include <cstddef>
#include <iosfwd>
#include <vector>

#include "hvi/cases/scene.hpp"
#include "hvi/common/geometry.hpp"
#include "hvi/common/snapshot.hpp"
#include "hvi/common/vec2.hpp"

namespace hvi::tvd {

//! An ordered chain of markers joined by straight segments. The object lies to the LEFT of the
//! direction of travel (counter-clockwise outer boundary, clockwise hole), so the outward normal
//! of a segment with tangent t is (t.z, -t.x). A line is always treated as closed (the last
//! point joins the first); `closed` is kept for output only.
struct MarkerLine {
  int object = -1;
  bool closed = true;
  std::vector<Vec2> points;  //!< cm
};

//! All marker lines of a run. Not safe for concurrent calls on one instance (rasterize and
//! advect share scratch buffers); each call is threaded internally with OpenMP.
class MarkerSet {
 public:
  MarkerSet() = default;

  //! Closed marker lines around each body of the scene (object index = body index), points
  //! spaced at most `scene.tvd.markerSpacing * grid.dx` apart; in r-z the part of a body at
  //! x < 0 is cut off and a body touching the axis gets a line that runs along the axis (its
  //! points there have x = 0 exactly and stay on it). Throws InputError for a bad spacing/grid.
  static MarkerSet fromBodies(const cases::Scene& scene, const GridSpec& grid);
  //! Same from a list of shapes (object index = position in the list).
  static MarkerSet fromShapes(const std::vector<cases::Shape>& shapes, const GridSpec& grid,
                              double spacingCells, Geometry g);
  //! From ready-made lines (object of each line given; holes are clockwise lines of the same
  //! object). `objects` is the number of objects (at least 1 + the largest line object).
  static MarkerSet fromLines(std::vector<MarkerLine> lines, int objects, double spacingCells,
                             Geometry g);

  //! Moves every marker with the cell-centred velocity (vx, vz arrays in cm/us, index k*nx+i)
  //! bilinearly interpolated, for time dt (us). The solver passes the time-centred velocity
  //! (the mean of the start- and end-of-step cell velocities); within the step the marker path
  //! is integrated by the explicit midpoint rule in space, so the position error is O(dt^3) per
  //! step. Outside the cell-centre range
  //! the nearest values are used, except at the r-z axis where vx is reflected oddly (vx = 0 on
  //! the axis). In r-z, markers on the axis keep x = 0 and no marker goes to x < 0.
  void advect(const GridSpec& grid, const double* vx, const double* vz, double dt);

  //! Keeps every segment between minCells*dx and maxCells*dx (defaults 0.5 and 2 times the
  //! spacing: 0.25 and 1.0 cells for the default 0.5-cell spacing): inserts markers on long
  //! segments (area unchanged) and collapses short segments into one point placed so that the
  //! enclosed volume (area in planar, integral of r dA in r-z) is unchanged. Lines whose area
  //! is below tinyLoopCells*dx^2 and that fit in 2x2 cells are deleted. See docs/markers.md.
  void redistribute(const GridSpec& grid);
  //! Changes the redistribution bounds, in cells. Requires 0 < minCells, 2*minCells <= maxCells.
  void setSpacingBounds(double minCells, double maxCells);
  void setTinyLoopCells(double cells) { tinyLoopCells_ = cells; }

  //! owner[c] = object covering the largest part of cell c, -1 if vacuum covers more than any
  //! object (vacuum is a candidate; ties go to the object, and between objects to the lower
  //! index); normal[c] = unit length-weighted mean normal of the marker segments inside cell c,
  //! pointing out of the owner (out of the material when the owner is vacuum), zero if the
  //! cell is not cut or the normals cancel (a sliver thinner than the cell). Both resized to
  //! grid.cells(). Cost O(markers + cells of the objects' bounding boxes + cells).
  void rasterize(const GridSpec& grid, std::vector<int>& owner, std::vector<Vec2>& normal) const;
  //! Same, and fraction[object * cells + c] = part of cell c's area covered by the object
  //! (nonzero winding rule, in [0, 1]).
  void rasterize(const GridSpec& grid, std::vector<int>& owner, std::vector<Vec2>& normal,
                 std::vector<double>& fraction) const;

  double area(int object) const;  //!< enclosed area (shoelace) of the object's lines, cm^2
  //! Volume represented by the object: area (per unit depth, cm^2) in planar geometry,
  //! 2 pi * integral of r dA (cm^3) in r-z.
  double volume(int object) const;
  std::vector<Polyline> polylines() const;
  const std::vector<MarkerLine>& lines() const { return lines_; }
  std::size_t size() const;  //!< total markers
  int objects() const { return objects_; }
  Geometry geometry() const { return geometry_; }
  double spacingCells() const { return spacingCells_; }
  double minSpacingCells() const { return minCells_; }
  double maxSpacingCells() const { return maxCells_; }

  void write(std::ostream&) const;  //!< exact binary, for checkpoints
  void read(std::istream&);         //!< throws InputError if the stream is not a MarkerSet

 private:
  void rasterizeInto(const GridSpec& grid, std::vector<int>& owner, std::vector<Vec2>& normal,
                     double* fraction) const;

  std::vector<MarkerLine> lines_;
  int objects_ = 0;
  Geometry geometry_ = Geometry::Planar;
  double spacingCells_ = 0.5;
  double minCells_ = 0.25;
  double maxCells_ = 1.0;
  double tinyLoopCells_ = 0.05;

  // Scratch reused between calls so that the per-step calls do not allocate.
  mutable std::vector<double> acc_;        // per-object coverage accumulation over its bounding box
  mutable std::vector<double> best_;       // largest object fraction so far, per cell
  mutable std::vector<double> total_;      // sum of object fractions, per cell
  mutable std::vector<double> cutLength_;  // length of marker segments inside each cell
  std::vector<Vec2> scratchPoints_;
};

}  // namespace hvi::tvd
