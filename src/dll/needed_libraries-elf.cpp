#include "dll/needed_libraries.h"

#include <fcntl.h>
#include <gelf.h>
#include <libelf.h>
#include <unistd.h>

namespace robottestingframework {
namespace plugin {

namespace {

// The DT_NEEDED names of the dynamic section `section` (its strings in section `strings`).
void neededOf(Elf* elf, Elf_Scn* section, std::size_t strings, std::vector<std::string>& names) {
    GElf_Shdr header;
    Elf_Data* data = elf_getdata(section, nullptr);
    if (gelf_getshdr(section, &header) == nullptr || data == nullptr || header.sh_entsize == 0) {
        return;
    }
    const std::size_t count = header.sh_size / header.sh_entsize;
    for (std::size_t i = 0; i < count; ++i) {
        GElf_Dyn entry;
        if (gelf_getdyn(data, static_cast<int>(i), &entry) == nullptr) {
            return;
        }
        if (entry.d_tag == DT_NULL) {
            return;
        }
        if (entry.d_tag == DT_NEEDED) {
            const char* name = elf_strptr(elf, strings, entry.d_un.d_val);
            if (name != nullptr) {
                names.emplace_back(name);
            }
        }
    }
}

}  // namespace

std::vector<std::string> neededLibraries(const std::string& path) {
    std::vector<std::string> names;
    if (elf_version(EV_CURRENT) == EV_NONE) {
        return names;
    }
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
        return names;
    }
    Elf* elf = elf_begin(fd, ELF_C_READ, nullptr);
    if (elf != nullptr && elf_kind(elf) == ELF_K_ELF) {
        Elf_Scn* section = nullptr;
        while ((section = elf_nextscn(elf, section)) != nullptr) {
            GElf_Shdr header;
            if (gelf_getshdr(section, &header) != nullptr && header.sh_type == SHT_DYNAMIC) {
                neededOf(elf, section, header.sh_link, names);
                break;
            }
        }
    }
    if (elf != nullptr) {
        elf_end(elf);
    }
    ::close(fd);
    return names;
}

}  // namespace plugin
}  // namespace robottestingframework
