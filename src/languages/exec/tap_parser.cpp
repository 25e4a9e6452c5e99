#include "languages/exec/tap_parser.h"

#include <cctype>
#include <cstddef>
#include <cstring>
#include <utility>

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

// "N..M" starts a plan line (the line may still be a malformed one).
bool startsAsPlan(const std::string& content) {
    std::size_t pos = 0;
    unsigned long ignored = 0;
    return readNumber(content, pos, ignored) && content.compare(pos, 2, "..") == 0;
}

// Point numbers told apart (to find one given twice) in a whole stream, over all its levels:
// 1 MiB of bits. A stream that numbers beyond it has its repeats there untold.
constexpr std::size_t kMaxTrackedNumbers = 8 * 1024 * 1024;

// Lines held back before the stream is known to be TAP, at most this many bytes.
constexpr std::size_t kMaxHeld = 64 * 1024;
// Subtest paths name at most this many levels ("a > b > ... > y > z"), so that deep nesting
// costs linear time.
constexpr std::size_t kPathHead = 2;
constexpr std::size_t kPathTail = 3;
constexpr std::size_t kMaxSubtestName = 256;

std::string subtestName(const std::string& afterKeyword) {
    std::string name = trim(afterKeyword);
    if (!name.empty() && name[0] == ':') {
        name = trim(name.substr(1));
    }
    return name.size() > kMaxSubtestName ? name.substr(0, kMaxSubtestName) + "..." : name;
}

}  // namespace

void TapParser::feed(const char* data, std::size_t size) {
    while (size > 0) {
        const char* newline = static_cast<const char*>(std::memchr(data, '\n', size));
        std::size_t take = newline ? static_cast<std::size_t>(newline - data) : size;
        std::size_t room = kMaxTapLine > partial_.size() ? kMaxTapLine - partial_.size() : 0;
        partial_.append(data, take < room ? take : room);
        partialCut_ += take > room ? take - room : 0;
        if (!newline) {
            return;
        }
        std::string text = std::move(partial_);
        partial_.clear();
        if (partialCut_ > 0) {
            text += " [... " + std::to_string(partialCut_) + " more bytes of this line dropped]";
            partialCut_ = 0;
        }
        line(std::move(text));
        data += take + 1;
        size -= take + 1;
    }
}

void TapParser::line(std::string text) {
    if (finished_) {
        return;
    }
    ++lineNumber_;
    if (!text.empty() && text.back() == '\r') {
        text.pop_back();
    }
    if (text.size() > kMaxTapLine) {
        std::size_t cut = text.size() - kMaxTapLine;
        text.resize(kMaxTapLine);
        text += " [... " + std::to_string(cut) + " more bytes of this line dropped]";
    }
    if (!isTap_) {
        heldBytes_ += text.size() + 1;
        held_.push_back(Held{Held::Kind::Line, text, false, {}});
        lineItem_ = held_.size() - 1;
    }
    process(text);
    while (!isTap_ && heldBytes_ > kMaxHeld && !held_.empty()) {
        // Too much before any TAP: the oldest lines are plain output after all.
        Held& oldest = held_.front();
        if (oldest.kind == Held::Kind::Line) {
            heldBytes_ -= oldest.raw.size() + 1;
            giveText(oldest.raw);
        }
        held_.pop_front();
        lineItem_ = lineItem_ > 0 ? lineItem_ - 1 : 0;
    }
}

void TapParser::process(const std::string& text) {
    if (bailedOut_) {
        emitText(text);  // after a bail out nothing is TAP any more
        return;
    }
    const bool blank = isBlank(text);
    const std::size_t lead = leadingSpaces(text);
    if (inYaml_) {
        const std::size_t indent = pendingIndent_ + 2;
        if (blank || lead >= indent) {
            if (lead == indent && trim(text) == "...") {
                closeYaml(true);
            } else if (pending_.diagnostics.size() < kMaxTapLine) {
                pending_.diagnostics += (blank ? std::string() : text.substr(indent)) + "\n";
            }
            return;
        }
        // A less indented line: text and comments are tolerated inside the block (TAP 14:
        // invalid lines should not fail a run); a TAP line means the block was not YAML
        // after all (its lines stay the point's diagnostics) and is read as what it is.
        const std::string content = text.substr(lead);
        if (!endsSubtests(content) && !startsWith(content, "pragma ")) {
            if (startsWith(content, "#")) {
                emitComment(trim(content.substr(1)));
            } else {
                nonTap(text);
            }
            return;
        }
        closeYaml(true);
    }
    if (blank) {
        return;
    }
    if (havePending_ && lead == pendingIndent_ + 2 && trim(text) == "---") {
        inYaml_ = true;
        yamlLine_ = lineNumber_;
        return;
    }
    flushPending();
    if (levels_.size() > 1 && lead < levels_.back().indent && !endsSubtests(text.substr(lead))) {
        // A less indented line that is not TAP (text, a comment) inside a subtest: TAP 14 reads
        // it as what it is, and the subtest goes on.
        const std::string content = text.substr(lead);
        if (startsWith(content, "#")) {
            emitComment(trim(content.substr(1)));
        } else {
            nonTap(text);
        }
        return;
    }
    while (levels_.size() > 1 && lead < levels_.back().indent) {
        closeLevel();
    }
    // A deeper line starts a subtest (one level per four spaces).
    while (lead >= levels_.back().indent + 4) {
        Level& parent = levels_.back();
        Level child;
        child.indent = parent.indent + 4;
        child.strict = parent.strict;
        child.name = std::move(parent.nextSubtest);
        parent.nextSubtest.clear();
        bool namesIt = false;
        if (child.name.empty() && lead == child.indent) {
            std::string content = text.substr(lead);
            if (startsWith(content, "# Subtest")) {
                child.name = subtestName(content.substr(9));  // the older form names it first
                namesIt = true;
            }
        }
        if (child.name.empty()) {
            child.name = "subtest";
        }
        levels_.push_back(std::move(child));
        if (namesIt) {
            return;
        }
    }
    Level& level = levels_.back();
    if (lead != level.indent) {
        nonTap(text);
        return;
    }
    std::string content = text.substr(lead);
    if (startsWith(content, "TAP version ")) {
        if (levels_.size() == 1) {
            decideTap();
        }
        std::size_t pos = 12;
        unsigned long version = 0;
        if (!readNumber(content, pos, version) || version < 12 || version > 14) {
            emitProblem(lineNumber_, "unsupported '" + content + "' (versions 12 to 14 are)");
        } else if (version == 12 && level.strict) {
            // TAP 12 has no version line (13 brought it): not TAP, which strict refuses.
            emitProblem(lineNumber_, "'" + content +
                                         "' is not TAP (TAP 12 has no version line; pragma "
                                         "+strict)");
        } else if (levels_.size() == 1) {
            version_ = static_cast<int>(version);
        }
        level.sawVersion = true;
    } else if (startsAsPlan(content)) {
        plan(content);
    } else if (startsWith(content, "ok") || startsWith(content, "not ok")) {
        if (!point(content)) {
            nonTap(text);
        }
    } else if (startsWithWordNoCase(content, "bail out!")) {
        // TAP 14: the words are case-insensitive, and the reason may escape '#' and '\'.
        decideTap();
        bailedOut_ = true;
        bailOutReason_ = unescape(trim(content.substr(9)));
        bailOutLine_ = lineNumber_;
    } else if (startsWith(content, "#")) {
        std::string comment = trim(content.substr(1));
        if (startsWith(comment, "Subtest")) {
            level.nextSubtest = subtestName(comment.substr(7));
        } else {
            emitComment(comment);
        }
    } else if (startsWith(content, "pragma ")) {
        // "pragma +strict" and "pragma -strict" (tap-parser's): whether a line that is not
        // TAP fails the stream, from here on, at this level and in the subtests it starts.
        // Other pragmas change nothing here.
        const std::string pragma = trim(content.substr(7));
        if (pragma == "+strict" || pragma == "-strict") {
            level.strict = pragma[0] == '+';
        }
    } else {
        nonTap(text);
    }
}

void TapParser::nonTap(const std::string& raw) {
    emitText(raw);
    if (levels_.back().strict) {
        emitProblem(lineNumber_,
                    "a line that is not TAP, under pragma +strict: '" + trim(raw) + "'");
    }
}

bool TapParser::firstTimeNumbered(unsigned long number) {
    std::vector<bool>& seen = levels_.back().seen;
    if (number < seen.size()) {
        const bool first = !seen[number];
        seen[number] = true;
        return first;
    }
    const std::size_t grown = static_cast<std::size_t>(number) + 1;
    if (number >= kMaxTrackedNumbers ||
        trackedNumbers_ + (grown - seen.size()) > kMaxTrackedNumbers) {
        return true;  // beyond the budget: not told
    }
    trackedNumbers_ += grown - seen.size();
    seen.resize(grown, false);
    seen[number] = true;
    return true;
}

// A line that is TAP of its own (a test point, a plan, a version, a bail out): less indented
// than the open subtests, it ends them. Anything else does not: text, and comments, a
// "# Subtest:" one too (TAP 14: the parent's test point ends a subtest; a stray "# Subtest:"
// inside one is a comment and names nothing).
bool TapParser::endsSubtests(const std::string& content) const {
    if (startsWith(content, "ok") || startsWith(content, "not ok")) {
        const std::size_t after = startsWith(content, "ok") ? 2 : 6;
        return after == content.size() || content[after] == ' ' || content[after] == '#';
    }
    return startsAsPlan(content) || startsWith(content, "TAP version ") ||
           startsWithWordNoCase(content, "bail out!");
}

// "N..M", then nothing or " # comment": the points numbered N to M (usually 1..M); "1..0" is
// a stream that skips everything. Anything else after the numbers, trailing spaces too, is a
// malformed plan. A plan whose end is before its start (and is not 1..0) is not TAP.
void TapParser::plan(const std::string& content) {
    Level& level = levels_.back();
    std::size_t pos = 0;
    unsigned long start = 0;
    unsigned long end = 0;
    readNumber(content, pos, start);
    pos += 2;  // ".."
    const bool wellFormed =
        readNumber(content, pos, end) &&
        (pos == content.size() || (std::isspace(static_cast<unsigned char>(content[pos])) &&
                                   trim(content.substr(pos)).rfind('#', 0) == 0));
    if (!wellFormed) {
        emitProblem(lineNumber_, "malformed plan '" + content +
                                     "' (a plan is 'N..M', and may be followed by ' # comment')");
        return;
    }
    const bool top = levels_.size() == 1;
    if (end < start && !(start == 1 && end == 0)) {
        if (top) {
            decideTap();
        }
        nonTap(content);
        return;
    }
    if (top) {
        decideTap();
    }
    if (level.planned >= 0) {
        emitProblem(lineNumber_, "more than one plan");
        return;
    }
    level.planned = static_cast<long>(end - start + 1);
    level.planStart = start;
    level.planEnd = end;
    level.planLine = lineNumber_;
    level.beforePlan = level.count;
    std::string rest = trim(content.substr(pos));
    if (start == 1 && end == 0) {
        level.planned = 0;
        if (top) {
            skipAll_ = true;
            if (!rest.empty() && rest[0] == '#') {
                rest = trim(rest.substr(1));
                skipReason_ = startsWithWordNoCase(rest, "skip") ? directiveReason(rest) : rest;
            }
        }
    }
}

bool TapParser::point(const std::string& content) {
    Level& level = levels_.back();
    TapPoint p;
    p.ok = startsWith(content, "ok");
    std::size_t pos = p.ok ? 2 : 6;
    if (pos < content.size() && content[pos] != ' ' && content[pos] != '#') {
        return false;  // "okay", "oknot": not a test line
    }
    decideTap();
    while (pos < content.size() && content[pos] == ' ') {
        ++pos;
    }
    unsigned long number = 0;
    bool numbered = readNumber(content, pos, number);
    ++level.count;
    // TAP 14: numbers out of order are valid ("ok 1", "ok 3", "ok 2"); one outside the plan is
    // checked when the level ends (only the highest and lowest are kept: memory stays bounded),
    // one given twice at once.
    if (numbered) {
        if (!level.numbered || number > level.highestNumber) {
            level.highestNumber = number;
        }
        if (!level.numbered || number < level.lowestNumber) {
            level.lowestNumber = number;
        }
        level.numbered = true;
        if (!firstTimeNumbered(number)) {
            emitProblem(lineNumber_,
                        "test number " + std::to_string(number) + " is given more than once");
        }
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
    p.subtest = path();
    p.line = lineNumber_;
    if (level.planned >= 0) {
        ++level.afterPlan;
    }
    level.nextSubtest.clear();
    pending_ = std::move(p);
    pendingIndent_ = level.indent;
    havePending_ = true;  // told once we know whether a YAML block follows
    return true;
}

void TapParser::closeYaml(bool closed) {
    inYaml_ = false;
    if (!closed) {
        emitProblem(yamlLine_, "YAML block not closed with '...'");
    }
    flushPending();
}

void TapParser::flushPending() {
    if (!havePending_) {
        return;
    }
    havePending_ = false;
    if (pending_.failed()) {
        ++failedPoints_;
    }
    listener_.point(pending_);
    pending_ = TapPoint();
}

// The innermost level ends: its plan is checked.
void TapParser::closeLevel() {
    const Level& level = levels_.back();
    if (level.planned < 0) {
        if (level.count > 0 || level.sawVersion) {
            emitProblem(0, "no plan (expected a line '1.." + std::to_string(level.count) + "')");
        }
    } else {
        if (level.beforePlan > 0 && level.afterPlan > 0) {
            emitProblem(level.planLine,
                        "the plan must come before the first test or after the last one");
        }
        const std::string range =
            std::to_string(level.planStart) + ".." + std::to_string(level.planEnd);
        if (static_cast<unsigned long>(level.planned) != level.count) {
            emitProblem(level.planLine, "planned " + std::to_string(level.planned) +
                                            " test(s) but ran " + std::to_string(level.count));
        } else if (level.numbered && level.highestNumber > level.planEnd) {
            emitProblem(level.planLine, "test number " + std::to_string(level.highestNumber) +
                                            " is beyond the plan " + range);
        } else if (level.numbered && level.lowestNumber < level.planStart) {
            emitProblem(level.planLine, "test number " + std::to_string(level.lowestNumber) +
                                            " is before the plan " + range);
        }
    }
    trackedNumbers_ -= level.seen.size();
    if (levels_.size() > 1) {
        levels_.pop_back();
        levels_.back().nextSubtest.clear();
    }
}

void TapParser::finish() {
    end(true);
}

void TapParser::abandon() {
    end(false);
}

void TapParser::end(bool check) {
    if (finished_) {
        return;
    }
    if (!partial_.empty() || partialCut_ > 0) {
        feed("\n", 1);
    }
    if (inYaml_) {
        inYaml_ = false;
        if (check) {
            emitProblem(yamlLine_, "YAML block not closed with '...'");
        }
    }
    flushPending();
    if (check && !bailedOut_) {
        while (levels_.size() > 1) {
            closeLevel();
        }
        closeLevel();
    }
    if (!isTap_) {
        // Plain output that may contain a comment or two: none of it is TAP.
        for (const Held& item : held_) {
            if (item.kind == Held::Kind::Line) {
                giveText(item.raw);
            }
        }
        held_.clear();
        heldBytes_ = 0;
    }
    finished_ = true;
}

void TapParser::decideTap() {
    if (isTap_) {
        return;
    }
    isTap_ = true;
    for (const Held& item : held_) {
        if (item.kind == Held::Kind::Line) {
            if (item.isText) {
                listener_.text(item.raw);
            }
        } else if (item.kind == Held::Kind::Comment) {
            listener_.comment(item.raw);
        } else {
            ++problems_;
            listener_.problem(item.problem);
        }
    }
    held_.clear();
    heldBytes_ = 0;
    heldBlankLines_ = 0;
}

std::string TapParser::path() const {
    std::string text;
    const std::size_t depth = levels_.size() - 1;
    for (std::size_t k = 1; k < levels_.size(); ++k) {
        if (depth > kPathHead + kPathTail + 1 && k > kPathHead && k <= depth - kPathTail) {
            if (k == kPathHead + 1) {
                text += " > ...";
            }
            continue;
        }
        text += (text.empty() ? "" : " > ") + levels_[k].name;
    }
    return text;
}

void TapParser::emitText(const std::string& raw) {
    if (!isTap_) {
        held_[lineItem_].isText = true;
    } else if (!isBlank(raw)) {
        listener_.text(raw);
    }
}

void TapParser::emitComment(const std::string& comment) {
    if (!isTap_) {
        held_.push_back(Held{Held::Kind::Comment, comment, false, {}});
    } else {
        listener_.comment(comment);
    }
}

void TapParser::emitProblem(unsigned int line, const std::string& message) {
    TapProblem problem;
    problem.line = line;
    const std::string where = path();
    problem.message = where.empty() ? message : "subtest '" + where + "': " + message;
    if (!isTap_) {
        held_.push_back(Held{Held::Kind::Problem, {}, false, std::move(problem)});
    } else {
        ++problems_;
        listener_.problem(problem);
    }
}

// Plain output of a stream that is not TAP: blank lines at its end are dropped.
void TapParser::giveText(const std::string& raw) {
    if (isBlank(raw)) {
        ++heldBlankLines_;
        return;
    }
    for (; heldBlankLines_ > 0; --heldBlankLines_) {
        listener_.text("");
    }
    listener_.text(raw);
}

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

namespace {

class Collector : public TapListener {
public:
    explicit Collector(TapStream& stream) : stream_(stream) {}
    void point(const TapPoint& point) override { stream_.points.push_back(point); }
    void comment(const std::string& text) override { stream_.comments.push_back(text); }
    void problem(const TapProblem& problem) override { stream_.problems.push_back(problem); }
    void text(const std::string& line) override { stream_.otherText.push_back(line); }

private:
    TapStream& stream_;
};

}  // namespace

TapStream parseTap(const std::string& text) {
    TapStream stream;
    Collector collector(stream);
    TapParser parser(collector);
    parser.feed(text.data(), text.size());
    parser.finish();
    stream.isTap = parser.isTap();
    stream.version = parser.version();
    stream.skipAll = parser.skipAll();
    stream.skipReason = parser.skipReason();
    stream.bailedOut = parser.bailedOut();
    stream.bailOutReason = parser.bailOutReason();
    stream.bailOutLine = parser.bailOutLine();
    return stream;
}

}  // namespace languages
}  // namespace robottestingframework
