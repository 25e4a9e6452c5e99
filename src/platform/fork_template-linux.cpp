// Linux: fork (dup_mmap) copies a mapping's page-table entries only when the mapping has an
// anon_vma, that is once one of its pages was written privately; a private mapping of a file
// that was only read or run is left to the child's page faults (vma_needs_copy). Writing one
// byte of such a mapping (its own value, under a brief PROT_WRITE) gives it an anon_vma; from
// then on each fork copies the entries this process has, which cover most of what a worker
// runs: a worker of the fork server took 75 page faults before, about 35 after.
#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "platform/fork_template.h"

namespace robottestingframework {
namespace platform {

namespace {

struct Mapping {
    std::uintptr_t start = 0;
    std::uintptr_t end = 0;
    int protection = 0;
    bool fileStart = false;  // maps the file's first page (its ELF header)
};

std::string readAll(const char* path) {
    std::string text;
    int fd = ::open(path, O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
        return text;
    }
    char buffer[8192];
    ssize_t n;
    while ((n = ::read(fd, buffer, sizeof buffer)) > 0) {
        text.append(buffer, static_cast<std::size_t>(n));
    }
    ::close(fd);
    return text;
}

// The private, read-only mappings of files that hold no private page yet: the program's and
// its libraries' code, read-only data and symbol tables. (Their relocated data, made read-only
// after relocation, holds private pages: it has its anon_vma already.)
std::vector<Mapping> readOnlyFileMappings() {
    std::vector<Mapping> found;
    const std::string smaps = readAll("/proc/self/smaps");
    bool candidate = false;
    Mapping mapping;
    std::size_t line = 0;
    while (line < smaps.size()) {
        std::size_t next = smaps.find('\n', line);
        if (next == std::string::npos) {
            next = smaps.size();
        }
        const std::string entry = smaps.substr(line, next - line);
        line = next + 1;
        if (entry.compare(0, 10, "Anonymous:") == 0) {
            if (candidate && std::strtoul(entry.c_str() + 10, nullptr, 10) == 0) {
                found.push_back(mapping);
            }
            candidate = false;
            continue;
        }
        // A mapping's first line: start-end perms offset dev inode path. Other lines are
        // "Name: value" fields of the current mapping.
        char* rest = nullptr;
        const std::uintptr_t start = std::strtoull(entry.c_str(), &rest, 16);
        if (rest == nullptr || *rest != '-') {
            continue;
        }
        candidate = false;
        mapping = Mapping();
        mapping.start = start;
        mapping.end = std::strtoull(rest + 1, &rest, 16);
        if (rest == nullptr || std::strlen(rest) < 6) {
            continue;
        }
        const char* perms = rest + 1;
        mapping.protection = PROT_READ | (perms[2] == 'x' ? PROT_EXEC : 0);
        mapping.fileStart = std::strtoull(perms + 4, nullptr, 16) == 0;
        candidate = perms[0] == 'r' && perms[1] == '-' && perms[3] == 'p' &&
                    entry.find(" /") != std::string::npos && mapping.end > mapping.start;
    }
    return found;
}

}  // namespace

void shareCodePagesWithForks() {
    // A writable private mapping is charged to the commit limit, and stays charged (in each
    // fork too): where that limit is enforced (overcommit_memory 2), leave it alone.
    if (readAll("/proc/sys/vm/overcommit_memory").compare(0, 1, "2") == 0) {
        return;
    }
    for (const Mapping& mapping : readOnlyFileMappings()) {
        void* start = reinterpret_cast<void*>(mapping.start);
        const std::size_t length = mapping.end - mapping.start;
        if (::mprotect(start, length, mapping.protection | PROT_WRITE) != 0) {
            continue;  // refused (a W^X policy): this mapping is faulted in by each child
        }
        volatile unsigned char* first = static_cast<volatile unsigned char*>(start);
        *first = *first;
        ::mprotect(start, length, mapping.protection);
        // A core dump writes whole every mapping holding a private page: code and read-only
        // data stay out of the dumps of this process and its forks as before (the mapping of
        // the file's first page is kept: it names the file, its build-id).
        if (!mapping.fileStart) {
            ::madvise(start, length, MADV_DONTDUMP);
        }
    }
}

}  // namespace platform
}  // namespace robottestingframework
