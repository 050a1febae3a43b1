// Writing output files so that a failure never leaves a half-written file behind (DESIGN.md §4):
// the content goes to a temporary name beside the target, which is renamed over it only once
// everything was written and flushed.
#pragma once

#include <tapeline/core/errors.h>

#include <cstdio>
#include <fstream>
#include <functional>
#include <string>
#include <system_error>

#include <unistd.h>

namespace tapeline {

/// Calls `write(stream)` on a temporary file next to `path`, then renames it to `path`.
/// If `write` throws or the stream fails, the temporary file is removed, `path` is left untouched
/// and the exception propagates (an I/O failure becomes InvalidInput naming the path).
inline void write_file_atomically(const std::string& path,
                                  const std::function<void(std::ostream&)>& write,
                                  bool binary = false) {
    const std::string tmp = path + ".tmp-" + std::to_string(::getpid());
    {
        std::ofstream out(tmp, binary ? std::ios::out | std::ios::binary | std::ios::trunc
                                      : std::ios::out | std::ios::trunc);
        if (!out) {
            throw InvalidInput(path + ": cannot open for writing");
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
            throw InvalidInput(path + ": write failed (disk full or no permission?)");
        }
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        std::error_code ec(errno, std::generic_category());
        std::remove(tmp.c_str());
        throw InvalidInput(path + ": cannot rename temporary file into place: " + ec.message());
    }
}

}  // namespace tapeline
