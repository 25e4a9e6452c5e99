#include "dll/shared_library.h"

#include <dlfcn.h>

#include <cstdlib>
#include <set>
#include <sstream>

#include "dll/library_naming.h"
#include "dll/rtf2_library.h"

namespace robottestingframework {
namespace plugin {

namespace {

std::string lastError(const char* fallback) {
    const char* text = ::dlerror();
    return text != nullptr ? text : fallback;
}

void splitInto(const std::string& text, char separator, std::vector<std::string>& out) {
    std::stringstream stream(text);
    std::string item;
    while (std::getline(stream, item, separator)) {
        if (!item.empty()) {
            out.push_back(item);
        }
    }
}

std::string ownFolder() {
    Dl_info info{};
    if (::dladdr(reinterpret_cast<void*>(&ownFolder), &info) == 0 || info.dli_fname == nullptr) {
        return {};
    }
    std::string path = info.dli_fname;
    std::size_t slash = path.rfind('/');
    return slash == std::string::npos ? std::string() : path.substr(0, slash);
}

}  // namespace

SharedLibrary::~SharedLibrary() {
    close();
}

bool SharedLibrary::open(const std::string& path) {
    close();
    // Never into this process: RTF 2.x's library would clash with this one (SIGABRT at best).
    const std::string rtf2 = rtf2LibraryNeeded(path);
    if (!rtf2.empty()) {
        error_ = builtAgainstRtf2(path, rtf2);
        return false;
    }
    ::dlerror();
    // RTLD_LOCAL: two plug-ins defining the same class names do not clash.
    handle_ = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle_ == nullptr) {
        error_ = lastError("unknown dlopen error");
        return false;
    }
    error_.clear();
    return true;
}

void SharedLibrary::close() {
    if (handle_ != nullptr) {
        ::dlclose(handle_);
        handle_ = nullptr;
    }
}

void* SharedLibrary::symbol(const char* name) {
    if (handle_ == nullptr) {
        error_ = "the library is not open";
        return nullptr;
    }
    ::dlerror();
    void* address = ::dlsym(handle_, name);
    if (address == nullptr) {
        error_ = lastError("symbol not found");
    }
    return address;
}

std::vector<std::string> SharedLibrary::searchPath() {
    std::vector<std::string> folders;
    if (const char* env = std::getenv(libraryPathVariable())) {
        splitInto(env, ':', folders);
    }
    std::string own = ownFolder();
    if (!own.empty()) {
        folders.push_back(own);
    }
    for (const std::string& folder : systemLibraryFolders()) {
        folders.push_back(folder);
    }

    // Each folder once, first place kept.
    std::vector<std::string> unique;
    std::set<std::string> seen;
    for (auto& folder : folders) {
        while (folder.size() > 1 && folder.back() == '/') {
            folder.pop_back();
        }
        if (seen.insert(folder).second) {
            unique.push_back(folder);
        }
    }
    return unique;
}

}  // namespace plugin
}  // namespace robottestingframework
