// Running a child program without a shell (io/spawn_process.hpp).
#include "io/spawn_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <thread>

extern char** environ;

namespace radx::io {

namespace {

using Clock = std::chrono::steady_clock;

// The file actions and attributes of one start, released when it is done.
class SpawnSetup {
 public:
  SpawnSetup() {
    posix_spawn_file_actions_init(&actions_);
    posix_spawnattr_init(&attr_);
  }
  ~SpawnSetup() {
    posix_spawn_file_actions_destroy(&actions_);
    posix_spawnattr_destroy(&attr_);
  }
  SpawnSetup(const SpawnSetup&) = delete;
  SpawnSetup& operator=(const SpawnSetup&) = delete;
  posix_spawn_file_actions_t* actions() { return &actions_; }
  posix_spawnattr_t* attr() { return &attr_; }

 private:
  posix_spawn_file_actions_t actions_;
  posix_spawnattr_t attr_;
};

std::vector<char*> pointers(const std::vector<std::string>& strings) {
  std::vector<char*> p;
  p.reserve(strings.size() + 1);
  for (const auto& s : strings) p.push_back(const_cast<char*>(s.c_str()));
  p.push_back(nullptr);
  return p;
}

std::string cannot_start(const ProcessRequest& request, int error) {
  return "cannot start " + request.argv[0] + ": " + std::strerror(error);
}

std::string lost(int error) {
  return std::string("lost the child process: ") + std::strerror(error);
}

// Waits for `pid` to end (EINTR retried); false, with errno, when waiting fails.
bool wait_for(pid_t pid, int& status) {
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return false;
  }
  return true;
}

void read_status(int status, ProcessResult& result) {
  if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
}

// Output into a file: waitpid polled, 2 ms doubling up to 50 ms, up to the time limit.
void wait_polled(pid_t pid, Clock::time_point start, const ProcessRequest& request, ProcessResult& result) {
  int status = 0;
  auto pause = std::chrono::milliseconds(2);
  for (;;) {
    const pid_t w = waitpid(pid, &status, WNOHANG);
    if (w == pid) break;
    if (w < 0 && errno != EINTR) {
      result.error = lost(errno);
      return;
    }
    if (Clock::now() - start >= request.timeout) {
      result.timed_out = true;
      kill(pid, SIGKILL);
      if (!wait_for(pid, status)) {
        result.error = lost(errno);
        return;
      }
      break;
    }
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::milliseconds(50));
  }
  result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  read_status(status, result);
}

// Output into a pipe: read to its end of file or to the time limit (then SIGKILL), then the child waited for.
void read_then_wait(pid_t pid, int fd, Clock::time_point start, const ProcessRequest& request,
                    ProcessResult& result) {
  const auto deadline = start + request.timeout;
  std::array<char, 4096> buf{};
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
    if (left.count() <= 0) {
      result.timed_out = true;
      kill(pid, SIGKILL);
      break;
    }
    pollfd p{fd, POLLIN, 0};
    const int ready = poll(&p, 1, static_cast<int>(left.count()));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;  // timeout: the deadline check above ends the loop
    const ssize_t n = read(fd, buf.data(), buf.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // end of file: the child closed its output (it is exiting)
    result.output.append(buf.data(), static_cast<std::size_t>(n));
    if (result.output.size() > request.max_output)
      result.output.erase(0, result.output.size() - request.max_output);
  }
  close(fd);
  int status = 0;
  if (!wait_for(pid, status)) {
    result.error = lost(errno);
    return;
  }
  result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  read_status(status, result);
}

// Starts the program with standard input from /dev/null and standard output and error into the request's
// file, or into `pipe_write` when it has none; the error number of posix_spawn (0: started).
int spawn(const ProcessRequest& request, int pipe_write, pid_t& pid) {
  std::vector<char*> argv = pointers(request.argv);
  std::vector<char*> envp;
  if (request.environment) envp = pointers(*request.environment);
  const std::string output_file = request.output_file.string();
  const std::string working_dir = request.working_dir.string();

  SpawnSetup setup;
  posix_spawn_file_actions_addopen(setup.actions(), 0, "/dev/null", O_RDONLY, 0);
  if (!output_file.empty()) {
    posix_spawn_file_actions_addopen(setup.actions(), 1, output_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    posix_spawn_file_actions_adddup2(setup.actions(), 1, 2);
  } else {
    posix_spawn_file_actions_adddup2(setup.actions(), pipe_write, 1);
    posix_spawn_file_actions_adddup2(setup.actions(), pipe_write, 2);
  }
  // After the output file is opened: its relative path is this process's, not the child's.
  if (!working_dir.empty()) posix_spawn_file_actions_addchdir_np(setup.actions(), working_dir.c_str());
  // The child starts with no blocked signals and default SIGPIPE, whatever this process set for itself.
  sigset_t none, defaults;
  sigemptyset(&none);
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGPIPE);
  posix_spawnattr_setsigmask(setup.attr(), &none);
  posix_spawnattr_setsigdefault(setup.attr(), &defaults);
  posix_spawnattr_setflags(setup.attr(), POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  return posix_spawn(&pid, argv[0], setup.actions(), setup.attr(), argv.data(),
                     request.environment ? envp.data() : environ);
}

}  // namespace

ProcessResult run_process(const ProcessRequest& request) {
  ProcessResult result;
  if (request.argv.empty()) {
    result.error = "cannot start a program: none given";
    return result;
  }
  pid_t pid = 0;
  if (!request.output_file.empty()) {
    const auto start = Clock::now();
    const int rc = spawn(request, -1, pid);
    if (rc != 0) {
      result.error = cannot_start(request, rc);
      return result;
    }
    wait_polled(pid, start, request, result);
    return result;
  }
  // Close-on-exec, so programs started by other threads at the same moment do not inherit the pipe (which
  // would keep it open and delay the end of file waited for). The dup2 copies in the child are inherited.
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) {
    result.error = cannot_start(request, errno);
    return result;
  }
  const auto start = Clock::now();
  const int rc = spawn(request, fds[1], pid);
  close(fds[1]);
  if (rc != 0) {
    close(fds[0]);
    result.error = cannot_start(request, rc);
    return result;
  }
  read_then_wait(pid, fds[0], start, request, result);
  return result;
}

}  // namespace radx::io
