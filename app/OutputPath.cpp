#include "OutputPath.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>

namespace ptview {

std::optional<std::string> checkOutputPath(const std::string& path, std::initializer_list<const char*> allowed) {
    std::filesystem::path out(path);
    std::string extension = out.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (std::none_of(allowed.begin(), allowed.end(), [&](const char* e) { return extension == e; })) {
        std::string list;
        for (const char* e : allowed) list += (list.empty() ? "" : " or ") + std::string(e);
        std::cerr << "ptview: " << path << ": unsupported output format (use " << list << ")\n";
        return std::nullopt;
    }
    if (!out.parent_path().empty() && !std::filesystem::is_directory(out.parent_path())) {
        std::cerr << "ptview: " << path << ": directory " << out.parent_path() << " does not exist\n";
        return std::nullopt;
    }
    return extension;
}

} // namespace ptview
