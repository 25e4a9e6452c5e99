// Variables and the one expander of ${...} that suite files, test files and the process
// fixture's world files share: ${NAME} a variable, ${env:NAME} the environment, $${ or ${{ a
// literal "${". A value may use other variables; it is expanded when used, and a chain that
// comes back to itself is an error naming the cycle.
#pragma once

#include <cstddef>
#include <functional>
#include <istream>
#include <map>
#include <string>
#include <vector>

namespace robottestingframework {
namespace variables {

// The most one value may grow to once expanded, and all the values of one file together: a
// few lines of variables that expand each other ten times reach gigabytes.
constexpr std::size_t maxExpandedValue = 1024 * 1024;
constexpr std::size_t maxExpandedTotal = 16 * 1024 * 1024;

// Who set a variable; a stronger source replaces a weaker one's value, whatever the order.
enum class Source {
    WorldFile = 0,    // a <variable> of a process fixture's world file (and world_dir)
    TestFile = 1,     // a <variable> default of a test file
    Suite = 2,        // a <variable> of the suite
    VarFile = 3,      // a line of --var-file (a later file wins over an earlier one)
    CommandLine = 4,  // --var NAME=VALUE
};

struct Variable {
    std::string name;
    std::string value;  // as written: it may use ${...}
    Source source = Source::Suite;
    std::string origin;  // for people: "--var", "vars.env:3", "suite.xml:4"
};

struct ExpandError {
    enum class Kind {
        Undefined,
        EnvironmentUnset,
        Unterminated,
        Cycle,
        TooLong,
        TooMuch,
        PoolNotTaken
    };
    Kind kind;
    std::string name;     // the variable being expanded when it happened
    std::string message;  // the whole story, without file and line (the caller knows them)
};

class VariableTable {
public:
    // Sets `variable` unless a stronger source already set it; equal sources: the later wins.
    void define(const Variable& variable);
    const Variable* find(const std::string& name) const;
    // Every variable, by name.
    const std::map<std::string, Variable>& all() const { return variables_; }

    // `text` with its ${...} replaced. Throws ExpandError. Each call counts towards
    // maxExpandedTotal (see resetTotal).
    std::string expand(const std::string& text);
    // The value of `name`, expanded (throws ExpandError when it is not defined); not counted
    // as a use of `name`.
    std::string valueOf(const std::string& name);
    // The items of each pool the suite took (pool -> "ID,ID"), once they are known (a world
    // file's): ${resource.POOL} expands to them, and to an error (PoolNotTaken) for a pool not
    // here. Until this is called, ${resource.POOL} stays a marker (resourceMarker).
    void giveResources(std::map<std::string, std::string> items);
    // A new file starts: the total of maxExpandedTotal counts again from zero.
    void resetTotal() { total_ = 0; }
    // The names that expand() looked up, defined or not.
    const std::vector<std::string>& used() const { return used_; }

    // Defined names close to `name` (a typo away), best first.
    std::vector<std::string> closeTo(const std::string& name) const;

private:
    std::string expandText(const std::string& text, const std::string& context);
    const std::string& resolve(const std::string& name);

    std::map<std::string, Variable> variables_;
    std::map<std::string, std::string> expanded_;  // values already expanded
    std::vector<std::string> resolving_;           // the chain being expanded, for cycles
    std::vector<std::string> used_;
    std::size_t total_ = 0;
    bool resourcesGiven_ = false;
    std::map<std::string, std::string> resources_;
};

// "a: x" for a parsed NAME=VALUE, or false with `error` saying what is wrong and where
// (`position`: 1-based column of the problem).
bool parseAssignment(const std::string& text, std::string& name, std::string& value,
                     std::string& error);

// "robot" is a valid name; names are letters, digits, '_', '-' and '.', not starting with a
// digit.
bool isVariableName(const std::string& name);

// Reads a --var-file: NAME=VALUE per line (spaces around both are dropped), blank lines and
// lines starting with # ignored. The variables are appended to `out` with Source::VarFile and
// "FILE:LINE" as their origin. False, with `error` ("FILE:LINE: what"), when it cannot.
bool readVariableFile(const std::string& path, std::vector<Variable>& out, std::string& error);
// The same from a stream (`path` names it in messages).
bool readVariables(std::istream& in, const std::string& path, std::vector<Variable>& out,
                   std::string& error);

// `value` written so that expanding it gives it back ("${" becomes "$${").
std::string escape(const std::string& value);

// ${resource.POOL} is known only when the scheduler gives the suite an item of the pool: until
// then it stays in the text as a marker (that escape() leaves alone), which fillResources()
// replaces. `value` gives the text for a pool.
std::string resourceMarker(const std::string& pool);
std::string fillResources(const std::string& text,
                          const std::function<std::string(const std::string&)>& value);
// The pools whose marker `text` holds.
std::vector<std::string> resourcesUsed(const std::string& text);

}  // namespace variables
}  // namespace robottestingframework
