"""pqmesh: quality meshes of polygons and polyhedra (S. A. Mitchell, 1993).

    mesh = pqmesh.tetrahedralize(points, facets, facet_markers=markers, max_size=0.5)
    report = pqmesh.check(mesh, mesh.domain)      # report.valid, report.messages
    print(mesh.alpha, mesh.max_aspect_ratio, pqmesh.quality(mesh).min_angle.min)

Inputs are numpy arrays or nested sequences; results hold read-only numpy views
(points float64, elements int32). Bad input raises pqmesh.InputError (a
ValueError) carrying the library's code, ids, path and line; bad option values
raise ValueError, like the CLI's usage errors. Meshing and checking release the
GIL. The functions call the library entry points `pqmesh mesh`, `pqmesh check`
and `pqmesh quality` call (quad_mesh, triangulate_without_boundary_steiner,
tet_mesh, check_mesh, quality_report).
"""

import math

from .errors import (DomainError, Error, InputError, InternalError, MeshNotSupported, OutputError,
                     ParseError)
from ._pqmesh import (CheckIssue, CheckReport, Domain2, Domain3, QualityReport, TetMesh, TriMesh,
                      check_topology, quality, read_domain)
from . import _pqmesh
from ._meshio import tet_to_meshio as _tet_to_meshio, tri_to_meshio as _tri_to_meshio

__all__ = [
    "tetrahedralize", "triangulate", "read_domain", "check", "check_topology", "quality",
    "Domain2", "Domain3", "TriMesh", "TetMesh", "CheckReport", "CheckIssue", "QualityReport",
    "Error", "InputError", "ParseError", "DomainError", "MeshNotSupported", "OutputError",
    "InternalError",
]

TriMesh.to_meshio = _tri_to_meshio
TetMesh.to_meshio = _tet_to_meshio


def _positive(name, value):
    """None (no limit) or a positive finite number, as the CLI's --max-size."""
    if value is None:
        return 0.0
    value = float(value)
    if not (value > 0 and math.isfinite(value)):
        raise ValueError(f"{name} must be a positive number, got {value!r}")
    return value


def _refine_angle(value):
    value = float(value)
    if not 0 <= value <= 30:
        raise ValueError(f"refine_angle must be between 0 (off) and 30 degrees, got {value!r}")
    return value


def _domain(cls, domain, points, elements, markers, holes, regions):
    """The domain to mesh: `domain`, a domain passed as `points`, or one built from the arrays."""
    if isinstance(points, cls):
        domain, points = points, None
    if domain is not None:
        if not isinstance(domain, cls):
            raise TypeError(f"domain must be a pqmesh.{cls.__name__}, got {type(domain).__name__}")
        if any(a is not None for a in (points, elements, markers, holes, regions)):
            raise TypeError("give either a domain or the arrays, not both")
        return domain
    if points is None or elements is None:
        raise TypeError("give a domain, or points and the boundary elements")
    return cls(points, elements, markers, holes, regions)


def triangulate(points=None, segments=None, segment_markers=None, holes=None, regions=None, *,
                domain=None, max_size=None, size_field=None, refine_angle=20.0, protect_edges=False,
                quadtree=False, improve=True, min_angle=None, no_boundary_steiner=False, keep_better_cdt=True,
                thesis_fans=False, quality_pass=True):
    """Mesh a polygon with holes (`pqmesh mesh` on a 2D input); returns a TriMesh.

    points (N, 2), segments (S, 2) vertex ids, segment_markers (S,), holes (H, 2)
    points inside holes, regions rows (x, y, attribute[, max area]) -- or
    domain=Domain2 (also accepted in place of points), e.g. from read_domain.

    max_size       no quadtree box side longer than this (CLI --max-size)
    size_field     a file of "x y size" lines, or a pair (points (K, 2), sizes (K,))
    refine_angle   Delaunay refinement target in degrees, 0 (off) to 30 (--refine-angle)
    protect_edges  thesis 4.1.4-4.1.5 edge protection (--protect-edges)
    quadtree       always the quadtree mesher, never the refined CDT of the input (--quadtree)
    improve        coarsening and smoothing after the construction that keep the angle bound
                   (on in the CLI; --no-improve); stats["constructed_triangles"] and
                   stats["constructed_min_angle"] describe the mesh before it
    min_angle      the smallest angle asked for, above 0 and at most 33 degrees: the target of
                   the refinement and of the improvement (--min-angle; replaces refine_angle);
                   with no_boundary_steiner up to 60 degrees: the target of the refined candidate,
                   reported in the attributes target and target_reached
    no_boundary_steiner  thesis ch. 5: add points only strictly inside the polygon; every
                   boundary vertex is an input vertex (--no-boundary-steiner). With it,
                   refine_angle applies to the mesh of R, and keep_better_cdt=False,
                   thesis_fans, quality_pass=False are --pipeline, --thesis-fans,
                   --no-quality-pass; max_size, size_field and protect_edges do not apply.

    The result's attributes: domain, alpha (degrees), min_angle, max_angle,
    max_aspect_ratio, stats and seconds (dicts); quad mesher: angle_bound
    (the measured guarantee, degrees); no_boundary_steiner: g, upper_bound,
    cdt_min_angle (degrees), path, fallback_reason, target, target_reached.
    """
    domain = _domain(Domain2, domain, points, segments, segment_markers, holes, regions)
    refine_angle = _refine_angle(refine_angle)
    if no_boundary_steiner:
        if max_size is not None or size_field is not None or protect_edges:
            raise ValueError("max_size, size_field and protect_edges do not apply with no_boundary_steiner")
        target = 0.0
        if min_angle is not None:
            target = float(min_angle)
            if not 0 < target <= 60:
                raise ValueError(f"min_angle must be above 0 and at most 60 degrees, got {min_angle!r}")
        return _pqmesh.triangulate_without_boundary_steiner(
            domain, refine_angle, bool(keep_better_cdt), bool(thesis_fans), bool(quality_pass), target)
    if min_angle is not None:
        refine_angle = float(min_angle)
        if not 0 < refine_angle <= 33:
            raise ValueError(f"min_angle must be above 0 and at most 33 degrees, got {min_angle!r}")
    return _pqmesh.mesh_polygon(domain, _positive("max_size", max_size), size_field, refine_angle,
                                bool(protect_edges), bool(quadtree), bool(improve))


def tetrahedralize(points=None, facets=None, facet_markers=None, holes=None, regions=None, *,
                   domain=None, max_size=None, size_field=None, aligned_grid=False, warp=True,
                   full_separation=False, improve=True, target_aspect=8.0, min_dihedral=None):
    """Mesh a polyhedral domain (`pqmesh mesh` on a 3D input); returns a TetMesh.

    points (N, 3); facets: a list of polygons, each a list of vertex ids (or a list
    of loops: the outer boundary, then holes), or an (F, K) integer array;
    facet_markers (F,); holes (H, 3) points outside the domain; regions rows
    (x, y, z, attribute[, max volume]) -- or domain=Domain3 (also accepted in
    place of points), e.g. from read_domain.

    max_size      no octree box side longer than this (CLI --max-size)
    size_field    a file of "x y z size" lines, or a pair (points (K, 3), sizes (K,)): the size asked for at x is
                  min over i of sizes[i] + |x - points[i]|
    aligned_grid  octree planes on the bounding box's dyadic grid (--aligned-grid)
    warp          the warping of thesis 4.3 (on in the CLI)
    full_separation  the thesis's octree with the separating splits at once, never the lighter
                  octree first (--full-separation; stats["separated"] says which one made the mesh)
    improve       coarsen the construction's mesh by edge collapses that never raise its worst
                  aspect ratio (on in the CLI; --no-improve)
    target_aspect a collapse may leave the tetrahedra it changes as bad as the worse of their
                  worst before and this aspect ratio (--target-aspect; at least 3)
    min_dihedral  quality target in degrees (--min-dihedral; 0: none): where the tetrahedra are
                  within target_aspect, a collapse never makes one with a smaller minimum dihedral
                  angle than this and the least it replaces; not guaranteed to be reached.
                  None: 20 without max_size and size_field, else none (stats["min_dihedral_target"])

    The result's attributes: domain, alpha (degrees), max_aspect_ratio,
    aspect_bound (the measured bound C / alpha), min_dihedral, max_dihedral
    (degrees), stats and seconds (dicts).
    """
    domain = _domain(Domain3, domain, points, facets, facet_markers, holes, regions)
    return _pqmesh.tet_mesh(domain, _positive("max_size", max_size), size_field,
                            not aligned_grid, bool(warp), bool(full_separation), bool(improve),
                            float(target_aspect), None if min_dihedral is None else float(min_dihedral))


def check(mesh, domain, *, no_boundary_steiner=False, max_issues=20, locate_vertices=True):
    """The validity checker against the input domain (`pqmesh check`); returns a CheckReport
    (.valid, .messages, .issues, .counts, .text). no_boundary_steiner also flags boundary
    vertices that are not input vertices."""
    return _pqmesh.check(mesh, domain, bool(no_boundary_steiner), int(max_issues),
                         bool(locate_vertices))
