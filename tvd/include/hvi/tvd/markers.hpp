//! @file Marker lines (front tracking) of the Eulerian TVD solver: construction, advection,
//! redistribution and exact rasterisation into a cell-ownership (configuration) array.
#pragma once
#include <array>
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
  //! The line's spacings (marker, minimum, maximum) in units of the set's: 1, or a power of 2
  //! once the line outgrew the point budget (MarkerSet::checkGrowth coarsens it).
  double scale = 1.0;
};

//! Wetted fraction ("aperture") of every cell face by every object, for the conservative
//! cut-cell interface mode (Hu, Khoo, Adams, Huang, J. Comput. Phys. 219 (2006) 553): the part
//! of the face where the object's winding number is nonzero (the nonzero rule, like rasterize's
//! fractions), in [0, 1]. Each face has two ONE-SIDED limits, so that an object edge lying
//! exactly on a grid line is seen by the cell on the object's side and not by the other one: a
//! face on an object's edge is wet on the object's side only; a face inside the object is wet on
//! both sides. Away from edges on grid lines the two limits are equal.
struct FaceApertures {
  int nx = 0, nz = 0, objects = 0;
  //! x faces (x = x0 + i dx, z in [z0 + k dz, z0 + (k+1) dz], i in [0, nx], k in [0, nz)):
  //! x[((o * 2 + side) * nz + k) * (nx + 1) + i]; side 0: the limit from x < X (cell i-1's
  //! side), side 1: from x > X (cell i's side).
  std::vector<double> x;
  //! z faces (z = z0 + k dz, x in [x0 + i dx, x0 + (i+1) dx], k in [0, nz], i in [0, nx)):
  //! z[((o * 2 + side) * (nz + 1) + k) * nx + i]; side 0: from z < Z (cell k-1), 1: from z > Z.
  std::vector<double> z;
  //! Wet span of every grid line, per object and side: faces [lo, hi) along the line hold every
  //! face the object wets there (lo >= hi: none). x lines (i = 0 .. nx, faces along z):
  //! xSpan[((o * 2 + side) * (nx + 1) + i) * 2 + {0: lo, 1: hi}]; z lines (k = 0 .. nz, faces
  //! along x): zSpan likewise with nz + 1. Phases::measure fits the bodies' apertures together
  //! only where two spans overlap (elsewhere one body's aperture alone is at most 1).
  std::vector<int> xSpan, zSpan;

  //! Aperture of x face (i, k) of object o seen from `side` (0: cell i-1, 1: cell i).
  [[nodiscard]] double ax(int o, int side, int i, int k) const {
    return x[static_cast<std::size_t>(((static_cast<long>(o) * 2 + side) * nz + k) * (nx + 1) + i)];
  }
  //! Aperture of z face (i, k) of object o seen from `side` (0: cell k-1, 1: cell k).
  [[nodiscard]] double az(int o, int side, int i, int k) const {
    return z[static_cast<std::size_t>(((static_cast<long>(o) * 2 + side) * (nz + 1) + k) * nx + i)];
  }
};

//! A cell's live phases cover it when their fractions sum to this or more (1 to the round-off
//! of the phases' fit, Phases::measure): every body's line may then read its velocity
//! (TvdSolver::markOwnCells, MarkerSet::advect's `own`).
inline constexpr double kOwnFilled = 1.0 - 1e-9;

//! All marker lines of a run. Not safe for concurrent calls on one instance (rasterize,
//! faceApertures and advect share scratch buffers); each call is threaded internally with OpenMP.
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
  //! `walls` (xmin, xmax, zmin, zmax; the conservative interfaces' walls): a marker on a wall
  //! keeps its normal coordinate and one inside does not cross it, so a body's side on a wall
  //! stays on it (docs/markers.md; without it the side's markers moved off the wall with the
  //! wall cell's velocity, and a body in lateral tension came off the wall). `oddWalls` also
  //! continues the normal velocity oddly across those sides (zero on the wall, as at the axis):
  //! off in the solver, since it made the energy floors take a quarter of the energy of a
  //! body driven onto a wall (docs/markers.md).
  //! `open` (sides xmin, xmax, zmin, zmax): a marker beyond an open (outflow) side stays where
  //! it is: what it bounded has left and must not be brought back by the edge cells' velocity
  //! (the cut-cell mode, docs/tvd.md "Outflow sides: no re-entry"); none open by default.
  //! `own` (optional, one array per object, cells of `grid`): where own[o][c] > 0 a line of
  //! object o may read cell c's velocity (o holds it, or bodies fill it together). Where some
  //! but not all cells of a line's interpolation stencil are marked, the line reads only the
  //! marked ones (the others take the value of a neighbour in the stencil that is; docs/tvd.md
  //! "Marker velocity: each line its own body's"); where none is, or with no `own`, every cell.
  void advect(const GridSpec& grid, const double* vx, const double* vz, double dt,
              std::array<bool, 4> walls = {}, std::array<bool, 4> open = {},
              bool oddWalls = false, const std::vector<std::vector<double>>* own = nullptr);

  //! Cuts the lines at the grid's sides in `sides` (xmin, xmax, zmin, zmax; the cut-cell mode's
  //! outflow sides): each closed line is clipped to the grid's half-planes of those sides
  //! (Sutherland-Hodgman), so the part beyond a side is removed and the line is closed along the
  //! side. The region inside is unchanged (crossing points on the side exactly; the other
  //! coordinate interpolated, so an r-z axis point stays at x = 0), every line keeps its
  //! direction, and a line with nothing left inside is removed. Where a line leaves and re-enters
  //! the result joins its parts by zero-width runs along the side, which cover nothing (nonzero
  //! rule; a segment along a grid line crosses none). Lines with no point beyond are not
  //! touched. Call redistribute afterwards (the cut gives short edges). Returns the number of
  //! lines removed. docs/markers.md, "Cutting at outflow sides".
  long clipToSides(const GridSpec& grid, std::array<bool, 4> sides);

  //! Removes every line of object `o`; returns how many.
  long removeObject(int o);

  //! Keeps every segment between minCells*dx and maxCells*dx (defaults 0.5 and 2 times the
  //! spacing: 0.25 and 1.0 cells for the default 0.5-cell spacing): inserts markers on long
  //! segments (area unchanged) and collapses short segments into one point placed so that the
  //! enclosed volume (area in planar, integral of r dA in r-z) is unchanged. Lines whose area
  //! is below tinyLoopCells*dx^2 and that fit in 2x2 cells are deleted. See docs/markers.md.
  void redistribute(const GridSpec& grid);
  //! Changes the redistribution bounds, in cells. Requires 0 < minCells, 2*minCells <= maxCells.
  void setSpacingBounds(double minCells, double maxCells);
  void setTinyLoopCells(double cells) { tinyLoopCells_ = cells; }
  //! How many times a line was coarsened since construction (checkGrowth; kept in checkpoints
  //! through the lines' scales, not this count).
  long coarsenings() const { return coarsenings_; }
  //! The largest scale of any line (1: none coarsened).
  double largestScale() const;
  //! The most a line's spacings are coarsened (checkGrowth; a checkpoint's scale beyond it is
  //! corrupt).
  static constexpr double kMaxLineScale = 64.0;

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
  //! Same, where `fraction` (if already of its size) is zero outside grid rows [rowLo, rowHi):
  //! only those rows and the rows the lines span (rowSpan) are cleared before the lines'
  //! coverage is written.
  void rasterize(const GridSpec& grid, std::vector<int>& owner, std::vector<Vec2>& normal,
                 std::vector<double>& fraction, int rowLo, int rowHi) const;
  //! The cut-cell mode's form: the owners and fraction[object][c], one array per object (any
  //! arrays of the right count and size are written in place, given they are zero outside grid
  //! rows [rowLo, rowHi); otherwise they are sized and zeroed), and no normals (the mode reads
  //! none). The owners and fractions are those of the forms above, bit for bit.
  void rasterizeFractions(const GridSpec& grid, std::vector<int>& owner,
                          std::vector<std::vector<double>>& fraction, int rowLo, int rowHi) const;

  //! Apertures of every cell face by every object (see FaceApertures), exact for the straight
  //! marker segments up to rounding. Parts of the lines outside the grid count (the winding
  //! number on the grid's faces is that of the whole line; nothing is clamped). out is resized
  //! (no allocation once its capacity suffices; scratch is reused likewise). Cost O(markers +
  //! line crossings + objects * faces); crossings are sorted per grid line. An `out` of the
  //! previous call's layout has only its wet spans (FaceApertures::xSpan) cleared, so the cost
  //! does not grow with the faces outside the objects; its faces must be as that call (or a fit
  //! that keeps zeros zero, Phases::measure) left them.
  void faceApertures(const GridSpec& grid, FaceApertures& out) const;
  //! Grid rows [lo, hi) the lines span, points beyond the grid clamped onto it (the rows where
  //! rasterize can give a fraction); lo = hi = 0 without lines.
  void rowSpan(const GridSpec& grid, int& lo, int& hi) const;

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
  //! Where the redistribution (spacing h within [minLen, maxLen], times each line's scale)
  //! would give the lines more than kMaxPointsPerCell points per grid cell, coarsens the
  //! longest lines (their scale doubled, up to kMaxLineScale) until the total is back under half of
  //! it; throws SimulationError if that cannot be done.
  void checkGrowth(const GridSpec& grid, double h, double minLen, double maxLen);
  //! `normal` null: no normals (and no marker lengths); `fraction` null: no fractions, else
  //! one array per object.
  void rasterizeInto(const GridSpec& grid, std::vector<int>& owner, std::vector<Vec2>* normal,
                     double* const* fraction) const;
  void clearRows(const GridSpec& grid, int rowLo, int rowHi) const;  // of objectFraction_

  std::vector<MarkerLine> lines_;
  int objects_ = 0;
  Geometry geometry_ = Geometry::Planar;
  double spacingCells_ = 0.5;
  double minCells_ = 0.25;
  double maxCells_ = 1.0;
  double tinyLoopCells_ = 0.05;
  long coarsenings_ = 0;

  // Scratch reused between calls so that the per-step calls do not allocate.
  mutable std::vector<double> acc_;    // per-object coverage accumulation over its bounding box
  mutable std::vector<double> best_;   // largest object fraction so far, per cell
  mutable std::vector<double> total_;  // sum of object fractions, then marker length, per cell
  mutable std::vector<double*> objectFraction_;  // each object's fraction array
  std::vector<Vec2> scratchPoints_;
  //! A crossing of a grid line by a segment (faceApertures): position along the line (cells),
  //! winding change, and which one-sided limits see it (bit 0: side 0, bit 1: side 1).
  struct LineCrossing {
    double at;
    int winding;
    int sides;
  };
  mutable std::vector<LineCrossing> crossings_;  // per object, bucketed by grid line
  mutable std::vector<long> crossingStart_;      // bucket offsets, one per grid line + 1
};

}  // namespace hvi::tvd
