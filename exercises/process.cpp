// exercises/process.hpp on Linux and macOS (POSIX: fork, exec, process groups, rlimits). Windows has
// none of these: there process_unsupported.cpp says so, and ./ocean check is not offered.
#include "exercises/process.hpp"

#include <fcntl.h>
#include <poll.h>
#if defined(__linux__)
#include <sys/prctl.h>  // PR_SET_PDEATHSIG: Linux only
#endif
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <thread>
#include <utility>

#include "common/error.hpp"
#include "common/text.hpp"

namespace exercises {

namespace {

using Clock = std::chrono::steady_clock;

constexpr int kTaskThrew = 3;                   // run_in_child's child: the task threw, its message follows
constexpr std::size_t kMaxChildText = 1 << 20;  // what run_in_child keeps of its child's text

Clock::time_point deadline_after(double seconds) {
    return Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

// A file descriptor, closed when it goes out of scope (or by close(), once).
struct Fd {
    int fd = -1;
    explicit Fd(int descriptor) : fd(descriptor) {}
    Fd(Fd&& other) noexcept : fd(std::exchange(other.fd, -1)) {}
    Fd(const Fd&) = delete;
    Fd& operator=(const Fd&) = delete;
    ~Fd() { close(); }
    void close() {
        if (fd >= 0) ::close(std::exchange(fd, -1));
    }
};

Fd open_or_throw(const std::filesystem::path& path, int flags) {
    Fd file(::open(path.c_str(), flags | O_CLOEXEC, 0644));
    if (file.fd < 0) throw ocean::Error("cannot open " + path.string() + ": " + std::strerror(errno));
    return file;
}

// In a child just forked: a process group of its own (the limit kills everything it starts), death
// with the tool (Ctrl-C on ./ocean check leaves nothing running), no core file, and the signals a
// limit sends at their default. Async-signal-safe calls only: nothing else is safe after a fork.
void become_limited_child(pid_t parent) {
    ::setpgid(0, 0);
#if defined(__linux__)
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // macOS has no such call: there the time limit alone ends it
#endif
    if (::getppid() != parent) ::_exit(127);  // the tool died before prctl
    const rlimit no_core{0, 0};
    ::setrlimit(RLIMIT_CORE, &no_core);
    struct sigaction default_action {};
    default_action.sa_handler = SIG_DFL;
    for (int signal : {SIGXFSZ, SIGPIPE, SIGINT, SIGTERM}) ::sigaction(signal, &default_action, nullptr);
    sigset_t none;
    ::sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
}

// Waits for child `pid` until `deadline`, then kills its process group: at the limit the child
// itself, in any case whatever it started and left behind. The child is reaped only after that kill,
// so that its group's id cannot have been given to another process meanwhile.
Ending wait_until(pid_t pid, Clock::time_point deadline) {
    bool timed_out = false;
    for (;;) {
        siginfo_t info{};
        const int waited = ::waitid(P_PID, id_t(pid), &info, WEXITED | WNOHANG | WNOWAIT);
        if (waited == 0 && info.si_pid == pid) break;
        if (waited != 0 && errno != EINTR) break;
        if (Clock::now() >= deadline) {
            timed_out = true;
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    ::kill(-pid, SIGKILL);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (timed_out) return {Ending::TimedOut, 0};
    if (WIFSIGNALED(status)) return {Ending::Signalled, WTERMSIG(status)};
    return {Ending::Exited, WEXITSTATUS(status)};
}

void write_all(int fd, const std::string& text) {
    for (std::size_t written = 0; written < text.size();) {
        const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
        if (n > 0)
            written += std::size_t(n);
        else if (n < 0 && errno != EINTR)
            return;
    }
}

// What the child writes to `fd` until it closes it or `deadline` passes (then the child is stopped).
std::string read_until(int fd, Clock::time_point deadline) {
    std::string text;
    char buffer[4096];
    for (;;) {
        const auto left =
            std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
        if (left <= 0) break;
        pollfd readable{fd, POLLIN, 0};
        const int ready = ::poll(&readable, 1, int(std::min<long long>(left + 1, 60000)));
        if (ready < 0 && errno == EINTR) continue;
        if (ready < 0) break;
        if (ready == 0) continue;  // the loop's top decides whether time is left
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;  // the child is done writing
        if (text.size() < kMaxChildText) text.append(buffer, std::size_t(n));
    }
    return text;
}

// A pipe whose ends close at exec (pipe2 where there is one; macOS has only pipe and fcntl).
bool make_pipe(int ends[2]) {
#if defined(__linux__)
    return ::pipe2(ends, O_CLOEXEC) == 0;
#else
    if (::pipe(ends) != 0) return false;
    ::fcntl(ends[0], F_SETFD, FD_CLOEXEC);
    ::fcntl(ends[1], F_SETFD, FD_CLOEXEC);
    return true;
#endif
}

}  // namespace

Ending run_program(const std::vector<std::string>& argv, const std::filesystem::path& stdout_file,
                   const std::filesystem::path& stderr_file, double seconds, std::uint64_t max_file_bytes) {
    // Everything the child needs is made before the fork: after it, only async-signal-safe calls.
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    const Fd input = open_or_throw("/dev/null", O_RDONLY);
    const Fd output = open_or_throw(stdout_file, O_WRONLY | O_CREAT | O_TRUNC);
    const Fd errors =
        stderr_file == stdout_file ? Fd(-1) : open_or_throw(stderr_file, O_WRONLY | O_CREAT | O_TRUNC);
    rlimit file_size{};
    ::getrlimit(RLIMIT_FSIZE, &file_size);
    file_size.rlim_cur = file_size.rlim_max = std::min<rlim_t>(rlim_t(max_file_bytes), file_size.rlim_max);
    int exec_report[2];  // the child's errno when exec fails; closed by a successful exec (O_CLOEXEC)
    if (!make_pipe(exec_report))
        throw ocean::Error(std::string("cannot make a pipe: ") + std::strerror(errno));
    Fd report_in(exec_report[0]), report_out(exec_report[1]);

    const pid_t parent = ::getpid();
    const pid_t pid = ::fork();
    if (pid < 0) throw ocean::Error(std::string("cannot start a process: ") + std::strerror(errno));
    if (pid == 0) {
        become_limited_child(parent);
        ::setrlimit(RLIMIT_FSIZE, &file_size);
        ::dup2(input.fd, 0);
        ::dup2(output.fd, 1);
        ::dup2(errors.fd >= 0 ? errors.fd : output.fd, 2);
        ::execv(args[0], args.data());
        const int error = errno;
        [[maybe_unused]] const ssize_t n = ::write(report_out.fd, &error, sizeof error);
        ::_exit(127);
    }
    ::setpgid(pid, pid);  // the child does it too: whichever runs first, the group exists before a kill
    report_out.close();
    int exec_error = 0;
    ssize_t n;
    while ((n = ::read(report_in.fd, &exec_error, sizeof exec_error)) < 0 && errno == EINTR) {
    }
    if (n == ssize_t(sizeof exec_error)) {
        ::waitpid(pid, nullptr, 0);
        throw ocean::Error("cannot run " + argv[0] + ": " + std::strerror(exec_error));
    }
    return wait_until(pid, deadline_after(seconds));
}

ChildResult run_in_child(const std::function<std::string()>& task, double seconds) {
    int channel[2];
    if (!make_pipe(channel))
        throw ocean::Error(std::string("cannot make a pipe: ") + std::strerror(errno));
    Fd from_child(channel[0]), to_parent(channel[1]);
    std::fflush(nullptr);  // else what stdio holds would be written twice, once by each process
    const pid_t parent = ::getpid();
    const pid_t pid = ::fork();
    if (pid < 0) throw ocean::Error(std::string("cannot start a process: ") + std::strerror(errno));
    if (pid == 0) {
        from_child.close();
        become_limited_child(parent);
        std::string text;
        int code = 0;
        try {
            text = task();
        } catch (const std::exception& error) {
            text = error.what();
            code = kTaskThrew;
        }
        write_all(to_parent.fd, text);
        std::fflush(nullptr);
        ::_exit(code);  // not exit(): the parent's atexit handlers and static objects are not the child's
    }
    ::setpgid(pid, pid);
    to_parent.close();
    const Clock::time_point deadline = deadline_after(seconds);
    ChildResult result;
    result.text = read_until(from_child.fd, deadline);
    result.ending = wait_until(pid, deadline);
    if (result.ending.kind == Ending::Exited && result.ending.code == kTaskThrew)
        throw ocean::Error(result.text);
    return result;
}

std::string signal_name(int signal) {
    return "signal " + std::to_string(signal) + " (" + ::strsignal(signal) + ")";
}

}  // namespace exercises
