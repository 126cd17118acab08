// The model file NAME_0000.hdf: the starter writes the validated Model once, the engine reads it back.
// One HDF5 file holding a VTKHDF 1.0 UnstructuredGrid of the undeformed mesh (docs/theory/results-format.md
// section 2, so ParaView opens it), /XDMF/MixedTopology, and under /radx everything of the Model in plain
// datasets and attributes. The layout is documented in docs/model-file.md. All values in work units.
#pragma once

#include <cstdint>
#include <string>

#include "solver/model/model.hpp"

namespace radx::io {

// Version of the layout under /radx, stored as the root attribute radx_model_format_version. A reader
// accepts exactly its own version: any change of the layout increments it (docs/model-file.md).
inline constexpr std::int64_t kModelFormatVersion = 21;

// Writes `m` to `path` crash-safely: the file is written as `path + ".part"`, closed, then renamed over
// `path` (atomic on POSIX), so `path` is either the previous file or the complete new one. On failure
// the .part file is removed, `path` is left untouched and `error` names the file and HDF5 object.
// Fails also when the mesh is inconsistent (connectivity or part index out of range, array lengths that
// differ from the id count), so no invalid VTKHDF is ever written.
bool write_model_file(const radx::model::Model& m, const std::string& path, std::string& error);

// Reads a model file written by write_model_file into `m` (replaced entirely) and rebuilds the IdMaps of
// the nodes and element blocks. On failure returns false, `error` names the file and HDF5 object, and
// `m` is left in an unspecified (but destructible) state.
bool read_model_file(const std::string& path, radx::model::Model& m, std::string& error);

}  // namespace radx::io
