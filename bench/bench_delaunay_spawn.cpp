// bench_delaunay_spawn.cpp — the suite's child processes: runs `bench_delaunay run ...`
// as a separate process (so that its peak memory is that tool's alone), collects its
// line and parses it into a Sample.
#include "bench_delaunay.h"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char **environ;

namespace
{

// Spawns args (args[0] the executable) with its stdout on a pipe, reads it to the end
// into *out and waits for it. False with err set if it could not run or did not exit 0.
bool run_child(std::vector<std::string> args, std::string *out, std::string &err)
{
    int fd[2];
    if (pipe(fd) != 0) {
        err = "pipe failed";
        return false;
    }
    std::vector<char *> av;
    for (auto &a : args) av.push_back(a.data());
    av.push_back(nullptr);
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addclose(&fa, fd[0]);
    posix_spawn_file_actions_adddup2(&fa, fd[1], 1);
    posix_spawn_file_actions_addclose(&fa, fd[1]);
    pid_t pid;
    int rc = posix_spawn(&pid, args[0].c_str(), &fa, nullptr, av.data(), environ);
    posix_spawn_file_actions_destroy(&fa);
    close(fd[1]);
    if (rc != 0) {
        close(fd[0]);
        err = std::string("posix_spawn: ") + std::strerror(rc);
        return false;
    }
    char buf[4096];
    for (;;) {
        ssize_t k = read(fd[0], buf, sizeof buf);
        if (k > 0)
            out->append(buf, size_t(k));
        else if (k == 0 || errno != EINTR)
            break;
    }
    close(fd[0]);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (WIFSIGNALED(status)) {
        err = std::string("killed by signal ") + std::to_string(WTERMSIG(status)) +
              (WTERMSIG(status) == SIGALRM ? " (timeout)" : "");
        return false;
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        err = "exit status " + std::to_string(WEXITSTATUS(status));
        return false;
    }
    return true;
}

// The value of " key=" in a run line.
bool line_field(const std::string &out, const char *key, std::string &val)
{
    std::string k = std::string(" ") + key + "=";
    size_t p = out.find(k);
    if (p == std::string::npos) return false;
    p += k.size();
    size_t e = out.find_first_of(" \n", p);
    val = out.substr(p, e == std::string::npos ? std::string::npos : e - p);
    return true;
}

} // namespace

std::string self_exe()
{
    char buf[4096];
    ssize_t k = readlink("/proc/self/exe", buf, sizeof buf - 1);
    if (k <= 0) return "";
    buf[k] = 0;
    return buf;
}

Sample spawn_run(const std::string &exe, const std::string &tool, int d, size_t n, uint64_t seed,
                 int timeout, std::string &err)
{
    Sample s;
    std::string out;
    if (!run_child({exe, "run", tool, std::to_string(d), std::to_string(n), std::to_string(seed),
                    "--timeout", std::to_string(timeout)},
                   &out, err))
        return s;
    std::string w, c, sx, pk;
    if (!line_field(out, "seconds", w) || !line_field(out, "cpu", c) ||
        !line_field(out, "simplices", sx) || !line_field(out, "peak_kb", pk)) {
        err = "unparsable output: " + out;
        return s;
    }
    s.wall = std::atof(w.c_str());
    s.cpu = std::atof(c.c_str());
    s.simplices = size_t(std::strtoull(sx.c_str(), nullptr, 10));
    s.peak_kb = std::atol(pk.c_str());
    std::string hw;
    if (line_field(out, "hull_seconds", hw)) s.hull_wall = std::atof(hw.c_str());
    s.ok = true;
    return s;
}
