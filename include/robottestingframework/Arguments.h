// Splitting a param string: into a C++ plug-in's argc/argv as RTF 2.x split it (parse(),
// ArgumentVector), into words the way a shell would (split()); reading options from argv.
#pragma once

#include <string>
#include <vector>

namespace robottestingframework {

class Arguments {
public:
    // Splits `line` in place (quotes and backslashes honoured), writing pointers into `args`
    // (`args` has `maxArgs` slots: at most maxArgs - 1 words, then a nullptr) and returning
    // the count.
    static int split(char* line, char** args, int maxArgs = 64);
    // The same on a copy: words of `line`, quotes removed.
    static std::vector<std::string> split(const std::string& line);
    // RTF 2.x's form and rules: splits `azParam` in place into `argv` (at most 63 words,
    // then a nullptr: `argv` needs 64 slots unless the line has fewer words) and sets `*argc`.
    // Words are separated by spaces; a double quote ends a word and starts or ends a quoted
    // part whose spaces belong to the word; empty words are dropped; backslashes, single
    // quotes and tabs are plain characters (C:\robots\arm stays whole). argv[0] is the first
    // word: this is how a fixture's param reaches its setup().
    static void parse(char* azParam, int* argc, char** argv);
    // Value of `--name value` (or `--name=value`) in argv; false when absent. argv[0] is
    // searched too: a fixture's argv starts with the first word of its param.
    static bool getOption(int argc, char** argv, const char* option, std::string& value);
    // True when `--name` is present in argv (argv[0] included).
    static bool hasOption(int argc, char** argv, const char* option);
};

// Owns the argv built from a param string, split by RTF 2.x's rules (as parse() splits): a
// test's has its name in argv[0], then the param's words; a fixture's (RTF 2.x's layout) has
// the param's words only, the first in argv[0].
class ArgumentVector {
public:
    ArgumentVector(const std::string& name, const std::string& param);
    explicit ArgumentVector(const std::string& param);
    // The argv of `words` as they are (split otherwise, e.g. by Arguments::split's shell rules).
    explicit ArgumentVector(std::vector<std::string> words);
    ArgumentVector(const ArgumentVector&) = delete;  // argv points into words_
    ArgumentVector& operator=(const ArgumentVector&) = delete;
    int argc() const { return static_cast<int>(words_.size()); }
    char** argv() { return pointers_.data(); }

private:
    std::vector<std::string> words_;
    std::vector<char*> pointers_;
};

}  // namespace robottestingframework
