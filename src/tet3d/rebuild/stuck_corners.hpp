#pragma once
// The tetrahedra at a warp table's stuck corners (docs/algorithm/mesh3d.md
// "Light construction first"): ring points §4.3 moves (within h/8 of a P
// edge or h/16 of a facet) whose every move (the full move, the fallbacks,
// the shortened and line moves) the side rules or the clearance test refused
// (warp.cpp settle_move, counted in WarpTable::conflicts). Such a point stays
// at its prewarped place, a sliver away from the facet when the plane of a
// nearly coplanar facet of its boxes passes on its other side. mesh_boxes
// hands the tetrahedra at them, from a trial on its first table, to
// BoxMeshOptions::stuck_review before the rebuild loop.
#include <span>
#include <vector>

#include "tet3d/facet_boxes.hpp"
#include "tet3d/rebuild/job_runs.hpp"
#include "tet3d/warp/warp.hpp"

namespace pqmesh::tet3d {

// The ring points (not square centres) the table built with `journal` left
// in place because the side rules refused every move, sorted, without
// repeats. `candidates`: the table's. Cost O(journal rows).
std::vector<GridPoint> stuck_points(const WarpCandidates& candidates, const WarpJournal& journal);

// A trial on `warps` of the jobs whose closed box holds a point of `stuck`
// (sorted): its tetrahedra that have a stuck point as a vertex (BoxMesh
// mesh.tetrahedra, keys, tet_job, tet_leaf), from the jobs in which no
// tetrahedron inverted (the rebuild loop remakes those). Cost: those jobs'
// share of a trial.
BoxMesh stuck_corner_tetrahedra(const BoxPass& pass, const WarpTable& warps, std::span<const GridPoint> stuck);

}  // namespace pqmesh::tet3d
