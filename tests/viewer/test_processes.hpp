// Child processes for the viewer's end-to-end tests: the viewer under
// xvfb-run, and matchcast-server on 127.0.0.1 port 0 with the bundled game.
// Every wait is bounded; a child that outlives it is killed.
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace mc::viewer::e2e {

inline const std::string kOut = MATCHCAST_OUTPUT_DIR;
inline const std::string kLog =
    std::string(MATCHCAST_SOURCE_DIR) + "/data/20261122030423-HELIOS_A_1-vs-HELIOS_B_5.rcg.gz";

// A child process: stdout to a pipe (read_fd) or a file, stderr to a file.
struct Child {
  pid_t pid = -1;
  int read_fd = -1;
};

inline Child spawn(const std::vector<std::string>& args, const std::string& log, bool pipe_stdout, const std::string& cwd) {
  Child c;
  int fds[2] = {-1, -1};
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (pipe_stdout) {
    if (pipe(fds) != 0) return c;
    posix_spawn_file_actions_adddup2(&actions, fds[1], 1);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
  } else {
    posix_spawn_file_actions_addopen(&actions, 1, (log + ".out").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  }
  posix_spawn_file_actions_addopen(&actions, 2, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (!cwd.empty()) posix_spawn_file_actions_addchdir_np(&actions, cwd.c_str());
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  if (posix_spawn(&c.pid, argv[0], &actions, nullptr, argv.data(), environ) != 0) c.pid = -1;
  posix_spawn_file_actions_destroy(&actions);
  if (pipe_stdout) {
    close(fds[1]);
    c.read_fd = fds[0];
  }
  return c;
}

// Exit code, or -1 after killing it when it outlives `seconds`.
inline int wait_for(pid_t pid, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  int status = 0;
  while (std::chrono::steady_clock::now() < end) {
    if (waitpid(pid, &status, WNOHANG) == pid) return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  kill(pid, SIGKILL);
  waitpid(pid, &status, 0);
  return -1;
}

inline std::string slurp(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// matchcast-server on 127.0.0.1 port 0; stopped with SIGTERM.
class Server {
 public:
  // `speed`: the log plays this many times faster than real time.
  explicit Server(const std::string& record_dir, const std::string& speed = "2") {
    std::filesystem::create_directories(kOut);
    child_ = spawn({MATCHCAST_SERVER, "--rcg", kLog, "--port", "0", "--threads", "1", "--speed", speed,
                    "--web", std::string(MATCHCAST_SOURCE_DIR) + "/web", "--record-dir", record_dir},
                   kOut + "/server.log", true, kOut);
    if (child_.pid < 0) return;
    // "Matchcast: open http://127.0.0.1:PORT/"
    std::string text;
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (port_ == 0 && std::chrono::steady_clock::now() < end) {
      pollfd p{child_.read_fd, POLLIN, 0};
      if (poll(&p, 1, 100) <= 0) continue;
      char buf[256];
      const ssize_t n = read(child_.read_fd, buf, sizeof buf);
      if (n <= 0) break;
      text.append(buf, static_cast<std::size_t>(n));
      const auto at = text.find("127.0.0.1:");
      if (at != std::string::npos && text.find('/', at) != std::string::npos)
        port_ = static_cast<std::uint16_t>(std::stoi(text.substr(at + 10)));
    }
  }
  ~Server() { stop(); }
  std::uint16_t port() const { return port_; }
  int stop() {
    if (child_.pid < 0) return 0;
    kill(child_.pid, SIGTERM);
    const int code = wait_for(child_.pid, 20);
    close(child_.read_fd);
    child_.pid = -1;
    return code;
  }

 private:
  Child child_;
  std::uint16_t port_ = 0;
};

// The start of an xvfb-run command line. A fixed auth file per run: without
// one, xvfb-run makes and removes a temporary directory, and that removal
// sometimes fails (exit 5) after the program ran.
inline std::vector<std::string> xvfb(const std::string& name) {
  return {MATCHCAST_XVFB_RUN, "-a", "-f", kOut + "/" + name + ".xauth", "-s", "-screen 0 1280x1024x24"};
}

}  // namespace mc::viewer::e2e
