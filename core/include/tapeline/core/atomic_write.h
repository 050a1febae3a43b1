// Writing output files so that a failure never leaves a half-written file behind (DESIGN.md §4):
// the content goes to a temporary name beside the target, which is renamed over it only once
// everything was written and flushed. A command with several outputs checks every path before it
// writes any (OutputFiles) and renames them all at the end, so that a failure leaves none.
//
// Temporary names are `.tapeline-tmp-PID-N.EXT` in the target's directory: short whatever the
// target's name (a 255-byte name still gets a temporary), hidden, and recognisable, so that those
// of a killed process (whose PID no longer runs) are removed by the next write into the directory.
#pragma once

#include <tapeline/core/errors.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <mutex>
#include <set>
#include <string>
#include <system_error>
#include <vector>

#include <signal.h>
#include <unistd.h>

namespace tapeline {

inline constexpr const char* temporary_file_prefix = ".tapeline-tmp-";

namespace internal {

inline std::filesystem::path output_directory(const std::string& path) {
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    return parent.empty() ? std::filesystem::path(".") : parent;
}

/// Removes `.tapeline-tmp-PID-*` files in `dir` whose process no longer exists (once per
/// directory and process; a PID that runs again, perhaps another program, keeps its files).
inline void remove_stale_temporaries(const std::filesystem::path& dir) {
    static std::mutex mutex;
    static std::set<std::string> done;
    {
        const std::lock_guard<std::mutex> lock(mutex);
        if (!done.insert(dir.string()).second) {
            return;
        }
    }
    std::error_code ec;
    const std::string prefix = temporary_file_prefix;
    for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.compare(0, prefix.size(), prefix) != 0) {
            continue;
        }
        const std::size_t dash = name.find('-', prefix.size());
        if (dash == std::string::npos || dash == prefix.size()) {
            continue;
        }
        long pid = 0;
        try {
            pid = std::stol(name.substr(prefix.size(), dash - prefix.size()));
        } catch (...) {
            continue;
        }
        if (pid > 0 && pid != long(::getpid()) && ::kill(pid_t(pid), 0) != 0 && errno == ESRCH) {
            std::error_code ignored;
            std::filesystem::remove(it->path(), ignored);
        }
    }
}

/// A fresh temporary name beside `path`, with its extension (writers choose the format by it).
inline std::string temporary_path_for(const std::string& path) {
    static std::atomic<unsigned> counter{0};
    const std::filesystem::path dir = output_directory(path);
    remove_stale_temporaries(dir);
    std::string ext = std::filesystem::path(path).extension().string();
    if (ext.size() > 16) {
        ext.clear();
    }
    const std::string name =
        temporary_file_prefix + std::to_string(::getpid()) + "-" + std::to_string(counter++) + ext;
    return (std::filesystem::path(path).parent_path() / name).string();
}

}  // namespace internal

/// Refuses, before anything is written, an output path that cannot be written: a directory, a
/// missing or unwritable directory, a file name longer than the file system allows.
///
/// \throws InvalidInput naming `path` and the reason.
inline void check_output_path(const std::string& path) {
    namespace fs = std::filesystem;
    if (path.empty()) {
        throw InvalidInput("an output path is empty");
    }
    std::error_code ec;
    if (fs::is_directory(path, ec)) {
        throw InvalidInput(path + ": is a directory; give a file name");
    }
    const fs::path dir = internal::output_directory(path);
    if (!fs::exists(dir, ec)) {
        throw InvalidInput(path + ": directory " + dir.string() + " does not exist");
    }
    if (!fs::is_directory(dir, ec)) {
        throw InvalidInput(path + ": " + dir.string() + " is not a directory");
    }
    if (::access(dir.c_str(), W_OK) != 0) {
        throw InvalidInput(path + ": directory " + dir.string() + " is not writable");
    }
    const long name_max = ::pathconf(dir.c_str(), _PC_NAME_MAX);
    const std::string name = fs::path(path).filename().string();
    if (name_max > 0 && name.size() > std::size_t(name_max)) {
        throw InvalidInput(path + ": the file name has " + std::to_string(name.size()) +
                           " bytes, more than the " + std::to_string(name_max) +
                           " this file system allows");
    }
}

/// check_output_path for each non-empty path, and no path given twice.
///
/// \throws InvalidInput for the first path refused, or a path given twice.
inline void check_output_paths(const std::vector<std::string>& paths) {
    std::set<std::string> seen;
    for (const std::string& p : paths) {
        if (p.empty()) {
            continue;
        }
        check_output_path(p);
        std::error_code ec;
        const std::string canonical = std::filesystem::weakly_canonical(p, ec).string();
        if (!seen.insert(ec ? p : canonical).second) {
            throw InvalidInput(p + ": given as two different outputs");
        }
    }
}

namespace internal {

inline void write_stream_to(const std::string& target, const std::string& tmp,
                            const std::function<void(std::ostream&)>& write, bool binary) {
    std::ofstream out(tmp, binary ? std::ios::out | std::ios::binary | std::ios::trunc
                                  : std::ios::out | std::ios::trunc);
    if (!out) {
        const std::error_code ec(errno, std::generic_category());
        throw InvalidInput(target + ": cannot open for writing: " + ec.message());
    }
    try {
        write(out);
        out.flush();
    } catch (...) {
        out.close();
        std::remove(tmp.c_str());
        throw;
    }
    if (!out) {
        out.close();
        std::remove(tmp.c_str());
        throw InvalidInput(target + ": write failed (disk full or no permission?)");
    }
}

inline void rename_into_place(const std::string& tmp, const std::string& path) {
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        const std::error_code ec(errno, std::generic_category());
        std::remove(tmp.c_str());
        throw InvalidInput(path + ": cannot rename temporary file into place: " + ec.message());
    }
}

}  // namespace internal

/// Calls `write(stream)` on a temporary file next to `path`, then renames it to `path`.
/// If `write` throws or the stream fails, the temporary file is removed, `path` is left untouched
/// and the exception propagates (an I/O failure becomes InvalidInput naming the path).
inline void write_file_atomically(const std::string& path,
                                  const std::function<void(std::ostream&)>& write,
                                  bool binary = false) {
    const std::string tmp = internal::temporary_path_for(path);
    internal::write_stream_to(path, tmp, write, binary);
    internal::rename_into_place(tmp, path);
}

/// The outputs of one command: every path is checked up front (constructor), each is written to
/// a temporary name (`temporary(path)` for writers that take a path, or `write`), and `commit()`
/// renames them all into place. Without commit() (an exception), the temporaries are removed and
/// no target is touched.
class OutputFiles {
public:
    /// Checks every non-empty path (see check_output_paths).
    ///
    /// \throws InvalidInput on a path that cannot be written or a path given twice.
    explicit OutputFiles(const std::vector<std::string>& paths) { check_output_paths(paths); }
    ~OutputFiles() {
        for (const auto& [tmp, path] : pending_) {
            std::remove(tmp.c_str());
        }
    }
    OutputFiles(const OutputFiles&) = delete;
    OutputFiles& operator=(const OutputFiles&) = delete;

    /// The temporary name to write `path`'s content to; renamed to `path` by commit().
    std::string temporary(const std::string& path) {
        pending_.push_back({internal::temporary_path_for(path), path});
        return pending_.back().first;
    }
    /// Writes `path`'s content through `write` to its temporary name now.
    ///
    /// \throws InvalidInput when the temporary cannot be opened or the write fails; exceptions
    ///         of `write` propagate.
    void write(const std::string& path, const std::function<void(std::ostream&)>& write,
               bool binary = false) {
        internal::write_stream_to(path, temporary(path), write, binary);
    }
    /// Renames every temporary into place, in the order they were made.
    ///
    /// \throws InvalidInput when a rename fails (the remaining temporaries are removed).
    void commit() {
        while (!pending_.empty()) {
            internal::rename_into_place(pending_.front().first, pending_.front().second);
            pending_.erase(pending_.begin());
        }
    }

private:
    std::vector<std::pair<std::string, std::string>> pending_;  // temporary, target
};

}  // namespace tapeline
