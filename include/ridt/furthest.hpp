// The farthest-point Delaunay triangulation (scipy's furthest_site=True).
#pragma once

#include <span>

#include "ridt/ridt.hpp"

namespace ridt {

/// The farthest-point Delaunay triangulation of `points`: the triangulation of their convex
/// hull's corners (the extreme points) in which every triangle's circumcircle holds every
/// point, inside or on it; the projection of the upper convex hull of the points lifted to the
/// paraboloid z = x^2 + y^2, as the ordinary Delaunay triangulation is of the lower. Its dual
/// is the farthest-point Voronoi diagram. Decided by the exact in-circle test; where corners
/// are cocircular every triangulation of them qualifies, and the one chosen is fixed by the
/// hull's order. Triangles counter-clockwise, neighbours as in triangulate(), `hull` the
/// corners counter-clockwise, `duplicates` as triangulate() finds them; points that are not
/// corners are vertices of no triangle. Fewer than three corners (collinear points, fewer than
/// three distinct): no triangle and a warning. The corners' triangulation costs O(h^2) in the
/// worst case for h corners (about h log h for points in general position), after an
/// ordinary triangulation of the points to find the hull.
Triangulation triangulate_furthest_site(std::span<const Point> points, const Options& options = {});

}  // namespace ridt
