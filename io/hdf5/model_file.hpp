// The model file NAME_0000.hdf: the starter writes the validated Model once, the engine reads it back.
// One HDF5 file holding a VTKHDF 1.0 UnstructuredGrid of the undeformed mesh (docs/theory/results-format.md
// section 2, so ParaView opens it), /XDMF/MixedTopology, and under /radx everything of the Model in plain
// datasets and attributes. The layout is documented in docs/model-file.md. All values in work units.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "io/hdf5/model_file_checks.hpp"
#include "solver/model/model.hpp"

namespace radx::io {

// Version of the layout of the file, stored as the root attribute radx_model_format_version. A reader
// accepts exactly its own version: any change of the layout increments it (docs/model-file.md).
inline constexpr std::int64_t kModelFormatVersion = 22;

// Where a model comes from, stamped into its file by the starter (docs/model-file.md section 3).
struct ModelFileOrigin {
  std::string run;                      // the run the model is for: NAME of NAME_0000.rad (run_files.hpp)
  std::string deck_hash;                // 16 hex digits: the hash of the deck's files, in the order read
  std::vector<std::string> deck_files;  // the deck's files as the starter read them, the main deck first
  std::string radx_commit;              // the git commit of the radx that writes the file
};

// The origin of the model of run `run` built from the deck files `deck_files` (Deck::files: the main deck,
// then each included file in the order read) by the radx of commit `radx_commit`: the files' hash chains
// their names and bytes; a file that cannot be read counts by its name.
ModelFileOrigin model_file_origin(std::string run, const std::vector<std::string>& deck_files,
                                  std::string radx_commit);

// The fingerprint read back from a model file.
struct ModelFileFingerprint {
  std::int64_t format_version = 0;
  std::string radx_version, radx_commit;
  std::string run;       // radx_run: the run the starter wrote the model for (empty: not said)
  std::string run_name;  // /radx@run_name, the starter deck's /BEGIN run name
  std::string deck_hash;
  std::vector<std::string> deck_files;
  std::string content_hash;   // as stored by the starter
  std::string computed_hash;  // of the content as read
};

// What reading a model file found. `error`: the file cannot be read at all (missing, not HDF5, a dataset
// missing or of the wrong shape), the message names the HDF5 object. `problems`: the file is read, but
// written by another format version, changed after the starter wrote it, or holds entries the engine
// cannot use (model_file_checks.hpp); each names its dataset and entry.
struct ModelFileReading {
  ModelFileFingerprint fingerprint;
  ModelFileProblems problems;
  std::string error;
  [[nodiscard]] bool ok() const { return error.empty() && problems.empty(); }
};

// Writes `m` to `path` crash-safely: the file is written as `path + ".part"`, closed, then renamed over
// `path` (atomic on POSIX), so `path` is either the previous file or the complete new one. On failure
// the .part file is removed, `path` is left untouched and `error` names the file and HDF5 object.
// Fails also when the mesh is inconsistent (connectivity or part index out of range, array lengths that
// differ from the id count), so no invalid VTKHDF is ever written. The fingerprint holds `origin` and
// the content hash of everything written.
bool write_model_file(const radx::model::Model& m, const std::string& path, const ModelFileOrigin& origin,
                      std::string& error);
// The same without an origin (run, deck hash and files empty, commit "unknown"): a file the engine refuses.
bool write_model_file(const radx::model::Model& m, const std::string& path, std::string& error);

// Reads a model file written by write_model_file into `m` (replaced entirely): checks its format version
// and its content hash, then every entry of the model (check_model_content), and rebuilds the IdMaps of
// the nodes and element blocks when nothing is wrong. Otherwise `m` is left in an unspecified (but
// destructible) state and must not be used.
ModelFileReading read_model_file(const std::string& path, radx::model::Model& m);
// The same, reduced to a yes or no; `error` then names the file and lists what is wrong.
bool read_model_file(const std::string& path, radx::model::Model& m, std::string& error);

}  // namespace radx::io
