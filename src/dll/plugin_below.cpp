#include "dll/plugin_below.h"

#include <algorithm>
#include <deque>
#include <filesystem>
#include <system_error>
#include <utility>

namespace robottestingframework {
namespace plugin {

namespace fs = std::filesystem;

namespace {

constexpr int maxDepth = 6;
constexpr int maxEntries = 20000;

}  // namespace

std::string findBelowWorkingFolder(const std::vector<std::string>& names) {
    std::deque<std::pair<fs::path, int>> folders{{fs::path("."), 0}};
    int entries = 0;
    while (!folders.empty() && entries < maxEntries) {
        const auto [folder, depth] = folders.front();
        folders.pop_front();
        std::vector<fs::directory_entry> inside;
        std::error_code error;
        for (fs::directory_iterator
                 it(folder, fs::directory_options::skip_permission_denied, error),
             end;
             !error && it != end && entries < maxEntries; it.increment(error)) {
            inside.push_back(*it);
            ++entries;
        }
        std::sort(inside.begin(), inside.end(),
                  [](const fs::directory_entry& a, const fs::directory_entry& b) {
                      return a.path().filename() < b.path().filename();
                  });
        for (const auto& entry : inside) {
            const std::string name = entry.path().filename().string();
            std::error_code ignored;
            if (entry.is_regular_file(ignored) &&
                std::find(names.begin(), names.end(), name) != names.end()) {
                return entry.path().lexically_normal().generic_string();
            }
        }
        for (const auto& entry : inside) {
            const std::string name = entry.path().filename().string();
            std::error_code ignored;
            if (depth + 1 < maxDepth && !name.empty() && name[0] != '.' &&
                !entry.is_symlink(ignored) && entry.is_directory(ignored)) {
                folders.emplace_back(entry.path(), depth + 1);
            }
        }
    }
    return {};
}

}  // namespace plugin
}  // namespace robottestingframework
