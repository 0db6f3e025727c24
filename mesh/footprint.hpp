// Graded 2-D triangulation of the layer's footprint (disc or square) in the (x, y) plane,
// CGAL constrained Delaunay refinement with the sizing field as local edge-length bound.
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <vector>

#include "skinfem/mesh/tet_mesh.hpp"
#include "skinfem/scene/scene.hpp"

namespace skinfem {

// Target edge length (mm) at a point (x, y) of the footprint.
using Size2d = std::function<double(double, double)>;

struct Footprint {
  Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor> points;  // V×2, mm
  RowMatrixX3i triangles;                                            // T×3, counter-clockwise
  std::vector<int> boundary;  // the outer loop, counter-clockwise, each vertex once
};

struct Circle {
  Vec2 centre;
  double radius;
};

// loop: closed polygon, counter-clockwise, first point not repeated; every edge is split as needed.
// circles: interior curves the triangulation must follow (a punch's edge), their vertices on the circle.
// cut_at_y0: the loop is a half (y ≥ 0) whose cut lies on y = 0; a circle centred on the cut is followed
// by its upper half only, from (x + r, 0) to (x − r, 0) exactly, and vertices on the cut stay there.
Footprint mesh_footprint(const std::vector<Vec2>& loop, const Size2d& size,
                         const std::vector<Circle>& circles = {}, bool cut_at_y0 = false);

// Boundary loops that follow the sizing field: a circle (cap) and a square (flat).
std::vector<Vec2> circle_loop(const Vec2& centre, double radius, const Size2d& size);
std::vector<Vec2> square_loop(double half_width, const Size2d& size);
// Their halves y ≥ centre y (a mirror-symmetric scene's meshed part): the arc or the three sides, then the
// cut along y = centre y, counter-clockwise.
std::vector<Vec2> half_circle_loop(const Vec2& centre, double radius, const Size2d& size);
std::vector<Vec2> half_square_loop(double half_width, const Size2d& size);

// The constrained Delaunay triangulation of a simple polygon with no point added (its edges are shared
// with other faces): triangles as indices into `loop`, counter-clockwise.
RowMatrixX3i triangulate_polygon(const std::vector<Vec2>& loop);

}  // namespace skinfem
