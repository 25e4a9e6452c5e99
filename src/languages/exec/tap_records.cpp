#include "languages/exec/tap_records.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>

namespace robottestingframework {
namespace languages {

namespace {

using Item = std::map<std::string, std::string>;

std::size_t indentOf(const std::string& line) {
    std::size_t at = 0;
    while (at < line.size() && line[at] == ' ') {
        ++at;
    }
    return at;
}

std::string trimmed(const std::string& text) {
    const std::size_t begin = text.find_first_not_of(" \t\r");
    if (begin == std::string::npos) {
        return std::string();
    }
    return text.substr(begin, text.find_last_not_of(" \t\r") - begin + 1);
}

// A YAML scalar: "double quoted" (with \" \\ \n \t), 'single quoted' ('' for '), or plain
// (a " #" starts a comment).
std::string scalar(const std::string& raw) {
    const std::string text = trimmed(raw);
    if (text.size() >= 2 && text.front() == '"' && text.back() == '"') {
        std::string out;
        for (std::size_t i = 1; i + 1 < text.size(); ++i) {
            if (text[i] == '\\' && i + 2 < text.size()) {
                const char next = text[++i];
                out += next == 'n' ? '\n' : next == 't' ? '\t' : next;
            } else {
                out += text[i];
            }
        }
        return out;
    }
    if (text.size() >= 2 && text.front() == '\'' && text.back() == '\'') {
        std::string out;
        for (std::size_t i = 1; i + 1 < text.size(); ++i) {
            out += text[i];
            if (text[i] == '\'' && text[i + 1] == '\'') {
                ++i;
            }
        }
        return out;
    }
    const std::size_t comment = text.find(" #");
    return trimmed(comment == std::string::npos ? text : text.substr(0, comment));
}

void keyValue(const std::string& text, Item& item) {
    const std::size_t colon = text.find(':');
    if (colon == std::string::npos) {
        return;
    }
    item[trimmed(text.substr(0, colon))] = scalar(text.substr(colon + 1));
}

bool isNull(const std::string& value) {
    return value.empty() || value == "~" || value == "null";
}

// A YAML number, .inf and .nan included (so that they are refused as not finite, by name).
// `tooLarge`: a finite number written beyond a double's range (1e400), which strtod makes
// infinite.
bool number(const std::string& text, double& value, bool& tooLarge) {
    tooLarge = false;
    if (text == ".inf" || text == "+.inf" || text == ".Inf") {
        value = std::numeric_limits<double>::infinity();
        return true;
    }
    if (text == "-.inf" || text == "-.Inf") {
        value = -std::numeric_limits<double>::infinity();
        return true;
    }
    if (text == ".nan" || text == ".NaN") {
        value = std::numeric_limits<double>::quiet_NaN();
        return true;
    }
    char* end = nullptr;
    errno = 0;
    value = std::strtod(text.c_str(), &end);
    tooLarge = errno == ERANGE && std::isinf(value);
    return !text.empty() && end == text.c_str() + text.size();
}

// Why `text` is no number a measurement can hold, quoting it as it was written: empty when it
// is one. A finite number too large for a double (1e400) is refused by what was written, not
// as the infinity strtod makes of it.
std::string notANumber(const std::string& key, const std::string& text, double& value) {
    bool tooLarge = false;
    if (!number(text, value, tooLarge)) {
        return key + " '" + text + "' is not a number";
    }
    if (tooLarge) {
        return key + " '" + text + "' is too large: a measurement holds at most 1.8e308";
    }
    return {};
}

void addMeasurement(const Item& item, std::size_t index, TapRecords& records) {
    const std::string where = "measurements item " + std::to_string(index) + ": ";
    auto field = [&item](const char* key) {
        const auto found = item.find(key);
        return found == item.end() ? std::string() : found->second;
    };
    Measurement measurement;
    measurement.name = field("name");
    measurement.unit = isNull(field("unit")) ? std::string() : field("unit");
    const std::string problem = notANumber("value", field("value"), measurement.value);
    if (!problem.empty()) {
        records.problems.push_back(where + problem);
        return;
    }
    for (const char* key : {"low", "high"}) {
        const std::string text = field(key);
        if (isNull(text)) {
            continue;
        }
        double limit = 0;
        const std::string problem = notANumber(key, text, limit);
        if (!problem.empty()) {
            records.problems.push_back(where + problem);
            return;
        }
        (key[0] == 'l' ? measurement.low : measurement.high) = limit;
    }
    records.measurements.push_back(measurement);
}

void addAttachment(const Item& item, std::size_t index, TapRecords& records) {
    const auto path = item.find("path");
    if (path == item.end() || path->second.empty()) {
        records.problems.push_back("attachments item " + std::to_string(index) +
                                   ": it has no path");
        return;
    }
    const auto description = item.find("description");
    records.attachments.push_back(
        {path->second, description == item.end() ? std::string() : description->second});
}

}  // namespace

TapRecords readTapRecords(const std::string& diagnostics) {
    TapRecords records;
    enum class Block { None, Measurements, Attachments } block = Block::None;
    std::size_t blockIndent = 0;
    std::vector<Item> items;
    auto close = [&]() {
        for (std::size_t i = 0; i < items.size(); ++i) {
            if (block == Block::Measurements) {
                addMeasurement(items[i], i + 1, records);
            } else if (block == Block::Attachments) {
                addAttachment(items[i], i + 1, records);
            }
        }
        items.clear();
        block = Block::None;
    };
    std::size_t begin = 0;
    while (begin <= diagnostics.size()) {
        std::size_t end = diagnostics.find('\n', begin);
        if (end == std::string::npos) {
            end = diagnostics.size();
        }
        const std::string line = diagnostics.substr(begin, end - begin);
        begin = end + 1;
        const std::string content = trimmed(line);
        if (content.empty() || content[0] == '#') {
            continue;
        }
        const std::size_t indent = indentOf(line);
        if (block != Block::None && indent <= blockIndent && content[0] != '-') {
            close();
        }
        if (block == Block::None) {
            if (content == "measurements:" || content == "attachments:") {
                block = content[0] == 'm' ? Block::Measurements : Block::Attachments;
                blockIndent = indent;
            }
            continue;
        }
        if (content[0] == '-') {
            items.emplace_back();
            keyValue(content.substr(1), items.back());
        } else if (!items.empty()) {
            keyValue(content, items.back());
        }
    }
    close();
    return records;
}

std::string withoutTapRecords(const std::string& diagnostics) {
    // The block's keys are at the indent of its first line that says something.
    std::size_t base = std::string::npos;
    std::string kept;
    bool skipping = false;
    bool anyKept = false;
    std::size_t at = 0;
    while (at < diagnostics.size()) {
        std::size_t end = diagnostics.find('\n', at);
        end = end == std::string::npos ? diagnostics.size() : end + 1;
        const std::string line = diagnostics.substr(at, end - at);
        at = end;
        const std::size_t indent = line.find_first_not_of(' ');
        const bool blank =
            indent == std::string::npos || line.find_first_not_of(" \t\r\n") == std::string::npos;
        if (!blank) {
            base = base == std::string::npos ? indent : base;
            if (indent <= base) {
                skipping = line.compare(indent, 13, "measurements:") == 0 ||
                           line.compare(indent, 12, "attachments:") == 0;
            }
        }
        if (!skipping) {
            kept += line;
            anyKept = anyKept || !blank;
        }
    }
    return anyKept ? kept : std::string();
}

namespace {

// The lines of `text`, '\r' dropped.
std::vector<std::string> linesOf(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t begin = 0;
    while (begin < text.size()) {
        std::size_t end = text.find('\n', begin);
        end = end == std::string::npos ? text.size() : end;
        std::string line = text.substr(begin, end - begin);
        if (!line.empty() && line.back() == '\r') {
            line.pop_back();
        }
        lines.push_back(std::move(line));
        begin = end + 1;
    }
    return lines;
}

// Where a top-level `key:` ends (the colon), or npos: a key is plain or quoted text followed
// by ':' and a space or the line's end, not a list item.
std::size_t keyEnd(const std::string& content) {
    if (content.empty() || content[0] == '-' || content[0] == '#') {
        return std::string::npos;
    }
    std::size_t from = 0;
    if (content[0] == '"' || content[0] == '\'') {
        from = content.find(content[0], 1);
        if (from == std::string::npos) {
            return std::string::npos;
        }
    }
    for (std::size_t at = content.find(':', from); at != std::string::npos;
         at = content.find(':', at + 1)) {
        if (at + 1 == content.size() || content[at + 1] == ' ') {
            return at;
        }
    }
    return std::string::npos;
}

// `lines` unindented by the least indent among them, blank lines kept empty, trailing ones
// dropped; joined with '\n'.
std::string unindented(const std::vector<std::string>& lines) {
    std::size_t least = std::string::npos;
    for (const std::string& line : lines) {
        if (!trimmed(line).empty()) {
            least = std::min(least, indentOf(line));
        }
    }
    std::string text;
    std::size_t pendingBlank = 0;
    for (const std::string& line : lines) {
        if (trimmed(line).empty()) {
            ++pendingBlank;
            continue;
        }
        if (!text.empty()) {
            text += std::string(pendingBlank + 1, '\n');
        }
        pendingBlank = 0;
        text += line.substr(least);
    }
    return text;
}

}  // namespace

TestMessage::Diagnostics tapDiagnostics(const std::string& diagnostics) {
    const std::vector<std::string> lines = linesOf(diagnostics);
    std::size_t base = std::string::npos;
    for (const std::string& line : lines) {
        const std::string content = trimmed(line);
        if (!content.empty() && content[0] != '#') {
            base = indentOf(line);
            break;
        }
    }
    TestMessage::Diagnostics found;
    if (base == std::string::npos) {
        return found;
    }
    // The key being read: its inline value, and the lines below it.
    std::string key, inline_;
    bool haveKey = false;
    std::vector<std::string> below;
    auto close = [&]() {
        if (!haveKey) {
            return;
        }
        std::string value;
        const std::string block = unindented(below);
        if (inline_.empty()) {
            value = block;  // a nested map or list
        } else if (inline_[0] == '|' || inline_[0] == '>') {
            value = block;  // a block scalar, its lines as written
        } else {
            value = scalar(inline_);
            if (!block.empty()) {  // a plain scalar that goes on below
                value += "\n" + block;
            }
        }
        // A key given again: its last value, in the first one's place (as YAML readers that
        // allow repeats read it; the reports write each key once).
        const auto given = std::find_if(found.begin(), found.end(),
                                        [&](const auto& entry) { return entry.first == key; });
        if (given == found.end()) {
            found.emplace_back(key, value);
        } else {
            given->second = value;
        }
        below.clear();
        haveKey = false;
    };
    for (const std::string& line : lines) {
        const std::string content = trimmed(line);
        if (content.empty() || content[0] == '#') {
            if (haveKey && !content.empty() && indentOf(line) > base) {
                below.push_back(line);
            } else if (haveKey && content.empty()) {
                below.push_back(std::string());
            }
            continue;
        }
        const std::size_t colon = indentOf(line) == base ? keyEnd(content) : std::string::npos;
        if (colon == std::string::npos) {
            if (!haveKey) {
                key = "yaml";
                inline_.clear();
                haveKey = true;
            }
            below.push_back(line);
            continue;
        }
        close();
        key = scalar(content.substr(0, colon));
        inline_ = trimmed(content.substr(colon + 1));
        if (!inline_.empty() && inline_[0] == '#') {
            inline_.clear();
        }
        haveKey = true;
    }
    close();
    return found;
}

}  // namespace languages
}  // namespace robottestingframework
