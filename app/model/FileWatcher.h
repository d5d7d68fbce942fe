#pragma once
// Notices when files change on disk, for hot reload. It polls (size and modification time)
// rather than using inotify: it is portable, and it sees an editor's save-by-rename (a new file
// under the old name) like any other write. A file caught mid-write is reported again when the
// write finishes, so the caller just reloads on every report and shrugs off a failed parse.

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

namespace ptview {

class FileWatcher {
public:
    using Clock = std::chrono::steady_clock;

    explicit FileWatcher(Clock::duration interval = std::chrono::milliseconds(250)) : interval_(interval) {}

    // Replaces the watched set and records each file's current state, so that none of them is
    // reported until it changes again.
    void watch(std::vector<std::filesystem::path> files);

    // The watched files whose state (existence, size, modification time) changed since the last
    // check, in the order given to watch(). Checks the disk at most once per interval: calls in
    // between return {} without touching it. Never throws: a file that cannot be read counts as
    // missing. The overload taking `now` lets tests step the clock instead of sleeping.
    std::vector<std::filesystem::path> poll() { return poll(Clock::now()); }
    std::vector<std::filesystem::path> poll(Clock::time_point now);

private:
    struct FileState {
        bool exists = false;
        std::filesystem::file_time_type modified{};
        std::uintmax_t size = 0;

        bool operator==(const FileState& o) const
        {
            return exists == o.exists && modified == o.modified && size == o.size;
        }
    };
    struct WatchedFile {
        std::filesystem::path path;
        FileState state;
    };

    static FileState stateOf(const std::filesystem::path& path);

    Clock::duration interval_;
    std::vector<WatchedFile> files_;
    std::optional<Clock::time_point> lastCheck_; // none: the next poll checks whatever the time
};

} // namespace ptview
