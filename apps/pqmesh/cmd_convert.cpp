// pqmesh convert: read a mesh in one format, write it in another.
#include <iostream>

#include "commands.hpp"
#include "format_option.hpp"
#include "load.hpp"
#include "pqmesh/mesh_io.hpp"
#include "quality_fields.hpp"

namespace pqmesh::cli {

int run_convert(const std::vector<std::string>& argv) {
  const Args args(argv, {"--msh22", "--ascii", "--compress"}, {"--dim", "--format"});
  args.expect_positional(2, 2);
  const AnyMesh mesh = load_mesh(args.positional()[0], dimension_option(args));
  const std::string& out = args.positional()[1];
  WriteOptions options;
  const std::optional<MeshFormat> forced = format_option(args, /*allow_svg=*/true);
  options.format = forced ? *forced : mesh_format_from_path(out, args.flag("--msh22"));
  options.binary = !args.flag("--ascii");
  options.compress = compress_option(args, *options.format, options.binary);
  if (*options.format == MeshFormat::Vtu) options.cell_fields = std::visit([](const auto& m) { return quality_cell_fields(m); }, mesh);
  std::visit([&](const auto& m) { write_mesh(m, out, options); }, mesh);
  std::cout << "wrote " << out << " (" << to_string(*options.format) << ")\n";
  return kExitOk;
}

}  // namespace pqmesh::cli
