// Writing text files: whole (the starter's listing, a deck's regression reference NAME.ref and the reports
// of `radx regress`), or as a stream whose write errors are kept (the engine's listing).
#pragma once

#include <ostream>
#include <streambuf>
#include <string>
#include <vector>

namespace radx::io {

// Writes `text` to `path` through `path`.part, flushed to disk, and a rename, so a reader never sees half a
// file and a failure leaves the old file whole. False with `error` set (naming the file and the system's
// reason, e.g. "No space left on device"; the .part file removed) on failure.
bool write_text_atomically(const std::string& path, const std::string& text, std::string& error);

// An output file as a std::ostream that keeps the reason of its first failed write: a stream says only that
// a write failed, and the errno of the failure is gone by the time the caller looks. Written through a
// 64 KiB buffer; after a failure the stream is bad and writes nothing more.
class CheckedOutputFile : public std::ostream {
 public:
  // Creates (truncates) `path`; is_open() says whether that worked, error() why not.
  explicit CheckedOutputFile(std::string path);
  ~CheckedOutputFile() override;
  CheckedOutputFile(const CheckedOutputFile&) = delete;
  CheckedOutputFile& operator=(const CheckedOutputFile&) = delete;

  [[nodiscard]] bool is_open() const { return buf_.fd >= 0; }
  // "" while every write succeeded, else "cannot write PATH: <the system's reason>". Writes what is
  // buffered first, so it covers everything written to the stream so far.
  [[nodiscard]] const std::string& error();

 private:
  struct Buffer : std::streambuf {
    int fd = -1;
    std::string path;
    std::string error;
    std::vector<char> bytes;
    int_type overflow(int_type c) override;
    int sync() override;
    bool drain();
  };
  Buffer buf_;
};

}  // namespace radx::io
