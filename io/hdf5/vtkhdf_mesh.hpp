// The mesh of a Model as a VTKHDF 1.0 UnstructuredGrid (docs/theory/results-format.md section 2): the /VTKHDF
// group and /XDMF/MixedTopology. Written into the model file (by the starter) and into the result mesh file
// P.mesh.hdf (by the engine) by the same code, so both are the same grid, cell for cell.
#pragma once

#include <hdf5.h>

#include <cstdint>

#include "solver/model/model.hpp"

namespace radx::io {

// Cell types of the VTKHDF Types dataset (VTK's numbering).
inline constexpr std::uint8_t kVtkLine = 3;
inline constexpr std::uint8_t kVtkTriangle = 5;
inline constexpr std::uint8_t kVtkQuad = 9;
inline constexpr std::uint8_t kVtkTetra = 10;
inline constexpr std::uint8_t kVtkHexahedron = 12;
inline constexpr std::uint8_t kVtkQuadraticHexahedron = 25;  // /BRIC20, VTK's node order (vtkhdf_mesh.cpp)

// Sizes of the grid written, for the indexes that describe it (XDMF needs the MixedTopology length).
struct VtkhdfMeshSizes {
  std::int64_t points = 0;
  std::int64_t cells = 0;
  std::int64_t connectivity_ids = 0;
  std::int64_t mixed_topology = 0;  // length of /XDMF/MixedTopology
};

// Throws h5::Failure (a std::runtime_error) when the mesh of `m` is inconsistent: node coordinate arrays
// of another length than the node ids, more nodes than 32-bit indices hold, an element block whose part
// or connectivity array does not match its ids, a part or node index out of range. Called before any file
// is created, so no invalid VTKHDF is ever written.
void check_vtkhdf_mesh(const radx::model::Model& m);

// Writes /VTKHDF (Version, Type, counts, undeformed Points, Connectivity, Offsets, Types,
// PointData/node_id, CellData/part_id, CellData/element_id) and /XDMF/MixedTopology into the open file
// `file`. Cells in model order: 4-node shells, 3-node shells, bricks; a 4-node shell whose last two nodes
// are equal is a triangle. `m` must pass check_vtkhdf_mesh. Throws h5::Failure naming the HDF5 object.
VtkhdfMeshSizes write_vtkhdf_mesh(hid_t file, const radx::model::Model& m);

}  // namespace radx::io
