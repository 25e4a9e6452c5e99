#include "runner/model/test_id.h"

#include <algorithm>
#include <filesystem>
#include <unordered_map>
#include <unordered_set>

namespace robottestingframework {
namespace runner {

namespace fs = std::filesystem;

namespace {

// A param on one line, as an id must be: runs of white space become one space.
std::string oneLine(const std::string& text) {
    std::string out;
    bool space = false;
    for (char c : text) {
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
            space = !out.empty();
            continue;
        }
        if (space) {
            out += ' ';
            space = false;
        }
        out += c;
    }
    return out;
}

// "a/b/c" below "a" is "b/c"; empty when `path` is not below `folder`.
std::string below(const fs::path& path, const fs::path& folder) {
    auto p = path.begin();
    for (auto f = folder.begin(); f != folder.end(); ++f, ++p) {
        if (f->empty()) {
            continue;  // the trailing "" of "a/b/"
        }
        if (p == path.end() || *p != *f) {
            return {};
        }
    }
    fs::path rest;
    for (; p != path.end(); ++p) {
        rest /= *p;
    }
    return rest.generic_string();
}

}  // namespace

std::string pluginIdPart(const std::string& plugin, const std::string& suiteFolder) {
    const fs::path written = fs::path(plugin).lexically_normal();
    // On Windows "\\x" (or "/x") is rooted on the current drive: no more relative to the suite
    // than "C:\\x" is.
    if (!written.is_absolute() && !written.has_root_directory()) {
        std::string text = written.generic_string();
        // "./x" is normal as "x"; a lone "." (never a plug-in) stays as written.
        return text.empty() ? plugin : text;
    }
    std::error_code error;
    fs::path folder = fs::absolute(suiteFolder.empty() ? "." : suiteFolder, error);
    if (!error) {
        const std::string relative = below(written, folder.lexically_normal());
        if (!relative.empty()) {
            return relative;
        }
    }
    return written.filename().generic_string();
}

void assignTestIds(SuiteSpec& suite, const std::string& suiteFolder) {
    // Hashed, not ordered: ids of one plug-in share a long prefix, which ordered sets compare
    // over and over (a suite of 10 000 runs of one plug-in spent a tenth of its run here).
    // The params each unnamed plug-in is given in this suite: more than one, and each says its own.
    std::unordered_map<std::string, std::unordered_set<std::string>> params;
    // Each plug-in path's part once: a suite often names one plug-in many times.
    std::unordered_map<std::string, std::string> partOf;
    for (auto& test : suite.tests) {
        if (test.name.empty()) {
            auto part = partOf.find(test.plugin);
            if (part == partOf.end()) {
                part = partOf.emplace(test.plugin, pluginIdPart(test.plugin, suiteFolder)).first;
            }
            test.id = part->second;
            auto& given = params[test.id];
            if (given.size() < 2) {  // two tell that the params say which is which
                given.insert(oneLine(test.param));
            }
        } else {
            test.id = test.name;
        }
    }
    std::unordered_set<std::string> taken;
    taken.reserve(suite.tests.size());
    // The next number to try for each id given twice: a suite of 10 000 runs of one plug-in
    // must not try 2, 3, ... again for each (that was quadratic in the suite's size).
    std::unordered_map<std::string, unsigned int> nextNumber;
    for (auto& test : suite.tests) {
        if (test.name.empty() && !test.param.empty()) {
            auto given = params.find(test.id);
            if (given != params.end() && given->second.size() > 1) {
                const std::string param = oneLine(test.param);
                if (!param.empty()) {
                    test.id += "[" + param + "]";
                }
            }
        }
        // A second test of the same id: "[2]", the next free number, in document order.
        if (!taken.insert(test.id).second) {
            // Looked up before it is added: emplace would build (and drop) a node each time.
            auto next = nextNumber.find(test.id);
            if (next == nextNumber.end()) {
                next = nextNumber.emplace(test.id, 2).first;
            }
            const std::string& base = next->first;
            unsigned int& k = next->second;
            do {
                test.id.assign(base).append("[").append(std::to_string(k++)).append("]");
            } while (!taken.insert(test.id).second);
        }
    }
}

std::string testId(const SuiteSpec& suite, const TestSpec& test) {
    // A spec made without a suite file (the unit tests) has no id yet: its name or plug-in.
    if (test.id.empty()) {
        return suite.name + "/" + ((test.name.empty() ? test.plugin : test.name).str());
    }
    return suite.name + "/" + test.id;
}

}  // namespace runner
}  // namespace robottestingframework
