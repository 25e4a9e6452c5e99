#include "runner/cli/sharded_run_setup.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>

#include "platform/environment.h"
#include "runner/plan/run_gate.h"
#include "runner/plan/shard_split.h"
#include "runner/reports/report_reader.h"

namespace robottestingframework {
namespace runner {

bool prepareShard(Options& options, ShardChoice& choice, std::string& error) {
    if (!chooseShard(
            options.shard, [](const char* name) { return std::getenv(name); }, choice, error)) {
        return false;
    }
    // Bazel: the JUnit report goes where Bazel collects it (--no-output too: Bazel reads it),
    // unless the command line already writes one there.
    const char* bazelXml = std::getenv("XML_OUTPUT_FILE");
    if (bazelXml != nullptr && *bazelXml != '\0') {
        bool written = false;
        for (const auto& output : options.outputs) {
            written = written || (output.type == "junit" && output.file == bazelXml);
        }
        if (!written) {
            options.outputs.push_back(OutputRequest{"junit", bazelXml});
        }
    }
    const char* scratch = std::getenv("TEST_TMPDIR");
    if (scratch != nullptr && *scratch != '\0') {
        platform::setEnvironment("TMPDIR", scratch);
    }
    // Bazel asks a test that shards to say so by touching this file.
    const char* status = std::getenv("TEST_SHARD_STATUS_FILE");
    if (status != nullptr && *status != '\0' && choice.sharded) {
        std::ofstream touch(status, std::ios::app);
        if (!touch) {
            error = "TEST_SHARD_STATUS_FILE " + std::string(status) + ": cannot be written";
            return false;
        }
    }
    for (const auto& name : shardVariables()) {
        platform::unsetEnvironment(name);
    }
    return true;
}

std::vector<unsigned int> shardsOf(const std::vector<SuiteSpec>& suites, unsigned int count,
                                   const std::optional<SuiteSeconds>& durations) {
    std::map<std::string, long long> known;
    if (durations) {
        for (const auto& suite : *durations) {
            known[suite.first] = std::llround(suite.second * 1000.0);
        }
    }
    std::vector<ShardItem> items;
    for (const auto& suite : suites) {
        ShardItem item;
        // By name, then file (as given): the same on every machine running the same command.
        item.id = suite.name + '\n' + suite.where.file;
        for (const auto& resource : suite.resources) {
            if (!resource.lock.empty()) {
                item.locks.push_back(resource.lock);
            }
        }
        const auto found = known.find(suite.name);
        item.milliseconds = found == known.end() ? -1 : found->second;
        items.push_back(std::move(item));
    }
    // A test that depends on a test of another suite: both suites on one shard, linked as a
    // shared lock links them (a key no lock name can be: lock names have no spaces).
    for (std::size_t s = 0; s < suites.size(); ++s) {
        for (const auto& test : suites[s].tests) {
            for (const auto& dependency : test.depends) {
                for (std::size_t other = 0; other < suites.size(); ++other) {
                    const auto& candidates = suites[other].tests;
                    if (other == s || std::none_of(candidates.begin(), candidates.end(),
                                                   [&dependency](const TestSpec& candidate) {
                                                       return dependencyNames(dependency,
                                                                              candidate);
                                                   })) {
                        continue;
                    }
                    const std::string link = "depends on suite " + std::to_string(other);
                    items[s].locks.push_back(link);
                    items[other].locks.push_back(link);
                }
            }
        }
    }
    return assignShards(items, count, durations.has_value());
}

std::string planIdentity(const std::vector<SuiteSpec>& suites, unsigned int count) {
    std::uint64_t hash = 14695981039346656037ULL;
    auto add = [&hash](const std::string& text) {
        for (const char c : text) {
            hash = (hash ^ static_cast<unsigned char>(c)) * 1099511628211ULL;
        }
        hash = (hash ^ 0x1fU) * 1099511628211ULL;  // ends each piece: "ab","c" is not "a","bc"
    };
    add(std::to_string(count));
    for (const auto& suite : suites) {
        add(suite.name);
        // The file's name only: machines check the sources out in folders of their own.
        add(std::filesystem::path(suite.where.file.str()).filename().string());
        for (const auto& test : suite.tests) {
            add(test.id);
        }
        add("\x1e");
    }
    std::string text(16, '0');
    for (std::size_t i = 16; i-- > 0; hash >>= 4) {
        text[i] = "0123456789abcdef"[hash & 0xfU];
    }
    return text;
}

}  // namespace runner
}  // namespace robottestingframework
