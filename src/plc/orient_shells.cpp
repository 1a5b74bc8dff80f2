// Stage 9 of 3D validation: consistent orientation, shells (the components of
// dP) and floaters (thesis §4.1.6).
//
// Method.
//  1. Breadth-first search over facets through shared edges fixes, per shell,
//     a relative flip so that the two facets at every edge traverse it in
//     opposite directions (a conflict means a non-orientable shell).
//  2. Outwardness: the sign of the shell's signed volume, sum over its
//     triangles of det(a, b, c) (six times the volume of the cone from the
//     origin). For a closed, consistently oriented, embedded surface it is
//     nonzero and positive exactly when the normals point away from the
//     enclosed volume. The sign is decided exactly: the double sum is accepted
//     when it clears a rounding-error bound, otherwise the sum is recomputed in
//     exact rational arithmetic (GMP), so no decision depends on rounding.
//  3. Nesting: shell A lies inside shell B iff a vertex of A is inside B, by
//     the perturbed ray parity of point_location.hpp counted per shell (shells
//     are disjoint after stages 7-8, so the vertex is on no other shell).
//  4. One shell must contain all others (the exterior shell); every other
//     shell (a floater bounding a cavity) must lie inside the exterior shell
//     and inside no other floater, else P is disconnected.
//  5. The exterior shell gets positive signed volume (normals out of P), each
//     floater negative (normals out of P, into its cavity).
#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "plc/report_error.hpp"
#include "plc/validate3.hpp"

namespace pqmesh::detail {

namespace {

double det3(Vec3 a, Vec3 b, Vec3 c) { return dot(a, cross(b, c)); }

double permanent3(Vec3 a, Vec3 b, Vec3 c) {
  return std::abs(a.x) * (std::abs(b.y * c.z) + std::abs(b.z * c.y)) +
         std::abs(a.y) * (std::abs(b.z * c.x) + std::abs(b.x * c.z)) +
         std::abs(a.z) * (std::abs(b.x * c.y) + std::abs(b.y * c.x));
}

mpq_class det3_exact(Vec3 a, Vec3 b, Vec3 c) {
  const mpq_class ax(a.x), ay(a.y), az(a.z), bx(b.x), by(b.y), bz(b.z), cx(c.x), cy(c.y), cz(c.z);
  return ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx);
}

// Exact sign of sum over triangles of (+/-) det(a, b, c); `negate[k]` flips the k-th term.
Sign signed_volume_sign(const std::vector<Vec3>& V, const std::vector<std::array<int, 3>>& tris,
                        const std::vector<int>& which, const std::vector<char>& negate) {
  double sum = 0, perm = 0;
  for (std::size_t k = 0; k < which.size(); ++k) {
    const auto& t = tris[which[k]];
    const double d = det3(V[t[0]], V[t[1]], V[t[2]]);
    sum += negate[k] ? -d : d;
    perm += permanent3(V[t[0]], V[t[1]], V[t[2]]);
  }
  // Each term carries a relative error below 8 eps of its permanent and the
  // recursive summation of n terms adds at most n eps times the sum of
  // magnitudes (<= sum of permanents); the constants are doubled for safety.
  const double eps = std::numeric_limits<double>::epsilon();
  const double bound = (16.0 + 4.0 * static_cast<double>(which.size())) * eps * perm;
  if (perm > 1e-250 && std::isfinite(bound)) {
    if (sum > bound) return Sign::Positive;
    if (-sum > bound) return Sign::Negative;
  }
  mpq_class exact = 0;
  for (std::size_t k = 0; k < which.size(); ++k) {
    const auto& t = tris[which[k]];
    const mpq_class d = det3_exact(V[t[0]], V[t[1]], V[t[2]]);
    if (negate[k])
      exact -= d;
    else
      exact += d;
  }
  return static_cast<Sign>(sgn(exact));
}

}  // namespace

ShellOrientation orient_shells(const Plc3& plc, const EdgeTopology& topo, const FacetTriangles& ft,
                               const SurfaceLocator& surface) {
  const SourceInfo& src = plc.source;
  const int nf = static_cast<int>(plc.facets.size());
  // Facet adjacency (CSR) with, per neighbour, whether the two facets traverse
  // the shared edge in the same direction (then exactly one must be flipped).
  std::vector<int> start(nf + 1, 0);
  for (const auto& e : topo.edges) {
    ++start[e.facets[0] + 1];
    ++start[e.facets[1] + 1];
  }
  for (int f = 0; f < nf; ++f) start[f + 1] += start[f];
  std::vector<int> nbr(start[nf]), fill(start.begin(), start.end() - 1);
  std::vector<char> same(start[nf]);
  std::vector<int> via(start[nf]);
  for (int e = 0; e < int(topo.edges.size()); ++e) {
    const auto& E = topo.edges[e];
    const bool s = topo.forward[e][0] == topo.forward[e][1];
    for (int side = 0; side < 2; ++side) {
      const int f = E.facets[side], k = fill[f]++;
      nbr[k] = E.facets[1 - side];
      same[k] = s;
      via[k] = e;
    }
  }
  ShellOrientation out;
  out.flip.assign(nf, 0);
  std::vector<int> shell_of(nf, -1);
  std::vector<std::vector<int>> shells;
  for (int root = 0; root < nf; ++root) {
    if (shell_of[root] >= 0) continue;
    const int id = static_cast<int>(shells.size());
    shells.push_back({root});
    shell_of[root] = id;
    for (std::size_t q = 0; q < shells[id].size(); ++q) {
      const int f = shells[id][q];
      for (int k = start[f]; k < start[f + 1]; ++k) {
        const int g = nbr[k];
        const char want = static_cast<char>(out.flip[f] ^ same[k]);
        if (shell_of[g] < 0) {
          shell_of[g] = id;
          out.flip[g] = want;
          shells[id].push_back(g);
        } else if (out.flip[g] != want) {
          const auto& E = topo.edges[via[k]];
          std::ostringstream msg;
          msg << "the shell containing facet " << file_id(src, root)
              << " is not orientable: no consistent orientation of facets " << file_id(src, f) << " and "
              << file_id(src, g) << " across edge (" << file_id(src, E.a) << ", " << file_id(src, E.b) << ")";
          throw_domain_error(src, ErrorCode::NonManifoldEdge, msg.str(), {f, g}, IdKind::Element);
        }
      }
    }
  }
  const int ns = static_cast<int>(shells.size());
  for (auto& s : shells) std::sort(s.begin(), s.end());

  // Outwardness of each shell as currently flipped.
  std::vector<std::vector<int>> tris_of(ns);
  for (int t = 0; t < int(ft.triangles.size()); ++t) tris_of[shell_of[ft.owner[t]]].push_back(t);
  std::vector<Sign> volume_sign(ns);
  for (int s = 0; s < ns; ++s) {
    std::vector<char> negate;
    for (int t : tris_of[s]) negate.push_back(out.flip[ft.owner[t]]);
    volume_sign[s] = signed_volume_sign(plc.vertices, ft.triangles, tris_of[s], negate);
    if (volume_sign[s] == Sign::Zero)
      throw InternalError("closed embedded shell with zero signed volume");  // impossible after stages 1-8
  }

  // Nesting: inside[a][b] = shell a lies inside shell b.
  std::vector<std::vector<char>> inside(ns, std::vector<char>(ns, 0));
  if (ns > 1) {
    for (int a = 0; a < ns; ++a) {
      const Vec3 q = plc.vertices[plc.facets[shells[a][0]].loops[0][0]];
      std::vector<char> parity(ns, 0);
      surface.for_each_crossed(
          q, [&](int t) { return shell_of[ft.owner[t]] == a; }, [&](int t) { parity[shell_of[ft.owner[t]]] ^= 1; });
      for (int b = 0; b < ns; ++b) inside[a][b] = parity[b];
    }
  }
  int exterior = -1;
  for (int e = 0; e < ns && exterior < 0; ++e) {
    bool all = true;
    for (int a = 0; a < ns; ++a) all = all && (a == e || inside[a][e]);
    if (all) exterior = e;
  }
  auto first = [&](int s) { return file_id(src, shells[s][0]); };
  if (exterior < 0) {
    // Name two shells of which neither contains the other.
    for (int a = 0; a < ns; ++a)
      for (int b = a + 1; b < ns; ++b)
        if (!inside[a][b] && !inside[b][a]) {
          std::ostringstream msg;
          msg << "the domain is disconnected: the shells containing facets " << first(a) << " and " << first(b)
              << " bound disjoint solids";
          throw_domain_error(src, ErrorCode::Disconnected, msg.str(), {shells[a][0], shells[b][0]}, IdKind::Element);
        }
    throw InternalError("no exterior shell but all shells nested");
  }
  for (int a = 0; a < ns; ++a)
    for (int b = 0; b < ns; ++b)
      if (a != exterior && b != exterior && a != b && inside[a][b]) {
        std::ostringstream msg;
        msg << "the domain is disconnected: the shell containing facet " << first(a)
            << " lies inside the cavity bounded by the shell containing facet " << first(b);
        throw_domain_error(src, ErrorCode::Disconnected, msg.str(), {shells[a][0], shells[b][0]}, IdKind::Element);
      }

  for (int s = 0; s < ns; ++s) {
    const Sign want = s == exterior ? Sign::Positive : Sign::Negative;
    if (volume_sign[s] != want)
      for (int f : shells[s]) out.flip[f] ^= 1;
  }
  out.shells.push_back(Shell{shells[exterior], true});
  for (int s = 0; s < ns; ++s)
    if (s != exterior) out.shells.push_back(Shell{shells[s], false});
  return out;
}

}  // namespace pqmesh::detail
