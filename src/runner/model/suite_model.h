// What a suite file (or the command line) asks to run, before anything is loaded.
#pragma once

#include <string>
#include <vector>

#include "runner/model/shared_string.h"

namespace robottestingframework {
namespace runner {

// Where a piece of the model came from, for error messages ("suite.xml:12").
struct SourceLocation {
    SharedString file;  // one string for every element of one file
    unsigned int line = 0;
    std::string toString() const;
};

// A variable of a suite once every source is applied (for --list-vars).
struct VariableValue {
    std::string name;
    std::string value;   // expanded
    std::string origin;  // "--var", "vars.env:3", "suite.xml:4"
};

// A suite's tests share their plug-in's strings (SharedString): 10 000 tests of one plug-in hold
// its path once.
struct TestSpec {
    SharedString plugin;  // as written: a path or a bare name
    SharedString path;    // resolved file; empty when it could not be found
    SharedString type;    // "dll", "python", "lua", "ruby", "exec"; empty: from the file
    SharedString name;    // optional name="..." from the suite; else the plug-in's name
    // Its id in its suite (model/test_id.h), given once the suite is read; "SUITE/id" is the
    // name every output and option uses for it.
    std::string id;
    SharedString param;           // --param's, when the test has none, is shared by all
    SharedString environment;     // the suite's and the command line's, shared when it adds none
    unsigned int repetition = 1;  // 0 in a suite file without one: --repetition, else 1
    double timeout = 0;           // seconds; 0: none (issue 3 fills the precedence)
    std::vector<std::string> depends;
    std::vector<std::string> tags;  // its own and its suite's
    SharedString skipReason;        // non-empty: skipped with this reason, never run
    SourceLocation where;
};

struct FixtureSpec {
    SharedString plugin;
    SharedString path;
    std::string type;  // "dll", "python", "process"; empty: from the file
    std::string param;
    SourceLocation where;
    // scope="run" (process fixtures only): one instance of the world for every suite of the
    // run that names the same world file with the same param (plan/shared_world.h); "suite"
    // (the default): the suite's own.
    enum class Scope { Suite, Run };
    Scope scope = Scope::Suite;
};

// A <resource> of a suite: an exclusive lock (`lock="robot:left-arm"`) or `count` items taken
// from a pool given by --resources (`pool="ros_domain" count="1"`), or by the suite's own
// `default="ID ..."` when no --resources file gives that pool. The scheduler holds them from
// fixture setup to teardown; shards keep suites sharing a lock together.
struct ResourceSpec {
    std::string lock;  // empty for a pool
    std::string pool;  // empty for a lock
    unsigned int count = 1;
    SourceLocation where;
    std::vector<std::string> defaults{};  // default="...": the pool's items without --resources
};

// The id of a pool's item, in a --resources file or a default="...": letters, digits, _, - and
// . (CTest's rule, with upper-case letters, '-' and '.' too).
bool isPoolItemId(const std::string& id);

struct SuiteSpec {
    std::string name;
    std::string description;
    std::string environment;
    double timeout = 0;
    std::vector<std::string> tags;  // tags="..." of the suite: given to each of its tests
    std::vector<FixtureSpec> fixtures;
    std::vector<TestSpec> tests;
    std::vector<ResourceSpec> resources;  // as written, in document order
    bool exclusive = false;               // exclusive="true": runs alone
    // network="private" (or --network private): its fixtures, tests and what they start live
    // in a network of their own (platform/private_network.h); "host" (the default): the
    // machine's.
    enum class Network { Host, Private };
    Network network = Network::Host;
    std::vector<VariableValue> variables;    // by name
    std::vector<std::string> variablesUsed;  // the names its ${...} looked up
    SourceLocation where;
};

}  // namespace runner
}  // namespace robottestingframework
