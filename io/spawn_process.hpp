// Running a child program without a shell (posix_spawn): the driver's deck runs in `radx regress` and the
// energy chart's /usr/bin/python3. Arguments pass byte for byte, argv[0] is the executable's path (no PATH
// search), standard input is /dev/null, and the child starts with no blocked signals and the default SIGPIPE
// handling, whatever this process set for itself. Standard output and error go together either into a file or
// into a pipe this process reads; the child is killed with SIGKILL at its time limit.
#pragma once

#include <chrono>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace radx::io {

struct ProcessRequest {
  std::vector<std::string> argv;  // argv[0]: the executable, an absolute path
  // NAME=VALUE entries; none: this process's environment.
  std::optional<std::vector<std::string>> environment;
  // The child's working folder; empty: this process's. Relative paths of the request (output_file) are
  // taken from this process's folder, not from this one.
  std::filesystem::path working_dir;
  // Standard output and error both into this file, created or truncated (mode 0644). Empty: both into a pipe,
  // returned in ProcessResult::output.
  std::filesystem::path output_file;
  // With a pipe: only the end of the output is kept, at most this many bytes (a Python traceback ends with
  // the line that explains it).
  std::size_t max_output = 16 * 1024;
  std::chrono::duration<double> timeout{};  // killed at this time after its start (0: at once)
};

struct ProcessResult {
  // Not empty when the program could not be started ("cannot start PROGRAM: REASON", also when its output
  // file cannot be opened) or when waiting for it failed ("lost the child process: REASON"); the other fields
  // then tell nothing about how it ended.
  std::string error;
  bool timed_out = false;  // killed (SIGKILL) at the time limit
  int exit_code = -1;      // when it exited
  int signal = 0;          // when a signal ended it (the time limit's SIGKILL included)
  double seconds = 0;      // wall time from the start to the end of the wait
  std::string output;      // with a pipe: standard output and error, interleaved (the end, see max_output)
};

// Starts the program and waits for it.
// Into a file: waitpid is polled (2 ms, doubling up to 50 ms) rather than woken by SIGCHLD, so no handler is
// installed in a process that may run other children; a few milliseconds of latency are nothing next to a
// deck's run.
// Into a pipe: the pipe is read up to its end of file (the child closed its output: it is exiting) or to the
// time limit, then the child is waited for. The pipe is close-on-exec in this process, so programs started by
// other threads at the same moment do not inherit it (which would delay its end of file).
ProcessResult run_process(const ProcessRequest& request);

}  // namespace radx::io
