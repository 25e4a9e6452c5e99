#include "runner/model/test_id.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace robottestingframework {
namespace runner {

namespace fs = std::filesystem;

namespace {

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

// A normal relative path that climbs out of its folder first ("../tests/x.py").
bool startsOutside(const fs::path& normal) {
    return !normal.empty() && *normal.begin() == "..";
}

// The part of a plug-in beside the suite's folder ("../tests/gripper.py" of a suite in robot/):
// its path from the folder it shares with the suite's folder ("tests/gripper.py"), so no id
// holds "..". A path that climbs out and back in ("../robot/x.py" of a suite in robot/) is the
// one inside ("x.py"). Lexical, as the rest of the id: the same on every machine.
std::string outsidePart(const fs::path& normal, const std::string& suiteFolder) {
    std::error_code error;
    fs::path folder =
        fs::absolute(suiteFolder.empty() ? "." : suiteFolder, error).lexically_normal();
    if (!folder.has_filename()) {
        folder = folder.parent_path();  // "/x/robot/" is "/x/robot": ".." leaves "robot"
    }
    if (!error) {
        const std::string inside = below((folder / normal).lexically_normal(), folder);
        if (!inside.empty()) {
            return inside;
        }
    }
    fs::path rest;
    for (const fs::path& part : normal) {
        if (!(rest.empty() && part == "..")) {
            rest /= part;
        }
    }
    return rest.empty() ? normal.generic_string() : rest.generic_string();
}

}  // namespace

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

std::string pluginIdPart(const std::string& plugin, const std::string& suiteFolder) {
    const fs::path written = fs::path(plugin).lexically_normal();
    // On Windows "\\x" (or "/x") is rooted on the current drive: no more relative to the suite
    // than "C:\\x" is.
    if (!written.is_absolute() && !written.has_root_directory()) {
        std::string text = written.generic_string();
        // "./x" is normal as "x"; a lone "." (never a plug-in) stays as written.
        if (text.empty()) {
            return plugin;
        }
        return startsOutside(written) ? outsidePart(written, suiteFolder) : text;
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
    std::vector<TestSpec>& tests = suite.tests;
    // Each test's id before the params and numbers: its name, or its plug-in's part of the path
    // (held by `partOf`, or by the test's name).
    std::vector<const std::string*> bases(tests.size());
    // Each plug-in path's part once: a suite often names one plug-in many times. Hashed, not
    // ordered: ids of one plug-in share a long prefix, which ordered sets compare over and over.
    std::unordered_map<std::string, std::string> partOf;
    // The params each unnamed plug-in is given in this suite: more than one, and each says its own.
    std::unordered_map<std::string_view, std::unordered_set<std::string>> params;
    // The tests of a suite mostly name the plug-in and give the param of the test before them:
    // neither is looked up again (10 000 tests of one plug-in hashed its path 10 000 times).
    const std::string* plugin = nullptr;
    const std::string* part = nullptr;
    std::unordered_set<std::string>* given = nullptr;
    const std::string* param = nullptr;
    for (std::size_t i = 0; i < tests.size(); ++i) {
        TestSpec& test = tests[i];
        if (!test.name.empty()) {
            bases[i] = &test.name.str();
            continue;
        }
        if (plugin == nullptr || *plugin != test.plugin.str()) {
            auto known = partOf.find(test.plugin);
            if (known == partOf.end()) {
                known = partOf.emplace(test.plugin, pluginIdPart(test.plugin, suiteFolder)).first;
            }
            plugin = &known->first;
            part = &known->second;
            given = &params[*part];
            param = nullptr;
        }
        bases[i] = part;
        // Two tell that the params say which is which; the same param again adds nothing.
        if (given->size() < 2 && (param == nullptr || *param != test.param.str())) {
            given->insert(oneLine(test.param));
            param = &test.param.str();
        }
    }
    // The ids given so far: each a view of an earlier test's final id, which no longer changes
    // (`tests` is not resized here).
    std::unordered_set<std::string_view> taken;
    taken.reserve(tests.size());
    // The next number to try for each id given twice: a suite of 10 000 runs of one plug-in
    // must not try 2, 3, ... again for each (that was quadratic in the suite's size).
    std::unordered_map<std::string_view, unsigned int> nextNumber;
    std::string id;
    for (std::size_t i = 0; i < tests.size(); ++i) {
        TestSpec& test = tests[i];
        id = *bases[i];
        if (test.name.empty() && !test.param.empty()) {
            auto said = params.find(id);
            if (said != params.end() && said->second.size() > 1) {
                const std::string text = oneLine(test.param);
                if (!text.empty()) {
                    id.append("[").append(text).append("]");
                }
            }
        }
        // A second test of the same id: "[2]", the next free number, in document order.
        auto earlier = taken.find(id);
        if (earlier != taken.end()) {
            auto next = nextNumber.try_emplace(*earlier, 2).first;
            const std::string_view base = next->first;
            unsigned int& k = next->second;
            do {
                id.assign(base).append("[").append(std::to_string(k++)).append("]");
            } while (taken.count(id) > 0);
        }
        test.id = id;
        taken.insert(test.id);
    }
}

namespace {

// Whether tests of two suites could share an id: "S/T" is one id for two suites only when they
// share a name, or one's name is the start of the other's up to a '/' ("a" and "a/b"). Tells
// without looking at a test: a run of 10 000 tests hashes no id here.
bool suitesMayCollide(const std::vector<SuiteSpec>& suites) {
    std::unordered_set<std::string_view> names;
    for (const auto& suite : suites) {
        if (!names.insert(suite.name).second) {
            return true;
        }
    }
    for (const auto& suite : suites) {
        const std::string_view name = suite.name;
        for (std::size_t slash = name.find('/'); slash != std::string_view::npos;
             slash = name.find('/', slash + 1)) {
            if (names.count(name.substr(0, slash)) > 0) {
                return true;
            }
        }
    }
    return false;
}

// The suites that share an id with another one; `error`, when given, names the first two tests
// of one id.
std::set<std::size_t> collidingSuites(const std::vector<SuiteSpec>& suites, std::string* error) {
    std::unordered_map<std::string, std::pair<std::size_t, std::size_t>> first;
    std::set<std::size_t> colliding;
    for (std::size_t s = 0; s < suites.size(); ++s) {
        for (std::size_t t = 0; t < suites[s].tests.size(); ++t) {
            const std::string id = testId(suites[s], suites[s].tests[t]);
            const auto found = first.emplace(id, std::make_pair(s, t));
            if (found.second || found.first->second.first == s) {
                continue;
            }
            colliding.insert(found.first->second.first);
            colliding.insert(s);
            if (error != nullptr && error->empty()) {
                const TestSpec& earlier =
                    suites[found.first->second.first].tests[found.first->second.second];
                const auto place = [](const SourceLocation& where) {
                    return where.file.empty() ? std::string("the command line") : where.toString();
                };
                *error = "two tests have the id " + id + ": " + place(earlier.where) + " and " +
                         place(suites[s].tests[t].where) +
                         " (test ids are unique within a run: give one of their suites another "
                         "name=)";
            }
        }
    }
    return colliding;
}

// The folder every path of `files` is below.
fs::path commonFolder(const std::vector<fs::path>& files) {
    fs::path common = files.front().parent_path();
    for (const fs::path& file : files) {
        // One path to iterate over: each parent_path() call makes a new one.
        const fs::path folder = file.parent_path();
        fs::path shared;
        auto a = common.begin();
        auto b = folder.begin();
        for (; a != common.end() && b != folder.end() && *a == *b; ++a, ++b) {
            shared /= *a;
        }
        common = shared;
    }
    return common;
}

}  // namespace

std::string makeIdsUniqueAcrossSuites(std::vector<SuiteSpec>& suites) {
    if (!suitesMayCollide(suites)) {
        return {};
    }
    const std::set<std::size_t> colliding = collidingSuites(suites, nullptr);
    if (colliding.empty()) {
        return {};
    }
    std::vector<std::size_t> withFile;
    std::vector<fs::path> files;
    for (const std::size_t s : colliding) {
        if (suites[s].where.file.empty()) {
            continue;  // the tests of the command line ("tests"): the suite files give way
        }
        std::error_code failed;
        fs::path file = fs::absolute(suites[s].where.file.str(), failed);
        if (failed) {
            file = suites[s].where.file.str();
        }
        withFile.push_back(s);
        files.push_back(file.lexically_normal());
    }
    // Several files: each says which it is. One file given several times (two copies of a
    // suite side by side, docs/how-to/parallel-runs-and-worlds.md): its copies are numbered.
    const std::set<fs::path> distinct(files.begin(), files.end());
    const fs::path common = distinct.size() > 1 ? commonFolder(files) : fs::path();
    std::map<fs::path, unsigned int> copies;
    for (std::size_t i = 0; i < withFile.size(); ++i) {
        SuiteSpec& suite = suites[withFile[i]];
        if (distinct.size() > 1) {
            const std::string relative = files[i].lexically_relative(common).generic_string();
            suite.name += "[" + (relative.empty() ? files[i].generic_string() : relative) + "]";
        }
        const unsigned int copy = ++copies[files[i]];
        if (copy > 1) {
            suite.name += "[" + std::to_string(copy) + "]";
        }
    }
    std::string error;
    collidingSuites(suites, &error);
    return error;
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
