#include "common/plot.h"

#include <spawn.h>
#include <spdlog/spdlog.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <string_view>
#include <vector>

#include "common/exit_status.h"
#include "common/json.h"

extern char** environ;

namespace ddb::app {

namespace {

// The failure message quotes this many of the script's last stderr lines: a Python
// traceback's cause (e.g. "ModuleNotFoundError: No module named 'matplotlib'") is on
// its last line, its call chain on the lines before.
constexpr int kStderrTailLines = 15;
// Only the end of stderr is kept, so that a chatty script cannot fill the memory.
constexpr std::size_t kStderrKeptBytes = 64 * 1024;

/// The last kStderrTailLines lines of `text`, each indented for the log.
std::string tail(std::string_view text) {
  while (!text.empty() && text.back() == '\n') text.remove_suffix(1);
  std::size_t begin = text.size();
  for (int lines = 0; begin > 0 && lines < kStderrTailLines; --begin) {
    if (text[begin - 1] == '\n' && ++lines == kStderrTailLines) break;
  }
  std::string s;
  for (std::size_t at = begin; at < text.size();) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    s += "\n  " + std::string(text.substr(at, end - at));
    at = end + 1;
  }
  return s;
}

/// Closes a pipe's ends that are still open.
struct Pipe {
  int fd[2] = {-1, -1};
  ~Pipe() {
    for (const int f : fd) {
      if (f >= 0) ::close(f);
    }
  }
  void close(int end) {
    ::close(fd[end]);
    fd[end] = -1;
  }
};

}  // namespace

std::string pythonInterpreter() { return DDB_PYTHON3; }

std::string plotFailure(const std::string& interpreter, const std::string& script,
                        const std::filesystem::path& out) {
  return plotFailure(interpreter, script, std::vector<std::string>{out.string()});
}

std::string plotFailure(const std::string& interpreter, const std::string& script,
                        const std::vector<std::string>& arguments) {
  Pipe errors;
  if (::pipe(errors.fd) != 0) return std::string("cannot create a pipe: ") + std::strerror(errno);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, errors.fd[1], STDERR_FILENO);
  posix_spawn_file_actions_addclose(&actions, errors.fd[0]);
  posix_spawn_file_actions_addclose(&actions, errors.fd[1]);
  std::vector<std::string> words{interpreter, script};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (auto& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  pid_t child = 0;
  // glibc's posix_spawnp reports a failed exec (missing or not executable interpreter)
  // as its return value, not as an exit status of the child.
  const int spawned =
      ::posix_spawnp(&child, interpreter.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) {
    return "cannot run the interpreter " + interpreter + ": " + std::strerror(spawned);
  }
  errors.close(1);
  std::string text;
  char buffer[4096];
  for (ssize_t n; (n = ::read(errors.fd[0], buffer, sizeof buffer)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;
    text.append(buffer, static_cast<std::size_t>(n));
    if (text.size() > 2 * kStderrKeptBytes) text.erase(0, text.size() - kStderrKeptBytes);
  }
  int status = 0;
  while (::waitpid(child, &status, 0) < 0) {
    if (errno != EINTR) return "cannot wait for " + interpreter + ": " + std::strerror(errno);
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return "";
  const std::string how = WIFEXITED(status)
                              ? "exited with status " + std::to_string(WEXITSTATUS(status))
                              : "was killed by signal " + std::to_string(WTERMSIG(status));
  const std::string last = tail(text);
  return script + " " + how +
         (last.empty() ? " (no message on stderr)" : "; the end of its stderr:" + last);
}

std::string runPlotScript(const std::string& script, const std::filesystem::path& out) {
  return runPlotScript(script, std::vector<std::string>{out.string()});
}

std::string runPlotScript(const std::string& script, const std::vector<std::string>& arguments) {
  const std::string interpreter = pythonInterpreter();
  spdlog::info("plotting: {} {} {}", interpreter, script, fmt::join(arguments, " "));
  const std::string failure = plotFailure(interpreter, script, arguments);
  if (!failure.empty()) spdlog::error("plotting failed: {}", failure);
  return failure;
}

int recordFiguresFailure(const std::filesystem::path& summary, const std::string& failure) {
  Json json = readJsonFile(summary);
  if (json.contains("status") && json["status"] == "ok") json["status"] = "figures_failed";
  json["figures_failure"] = failure;
  writeJsonFile(summary, json);
  return kExitFailed;
}

}  // namespace ddb::app
