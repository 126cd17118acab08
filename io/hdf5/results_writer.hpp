// Animation states for ParaView (docs/theory/results-format.md): one mesh file P.mesh.hdf written once, one
// HDF5 file per state P_%06d.hdf whose topology and time-invariant arrays are external links into the mesh
// file, and two indexes rewritten after every state: P.hdf.series (ParaView's file series, what users open)
// and P.xmf (XDMF 3.0 temporal collection). Every file goes through `name.part` (or `.tmp`) and an
// atomic rename, and no HDF5 file stays open between states, so a process killed at any moment leaves
// a readable result set (the finished states, listed by the index).
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "solver/model/model.hpp"

namespace radx::io {

// One array of every state, after the always-present ones (Points, displacement, velocity,
// element_status, vtkGhostType). Names contain no '/' or '.'. Values are stored as float32 [N, components]
// ([N] when components == 1).
struct ResultArray {
  std::string name;
  int components = 1;
  bool on_points = true;  // PointData [NP, k] or CellData [NC, k]
  std::string unit;       // label of the values' unit in the model's work units ("1": dimensionless)
};

// The data of one state. Spans are read during write_state only.
struct ResultState {
  double time = 0;
  std::span<const double> points;                // [3 NP] current coordinates, x y z per node
  std::span<const float> displacement;           // [3 NP]
  std::span<const float> velocity;               // [3 NP]
  std::span<const std::uint8_t> element_status;  // [NC] 1 active, 0 deleted
  std::vector<std::span<const float>> arrays;    // one per ResultArray of the set, [N * components]
};

// Removes the result set of prefix `prefix` in `dir` (state files, the mesh, both indexes and their stray
// .part/.tmp files); nothing when `dir` does not exist. Throws std::runtime_error naming a file it cannot
// remove.
void remove_result_set(const std::string& dir, const std::string& prefix);

class ResultsWriter {
 public:
  // Starts the result set of prefix `prefix` in `dir` (created if needed): removes what an earlier run
  // left there under that prefix (state files, stray .part/.tmp files, both indexes), then writes
  // P.mesh.hdf from the model (cells in model order: 4-node shells, 3-node shells, bricks, as the model
  // file), with the part ids and titles as field data. Every dataset of the states carries its unit (an
  // attribute `units`, labels from the model's work units), and every state lists them in its field data
  // `units` (docs/results.md). Throws std::runtime_error naming the file and HDF5 object on failure.
  ResultsWriter(const model::Model& model, std::string dir, std::string prefix,
                std::vector<ResultArray> arrays);
  ~ResultsWriter();
  ResultsWriter(const ResultsWriter&) = delete;
  ResultsWriter& operator=(const ResultsWriter&) = delete;

  // Writes the next state P_%06d.hdf and rewrites both indexes. A state whose time is not strictly
  // greater than the previous one's is not written (returns false). Throws std::runtime_error on an
  // I/O failure (the earlier states and indexes stay valid).
  bool write_state(const ResultState& state);

  [[nodiscard]] int states_written() const;
  [[nodiscard]] double seconds_writing() const;  // wall time spent in the constructor and write_state
  [[nodiscard]] std::string series_path() const;
  [[nodiscard]] std::string xmf_path() const;
  [[nodiscard]] std::string mesh_path() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace radx::io
