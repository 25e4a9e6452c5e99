// Finding a plug-in file the way the platform finds libraries (SPEC 2, suite files).
#include <robottestingframework/dll/DllPluginLoader.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "dll/library_naming.h"
#include "dll/plugin_below.h"
#include "dll/shared_library.h"
#include "platform/file_kind.h"

namespace robottestingframework {
namespace plugin {

namespace {

// std::filesystem rather than stat(): the same answers on POSIX and Windows (which has no
// S_ISSOCK). Symbolic links are followed, as stat() does.
bool isFile(const std::string& path) {
    std::error_code error;
    return std::filesystem::is_regular_file(path, error);
}

// What `path` is when it exists but is no file a plug-in can be read from; empty otherwise.
std::string whatElse(const std::string& path) {
    using std::filesystem::file_type;
    std::error_code error;
    const file_type type = std::filesystem::status(path, error).type();
    if (error || type == file_type::not_found || type == file_type::regular) {
        return {};
    }
    return std::string("is ") + platform::fileKindText(type) + ", not a plug-in file: " + path;
}

// "/x", and on Windows "C:\x", "\x" and "\\server\x" too.
bool isRooted(const std::string& path) {
    const std::filesystem::path given(path);
    return given.is_absolute() || given.has_root_directory();
}

// A path rather than a bare name: it has a folder separator ('/', and on Windows a backslash).
bool isPath(const std::string& name) {
    return name.find('/') != std::string::npos ||
           name.find(static_cast<char>(std::filesystem::path::preferred_separator)) !=
               std::string::npos;
}

// The dynamic loader looks a bare "libfoo.so" up on the library path, not in the current
// folder: what was found is handed on as an absolute path.
std::string absolute(const std::string& path) {
    if (path.empty() || isRooted(path)) {
        return path;
    }
    std::error_code error;
    std::filesystem::path full = std::filesystem::absolute(path, error);
    return error ? path : full.lexically_normal().string();
}

bool startsWith(const std::string& text, const std::string& prefix) {
    return text.compare(0, prefix.size(), prefix) == 0;
}

bool endsWith(const std::string& text, const std::string& suffix) {
    return text.size() >= suffix.size() &&
           text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string join(const std::string& folder, const std::string& name) {
    if (folder.empty() || folder == ".") {
        return name;
    }
    return folder.back() == '/' ? folder + name : folder + "/" + name;
}

// `name`, then with the platform's prefix and suffix added where missing.
std::vector<std::string> spellings(const std::string& name) {
    const std::string prefix = SharedLibrary::prefix();
    const std::string suffix = SharedLibrary::suffix();
    std::vector<std::string> names{name};
    auto add = [&names](const std::string& candidate) {
        if (std::find(names.begin(), names.end(), candidate) == names.end()) {
            names.push_back(candidate);
        }
    };
    const bool hasPrefix = startsWith(name, prefix);
    const bool hasSuffix = endsWith(name, suffix);
    if (!hasPrefix) {
        add(prefix + name);
    }
    if (!hasSuffix) {
        add(name + suffix);
    }
    if (!hasPrefix && !hasSuffix) {
        add(prefix + name + suffix);
    }
    return names;
}

std::string list(const std::vector<std::string>& items) {
    std::string text;
    for (const auto& item : items) {
        text += (text.empty() ? "" : ", ") + item;
    }
    return text;
}

// The folders of RTF_PLUGIN_PATH (separated as PATH is: ':', on Windows ';'; empty entries
// left out).
std::vector<std::string> pluginSearchPath() {
    std::vector<std::string> folders;
    const char* value = std::getenv("RTF_PLUGIN_PATH");
    std::string text = value != nullptr ? value : "";
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find(pathListSeparator(), start);
        if (end == std::string::npos) {
            end = text.size();
        }
        std::string folder = text.substr(start, end - start);
        while (folder.size() > 1 && folder.back() == '/') {
            folder.pop_back();
        }
        if (!folder.empty()) {
            folders.push_back(folder);
        }
        start = end + 1;
    }
    return folders;
}

// Where a bare name was looked for, each place said by what it is (the suite's folder, the
// --plugin-path folders and RTF_PLUGIN_PATH, the loader's path), and when a file of that name
// is below the working folder, the option that would find it.
std::string notFound(const std::vector<std::string>& names, const std::string& besideDir) {
    std::string text = "not found as " + list(names);
    if (!besideDir.empty()) {
        // Absolute: given relative, the suite's folder may read ".".
        std::filesystem::path full(absolute(besideDir));
        if (full.has_relative_path() && !full.has_filename()) {
            full = full.parent_path();  // "/x/." is "/x/"
        }
        text += " in the suite's folder " + full.string() + ";";
    }
    const std::vector<std::string> given = pluginSearchPath();
    text +=
        " in --plugin-path and RTF_PLUGIN_PATH: " + (given.empty() ? "none given" : list(given));
    text += "; in the library path: " + list(SharedLibrary::searchPath());
    const std::string below = findBelowWorkingFolder(names);
    if (!below.empty()) {
        const std::string folder = std::filesystem::path(below).parent_path().generic_string();
        const std::string option = folder.empty() ? "." : folder;
        text += ". " + below + " is below the working folder: --plugin-path " + option +
                " (or RTF_PLUGIN_PATH=" + option + ") finds it";
    }
    return text;
}

}  // namespace

std::string findPlugin(const std::string& name, const std::string& besideDir,
                       std::string* searched) {
    if (name.empty()) {
        if (searched != nullptr) {
            *searched = "no plug-in name given";
        }
        return {};
    }
    if (isPath(name)) {
        // A path: absolute as is; relative to the suite's folder first, then the current one.
        std::vector<std::string> tried;
        if (!isRooted(name) && !besideDir.empty()) {
            tried.push_back(join(besideDir, name));
        }
        tried.push_back(name);
        for (const auto& path : tried) {
            if (isFile(path)) {
                return absolute(path);
            }
        }
        if (searched != nullptr) {
            *searched = "no such file: " + list(tried);
            for (const auto& path : tried) {
                if (!whatElse(path).empty()) {
                    *searched = whatElse(path);
                    break;
                }
            }
        }
        return {};
    }

    std::vector<std::string> folders;
    if (!besideDir.empty()) {
        folders.push_back(besideDir);
    }
    for (const auto& folder : pluginSearchPath()) {
        if (std::find(folders.begin(), folders.end(), folder) == folders.end()) {
            folders.push_back(folder);
        }
    }
    for (const auto& folder : SharedLibrary::searchPath()) {
        if (std::find(folders.begin(), folders.end(), folder) == folders.end()) {
            folders.push_back(folder);
        }
    }
    const auto names = spellings(name);
    std::string other;  // the first candidate that exists but is no file
    for (const auto& folder : folders) {
        for (const auto& candidate : names) {
            std::string path = join(folder, candidate);
            if (isFile(path)) {
                return absolute(path);
            }
            if (other.empty()) {
                other = whatElse(path);
            }
        }
    }
    // A bare script's name (arm_test.lua: an extension that is no library's): RTF 2.x opened
    // it from the current folder, where a suite run from a project's root finds it. Last, so a
    // file beside the suite or on a search path is found first.
    const std::string extension = std::filesystem::path(name).extension().string();
    if (!extension.empty() && extension != kLibraryNaming.suffix && isFile(name)) {
        return absolute(name);
    }
    if (searched != nullptr && !other.empty()) {
        *searched = other;
    } else if (searched != nullptr) {
        *searched = notFound(names, besideDir);
    }
    return {};
}

}  // namespace plugin
}  // namespace robottestingframework
