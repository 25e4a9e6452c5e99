#include "variables/variables.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <utility>

#include "platform/bounded_file.h"

namespace robottestingframework {
namespace variables {

namespace {

std::size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) {
        row[j] = j;
    }
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = above;
        }
    }
    return row[b.size()];
}

}  // namespace

void VariableTable::define(const Variable& variable) {
    auto known = variables_.find(variable.name);
    if (known != variables_.end() && known->second.source > variable.source) {
        return;
    }
    variables_[variable.name] = variable;
    expanded_.clear();  // a value may have used the old one
}

void VariableTable::giveResources(std::map<std::string, std::string> items) {
    resources_ = std::move(items);
    resourcesGiven_ = true;
    expanded_.clear();  // a value expanded before holds markers
}

const Variable* VariableTable::find(const std::string& name) const {
    auto known = variables_.find(name);
    return known == variables_.end() ? nullptr : &known->second;
}

std::vector<std::string> VariableTable::closeTo(const std::string& name) const {
    std::vector<std::pair<std::size_t, std::string>> close;
    const std::size_t limit = std::max<std::size_t>(2, name.size() / 3);
    for (const auto& variable : variables_) {
        const std::size_t distance = editDistance(name, variable.first);
        if (distance <= limit) {
            close.emplace_back(distance, variable.first);
        }
    }
    std::sort(close.begin(), close.end());
    std::vector<std::string> names;
    for (const auto& entry : close) {
        names.push_back(entry.second);
    }
    return names;
}

std::string VariableTable::expand(const std::string& text) {
    std::string out = expandText(text, "");
    total_ += out.size();
    return out;
}

std::string VariableTable::valueOf(const std::string& name) {
    // Not a use of `name` (used() is for the warning about --var nothing reads).
    if (variables_.count(name) == 0) {
        throw ExpandError{ExpandError::Kind::Undefined, name, "undefined variable ${" + name + "}"};
    }
    std::string value = resolve(name);
    if (total_ + value.size() > maxExpandedTotal) {
        throw ExpandError{ExpandError::Kind::TooMuch, name,
                          "the values of the file grow past 16 MiB together, their limit, once "
                          "${" +
                              name + "} is expanded (variables that expand each other?)"};
    }
    total_ += value.size();
    return value;
}

const std::string& VariableTable::resolve(const std::string& name) {
    auto done = expanded_.find(name);
    if (done != expanded_.end()) {
        return done->second;
    }
    auto cycleStart = std::find(resolving_.begin(), resolving_.end(), name);
    if (cycleStart != resolving_.end()) {
        std::string cycle;
        for (auto it = cycleStart; it != resolving_.end(); ++it) {
            cycle += *it + " -> ";
        }
        throw ExpandError{ExpandError::Kind::Cycle, name,
                          "variable ${" + name + "} refers to itself: " + cycle + name};
    }
    const Variable& variable = variables_.at(name);
    resolving_.push_back(name);
    std::string value;
    try {
        value = expandText(variable.value, name);
    } catch (...) {
        resolving_.pop_back();
        throw;
    }
    resolving_.pop_back();
    return expanded_[name] = std::move(value);
}

std::string VariableTable::expandText(const std::string& text, const std::string& context) {
    std::string out;
    auto checkSize = [&](const std::string& name) {
        if (out.size() > maxExpandedValue) {
            throw ExpandError{
                ExpandError::Kind::TooLong, name,
                (context.empty() ? std::string("a value") : "the value of ${" + context + "}") +
                    " grows past 1 MiB, the limit of one value, once ${" + name +
                    "} is expanded (variables that expand each other?)"};
        }
        if (total_ + out.size() > maxExpandedTotal) {
            throw ExpandError{ExpandError::Kind::TooMuch, name,
                              "the values of the file grow past 16 MiB together, their limit, "
                              "once ${" +
                                  name + "} is expanded (variables that expand each other?)"};
        }
    };
    std::size_t i = 0;
    while (i < text.size()) {
        // Every form below starts with '$': the text up to the next one is copied as it is, in
        // one piece (a suite of 10 000 tests expands every path and name).
        const std::size_t dollar = text.find('$', i);
        if (dollar != i) {
            const std::size_t end = dollar == std::string::npos ? text.size() : dollar;
            out.append(text, i, end - i);
            i = end;
            continue;
        }
        if (text.compare(i, 3, "$${") == 0 || text.compare(i, 3, "${{") == 0) {
            out += "${";
            i += 3;
            continue;
        }
        if (text.compare(i, 2, "${") != 0) {
            out += text[i++];
            continue;
        }
        const std::size_t close = text.find('}', i + 2);
        if (close == std::string::npos) {
            throw ExpandError{ExpandError::Kind::Unterminated, context,
                              "unterminated '${' at column " + std::to_string(i + 1) + " of '" +
                                  text + "' (write $${ for a literal ${)"};
        }
        const std::string name = text.substr(i + 2, close - i - 2);
        if (name.compare(0, 9, "resource.") == 0 && name.size() > 9 && resourcesGiven_) {
            const auto found = resources_.find(name.substr(9));
            if (found == resources_.end()) {
                throw ExpandError{ExpandError::Kind::PoolNotTaken, name,
                                  "${" + name + "} but the suite takes no item of pool " +
                                      name.substr(9) + " (add <resource pool=\"" + name.substr(9) +
                                      "\"/> to the suite)"};
            }
            out += found->second;
        } else if (name.compare(0, 9, "resource.") == 0 && name.size() > 9) {
            out += resourceMarker(name.substr(9));  // filled in when the suite is started
        } else if (name.compare(0, 4, "env:") == 0) {
            const char* value = std::getenv(name.substr(4).c_str());
            if (value == nullptr) {
                throw ExpandError{ExpandError::Kind::EnvironmentUnset, name,
                                  "environment variable '" + name.substr(4) +
                                      "' is not set (used as ${" + name + "})"};
            }
            out += value;
        } else {
            if (std::find(used_.begin(), used_.end(), name) == used_.end()) {
                used_.push_back(name);
            }
            if (variables_.count(name) == 0) {
                std::string message = "undefined variable ${" + name + "}";
                std::vector<std::string> close = closeTo(name);
                if (!close.empty()) {
                    message += "; did you mean";
                    for (std::size_t k = 0; k < close.size() && k < 3; ++k) {
                        message += (k == 0 ? " ${" : " or ${") + close[k] + "}";
                    }
                    message += "?";
                }
                throw ExpandError{ExpandError::Kind::Undefined, name, message};
            }
            out += resolve(name);
        }
        checkSize(name);
        i = close + 1;
    }
    return out;
}

bool isVariableName(const std::string& name) {
    if (name.empty() || (name[0] >= '0' && name[0] <= '9')) {
        return false;
    }
    return std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
               c == '_' || c == '-' || c == '.';
    });
}

bool parseAssignment(const std::string& text, std::string& name, std::string& value,
                     std::string& error) {
    // A NUL would end the name early in every later message.
    const std::size_t nul = text.find('\0');
    if (nul != std::string::npos) {
        error = "a NUL byte at column " + std::to_string(nul + 1);
        return false;
    }
    const std::size_t equal = text.find('=');
    if (equal == std::string::npos) {
        error = "no '=' in '" + text + "' (expected NAME=VALUE)";
        return false;
    }
    name = text.substr(0, equal);
    const std::size_t first = name.find_first_not_of(" \t");
    const std::size_t last = name.find_last_not_of(" \t");
    name = first == std::string::npos ? std::string() : name.substr(first, last - first + 1);
    if (name.empty()) {
        error = "no name before '=' at column " + std::to_string(equal + 1) + " of '" + text +
                "' (expected NAME=VALUE)";
        return false;
    }
    const std::size_t begin = text.find_first_not_of(" \t");
    for (std::size_t i = begin; i < begin + name.size(); ++i) {
        const char c = text[i];
        const bool letter =
            (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == '-' || c == '.';
        const bool digit = c >= '0' && c <= '9';
        if (!(letter || (digit && i != begin))) {
            error = "'" + std::string(1, c) + "' at column " + std::to_string(i + 1) + " of '" +
                    text +
                    "' is not allowed in a variable name (letters, digits, _, - and ., not "
                    "starting with a digit)";
            return false;
        }
    }
    value = text.substr(equal + 1);
    return true;
}

bool readVariableFile(const std::string& path, std::vector<Variable>& out, std::string& error) {
    // A regular file or a pipe (`<(...)`), of at most 16 MiB: /dev/zero is refused, not read
    // until memory runs out.
    std::string text;
    if (!platform::readBoundedFile(path, "variable file", maxExpandedTotal, platform::Pipes::Read,
                                   text, error)) {
        return false;
    }
    std::istringstream in(text);
    return readVariables(in, path, out, error);
}

bool readVariables(std::istream& in, const std::string& path, std::vector<Variable>& out,
                   std::string& error) {
    std::string line;
    unsigned int number = 0;
    std::size_t bytes = 0;
    while (std::getline(in, line)) {
        ++number;
        bytes += line.size();
        if (bytes > maxExpandedTotal) {
            error = path + ": the variable file is larger than 16 MiB";
            return false;
        }
        if (!line.empty() && line.back() == '\r') {
            line.pop_back();
        }
        const std::size_t first = line.find_first_not_of(" \t");
        if (first == std::string::npos || line[first] == '#') {
            continue;
        }
        Variable variable;
        std::string problem;
        if (!parseAssignment(line, variable.name, variable.value, problem)) {
            error = path + ":" + std::to_string(number) + ": " + problem;
            return false;
        }
        const std::size_t begin = variable.value.find_first_not_of(" \t");
        const std::size_t end = variable.value.find_last_not_of(" \t");
        variable.value = begin == std::string::npos ? std::string()
                                                    : variable.value.substr(begin, end - begin + 1);
        variable.source = Source::VarFile;
        variable.origin = path + ":" + std::to_string(number);
        out.push_back(std::move(variable));
    }
    if (in.bad()) {
        error = path + ": cannot read the variable file";
        return false;
    }
    return true;
}

std::string escape(const std::string& value) {
    std::string out;
    for (std::size_t i = 0; i < value.size(); ++i) {
        if (value.compare(i, 2, "${") == 0) {
            out += "$${";
            ++i;
        } else {
            out += value[i];
        }
    }
    return out;
}

namespace {
const char markerEdge = '\x1e';  // ASCII record separator: never in a suite file's text
const std::string markerStart = std::string(1, markerEdge) + "resource.";
}  // namespace

std::string resourceMarker(const std::string& pool) {
    return markerStart + pool + markerEdge;
}

std::string fillResources(const std::string& text,
                          const std::function<std::string(const std::string&)>& value) {
    std::string out;
    std::size_t from = 0;
    for (;;) {
        const std::size_t start = text.find(markerStart, from);
        const std::size_t end = start == std::string::npos
                                    ? std::string::npos
                                    : text.find(markerEdge, start + markerStart.size());
        if (end == std::string::npos) {
            return out + text.substr(from);
        }
        out += text.substr(from, start - from);
        out += value(text.substr(start + markerStart.size(), end - start - markerStart.size()));
        from = end + 1;
    }
}

std::vector<std::string> resourcesUsed(const std::string& text) {
    std::vector<std::string> pools;
    if (text.find(markerStart) == std::string::npos) {
        return pools;  // the common case, asked for each test's param and environment
    }
    fillResources(text, [&pools](const std::string& pool) {
        pools.push_back(pool);
        return std::string();
    });
    return pools;
}

}  // namespace variables
}  // namespace robottestingframework
