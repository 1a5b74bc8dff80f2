#pragma once
// Loading what the subcommands work on: a validated input domain (2D or 3D)
// and a mesh file of a given dimension.
#include <optional>
#include <string>
#include <variant>

#include "args.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/mesh.hpp"
#include "pqmesh/read_domain.hpp"

namespace pqmesh::cli {

struct LoadedDomain {
  std::variant<Domain2, Domain3> domain;
  ReadReport report;  // meaningful for 3D triangle soups
  int dimension() const { return std::holds_alternative<Domain2>(domain) ? 2 : 3; }
};

// Options shared by every command that reads a domain: --merge-angle, --no-merge.
ReadOptions read_options_from(const Args& args);

// Reads and validates; throws ParseError / DomainError on bad input.
LoadedDomain load_domain(const std::string& path, const ReadOptions& options);

using AnyMesh = std::variant<TriMesh2, TetMesh3>;

// Reads a mesh; dimension 0 means: 3D if the file holds tetrahedra, else 2D.
AnyMesh load_mesh(const std::string& path, int dimension);

// --dim 2|3 (0 when absent).
int dimension_option(const Args& args);

}  // namespace pqmesh::cli
