#include "runner/cli/output_paths.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <map>
#include <set>

#include "platform/file_identity.h"
#include "reporters/atomic_file.h"
#include "reporters/standard_output.h"

namespace robottestingframework {
namespace runner {

namespace {

// What identifies a file: its identity (device and inode, or Windows' own) when it exists, else its
// absolute path with the links of its folders resolved. `writtenThrough`: a FIFO or a device, which
// several outputs may share (each written in turn).
std::string identity(const std::string& path, bool* writtenThrough = nullptr) {
    std::string file = platform::fileIdentity(path, writtenThrough);
    if (!file.empty()) {
        return file;
    }
    std::error_code error;
    std::filesystem::path full =
        std::filesystem::weakly_canonical(std::filesystem::absolute(path), error);
    return error ? path : full.string();
}

std::string describe(const OutputRequest& output) {
    return "--output " + output.type + ":" + output.file;
}

}  // namespace

std::string checkOutputPaths(const std::vector<OutputRequest>& outputs,
                             const std::vector<SuiteSpec>& suites) {
    if (outputs.empty()) {
        return {};  // nothing is written: nothing can be replaced
    }
    // What the run reads, by identity: the outputs must replace none of it. Each path once
    // (a stat each): a suite of 10 000 tests names a few files.
    std::map<std::string, std::string> inputs;
    std::set<std::string> seen;
    auto input = [&inputs, &seen](const std::string& path, const std::string& what) {
        if (!path.empty() && seen.insert(path).second) {
            inputs.emplace(identity(path), what + " " + path);
        }
    };
    for (const auto& suite : suites) {
        input(suite.where.file, "the suite file");
        for (const auto& fixture : suite.fixtures) {
            input(fixture.path, "the fixture");
        }
        for (const auto& test : suite.tests) {
            input(test.path, "the test");
        }
    }

    std::map<std::string, const OutputRequest*> files;
    const OutputRequest* standardOutput = nullptr;
    for (const auto& output : outputs) {
        if (reporters::namesStandardOutput(output.file)) {
            if (standardOutput != nullptr) {
                return describe(output) + ": " + describe(*standardOutput) +
                       " goes to the standard output already; one output can go there";
            }
            standardOutput = &output;
            continue;
        }
        const std::string notFile = reporters::notAnOutputFile(output.file);
        if (!notFile.empty()) {
            return describe(output) + ": " + notFile;
        }
        bool writtenThrough = false;
        const std::string id = identity(output.file, &writtenThrough);
        auto read = inputs.find(id);
        if (read != inputs.end()) {
            return describe(output) + ": " + output.file + " is " + read->second +
                   "; the output would replace it";
        }
        if (writtenThrough) {
            continue;
        }
        auto other = files.emplace(id, &output);
        if (!other.second) {
            return describe(output) + ": " + output.file + " is also the file of " +
                   describe(*other.first->second) + "; each output needs a file of its own";
        }
    }
    return {};
}

bool createOutputFolders(const std::vector<OutputRequest>& outputs, std::string& error) {
    for (const auto& output : outputs) {
        if (reporters::namesStandardOutput(output.file)) {
            continue;
        }
        const std::filesystem::path folder = std::filesystem::path(output.file).parent_path();
        std::error_code failed;
        if (folder.empty() || std::filesystem::is_directory(folder, failed)) {
            continue;
        }
        std::filesystem::create_directories(folder, failed);
        if (failed) {
            error = describe(output) + ": cannot create the folder " + folder.generic_string() +
                    " (" + failed.message() + ")";
            return false;
        }
    }
    return true;
}

bool keepStandardOutputForReports(const Options& options, std::string& error) {
    bool toStandardOutput = reporters::namesStandardOutput(options.merge.file);
    for (const auto& output : options.outputs) {
        toStandardOutput = toStandardOutput || reporters::namesStandardOutput(output.file);
    }
    if (toStandardOutput && !reporters::keepStandardOutputForReports()) {
        error =
            std::string("cannot keep the standard output for the reports: ") + std::strerror(errno);
        return false;
    }
    return true;
}

}  // namespace runner
}  // namespace robottestingframework
