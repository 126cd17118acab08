// The decomposition file: the shared VTKHDF mesh plus the domain arrays (domain_file.hpp).
#include "io/hdf5/domain_file.hpp"

#include <filesystem>
#include <stdexcept>

#include "io/hdf5/hdf5_util.hpp"
#include "io/hdf5/vtkhdf_mesh.hpp"

namespace radx::io {

void write_domain_file(const std::string& path, const model::Model& model,
                       std::span<const std::int32_t> cell_domain, std::span<const std::int32_t> cell_group,
                       std::span<const std::int32_t> node_owner) {
  if (cell_domain.size() != model.cell_count() || cell_group.size() != model.cell_count() ||
      node_owner.size() != model.nodes.size())
    throw std::invalid_argument("write_domain_file: one domain and group per cell, one owner per node");
  check_vtkhdf_mesh(model);
  const std::string part = path + ".part";
  try {
    h5::WriteFile file = h5::create_file(part);
    write_vtkhdf_mesh(file, model);
    {  // every object closed before the file (its close degree refuses open objects)
      const h5::Handle vtk = h5::open_group(file, "VTKHDF");
      const h5::Handle cells = h5::open_group(vtk, "CellData");
      h5::write_dataset(cells, "domain", cell_domain);
      h5::write_dataset(cells, "group", cell_group);
      const h5::Handle points = h5::open_group(vtk, "PointData");
      h5::write_dataset(points, "node_owner", node_owner);
    }
    file.close();
    h5::sync_file(part);
    h5::replace_file(part, path);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(part, ignored);
    throw;
  }
}

}  // namespace radx::io
