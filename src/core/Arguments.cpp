#include <robottestingframework/Arguments.h>

#include <cstring>
#include <utility>

namespace robottestingframework {

namespace {

bool isBlank(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

// The POSIX shell's rules without expansions: '...' is literal, "..." honours \" \\ \$ \`,
// a backslash outside quotes takes the next character as is. An unterminated quote runs to
// the end of the line rather than being an error: a param string is not a script.
std::vector<std::string> splitWords(const char* s) {
    std::vector<std::string> words;
    std::size_t i = 0;
    for (;;) {
        while (s[i] != '\0' && isBlank(s[i])) {
            ++i;
        }
        if (s[i] == '\0') {
            break;
        }
        std::string word;
        while (s[i] != '\0' && !isBlank(s[i])) {
            const char c = s[i];
            if (c == '\'') {
                ++i;
                while (s[i] != '\0' && s[i] != '\'') {
                    word += s[i++];
                }
                if (s[i] != '\0') {
                    ++i;
                }
            } else if (c == '"') {
                ++i;
                while (s[i] != '\0' && s[i] != '"') {
                    if (s[i] == '\\' && s[i + 1] != '\0' && std::strchr("\"\\$`\n", s[i + 1])) {
                        if (s[i + 1] != '\n') {
                            word += s[i + 1];
                        }
                        i += 2;
                    } else {
                        word += s[i++];
                    }
                }
                if (s[i] != '\0') {
                    ++i;
                }
            } else if (c == '\\') {
                if (s[i + 1] == '\0') {
                    word += c;  // a trailing backslash escapes nothing: keep it
                    ++i;
                } else {
                    if (s[i + 1] != '\n') {
                        word += s[i + 1];
                    }
                    i += 2;
                }
            } else {
                word += c;
                ++i;
            }
        }
        words.push_back(std::move(word));
    }
    return words;
}

// RTF 2.x's rules for a plug-in's argv, which C++ tests and fixtures written for it read:
// words are separated by spaces (only), a double quote ends the word before it and starts or
// ends a quoted part in which spaces belong to the word, and empty words are dropped. Nothing
// else is special: a backslash (C:\robots\arm, a\d+), a single quote (robot's) and a tab are
// characters of the word.
std::vector<std::string> splitAsRtf2(const char* s) {
    std::vector<std::string> words;
    std::string word;
    bool quoted = false;
    auto end = [&] {
        if (!word.empty()) {
            words.push_back(std::move(word));
            word.clear();
        }
    };
    for (std::size_t i = 0; s[i] != '\0'; ++i) {
        if (s[i] == '"') {
            end();
            quoted = !quoted;
        } else if (s[i] == ' ' && !quoted) {
            end();
        } else {
            word += s[i];
        }
    }
    end();
    return words;
}

// Writes `words` back into `line`, each with its terminator, and their pointers into `args`
// (at most maxArgs - 1 words, then a nullptr); returns the count. Both splitting rules only
// remove characters and each word but the last ends at a removed one, so they fit.
int writeInPlace(char* line, const std::vector<std::string>& words, char** args, int maxArgs) {
    char* out = line;
    int count = 0;
    for (const std::string& word : words) {
        if (count >= maxArgs - 1) {
            break;
        }
        std::memcpy(out, word.c_str(), word.size() + 1);
        args[count++] = out;
        out += word.size() + 1;
    }
    args[count] = nullptr;
    return count;
}

// `name`, then `words`: a test's argv.
std::vector<std::string> withName(const std::string& name, std::vector<std::string> words) {
    words.insert(words.begin(), name);
    return words;
}

// "name" and "--name" both mean the option --name.
std::string optionName(const char* option) {
    if (option[0] == '-') {
        return option;
    }
    return std::string("--") + option;
}

}  // namespace

int Arguments::split(char* line, char** args, int maxArgs) {
    if (args == nullptr || maxArgs <= 0) {
        return 0;
    }
    if (line == nullptr) {
        args[0] = nullptr;
        return 0;
    }
    return writeInPlace(line, splitWords(line), args, maxArgs);
}

void Arguments::parse(char* azParam, int* argc, char** argv) {
    int count = 0;
    if (argv != nullptr) {
        if (azParam == nullptr) {
            argv[0] = nullptr;
        } else {
            count = writeInPlace(azParam, splitAsRtf2(azParam), argv, 64);
        }
    }
    if (argc != nullptr) {
        *argc = count;
    }
}

std::vector<std::string> Arguments::split(const std::string& line) {
    return splitWords(line.c_str());
}

bool Arguments::getOption(int argc, char** argv, const char* option, std::string& value) {
    if (argv == nullptr || option == nullptr) {
        return false;
    }
    const std::string name = optionName(option);
    const std::string prefix = name + "=";
    for (int i = 0; i < argc; ++i) {
        if (argv[i] == nullptr) {
            break;
        }
        if (name == argv[i]) {
            value = (i + 1 < argc && argv[i + 1] != nullptr) ? argv[i + 1] : "";
            return true;
        }
        if (std::strncmp(argv[i], prefix.c_str(), prefix.size()) == 0) {
            value = argv[i] + prefix.size();
            return true;
        }
    }
    return false;
}

bool Arguments::hasOption(int argc, char** argv, const char* option) {
    std::string value;  // unused: found is what counts
    return getOption(argc, argv, option, value);
}

ArgumentVector::ArgumentVector(const std::string& name, const std::string& param)
    : ArgumentVector(withName(name, splitAsRtf2(param.c_str()))) {}

ArgumentVector::ArgumentVector(const std::string& param)
    : ArgumentVector(splitAsRtf2(param.c_str())) {}

ArgumentVector::ArgumentVector(std::vector<std::string> words) : words_(std::move(words)) {
    pointers_.reserve(words_.size() + 1);
    for (std::string& word : words_) {
        pointers_.push_back(&word[0]);
    }
    pointers_.push_back(nullptr);
}

}  // namespace robottestingframework
