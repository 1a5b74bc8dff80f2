#pragma once
// Practical deviation from thesis §5.1.1 (docs/algorithm/nosteiner2d.md "Spoke
// floor"): the spokes of a welded vertex wedge are never shorter than a fixed
// fraction of delta_P(V), the distance from V to the closest face of dP not
// containing V. The thesis's smallest spirals shrink geometrically and, with
// strong interference on both sides of a corner, meet below the resolution of
// doubles (docs/algorithm/nosteiner2d.md "Known limits"); the floor keeps every
// spoke end (and hence Q and R) representable.
#include "nosteiner2d/stages.hpp"

namespace pqmesh::detail {

// Fraction of delta_P(V) below which no spoke is shortened. Any value < 1
// keeps the floored part of the wedge inside the open disk of radius
// delta_P(V), which no face of dP other than the two sides at V meets.
inline constexpr double kSpokeFloorFraction = 1.0 / 16;

// Raises every spoke's log radius to at least log_floor and re-spaces each
// run of >= 2 consecutive floored spokes: the run's first and last spokes keep
// their angles, the ones between are replaced by min(old count,
// ceil(span / (pi/3))) equal steps on the floor circle (isosceles triangles).
// A run's new step is never below the smallest old step inside it and at most
// pi/2, and raising a spoke only brings the ratio of two consecutive spokes
// closer to 1, so the wedge's min angle does not decrease (up to rounding).
// Returns the number of spokes raised. The first and last spokes keep their
// angles (the edge welding of Fig. 5.11 reads them). After a re-spacing
// thirds_first would not index Fig. 5.10's spokes and is set to -1.
int floor_spokes(VertexWedge& w, double log_floor);

}  // namespace pqmesh::detail
