#include "io/text_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace radx::io {

namespace fs = std::filesystem;

namespace {

// Writes all of [data, data + size) to `fd`; 0, or the errno of the failure.
int write_all(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return n < 0 ? errno : EIO;
    data += n;
    size -= static_cast<std::size_t>(n);
  }
  return 0;
}

}  // namespace

bool write_text_atomically(const std::string& path, const std::string& text, std::string& error) {
  const std::string part = path + ".part";
  const int fd = ::open(part.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    error = "cannot create " + part + ": " + std::strerror(errno);
    return false;
  }
  int failure = write_all(fd, text.data(), text.size());
  if (failure == 0 && ::fsync(fd) != 0) failure = errno;
  if (::close(fd) != 0 && failure == 0) failure = errno;
  std::error_code ec;
  if (failure != 0) {
    error = "cannot write " + part + ": " + std::strerror(failure);
    fs::remove(part, ec);
    return false;
  }
  fs::rename(part, path, ec);
  if (ec) {
    error = "cannot rename " + part + " to " + path + ": " + ec.message();
    fs::remove(part, ec);
    return false;
  }
  return true;
}

CheckedOutputFile::CheckedOutputFile(std::string path) : std::ostream(nullptr) {
  buf_.path = std::move(path);
  buf_.fd = ::open(buf_.path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (buf_.fd < 0) {
    buf_.error = "cannot create " + buf_.path + ": " + std::strerror(errno);
    setstate(std::ios::badbit);
    return;
  }
  buf_.bytes.resize(std::size_t{1} << 16);
  buf_.drain();  // sets the buffer up (empty)
  rdbuf(&buf_);
}

CheckedOutputFile::~CheckedOutputFile() {
  if (buf_.fd < 0) return;
  buf_.drain();
  ::close(buf_.fd);
}

const std::string& CheckedOutputFile::error() {
  if (!buf_.drain()) setstate(std::ios::badbit);
  return buf_.error;
}

bool CheckedOutputFile::Buffer::drain() {
  if (!error.empty()) return false;
  const int failure = write_all(fd, pbase(), static_cast<std::size_t>(pptr() - pbase()));
  setp(bytes.data(), bytes.data() + bytes.size());
  if (failure != 0) error = "cannot write " + path + ": " + std::strerror(failure);
  return failure == 0;
}

CheckedOutputFile::Buffer::int_type CheckedOutputFile::Buffer::overflow(int_type c) {
  if (!drain()) return traits_type::eof();
  if (!traits_type::eq_int_type(c, traits_type::eof())) {
    *pptr() = traits_type::to_char_type(c);
    pbump(1);
  }
  return traits_type::not_eof(c);
}

int CheckedOutputFile::Buffer::sync() {
  return drain() ? 0 : -1;
}

}  // namespace radx::io
