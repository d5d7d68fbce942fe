#pragma once
// Files in tests: a fresh directory for the files one test writes, and reading a file back whole.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

namespace ptview::testing {

// Named after the process and the test, so tests running in parallel never share one; removed
// when the test ends. A parameterized test's name holds a '/' ("Case/mesh"), which would make
// the directory a subdirectory whose empty parent nothing removes: it becomes '_'.
class ScratchFiles {
public:
    explicit ScratchFiles(const std::string& prefix) {
        const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
        std::string testName = test->name();
        std::replace(testName.begin(), testName.end(), '/', '_');
        dir_ = std::filesystem::temp_directory_path() / ("ptview_" + prefix + "_" + std::to_string(::getpid()) + "_" + testName);
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_);
    }
    ~ScratchFiles() {
        std::error_code ignored;
        std::filesystem::remove_all(dir_, ignored);
    }
    ScratchFiles(const ScratchFiles&) = delete;
    ScratchFiles& operator=(const ScratchFiles&) = delete;

    // Writes text (bytes, as given) to name in the directory and returns its path.
    std::filesystem::path write(const std::string& name, const std::string& text) const {
        const std::filesystem::path path = dir_ / name;
        std::ofstream(path, std::ios::binary) << text;
        return path;
    }

    const std::filesystem::path& directory() const { return dir_; }

private:
    std::filesystem::path dir_;
};

// The file's bytes; empty when it cannot be read (the assertion that follows says so).
inline std::string readFileBytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

} // namespace ptview::testing
