// platform::shareCodePagesWithForks (Linux): a fork starts with the parent's page-table entries
// of the program's code, instead of faulting them in again; nothing else about the mappings
// changes.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "platform/fork_template.h"

namespace {

using robottestingframework::platform::shareCodePagesWithForks;

// The lines of /proc/self/maps that map files: address range, protection, offset, file.
std::string fileMappings() {
    std::ifstream maps("/proc/self/maps");
    std::string line;
    std::string lines;
    while (std::getline(maps, line)) {
        if (line.find(" /") != std::string::npos) {
            lines += line + "\n";
        }
    }
    return lines;
}

// The resident size (kB) of the mapping holding `address`, from /proc/self/smaps.
long residentKbAt(std::uintptr_t address) {
    std::ifstream smaps("/proc/self/smaps");
    std::string line;
    bool inside = false;
    while (std::getline(smaps, line)) {
        char* rest = nullptr;
        const std::uintptr_t start = std::strtoull(line.c_str(), &rest, 16);
        if (rest != nullptr && *rest == '-') {
            const std::uintptr_t end = std::strtoull(rest + 1, nullptr, 16);
            inside = start <= address && address < end;
        } else if (inside && line.compare(0, 4, "Rss:") == 0) {
            return std::strtol(line.c_str() + 4, nullptr, 10);
        }
    }
    return -1;
}

// In a fork: the resident size of the mapping holding `address`, before the child runs
// anything but this.
long residentKbInAFork(std::uintptr_t address) {
    int pipeFds[2];
    EXPECT_EQ(::pipe(pipeFds), 0);
    pid_t pid = ::fork();
    if (pid == 0) {
        long kb = residentKbAt(address);
        ssize_t written = ::write(pipeFds[1], &kb, sizeof kb);
        ::_exit(written == sizeof kb ? 0 : 1);
    }
    ::close(pipeFds[1]);
    long kb = -1;
    EXPECT_EQ(::read(pipeFds[0], &kb, sizeof kb), static_cast<ssize_t>(sizeof kb));
    ::close(pipeFds[0]);
    int status = 0;
    ::waitpid(pid, &status, 0);
    return kb;
}

int codeOfThisTest() {
    return 42;
}

TEST(ForkTemplate, AForkStartsWithTheCodePagesThisProcessHas) {
    const auto code = reinterpret_cast<std::uintptr_t>(&codeOfThisTest);
    // Without it, the fork maps only the pages it touches itself (reading smaps: a few
    // fault-around blocks of 64 kB); this test program has run far more of its code than that.
    const long before = residentKbInAFork(code);
    shareCodePagesWithForks();
    const long parent = residentKbAt(code);
    const long after = residentKbInAFork(code);
    ASSERT_LT(before, parent) << "the test program has not run enough of its code to tell";
    EXPECT_GE(after, parent) << "the fork mapped " << after << " kB of the " << parent
                             << " kB its parent had (" << before << " kB before)";
    EXPECT_EQ(codeOfThisTest(), 42);
}

TEST(ForkTemplate, MappingsKeepTheirRangesAndProtections) {
    const std::string before = fileMappings();
    shareCodePagesWithForks();
    EXPECT_EQ(fileMappings(), before);
}

}  // namespace
