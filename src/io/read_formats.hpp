#pragma once
// One reader per input format (read_<format>.cpp); read_domain.cpp dispatches
// on the file extension. Every reader throws ParseError with file and line.
#include <string>

#include "pqmesh/plc.hpp"
#include "pqmesh/read_domain.hpp"

namespace pqmesh::detail {

Pslg2 read_triangle_poly(const std::string& path);
Plc3 read_tetgen_poly(const std::string& path, ReadReport& report);   // .poly with dimension 3
Plc3 read_tetgen_smesh(const std::string& path, ReadReport& report);  // .smesh
Plc3 read_off(const std::string& path, const ReadOptions& options, ReadReport& report);
Plc3 read_stl(const std::string& path, const ReadOptions& options, ReadReport& report);
Plc3 read_obj(const std::string& path, const ReadOptions& options, ReadReport& report);
Plc3 read_medit_surface(const std::string& path, const ReadOptions& options, ReadReport& report);

// The dimension written in a .poly header (or in its companion .node's).
int poly_dimension(const std::string& path);

}  // namespace pqmesh::detail
