// The decomposition for ParaView (radx-engine --decompose P): the model's mesh as the VTKHDF UnstructuredGrid
// of the model file and the results (vtkhdf_mesh.hpp), with three integer arrays:
//   CellData/domain      the rank that computes the cell (-1: a cell in no element group)
//   CellData/group       the cell's flat element group (-1: none)
//   PointData/node_owner the rank that owns the node (-1: a node no element touches)
// One file, written to NAME.part and renamed, so no half-written file is ever left under its name.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "solver/model/model.hpp"

namespace radx::io {

// Writes `path` (replacing it). cell_domain and cell_group have one value per cell of the model
// (model.cell_count(), in the mesh's cell order), node_owner one per node. Throws std::runtime_error naming
// the file on failure, with nothing left at `path` or `path`.part.
void write_domain_file(const std::string& path, const model::Model& model,
                       std::span<const std::int32_t> cell_domain, std::span<const std::int32_t> cell_group,
                       std::span<const std::int32_t> node_owner);

}  // namespace radx::io
