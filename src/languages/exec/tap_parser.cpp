#include "tap_parser.h"

#include <cctype>
#include <cstddef>

namespace robottestingframework {
namespace languages {

namespace {

std::size_t leadingSpaces(const std::string& line) {
    std::size_t n = 0;
    while (n < line.size() && line[n] == ' ') {
        ++n;
    }
    return n;
}

bool isBlank(const std::string& line) {
    for (char c : line) {
        if (!std::isspace(static_cast<unsigned char>(c))) {
            return false;
        }
    }
    return true;
}

std::string trim(const std::string& text) {
    std::size_t begin = 0;
    std::size_t end = text.size();
    while (begin < end && std::isspace(static_cast<unsigned char>(text[begin]))) {
        ++begin;
    }
    while (end > begin && std::isspace(static_cast<unsigned char>(text[end - 1]))) {
        --end;
    }
    return text.substr(begin, end - begin);
}

bool startsWith(const std::string& text, const char* prefix) {
    return text.rfind(prefix, 0) == 0;
}

bool startsWithWordNoCase(const std::string& text, const char* word) {
    std::size_t i = 0;
    for (; word[i] != '\0'; ++i) {
        if (i >= text.size() || std::tolower(static_cast<unsigned char>(text[i])) != word[i]) {
            return false;
        }
    }
    return true;
}

// Reads "123" at `pos`; false when there is no digit there.
bool readNumber(const std::string& text, std::size_t& pos, unsigned long& value) {
    std::size_t start = pos;
    value = 0;
    while (pos < text.size() && std::isdigit(static_cast<unsigned char>(text[pos]))) {
        value = value * 10 + static_cast<unsigned long>(text[pos] - '0');
        ++pos;
    }
    return pos > start;
}

// "a \# b" -> "a # b"; "\\" -> "\".
std::string unescape(const std::string& text) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '\\' && i + 1 < text.size() && (text[i + 1] == '#' || text[i + 1] == '\\')) {
            ++i;
        }
        out += text[i];
    }
    return out;
}

// The directive's text after its keyword ("SKIP", "skipped: no robot", "TODO later").
std::string directiveReason(const std::string& text) {
    std::size_t i = 0;
    while (i < text.size() && std::isalpha(static_cast<unsigned char>(text[i]))) {
        ++i;
    }
    std::string reason = trim(text.substr(i));
    if (!reason.empty() && reason[0] == ':') {
        reason = trim(reason.substr(1));
    }
    return reason;
}

class Parser {
public:
    Parser(const std::string& text, TapStream& out) : out_(out) {
        std::size_t start = 0;
        while (start < text.size()) {
            std::size_t end = text.find('\n', start);
            if (end == std::string::npos) {
                end = text.size();
            }
            std::string line = text.substr(start, end - start);
            if (!line.empty() && line.back() == '\r') {
                line.pop_back();
            }
            lines_.push_back(std::move(line));
            start = end + 1;
        }
    }

    void parse() {
        Level top = block(0, lines_.size(), 0, "");
        out_.isTap = top.sawVersion || top.planned >= 0 || top.count > 0 || out_.bailedOut;
        if (!out_.isTap) {
            // Plain output that happens to contain a comment or two: none of it is TAP.
            out_.comments.clear();
            out_.problems.clear();
            out_.otherText.clear();
            for (const auto& line : lines_) {
                out_.otherText.push_back(line);
            }
            while (!out_.otherText.empty() && isBlank(out_.otherText.back())) {
                out_.otherText.pop_back();
            }
        }
    }

private:
    struct Level {
        bool sawVersion = false;
        long planned = -1;
        unsigned int planLine = 0;
        unsigned int count = 0;
        unsigned int beforePlan = 0;
        unsigned int afterPlan = 0;
    };

    void problem(std::size_t index, const std::string& path, const std::string& message) {
        TapProblem p;
        p.line = index == std::string::npos ? 0 : static_cast<unsigned int>(index + 1);
        p.message = path.empty() ? message : "subtest '" + path + "': " + message;
        out_.problems.push_back(std::move(p));
    }

    // Parses lines [begin, end) that belong to one stream indented by `indent` spaces.
    Level block(std::size_t begin, std::size_t end, std::size_t indent, const std::string& path) {
        Level level;
        std::string subtestName;
        long lastPoint = -1;  // index in out_.points a YAML block would belong to
        for (std::size_t i = begin; i < end && !out_.bailedOut; ++i) {
            const std::string& line = lines_[i];
            if (isBlank(line)) {
                continue;
            }
            std::size_t lead = leadingSpaces(line);
            if (lastPoint >= 0 && lead == indent + 2 && trim(line) == "---") {
                i = yamlBlock(i, end, indent + 2, out_.points[static_cast<std::size_t>(lastPoint)],
                              path);
                lastPoint = -1;
                continue;
            }
            lastPoint = -1;
            if (lead >= indent + 4) {
                i = subtest(i, end, indent, path, subtestName) - 1;
                subtestName.clear();
                continue;
            }
            if (lead != indent) {
                out_.otherText.push_back(line);
                continue;
            }
            std::string content = line.substr(indent);
            if (startsWith(content, "TAP version ")) {
                std::size_t pos = 12;
                unsigned long version = 0;
                if (!readNumber(content, pos, version) || version < 12 || version > 14) {
                    problem(i, path, "unsupported '" + content + "' (versions 12 to 14 are)");
                } else if (indent == 0) {
                    out_.version = static_cast<int>(version);
                }
                level.sawVersion = true;
            } else if (startsWith(content, "1..")) {
                plan(i, content, path, indent, level);
            } else if (startsWith(content, "ok") || startsWith(content, "not ok")) {
                if (!point(i, content, path, level)) {
                    out_.otherText.push_back(line);
                    continue;
                }
                lastPoint = static_cast<long>(out_.points.size()) - 1;
                subtestName.clear();
            } else if (startsWith(content, "Bail out!")) {
                out_.bailedOut = true;
                out_.bailOutReason = trim(content.substr(9));
            } else if (startsWith(content, "#")) {
                std::string comment = trim(content.substr(1));
                if (startsWith(comment, "Subtest")) {
                    std::string name = trim(comment.substr(7));
                    if (!name.empty() && name[0] == ':') {
                        name = trim(name.substr(1));
                    }
                    subtestName = name;
                } else {
                    out_.comments.push_back(comment);
                }
            } else if (startsWith(content, "pragma ")) {
                // Parser pragmas change nothing here.
            } else {
                out_.otherText.push_back(line);
            }
        }
        if (!out_.bailedOut) {
            checkPlan(path, level);
        }
        return level;
    }

    void plan(std::size_t i, const std::string& content, const std::string& path,
              std::size_t indent, Level& level) {
        std::size_t pos = 3;
        unsigned long planned = 0;
        if (!readNumber(content, pos, planned)) {
            problem(i, path, "malformed plan '" + content + "'");
            return;
        }
        if (level.planned >= 0) {
            problem(i, path, "more than one plan");
            return;
        }
        level.planned = static_cast<long>(planned);
        level.planLine = static_cast<unsigned int>(i + 1);
        level.beforePlan = level.count;
        std::string rest = trim(content.substr(pos));
        if (planned == 0 && indent == 0) {
            out_.skipAll = true;
            if (!rest.empty() && rest[0] == '#') {
                rest = trim(rest.substr(1));
                out_.skipReason = startsWithWordNoCase(rest, "skip") ? directiveReason(rest) : rest;
            }
        }
    }

    bool point(std::size_t i, const std::string& content, const std::string& path, Level& level) {
        TapPoint p;
        p.ok = startsWith(content, "ok");
        std::size_t pos = p.ok ? 2 : 6;
        if (pos < content.size() && content[pos] != ' ' && content[pos] != '#') {
            return false;  // "okay", "oknot": not a test line
        }
        while (pos < content.size() && content[pos] == ' ') {
            ++pos;
        }
        unsigned long number = 0;
        bool numbered = readNumber(content, pos, number);
        ++level.count;
        if (numbered && number != level.count) {
            problem(i, path,
                    "test number " + std::to_string(number) + " out of sequence (expected " +
                        std::to_string(level.count) + ")");
        }
        p.number = numbered ? static_cast<unsigned int>(number) : level.count;
        std::string rest = content.substr(pos);
        // The description ends at the first unescaped '#': a directive may follow.
        std::size_t hash = std::string::npos;
        for (std::size_t k = 0; k < rest.size(); ++k) {
            if (rest[k] == '\\') {
                ++k;
            } else if (rest[k] == '#') {
                hash = k;
                break;
            }
        }
        std::string description = trim(rest.substr(0, hash));
        if (startsWith(description, "-")) {
            description = trim(description.substr(1));
        }
        p.description = unescape(description);
        if (hash != std::string::npos) {
            std::string directive = trim(rest.substr(hash + 1));
            if (startsWithWordNoCase(directive, "skip")) {
                p.directive = TapPoint::Directive::Skip;
                p.reason = directiveReason(directive);
            } else if (startsWithWordNoCase(directive, "todo")) {
                p.directive = TapPoint::Directive::Todo;
                p.reason = directiveReason(directive);
            } else if (!directive.empty()) {
                p.description += " # " + directive;
            }
        }
        p.subtest = path;
        p.line = static_cast<unsigned int>(i + 1);
        if (level.planned >= 0) {
            ++level.afterPlan;
        }
        out_.points.push_back(std::move(p));
        return true;
    }

    // Reads the YAML block starting at `i` ("---"); returns the index of its "..." line.
    std::size_t yamlBlock(std::size_t i, std::size_t end, std::size_t indent, TapPoint& point,
                          const std::string& path) {
        std::string yaml;
        for (std::size_t k = i + 1; k < end; ++k) {
            const std::string& line = lines_[k];
            if (leadingSpaces(line) == indent && trim(line) == "...") {
                point.diagnostics = yaml;
                return k;
            }
            yaml += (line.size() >= indent ? line.substr(indent) : trim(line)) + "\n";
        }
        problem(i, path, "YAML block not closed with '...'");
        point.diagnostics = yaml;
        return end - 1;
    }

    // Parses the indented stream starting at `i`; returns the index after it.
    std::size_t subtest(std::size_t i, std::size_t end, std::size_t indent, const std::string& path,
                        std::string name) {
        std::size_t j = i;
        while (j < end && (isBlank(lines_[j]) || leadingSpaces(lines_[j]) >= indent + 4)) {
            ++j;
        }
        // The older form names the subtest on the first line of the indented stream.
        std::string first = trim(lines_[i]);
        std::size_t from = i;
        if (name.empty() && startsWith(first, "# Subtest")) {
            name = trim(first.substr(9));
            if (!name.empty() && name[0] == ':') {
                name = trim(name.substr(1));
            }
            from = i + 1;
        }
        if (name.empty()) {
            name = "subtest";
        }
        block(from, j, indent + 4, path.empty() ? name : path + " > " + name);
        return j;
    }

    void checkPlan(const std::string& path, const Level& level) {
        if (level.planned < 0) {
            if (level.count > 0 || level.sawVersion) {
                problem(std::string::npos, path,
                        "no plan (expected a line '1.." + std::to_string(level.count) + "')");
            }
            return;
        }
        if (level.beforePlan > 0 && level.afterPlan > 0) {
            problem(level.planLine - 1, path,
                    "the plan must come before the first test or after the last one");
        }
        if (static_cast<unsigned long>(level.planned) != level.count) {
            problem(level.planLine - 1, path,
                    "planned " + std::to_string(level.planned) + " test(s) but ran " +
                        std::to_string(level.count));
        }
    }

    std::vector<std::string> lines_;
    TapStream& out_;
};

}  // namespace

bool TapStream::failed() const {
    if (bailedOut || !problems.empty()) {
        return true;
    }
    for (const auto& point : points) {
        if (point.failed()) {
            return true;
        }
    }
    return false;
}

TapStream parseTap(const std::string& text) {
    TapStream stream;
    Parser(text, stream).parse();
    return stream;
}

}  // namespace languages
}  // namespace robottestingframework
