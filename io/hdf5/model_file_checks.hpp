// The checks of a model read from a model file, before the engine uses it: every dense index against the
// collection it points into, every count against the arrays it describes, every id map one to one, every
// user-id reference (skew, sensor, frame) against the ids the model has, every enum code against its
// values, and the values the physics needs finite (and masses, thicknesses, areas, densities and moduli
// not negative). The engine trusts a Model (habit 1 of the design: validate once, at the boundary); a model
// file is a boundary too, since anything can have changed it after the starter wrote it.
//
// Each problem names the dataset of the file and the entry (row, and column of a 2-D dataset) that holds
// the bad value, the record it belongs to with its user id, what it holds and what is accepted. The
// datasets are those of docs/model-file.md (a CSR column's entry is its position in the values dataset).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "solver/model/model.hpp"

namespace radx::io {

// What is wrong, by the diagnostic code it is reported with (parser/reading/diagnostics.hpp, 9xx: the
// model file). The numbers are those codes.
enum class ModelFileCode : std::uint16_t {
  BadReference = 901,  // an index out of range, a count that does not match, a repeated id, an unknown code
  BadValue = 902,      // a value the physics cannot take: not finite, a negative or all-zero mass, ...
  OtherFormat = 903,   // written in another model-file format version (another radx)
  Changed = 904,       // the content differs from what the starter wrote (its content hash)
  OtherRun = 905,      // the model of another run (another deck)
};

struct ModelFileProblem {
  ModelFileCode code = ModelFileCode::BadReference;
  std::string where;  // dataset and entry: "/radx/node_groups/nodes[12]", "/radx/elements/shell4/conn[3, 1]"
  std::string message;  // the record (with its user id), the value, what is accepted
};

// The problems found, the first kKept of them kept: a damaged file can hold millions of bad entries, and
// the first ones say what happened.
struct ModelFileProblems {
  static constexpr std::size_t kKept = 100;
  std::vector<ModelFileProblem> items;
  std::size_t count = 0;  // all of them, also those not kept
  void add(ModelFileCode code, std::string where, std::string message);
  [[nodiscard]] bool empty() const { return count == 0; }
};

// Checks `m` as read from a model file (its IdMaps need not be built). O(size of the model), once.
ModelFileProblems check_model_content(const model::Model& m);

}  // namespace radx::io
