// Starting a child program (io/spawn_process.hpp), with /bin/sh as the child: its exit code and the signal
// that ended it, standard output and error into a file (truncated, opened from the caller's folder) or
// through the pipe (only the end kept), standard input from /dev/null, the working folder, the environment,
// SIGPIPE back to its default, the time limit, and the errors of a program that cannot be started.
//
// Timing: the children that must be killed sleep 30 s against a limit of 0.3 s, and the check allows 10 s for
// the kill, so a loaded machine does not fail it while a limit that is not enforced does.
#include <catch2/catch.hpp>

#include <signal.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "io/spawn_process.hpp"
#include "test_util.hpp"

namespace {

namespace fs = std::filesystem;
using radx::io::ProcessRequest;
using radx::io::ProcessResult;
using radx::io::run_process;

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// /bin/sh -c SCRIPT, output through the pipe, a generous limit.
ProcessRequest shell(const std::string& script) {
  ProcessRequest r;
  r.argv = {"/bin/sh", "-c", script};
  r.timeout = std::chrono::seconds(60);
  return r;
}

}  // namespace

TEST_CASE("spawn: the exit code, or the signal that ended the child", "[spawn]") {
  for (const bool to_file : {false, true}) {
    radx::test::TempDir tmp;
    INFO((to_file ? "output into a file" : "output through the pipe"));
    const auto run = [&](const std::string& script) {
      ProcessRequest r = shell(script);
      if (to_file) r.output_file = tmp.path() / "out.log";
      return run_process(r);
    };
    const ProcessResult ok = run("exit 0");
    CHECK(ok.error.empty());
    CHECK(ok.exit_code == 0);
    CHECK(ok.signal == 0);
    CHECK_FALSE(ok.timed_out);
    CHECK(ok.seconds > 0.0);
    CHECK(run("exit 7").exit_code == 7);
    const ProcessResult killed = run("kill -TERM $$");
    CHECK(killed.error.empty());
    CHECK(killed.exit_code == -1);
    CHECK(killed.signal == SIGTERM);
    CHECK_FALSE(killed.timed_out);
  }
}

TEST_CASE("spawn: standard output and error into a file, truncated, nothing captured", "[spawn]") {
  radx::test::TempDir tmp;
  tmp.write("run.log", "an older and much longer log that must not survive\n");
  ProcessRequest r = shell("echo out; echo err >&2; echo out again");
  r.output_file = tmp.path() / "run.log";
  const ProcessResult p = run_process(r);
  REQUIRE(p.error.empty());
  CHECK(p.exit_code == 0);
  CHECK(read_text(tmp.path() / "run.log") == "out\nerr\nout again\n");
  CHECK(p.output.empty());
  // Mode 0644 (less under a stricter umask): never executable, never writable by others.
  const fs::perms mode = fs::status(tmp.path() / "run.log").permissions();
  CHECK((mode & fs::perms::owner_write) != fs::perms::none);
  CHECK((mode & (fs::perms::owner_exec | fs::perms::group_write | fs::perms::group_exec |
                 fs::perms::others_write | fs::perms::others_exec)) == fs::perms::none);
}

TEST_CASE("spawn: standard output and error through the pipe, only the end kept", "[spawn]") {
  const ProcessResult both = run_process(shell("echo out; echo err >&2; echo out again"));
  REQUIRE(both.error.empty());
  CHECK(both.output == "out\nerr\nout again\n");

  // 200 lines of 10 bytes against a limit of 95 bytes: the last 95 bytes, ending with the last line.
  ProcessRequest r = shell("i=100; while [ $i -lt 300 ]; do echo \"line  $i\"; i=$((i + 1)); done");
  r.max_output = 95;
  const ProcessResult tail = run_process(r);
  REQUIRE(tail.error.empty());
  CHECK(tail.exit_code == 0);
  CHECK(tail.output.size() == 95);
  CHECK(tail.output.ends_with("line  298\nline  299\n"));
}

TEST_CASE("spawn: standard input is /dev/null", "[spawn]") {
  // This process's standard input becomes a pipe nobody writes to or closes: a child that inherited it would
  // wait in `cat` up to its limit; on /dev/null `cat` ends at once.
  int fds[2];
  REQUIRE(pipe(fds) == 0);
  const int saved = dup(0);
  REQUIRE(saved >= 0);
  REQUIRE(dup2(fds[0], 0) == 0);
  ProcessRequest r = shell("cat; echo end");
  r.timeout = std::chrono::seconds(5);
  const ProcessResult p = run_process(r);
  dup2(saved, 0);
  close(saved);
  close(fds[0]);
  close(fds[1]);
  REQUIRE(p.error.empty());
  CHECK_FALSE(p.timed_out);
  CHECK(p.output == "end\n");
}

TEST_CASE("spawn: the working folder, and an output file named from the caller's folder", "[spawn]") {
  radx::test::TempDir tmp;
  fs::create_directories(tmp.path() / "work");
  const fs::path work = fs::canonical(tmp.path() / "work");

  ProcessRequest piped = shell("pwd -P; echo made > made.txt");
  piped.working_dir = work;
  const ProcessResult p = run_process(piped);
  REQUIRE(p.error.empty());
  CHECK(p.output == work.string() + "\n");
  CHECK(read_text(work / "made.txt") == "made\n");

  // A relative output file is opened before the child changes folder: it is the caller's, not the child's.
  const fs::path caller = fs::current_path();
  fs::current_path(tmp.path());
  ProcessRequest logged = shell("pwd -P");
  logged.working_dir = work;
  logged.output_file = "relative.log";
  const ProcessResult q = run_process(logged);
  fs::current_path(caller);
  REQUIRE(q.error.empty());
  CHECK(read_text(tmp.path() / "relative.log") == work.string() + "\n");
  CHECK_FALSE(fs::exists(work / "relative.log"));
}

TEST_CASE("spawn: the environment given, or this process's", "[spawn]") {
  ProcessRequest given = shell("echo \"[$RADX_SPAWN_TEST]\"");
  given.environment = std::vector<std::string>{"RADX_SPAWN_TEST=given value"};
  CHECK(run_process(given).output == "[given value]\n");

  REQUIRE(setenv("RADX_SPAWN_TEST", "inherited", 1) == 0);
  const ProcessResult inherited = run_process(shell("echo \"[$RADX_SPAWN_TEST]\""));
  unsetenv("RADX_SPAWN_TEST");
  CHECK(inherited.output == "[inherited]\n");

  ProcessRequest empty = shell("echo \"[$HOME]\"");
  empty.environment = std::vector<std::string>{};
  CHECK(run_process(empty).output == "[]\n");
}

TEST_CASE("spawn: SIGPIPE is back to its default and no signal is blocked in the child", "[spawn]") {
  // Ignored and blocked here; the child must still be ended by SIGPIPE when it writes into a closed pipe, and
  // see no blocked signal (SigBlk of /proc/self/status all zero).
  struct sigaction ignore {
  }, before{};
  ignore.sa_handler = SIG_IGN;
  sigemptyset(&ignore.sa_mask);
  REQUIRE(sigaction(SIGPIPE, &ignore, &before) == 0);
  sigset_t block, old_mask;
  sigemptyset(&block);
  sigaddset(&block, SIGUSR1);
  REQUIRE(pthread_sigmask(SIG_BLOCK, &block, &old_mask) == 0);

  // `yes` writes until `head` closes the pipe: SIGPIPE ends it and the shell reports 128 + SIGPIPE. With
  // SIGPIPE still ignored it would end on the write error instead, with status 1.
  const ProcessResult pipe_end = run_process(shell("(yes; echo \"yes: $?\" >&2) | head -n 1 >/dev/null"));
  // grep itself, not through a shell (dash clears its signal mask when it starts).
  ProcessRequest grep;
  grep.argv = {"/bin/grep", "^SigBlk:", "/proc/self/status"};
  grep.timeout = std::chrono::seconds(60);
  const ProcessResult mask = run_process(grep);

  pthread_sigmask(SIG_SETMASK, &old_mask, nullptr);
  sigaction(SIGPIPE, &before, nullptr);
  REQUIRE(pipe_end.error.empty());
  CHECK(pipe_end.output == "yes: " + std::to_string(128 + SIGPIPE) + "\n");
  REQUIRE(mask.error.empty());
  CHECK(mask.output == "SigBlk:\t0000000000000000\n");
}

TEST_CASE("spawn: a child past its time limit is killed with SIGKILL", "[spawn]") {
  for (const bool to_file : {false, true}) {
    radx::test::TempDir tmp;
    INFO((to_file ? "output into a file" : "output through the pipe"));
    ProcessRequest r = shell("echo started; exec sleep 30");
    r.timeout = std::chrono::duration<double>(0.3);
    if (to_file) r.output_file = tmp.path() / "out.log";
    const auto start = std::chrono::steady_clock::now();
    const ProcessResult p = run_process(r);
    const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    REQUIRE(p.error.empty());
    CHECK(p.timed_out);
    CHECK(p.signal == SIGKILL);
    CHECK(p.exit_code == -1);
    CHECK(took >= 0.29);  // the pipe's wait counts whole milliseconds
    CHECK(p.seconds >= 0.29);
    CHECK(took < 10.0);
    CHECK((to_file ? read_text(tmp.path() / "out.log") : p.output) == "started\n");
  }
}

TEST_CASE("spawn: a program that cannot be started is an error naming it, not an exception", "[spawn]") {
  radx::test::TempDir tmp;
  for (const bool to_file : {false, true}) {
    INFO((to_file ? "output into a file" : "output through the pipe"));
    ProcessRequest r;
    r.argv = {(tmp.path() / "no-such-program").string(), "--flag"};
    r.timeout = std::chrono::seconds(10);
    if (to_file) r.output_file = tmp.path() / "out.log";
    ProcessResult p;
    REQUIRE_NOTHROW(p = run_process(r));
    CHECK(p.error == "cannot start " + r.argv[0] + ": No such file or directory");
    CHECK(p.exit_code == -1);
    CHECK_FALSE(p.timed_out);
  }

  // Not executable.
  const std::string text = tmp.write("not-a-program", "just text\n");
  ProcessRequest r;
  r.argv = {text};
  r.timeout = std::chrono::seconds(10);
  CHECK(run_process(r).error == "cannot start " + text + ": Permission denied");

  // No PATH search: a bare name is a path from the caller's folder, which has no `sh` (PATH has).
  const fs::path caller = fs::current_path();
  fs::current_path(tmp.path());
  r.argv = {"sh", "-c", "exit 0"};
  const ProcessResult bare = run_process(r);
  fs::current_path(caller);
  CHECK(bare.error == "cannot start sh: No such file or directory");

  // An output file that cannot be opened: the child never starts.
  ProcessRequest logged = shell("echo never");
  logged.output_file = tmp.path() / "missing folder" / "run.log";
  CHECK(run_process(logged).error == "cannot start /bin/sh: No such file or directory");

  // A working folder that does not exist.
  ProcessRequest moved = shell("echo never");
  moved.working_dir = tmp.path() / "missing folder";
  CHECK(run_process(moved).error == "cannot start /bin/sh: No such file or directory");

  // No program at all.
  CHECK(run_process(ProcessRequest{}).error == "cannot start a program: none given");
}
