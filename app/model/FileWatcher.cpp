#include <ptview/model/FileWatcher.h>

namespace ptview {

void FileWatcher::watch(std::vector<std::filesystem::path> files)
{
    files_.clear();
    for (std::filesystem::path& path : files) {
        FileState state = stateOf(path);
        files_.push_back({std::move(path), state});
    }
    lastCheck_.reset();
}

std::vector<std::filesystem::path> FileWatcher::poll(Clock::time_point now)
{
    if (lastCheck_ && now - *lastCheck_ < interval_) return {};
    lastCheck_ = now;

    std::vector<std::filesystem::path> changed;
    for (WatchedFile& file : files_) {
        FileState state = stateOf(file.path);
        if (state == file.state) continue;
        file.state = state;
        changed.push_back(file.path);
    }
    return changed;
}

FileWatcher::FileState FileWatcher::stateOf(const std::filesystem::path& path)
{
    // The error_code overloads, since a file may vanish between any two of these calls (an
    // editor's rename); a failure anywhere reads as "missing" and the next poll sees it again.
    std::error_code error;
    FileState state;
    state.modified = std::filesystem::last_write_time(path, error);
    if (error) return {};
    state.size = std::filesystem::file_size(path, error);
    if (error) return {};
    state.exists = true;
    return state;
}

} // namespace ptview
