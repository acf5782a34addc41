// The Johnson-Cohen approximation of the triangle distance (paper 3.2.1, G4),
// kept as the baseline the precise method is measured against.
#pragma once

#include "geometry/triangle_distance.h"

namespace prox::geometry {

// The closest of the 7 x 7 pairs of feature points (3 vertices, 3 edge
// midpoints, the centroid of each triangle). The features are those of the
// chosen points; `intersects` is always false: the approximation cannot tell.
TriangleDistance sampled_triangle_distance(const Triangle& a, const Triangle& b);

}  // namespace prox::geometry
