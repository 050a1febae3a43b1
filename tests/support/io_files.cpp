// Plain file helpers for the mesh I/O tests.
#include <tapeline_test/io.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <unistd.h>

namespace tapeline_test {

namespace {

std::filesystem::path process_dir() {
    return std::filesystem::temp_directory_path() / ("tapeline_io_" + std::to_string(::getpid()));
}

/// Removes this process's test files at exit (leave them with TAPELINE_KEEP_TEST_FILES=1).
struct Cleanup {
    ~Cleanup() {
        if (std::getenv("TAPELINE_KEEP_TEST_FILES") == nullptr) {
            std::error_code ignored;
            std::filesystem::remove_all(process_dir(), ignored);
        }
    }
} cleanup;

}  // namespace

std::string temp_dir(const std::string& name) {
    const std::filesystem::path dir = process_dir() / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir.string();
}

void write_bytes(const std::string& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) {
        throw std::runtime_error("test helper cannot write " + path);
    }
}

bool file_exists(const std::string& path) {
    return std::filesystem::exists(path);
}

}  // namespace tapeline_test
