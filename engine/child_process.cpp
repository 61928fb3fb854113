#include "engine/child_process.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <memory>
#include <thread>

#include "engine/input_error.h"

namespace mtcut::engine {
namespace {

std::string read_all(std::FILE* f) {
  std::string text;
  std::rewind(f);
  char buffer[1 << 16];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, f)) > 0) text.append(buffer, n);
  return text;
}

// work(result) in this thread, as run_in_child's fallback.
ChildRun run_here(const std::function<int(std::FILE* result)>& work, std::FILE* result) {
  ChildRun run;
  try {
    run.code = work(result) & 0xff;  // as an exit status is
  } catch (...) {
    run.code = 1;
  }
  std::fflush(result);
  run.output = read_all(result);
  return run;
}

}  // namespace

bool process_runs_other_threads() {
  std::FILE* status = std::fopen("/proc/self/status", "r");
  if (!status) return true;  // unknown: the safe answer
  char line[256];
  long threads = -1;
  while (std::fgets(line, sizeof line, status))
    if (std::sscanf(line, "Threads: %ld", &threads) == 1) break;
  std::fclose(status);
  return threads != 1;
}

std::string signal_name(int signal) {
  const char* name = ::strsignal(signal);
  return name ? name : "signal " + std::to_string(signal);
}

ChildRun run_in_child(const std::function<int(std::FILE* result)>& work, const ChildOptions& options) {
  using Clock = std::chrono::steady_clock;
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> result(std::tmpfile(), &std::fclose);
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> chatter(std::tmpfile(), &std::fclose);
  if (!result || !chatter) throw InputError("cannot make a temporary file for a child process");
  if (process_runs_other_threads()) return run_here(work, result.get());
  std::fflush(stdout);
  std::fflush(stderr);
  // A SIGCHLD the process was started ignoring would reap the child before waitpid sees it.
  struct sigaction child_default {}, saved_child {};
  child_default.sa_handler = SIG_DFL;
  ::sigaction(SIGCHLD, &child_default, &saved_child);
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::sigaction(SIGCHLD, &saved_child, nullptr);
    throw InputError("cannot start a child process");
  }
  if (pid == 0) {
    // The child ends with its parent, and takes Ctrl-C as a process does
    // (not through the parent's handlers, which only set flags).
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(1);
    ::signal(SIGINT, SIG_DFL);
    ::signal(SIGTERM, SIG_DFL);
    if (options.quiet) {
      const int sink = options.keep_chatter ? ::fileno(chatter.get()) : ::open("/dev/null", O_WRONLY);
      ::dup2(sink, STDOUT_FILENO);
      ::dup2(sink, STDERR_FILENO);
    }
    int code = 1;
    try {
      code = work(result.get());
    } catch (...) {
      code = 1;
    }
    std::fflush(stdout);
    std::fflush(stderr);
    std::fflush(result.get());
    ::_exit(code);  // no atexit handlers, destructors or leak checks of the parent's state
  }

  ChildRun run;
  int status = 0;
  // Reports fall on whole seconds since the start.
  auto next_report = options.start + std::chrono::seconds(1 + static_cast<long>(std::chrono::duration<double>(
                                                                   Clock::now() - options.start)
                                                                   .count()));
  for (auto pause = std::chrono::milliseconds(1);; pause = std::min(2 * pause, std::chrono::milliseconds(50))) {
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) {
      ::kill(pid, SIGKILL);
      ::sigaction(SIGCHLD, &saved_child, nullptr);
      throw InputError("lost a child process");
    }
    const auto now = Clock::now();
    if (now >= options.deadline) {
      ::kill(pid, SIGKILL);
      while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
      ::sigaction(SIGCHLD, &saved_child, nullptr);
      run.outcome = ChildRun::Outcome::kTimedOut;
      return run;
    }
    if (options.progress && now >= next_report) {
      options.progress(std::chrono::duration<double>(now - options.start).count());
      while (next_report <= now) next_report += std::chrono::seconds(1);
    }
    std::this_thread::sleep_for(pause);
  }
  ::sigaction(SIGCHLD, &saved_child, nullptr);
  run.chatter = read_all(chatter.get());
  if (WIFSIGNALED(status)) {
    run.outcome = ChildRun::Outcome::kCrashed;
    run.code = WTERMSIG(status);
    return run;
  }
  run.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.output = read_all(result.get());
  return run;
}

}  // namespace mtcut::engine
