#include "languages/exec/tap_records.h"

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

}  // namespace languages
}  // namespace robottestingframework
