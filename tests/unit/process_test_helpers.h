// Helpers of the process fixture's unit tests: a fresh folder per test under the build tree, and
// a look at the process table.
#pragma once

#include <dirent.h>
#include <signal.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "build_paths.h"

namespace rtf_process_test {

// An empty folder named after the running test, under the build tree.
inline std::filesystem::path freshFolder() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::filesystem::path base = build_paths::unitTestTmpDir();
    std::filesystem::path folder =
        base / "process_fixture" / (std::string(info->test_suite_name()) + "." + info->name());
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

inline std::filesystem::path writeFile(const std::filesystem::path& path, const std::string& text) {
    std::ofstream(path) << text;
    return path;
}

// Pids of the live (not zombie) processes whose environment holds `entry` (NAME=VALUE).
inline std::vector<int> processesWith(const std::string& entry) {
    std::vector<int> found;
    DIR* proc = ::opendir("/proc");
    if (proc == nullptr) {
        return found;
    }
    while (dirent* e = ::readdir(proc)) {
        const int pid = std::atoi(e->d_name);
        if (pid <= 0) {
            continue;
        }
        const std::string dir = std::string("/proc/") + e->d_name;
        std::ifstream stat(dir + "/stat");
        std::string statLine;
        std::getline(stat, statLine);
        const auto close = statLine.rfind(')');
        if (close != std::string::npos && close + 2 < statLine.size() &&
            statLine[close + 2] == 'Z') {
            continue;
        }
        std::ifstream env(dir + "/environ", std::ios::binary);
        std::string content((std::istreambuf_iterator<char>(env)),
                            std::istreambuf_iterator<char>());
        std::string padded = std::string(1, '\0') + content + std::string(1, '\0');
        if (padded.find(std::string(1, '\0') + entry + std::string(1, '\0')) != std::string::npos) {
            found.push_back(pid);
        }
    }
    ::closedir(proc);
    return found;
}

inline bool alive(int pid) {
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string line;
    if (!std::getline(stat, line)) {
        return false;
    }
    const auto close = line.rfind(')');
    return close == std::string::npos || close + 2 >= line.size() || line[close + 2] != 'Z';
}

}  // namespace rtf_process_test
