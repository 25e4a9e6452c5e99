// What --list and --list-vars print: the suites as read, with every variable and command-line
// override applied, and nothing loaded or started.
#pragma once

#include <string>
#include <vector>

#include "runner/model/suite_model.h"

namespace robottestingframework {
namespace runner {

// A block per suite, a line per test: id, type, resolved plug-in, param, tags, timeout.
// `shards`, when not empty: the shard of each suite (of `count`), shown on its line.
std::string listText(const std::vector<SuiteSpec>& suites,
                     const std::vector<unsigned int>& shards = {}, unsigned int count = 0);
// The same as one JSON document: {"suites": [{"name", "file", "network" ("host" or "private"),
// "fixtures": [{"plugin", "path", "type", "param", "scope" ("suite" or "run"); a shared world
// (scope "run") also "world" (its name), "world_file" (absolute) and "identity"}], "tests":
// [{"id", "name", "type", "plugin", "path", "param", "environment", "tags", "timeout",
// "repetition", "depends"}]}]}.
// With `shards`, each suite has "shard" too.
std::string listJson(const std::vector<SuiteSpec>& suites,
                     const std::vector<unsigned int>& shards = {});
// Writes listJson to `file`, whole or not at all; false with `error` when it cannot.
bool writeListJson(const std::string& file, const std::vector<SuiteSpec>& suites,
                   std::string& error, const std::vector<unsigned int>& shards = {});
// A block per suite, a line per variable: NAME = VALUE (where it came from).
std::string listVariablesText(const std::vector<SuiteSpec>& suites);

}  // namespace runner
}  // namespace robottestingframework
