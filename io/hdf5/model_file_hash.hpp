// The content hash of a model file (docs/model-file.md section 3): a 64-bit hash of every dataset and
// attribute of the file, in a fixed order, that the starter stores as the root attribute
// radx_content_hash and the engine computes again, so that a change made to the file after the starter
// wrote it (by h5py, a disk fault, a copy cut short) is found before the model is used. Internal to
// io/hdf5: the HDF5 helpers of hdf5_util.hpp throw h5::Failure.
#pragma once

#include <hdf5.h>

#include <cstddef>
#include <cstdint>
#include <string>

namespace radx::io {

// The root attribute that holds the hash, the one attribute the hash leaves out.
inline constexpr const char* kContentHashAttribute = "radx_content_hash";

// 64-bit hash of `size` bytes (an xxHash64-like construction: four multiply-rotate lanes over 32-byte
// stripes, then the tail and a final avalanche), `seed` chaining it to what came before. Not a
// cryptographic hash: it finds changes, it does not resist someone who wants to hide one.
std::uint64_t hash_bytes(const void* data, std::size_t size, std::uint64_t seed);

// The content hash of the open file `file`, as 16 lower-case hex digits. Walks the groups from the root
// by link name (increasing), and hashes for each object its path, then each attribute (by name, except
// kContentHashAttribute at the root) and, for a dataset, its shape, its type's class and size, and its
// values: the stored bytes of fixed-size types, the text of variable-length strings.
std::string model_content_hash(hid_t file);

}  // namespace radx::io
