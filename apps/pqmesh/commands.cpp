#include "commands.hpp"

namespace pqmesh::cli {

const std::vector<Command>& commands() {
  static const std::vector<Command> list = {
      {"info", "validate an input domain; print counts, shells, volume/area and alpha",
       "usage: pqmesh info INPUT [--merge-angle DEG] [--no-merge]\n"
       "\n"
       "Reads a 2D domain (Triangle .poly) or a 3D domain (TetGen .poly/.smesh, OFF, STL ASCII or\n"
       "binary, OBJ, Medit .mesh surface), validates it (thesis 1.4: closed, manifold, planar facets,\n"
       "no self-intersection, connected) and prints its summary and alpha, the smallest interior angle\n"
       "between faces (thesis ch. 3), with the faces that realise it.\n"
       "\n"
       "Triangle soups (STL, OFF, OBJ, Medit) are merged: adjacent exactly coplanar triangles become one\n"
       "polygonal facet, so that only real features count as edges.\n"
       "  --merge-angle DEG  also merge neighbours whose planes differ by at most DEG degrees\n"
       "                     (made planar by projection; the count is reported)\n"
       "  --no-merge         keep every input polygon as its own facet\n"
       "\n"
       "Exit 0 when the domain is valid, 2 with the offending ids and file line when it is not.\n",
       run_info},
      {"mesh", "mesh a 2D or 3D domain; check and write the mesh",
       "usage: pqmesh mesh INPUT -o OUTPUT [--max-size S] [--size-field FILE] [--refine-angle DEG]\n"
       "                   [--protect-edges] [--aligned-grid] [--no-boundary-steiner [--pipeline]]\n"
       "                   [--format F] [--quiet]\n"
       "\n"
       "2D: meshes a polygon with holes (Triangle .poly) with the quadtree mesher, the 2D analog of\n"
       "thesis ch. 4 (docs/ALGORITHM.md section 8): every angle is at least min(C * alpha, THETA0),\n"
       "alpha the smallest input angle, and the triangle count is within a constant factor of the\n"
       "fewest a mesh with bounded angles needs.\n"
       "3D (TetGen .poly/.smesh, OFF, STL, OBJ, Medit surface): tetrahedra from the octree of thesis\n"
       "ch. 4 (docs/ALGORITHM.md sections 10, 12, 13), boundary triangles carry the input facet\n"
       "markers, tetrahedra the region attribute. Work in progress (issue 5): every box kind is\n"
       "meshed and checked, but the first warping pass is missing, so the aspect ratio is not yet\n"
       "bounded by C / alpha; a configuration the box code does not cover yet (see the README's\n"
       "status table) stops the run with exit 2, naming the leaf, 'not supported yet (issue 5)'.\n"
       "\n"
       "The mesh is checked as by 'pqmesh check' before it is written; a mesh that fails is a bug\n"
       "(exit 70) and nothing is written. The summary gives alpha, the quality achieved (2D: angles\n"
       "and the bound; 3D: max aspect ratio, min/max dihedral angles), the counts, the size estimate\n"
       "I = integral over P of 1/lfs^2 (3D: I3 = integral of 1/lfs^3, pqmesh/lfs3.hpp) with elements\n"
       "/ I, the mesher's counters (2D: leaves, splits by cause, vertex boxes; 3D: leaves and boxes\n"
       "per kind), timings per stage and the check result. 3D runs show progress (phase, boxes,\n"
       "tetrahedra, elapsed) on stderr when it is a terminal.\n"
       "  -o, --output OUTPUT  the mesh file; its extension gives the format as for 'pqmesh convert'\n"
       "                       (.vtu, .msh, .mesh, .node writes .node/.ele/.poly, .svg (2D only))\n"
       "  --format F           vtu, msh, msh22, mesh, node or svg (2D), whatever OUTPUT's extension\n"
       "  --max-size S         no tree box side longer than S (S > 0)\n"
       "  --size-field FILE    desired sizes at points, one 'x y size' (2D) or 'x y z size' (3D) per\n"
       "                       line ('#' comments); the size asked for at x is the min over the\n"
       "                       points of size + |x - point|\n"
       "  --refine-angle DEG   2D: Delaunay refinement of the quadtree triangulation towards DEG\n"
       "                       (default 20; 0 turns it off; at most 30); triangles at input angles\n"
       "                       below 60 degrees are excused\n"
       "  --protect-edges      2D: thesis 4.1.4-4.1.5 edge protection: split every box on an input\n"
       "                       edge once more (off by default: more triangles, no better angles)\n"
       "  --aligned-grid       3D: octree planes on the dyadic grid of the bounding box instead of the\n"
       "                       generic grid shifted off every input coordinate (the default)\n"
       "  --no-boundary-steiner  2D: triangulate adding points only strictly inside the polygon\n"
       "                       (thesis ch. 5, ALGORITHM.md section 11): every input vertex and segment\n"
       "                       is kept exactly, also a subdivided boundary with straight angles (local\n"
       "                       remeshing; --fixed-boundary is a synonym). Summary: g(P), the bound\n"
       "                       min(60, C*g) on any such triangulation (C = pi(1+ln 2)), achieved min\n"
       "                       angle and achieved/g, the pipeline's path (full, or the q-only / cdt\n"
       "                       fallback with its reason), the CDT's min angle. When the CDT of the input\n"
       "                       has the larger min angle it is written instead (path cdt-better;\n"
       "                       --pipeline keeps the pipeline's mesh). With it: -o, --format,\n"
       "                       --refine-angle (the mesh of R), --quiet.\n"
       "  --quiet              print nothing on success\n"
       "\n"
       "Exit 2 for an invalid domain or size field (the message names the file line) and for a 3D\n"
       "leaf kind not supported yet, 64 for a bad command line, 70 for an internal error.\n",
       run_mesh},
      {"octree", "build the octree of thesis 4.1 for a 3D domain; write its leaves as .vtu",
       "usage: pqmesh octree INPUT -o BOXES.vtu [--max-size H] [--size-field FILE] [--generic-grid]\n"
       "                     [--merge-angle DEG] [--no-merge] [--quiet]\n"
       "\n"
       "Builds the Mitchell-Vavasis octree of a 3D domain (thesis 4.1: size phase, vertex phase,\n"
       "vertex centering, edge phase, edge separating splits, edge-box protection, facet phase,\n"
       "facet separating splits, facet-box protection; duplicates per component of P in a box;\n"
       "balance between balance-adjacent boxes) and writes its leaves as VTK hexahedra (ASCII\n"
       ".vtu) with cell data: level, component (-1 outside P), duplicate, protected, phase that\n"
       "created the box (0 root, 1 vertex, 2 centering, 3 edge, 4 facet, 5 balance, 6 size,\n"
       "7 edge-separate, 8 facet-separate), vertex_owner (the input vertex whose united box\n"
       "holds the leaf, -1 if none), cone_kind (0 outside, 1 empty inside P, 2 vertex cone, 3 edge\n"
       "cone, 4 facet cone, 5 two facets of an edge outside the box, 6 other) and protected_by\n"
       "(the phase number of the step that protected the leaf, 0 if unprotected). Prints the leaf\n"
       "count, leaves per kind, splits, leaves and time per phase, duplicates. The file is\n"
       "written atomically.\n"
       "  -o, --output FILE  the .vtu file\n"
       "  --max-size H       split boxes larger than H (thesis 1.1 user size function)\n"
       "  --size-field FILE  lines 'x y z size': boxes larger than min_i size_i + |x - p_i| are\n"
       "                     split (docs/FORMATS.md, 3D size fields)\n"
       "  --generic-grid     shift every box plane off the input's coordinates (the grid 'pqmesh mesh'\n"
       "                     uses on 3D input; ALGORITHM.md §10)\n"
       "  --merge-angle DEG, --no-merge  as for 'pqmesh info'\n"
       "  --quiet            print nothing on success\n"
       "\n"
       "Exit 2 for a 2D or invalid domain, 64 for a bad command line, 70 for an internal error.\n",
       run_octree},
      {"check", "check a mesh against its input domain (validity report)",
       "usage: pqmesh check MESH --domain INPUT [--no-boundary-steiner] [--max-issues N]\n"
       "\n"
       "Runs the validity checker (docs/ALGORITHM.md, 'Validity checker'): element orientation,\n"
       "face-to-face conformity, boundary faces, total volume/area equal to the domain's, every input\n"
       "vertex present, every input edge and facet recovered as a union of mesh edges and boundary\n"
       "triangles, no mesh vertex outside the domain. MESH may be .vtu, .msh (4.1 or 2.2), .mesh or\n"
       ".node/.ele; its dimension is that of INPUT.\n"
       "  --domain INPUT          the input domain the mesh claims to mesh (required)\n"
       "  --no-boundary-steiner   also require that no mesh vertex lies on the input boundary other\n"
       "                          than the input vertices (thesis ch. 5)\n"
       "  --max-issues N          list at most N violations of each kind (default 20)\n"
       "  --merge-angle DEG, --no-merge   as for 'pqmesh info', applied to INPUT\n"
       "\n"
       "Exit 0 only when the mesh is valid; 1 when it is not.\n",
       run_check},
      {"quality", "element quality report and histograms of a mesh",
       "usage: pqmesh quality MESH [--dim 2|3] [--svg FILE]\n"
       "\n"
       "Prints per-mesh summaries of the measures of thesis ch. 3: aspect ratio (smallest enclosing\n"
       "sphere radius / inscribed radius; regular tetrahedron 3, equilateral triangle 2), sphere ratio\n"
       "(circumradius / inradius), radius-edge ratio, min/max dihedral angle (3D) or min/max angle\n"
       "(2D), with the worst element's id, and histograms. Also checks the mesh's own topology\n"
       "(orientation, conformity); use 'pqmesh check' to check it against a domain.\n"
       "  --dim 2|3     force the mesh dimension (default: 3 if the file has tetrahedra, else 2)\n"
       "  --svg FILE    write the histogram of the angle measure as an SVG bar chart\n",
       run_quality},
      {"convert", "convert a mesh between formats",
       "usage: pqmesh convert IN OUT [--dim 2|3] [--msh22] [--ascii]\n"
       "\n"
       "Reads a mesh and writes it in the format given by OUT's extension: .vtu (VTK XML, cell data\n"
       "'marker' and quality), .msh (Gmsh 4.1; --msh22 for 2.2), .mesh (Medit), .node (writes\n"
       ".node/.ele/.face in 3D, .node/.ele/.poly in 2D), .svg (2D picture coloured by min angle).\n"
       "  --dim 2|3   force the mesh dimension (default: 3 if IN has tetrahedra, else 2)\n"
       "  --msh22     write Gmsh 2.2 instead of 4.1\n"
       "  --ascii     text instead of binary where the format has both (.vtu)\n",
       run_convert},
  };
  return list;
}

}  // namespace pqmesh::cli
