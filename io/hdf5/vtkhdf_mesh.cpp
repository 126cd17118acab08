// The mesh of a Model as VTKHDF 1.0 UnstructuredGrid + /XDMF/MixedTopology
// (docs/theory/results-format.md section 2).
#include "io/hdf5/vtkhdf_mesh.hpp"

#include <array>
#include <limits>
#include <string>
#include <vector>

#include "io/hdf5/hdf5_util.hpp"

namespace radx::io {

namespace {

using model::Model;

// XDMF "Mixed" topology type codes.
constexpr std::int64_t kXdmfPolyline = 2, kXdmfTriangle = 4, kXdmfQuad = 5, kXdmfTetrahedron = 6,
                       kXdmfHexahedron = 9, kXdmfHexahedron20 = 48;

// VTK_QUADRATIC_HEXAHEDRON (and XDMF Hexahedron_20) take the corners, then the mid-side nodes of the bottom
// face's edges, of the top face's, and of the four vertical edges; Radioss's /BRIC20 has the vertical
// edges before the top face's. Position v of the cell is the element's node kHex20ToVtk[v].
constexpr std::array<std::size_t, 20> kHex20ToVtk = {0,  1,  2,  3,  4,  5,  6,  7,  8,  9,
                                                     10, 11, 16, 17, 18, 19, 12, 13, 14, 15};

const char* block_name(model::ElementType t) {
  switch (t) {
    case model::ElementType::Shell4: return "shell";
    case model::ElementType::Shell3: return "3-node shell";
    case model::ElementType::Brick8: return "brick";
    case model::ElementType::Tetra4: return "tetrahedron";
    case model::ElementType::Spring2: return "spring";
    case model::ElementType::Truss2: return "truss";
    case model::ElementType::Beam2: return "beam";
    case model::ElementType::Brick20: return "20-node brick";
  }
  return "element";
}

// The element blocks in cell order.
template <class Fn>
void for_each_block(const Model& m, Fn&& fn) {
  fn(m.shells);
  fn(m.shells3);
  fn(m.bricks);
  fn(m.tetras);
  fn(m.bricks20);
}

// The line elements, whose cells follow the mesh's: springs (n1 n2 of their three slots), then trusses.
template <class Fn>
void for_each_line_block(const Model& m, Fn&& fn) {
  fn(m.springs, std::size_t{3});
  fn(m.trusses, std::size_t{2});
  fn(m.beams, std::size_t{3});
}

}  // namespace

void check_vtkhdf_mesh(const Model& m) {
  const std::size_t nn = m.nodes.size();
  if (m.nodes.x.size() != nn || m.nodes.y.size() != nn || m.nodes.z.size() != nn) {
    throw h5::Failure("invalid model: the node coordinate arrays do not have one value per node id");
  }
  if (nn > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) {
    throw h5::Failure("invalid model: too many nodes for 32-bit node indices");
  }
  for_each_block(m, [&](const model::ElementBlock& b) {
    const std::size_t n = b.size();
    if (b.part.size() != n || b.conn.size() != n * static_cast<std::size_t>(b.npe())) {
      throw h5::Failure(std::string("invalid model: the ") + block_name(b.type) +
                        " block part or connectivity array does not match its id count");
    }
    for (std::size_t e = 0; e < n; ++e) {
      if (b.part[e] < 0 || static_cast<std::size_t>(b.part[e]) >= m.parts.size()) {
        throw h5::Failure(std::string("invalid model: ") + block_name(b.type) + " " +
                          std::to_string(b.id[e]) + " has part index " + std::to_string(b.part[e]) +
                          " out of range");
      }
      for (int k = 0; k < b.npe(); ++k) {
        const std::int32_t node = b.conn[e * static_cast<std::size_t>(b.npe()) + static_cast<std::size_t>(k)];
        if (node < 0 || static_cast<std::size_t>(node) >= nn) {
          throw h5::Failure(std::string("invalid model: ") + block_name(b.type) + " " +
                            std::to_string(b.id[e]) + " has node index " + std::to_string(node) +
                            " out of range");
        }
      }
    }
  });
  // Springs and trusses: n1 and n2 must exist; a spring's orientation node n3 is optional.
  for_each_line_block(m, [&](const model::ElementBlock& b, std::size_t stride) {
    const std::string name = block_name(b.type);
    if (b.part.size() != b.size() || b.conn.size() != stride * b.size())
      throw h5::Failure("invalid model: the " + name +
                        " block part or connectivity array does not match its id count");
    for (std::size_t e = 0; e < b.size(); ++e) {
      if (b.part[e] < 0 || static_cast<std::size_t>(b.part[e]) >= m.parts.size())
        throw h5::Failure("invalid model: " + name + " " + std::to_string(b.id[e]) + " has part index " +
                          std::to_string(b.part[e]) + " out of range");
      for (std::size_t k = 0; k < 2; ++k) {
        const std::int32_t node = b.conn[stride * e + k];
        if (node < 0 || static_cast<std::size_t>(node) >= nn)
          throw h5::Failure("invalid model: " + name + " " + std::to_string(b.id[e]) + " has node index " +
                            std::to_string(node) + " out of range");
      }
    }
  });
}

VtkhdfMeshSizes write_vtkhdf_mesh(hid_t file, const Model& m) {
  const std::size_t nn = m.nodes.size();
  const std::size_t nc = m.cell_count();
  const std::size_t max_conn = 4 * m.shells.size() + 3 * m.shells3.size() + 8 * m.bricks.size() +
                               4 * m.tetras.size() + 20 * m.bricks20.size() + 2 * m.springs.size() +
                               2 * m.trusses.size() + 2 * m.beams.size();

  std::vector<std::int64_t> connectivity, offsets, element_id, mixed;
  std::vector<std::uint8_t> types;
  std::vector<std::int64_t> part_id;  // user ids are 64-bit everywhere, as node_id and element_id
  connectivity.reserve(max_conn);
  mixed.reserve(max_conn + nc);
  offsets.reserve(nc + 1);
  types.reserve(nc);
  part_id.reserve(nc);
  element_id.reserve(nc);
  offsets.push_back(0);
  for_each_block(m, [&](const model::ElementBlock& b) {
    const auto npe = static_cast<std::size_t>(b.npe());
    for (std::size_t e = 0; e < b.size(); ++e) {
      const std::int32_t* nodes = b.conn.data() + e * npe;
      std::size_t used = npe;
      std::uint8_t vtk = kVtkHexahedron;
      std::int64_t xdmf = kXdmfHexahedron;
      const bool quadratic = b.type == model::ElementType::Brick20;
      if (quadratic) {
        vtk = kVtkQuadraticHexahedron;
        xdmf = kXdmfHexahedron20;
      } else if (b.type == model::ElementType::Tetra4) {
        vtk = kVtkTetra;
        xdmf = kXdmfTetrahedron;
      } else if (b.type == model::ElementType::Shell4 && nodes[2] != nodes[3]) {
        vtk = kVtkQuad;
        xdmf = kXdmfQuad;
      } else if (b.type != model::ElementType::Brick8) {  // 3-node shell, or a quad with n3 == n4
        used = 3;
        vtk = kVtkTriangle;
        xdmf = kXdmfTriangle;
      }
      mixed.push_back(xdmf);
      for (std::size_t k = 0; k < used; ++k) {
        const std::int32_t node = nodes[quadratic ? kHex20ToVtk[k] : k];
        connectivity.push_back(node);
        mixed.push_back(node);
      }
      offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
      types.push_back(vtk);
      part_id.push_back(m.parts[static_cast<std::size_t>(b.part[e])].id);
      element_id.push_back(b.id[e]);
    }
  });
  // Springs and trusses after the mesh cells, as VTK lines; XDMF's polyline names its node count.
  for_each_line_block(m, [&](const model::ElementBlock& b, std::size_t stride) {
    for (std::size_t e = 0; e < b.size(); ++e) {
      const std::int32_t* nodes = b.conn.data() + stride * e;
      mixed.push_back(kXdmfPolyline);
      mixed.push_back(2);
      for (std::size_t k = 0; k < 2; ++k) {
        connectivity.push_back(nodes[k]);
        mixed.push_back(nodes[k]);
      }
      offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
      types.push_back(kVtkLine);
      part_id.push_back(m.parts[static_cast<std::size_t>(b.part[e])].id);
      element_id.push_back(b.id[e]);
    }
  });
  std::vector<double> points(3 * nn);
  for (std::size_t i = 0; i < nn; ++i) {
    points[3 * i] = m.nodes.x[i];
    points[3 * i + 1] = m.nodes.y[i];
    points[3 * i + 2] = m.nodes.z[i];
  }

  const h5::Handle vtk = h5::create_group(file, "VTKHDF");
  const std::array<std::int64_t, 2> version{1, 0};
  h5::write_attr(vtk, "Version", version.data(), version.size());
  h5::write_fixed_string_attr(vtk, "Type", "UnstructuredGrid");  // exactly 16 bytes, no NUL
  const VtkhdfMeshSizes sizes{static_cast<std::int64_t>(nn), static_cast<std::int64_t>(nc),
                              static_cast<std::int64_t>(connectivity.size()),
                              static_cast<std::int64_t>(mixed.size())};
  h5::write_dataset(vtk, "NumberOfPoints", std::vector<std::int64_t>{sizes.points});
  h5::write_dataset(vtk, "NumberOfCells", std::vector<std::int64_t>{sizes.cells});
  h5::write_dataset(vtk, "NumberOfConnectivityIds", std::vector<std::int64_t>{sizes.connectivity_ids});
  h5::write_dataset(vtk, "Points", points, 3);
  h5::write_dataset(vtk, "Connectivity", connectivity);
  h5::write_dataset(vtk, "Offsets", offsets);
  h5::write_dataset(vtk, "Types", types);
  const h5::Handle point_data = h5::create_group(vtk, "PointData");
  h5::write_dataset(point_data, "node_id", m.nodes.id);
  const h5::Handle cell_data = h5::create_group(vtk, "CellData");
  h5::write_dataset(cell_data, "part_id", part_id);
  h5::write_dataset(cell_data, "element_id", element_id);
  const h5::Handle xdmf = h5::create_group(file, "XDMF");
  h5::write_dataset(xdmf, "MixedTopology", mixed);
  return sizes;
}

}  // namespace radx::io
