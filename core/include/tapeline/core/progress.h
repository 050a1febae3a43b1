// Progress of long work on stderr: one small reporter for every loop that can run longer than a
// few seconds (distance fields, benchmarks, grading generations, batch imports, the drape).
//
// Policy (process-wide, set once by the program): by default a line is drawn only when stderr is a
// terminal; `ProgressMode::always` also writes to a pipe or a log file (one line per update, at a
// lower rate), `ProgressMode::never` is silent (`--quiet`). A program that embeds the library can
// route the events elsewhere with set_progress_sink(). Updates are rate-limited and cheap enough
// to call once per item from TBB worker threads.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>

#include <unistd.h>

namespace tapeline {

/// When progress is drawn: on a terminal only, always, or never.
enum class ProgressMode { automatic, always, never };

/// One update: the phase ("exact-mmp distances"), items done and the total (0 when unknown),
/// seconds since the phase began, an optional note ("residual 3.1e-4"), and whether the phase
/// has finished.
struct ProgressEvent {
    std::string phase;      ///< what the loop does
    std::size_t done = 0;   ///< items done
    std::size_t total = 0;  ///< total items, 0 when unknown
    double seconds = 0.0;   ///< seconds since the phase began
    std::string note;       ///< extra figures, may be empty
    bool finished = false;  ///< the last event of the phase
};

/// Receiver of progress events (tests, a GUI, a log).
using ProgressSink = std::function<void(const ProgressEvent&)>;

/// Thrown by Progress::advance() and Progress::set() after request_cancel(): long work stops at
/// its next progress point (a GUI's cancel button, Ctrl-C in the Python module).
class Cancelled : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

namespace internal {
struct ProgressSettings {
    std::mutex mutex;
    ProgressMode mode = ProgressMode::automatic;
    ProgressSink sink;
};
inline ProgressSettings& progress_settings() {
    static ProgressSettings s;
    return s;
}

/// The process-wide cancel request (a lock-free flag: safe to set from a signal handler).
inline std::atomic<bool>& cancel_flag() noexcept {
    static std::atomic<bool> requested{false};
    return requested;
}
}  // namespace internal

/// Asks every running phase to stop: its next advance() or set() throws Cancelled. Safe to call
/// from a signal handler or another thread.
inline void request_cancel() noexcept {
    internal::cancel_flag().store(true, std::memory_order_relaxed);
}
/// Withdraws a cancel request (before starting new work).
inline void clear_cancel() noexcept {
    internal::cancel_flag().store(false, std::memory_order_relaxed);
}

/// Sets when progress is drawn on stderr (the command-line tool: `--quiet` → never,
/// `--progress` → always).
inline void set_progress_mode(ProgressMode mode) {
    auto& s = internal::progress_settings();
    std::lock_guard<std::mutex> lock(s.mutex);
    s.mode = mode;
}

/// The mode set by set_progress_mode (automatic by default).
inline ProgressMode progress_mode() {
    auto& s = internal::progress_settings();
    std::lock_guard<std::mutex> lock(s.mutex);
    return s.mode;
}

/// Routes every event to `sink` instead of stderr (an empty function restores stderr).
inline void set_progress_sink(ProgressSink sink) {
    auto& s = internal::progress_settings();
    std::lock_guard<std::mutex> lock(s.mutex);
    s.sink = std::move(sink);
}

/// A phase of long work. Construct it before the loop, call advance() per item (any thread),
/// note() for extra figures; the destructor (or finish()) closes the line. Reports nothing for
/// a phase that ends before `delay` seconds, so short calls stay silent.
class Progress {
public:
    /// \param phase what the loop does, shown in front of the counts.
    /// \param total the number of items, 0 when unknown.
    /// \param delay seconds before the first report.
    explicit Progress(std::string phase, std::size_t total = 0, double delay = 1.0)
        : phase_(std::move(phase)),
          total_(total),
          delay_(delay),
          start_(std::chrono::steady_clock::now()) {
        auto& s = internal::progress_settings();
        std::lock_guard<std::mutex> lock(s.mutex);
        sink_ = s.sink;
        if (!sink_) {
            const bool terminal = ::isatty(::fileno(stderr)) != 0;
            enabled_ =
                s.mode == ProgressMode::always || (s.mode == ProgressMode::automatic && terminal);
            terminal_ = terminal;
        } else {
            enabled_ = s.mode != ProgressMode::never;
        }
        // A terminal line is redrawn in place often; a log gets a line every few seconds.
        interval_ = terminal_ && !sink_ ? 0.2 : 5.0;
    }
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;
    ~Progress() { finish(); }

    /// False when nothing will be reported (mode never, or automatic off a terminal).
    bool enabled() const { return enabled_; }

    /// Counts `n` more items done; thread-safe.
    /// \throws Cancelled after request_cancel().
    void advance(std::size_t n = 1) {
        check_cancel();
        const std::size_t done = done_.fetch_add(n, std::memory_order_relaxed) + n;
        if (enabled_)
            maybe_report(done, false);
    }
    /// Sets the number of items done.
    /// \throws Cancelled after request_cancel().
    void set(std::size_t done) {
        check_cancel();
        done_.store(done, std::memory_order_relaxed);
        if (enabled_)
            maybe_report(done, false);
    }
    /// Sets the total once it is known.
    void set_total(std::size_t total) { total_ = total; }
    /// Extra figures shown after the counts in the next report.
    void note(std::string text) {
        if (!enabled_)
            return;
        std::lock_guard<std::mutex> lock(mutex_);
        note_ = std::move(text);
    }
    /// Closes the phase: a last report if anything was reported; idempotent.
    void finish() {
        if (finished_.exchange(true))
            return;
        if (enabled_ && reported_)
            maybe_report(done_.load(), true);
    }

private:
    void check_cancel() const {
        if (internal::cancel_flag().load(std::memory_order_relaxed))
            throw Cancelled(phase_ + ": cancelled");
    }
    double elapsed() const {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }
    void maybe_report(std::size_t done, bool final_line) {
        const double t = elapsed();
        if (!final_line && (t < delay_ || t - last_ < interval_))
            return;
        std::unique_lock<std::mutex> lock(mutex_, std::try_to_lock);
        if (!lock.owns_lock()) {
            if (!final_line)
                return;
            lock.lock();
        }
        if (!final_line && t - last_ < interval_)
            return;
        last_ = t;
        reported_ = true;
        ProgressEvent e{phase_, done, total_, t, note_, final_line};
        if (sink_) {
            sink_(e);
            return;
        }
        char line[256];
        if (total_ > 0) {
            std::snprintf(line, sizeof line, "%s: %zu/%zu (%.0f%%) %.1f s", phase_.c_str(), done,
                          total_, 100.0 * double(done) / double(total_), t);
        } else {
            std::snprintf(line, sizeof line, "%s: %zu %.1f s", phase_.c_str(), done, t);
        }
        std::string text = line;
        if (!note_.empty())
            text += "  " + note_;
        if (terminal_) {
            std::fprintf(stderr, "\r\033[K%s%s", text.c_str(), final_line ? "\n" : "");
        } else {
            std::fprintf(stderr, "%s%s\n", text.c_str(), final_line ? " done" : "");
        }
        std::fflush(stderr);
    }

    std::string phase_;
    std::size_t total_;
    double delay_;
    std::chrono::steady_clock::time_point start_;
    ProgressSink sink_;
    bool enabled_ = false;
    bool terminal_ = false;
    double interval_ = 0.2;
    std::atomic<std::size_t> done_{0};
    std::atomic<bool> finished_{false};
    std::mutex mutex_;
    std::string note_;
    double last_ = -1e300;
    bool reported_ = false;
};

}  // namespace tapeline
