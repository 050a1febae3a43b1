#include <tapeline/bench/isolation.h>

#include <tapeline/core/errors.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace tapeline::bench {

namespace {

std::string format_gb(double gb) {
    std::ostringstream out;
    out << gb;
    return out.str();
}

bool write_all(int fd, const void* data, std::size_t n) {
    const char* p = static_cast<const char*>(data);
    while (n > 0) {
        const ssize_t w = ::write(fd, p, n);
        if (w < 0) {
            if (errno == EINTR) {
                continue;
            }
            return false;
        }
        p += w;
        n -= static_cast<std::size_t>(w);
    }
    return true;
}

}  // namespace

ChildOutcome run_isolated(const IsolatedWork& work, double timeout_seconds,
                          double memory_limit_gb) {
    int fds[2];
    if (::pipe(fds) != 0) {
        throw std::runtime_error("pipe() failed");
    }
    std::cout.flush();
    std::cerr.flush();
    const pid_t pid = ::fork();
    if (pid < 0) {
        throw std::runtime_error("fork() failed");
    }
    if (pid == 0) {
        ::close(fds[0]);
        if (memory_limit_gb > 0) {
            // An allocation beyond the limit becomes std::bad_alloc ("crash: out of memory")
            // instead of the machine's OOM killer picking a victim.
            const rlim_t bytes = static_cast<rlim_t>(memory_limit_gb * 1e9);
            const rlimit limit{bytes, bytes};
            ::setrlimit(RLIMIT_AS, &limit);
        }
        nlohmann::json fields;
        std::vector<double> distances;
        try {
            work(fields, distances);
            fields["status"] = "ok";
        } catch (const InvalidInput& e) {
            fields = {{"status", "invalid_input"}, {"message", e.what()}};
        } catch (const TopologyError& e) {
            fields = {{"status", "invalid_input"}, {"message", e.what()}};
        } catch (const SolverFailure& e) {
            fields = {{"status", "solver_failed"}, {"message", e.what()}};
        } catch (const std::bad_alloc&) {
            fields = {{"status", "crash"},
                      {"message", memory_limit_gb > 0 ? "out of memory (--memory-limit " +
                                                            format_gb(memory_limit_gb) + " GB)"
                                                      : std::string("out of memory")}};
        } catch (const std::exception& e) {
            fields = {{"status", "crash"}, {"message", std::string("exception: ") + e.what()}};
        }
        const std::string text = fields.dump();
        const std::uint64_t len = text.size(), n = distances.size();
        const bool ok = write_all(fds[1], &len, sizeof len) &&
                        write_all(fds[1], text.data(), len) && write_all(fds[1], &n, sizeof n) &&
                        write_all(fds[1], distances.data(), n * sizeof(double));
        ::close(fds[1]);
        ::_exit(ok ? 0 : 3);
    }
    ::close(fds[1]);
    std::string buffer;
    const auto start = std::chrono::steady_clock::now();
    bool timed_out = false;
    char chunk[1 << 16];
    for (;;) {
        int wait_ms = -1;
        if (timeout_seconds > 0) {
            const double left =
                timeout_seconds -
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            if (left <= 0) {
                timed_out = true;
                ::kill(pid, SIGKILL);
                break;
            }
            wait_ms = static_cast<int>(std::ceil(left * 1000));
        }
        pollfd p{fds[0], POLLIN, 0};
        const int r = ::poll(&p, 1, wait_ms);
        if (r < 0 && errno == EINTR) {
            continue;
        }
        if (r == 0) {
            continue;  // the deadline check above fires
        }
        const ssize_t got = ::read(fds[0], chunk, sizeof chunk);
        if (got < 0 && errno == EINTR) {
            continue;
        }
        if (got <= 0) {
            break;
        }
        buffer.append(chunk, static_cast<std::size_t>(got));
    }
    ::close(fds[0]);
    int wstatus = 0;
    rusage usage{};
    while (::wait4(pid, &wstatus, 0, &usage) < 0 && errno == EINTR) {
    }
    ChildOutcome outcome;
    outcome.peak_rss_bytes = static_cast<std::size_t>(usage.ru_maxrss) * 1024;  // Linux: KiB
    if (timed_out) {
        outcome.status = "timeout";
        outcome.message = "killed after " + std::to_string(timeout_seconds) + " s";
        return outcome;
    }
    if (WIFSIGNALED(wstatus)) {
        outcome.status = "crash";
        outcome.message = std::string("killed by signal ") + ::strsignal(WTERMSIG(wstatus));
        return outcome;
    }
    std::uint64_t len = 0, n = 0;
    if (buffer.size() < sizeof len) {
        outcome.status = "crash";
        outcome.message =
            "child exited with code " + std::to_string(WEXITSTATUS(wstatus)) + " without a result";
        return outcome;
    }
    std::memcpy(&len, buffer.data(), sizeof len);
    if (buffer.size() < sizeof len + len + sizeof n) {
        outcome.status = "crash";
        outcome.message = "truncated result from child";
        return outcome;
    }
    outcome.fields = nlohmann::json::parse(buffer.substr(sizeof len, len));
    std::memcpy(&n, buffer.data() + sizeof len + len, sizeof n);
    const std::size_t offset = sizeof len + len + sizeof n;
    if (buffer.size() != offset + n * sizeof(double)) {
        outcome.status = "crash";
        outcome.message = "truncated distances from child";
        return outcome;
    }
    outcome.distances.resize(n);
    std::memcpy(outcome.distances.data(), buffer.data() + offset, n * sizeof(double));
    outcome.status = outcome.fields.value("status", "crash");
    outcome.message = outcome.fields.value("message", "");
    return outcome;
}

}  // namespace tapeline::bench
