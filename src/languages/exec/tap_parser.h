// Reads a TAP stream (Test Anything Protocol, versions 12, 13 and 14) as a program prints it:
// test points with their directives and YAML diagnostics, subtests (indented streams, and the
// older "# Subtest:" form), plans, comments and "Bail out!". It never throws: whatever does not
// follow the protocol is either kept as plain output or listed as a problem.
//
// TapParser reads the stream as it arrives, line by line, and tells a TapListener what it
// finds at once (a test that is stopped half-way keeps what it reported). Time is linear in the
// stream's size and memory bounded whatever the stream holds (deep subtests, endless lines,
// millions of points): it keeps no point, only counters, and cuts lines at kMaxTapLine bytes.
#pragma once

#include <cstddef>
#include <deque>
#include <string>
#include <vector>

namespace robottestingframework {
namespace languages {

struct TapPoint {
    enum class Directive { None, Skip, Todo };

    bool ok = false;
    unsigned int number = 0;  // as printed, or its position when the line has no number
    std::string description;
    Directive directive = Directive::None;
    std::string reason;       // the directive's text
    std::string diagnostics;  // the YAML block after the point, without its --- and ... lines
    std::string subtest;      // the enclosing subtests' names ("outer > inner"); empty at top
    unsigned int line = 0;    // 1-based line of the point in the stream

    // A failing TODO point is expected to fail, and a failing SKIP point was not run (TAP 14:
    // "Harnesses must not treat failing SKIP test points as a test failure"): neither fails
    // the stream.
    bool failed() const { return !ok && directive == Directive::None; }
};

// Something in the stream that makes it fail although no point failed: a plan that does not
// match, a plan in the middle, a missing plan, a test number beyond the plan. (Numbers out of
// order are valid TAP 14; lines that are not TAP never fail a stream.)
struct TapProblem {
    unsigned int line = 0;  // where it was noticed (0: at the end of the stream)
    std::string message;
};

// Longer lines are cut (the rest is dropped, and the line says so); YAML diagnostics of one
// point are kept up to the same size.
constexpr std::size_t kMaxTapLine = 64 * 1024;

class TapListener {
public:
    virtual ~TapListener() = default;
    virtual void point(const TapPoint& /*point*/) {}      // once its diagnostics are read
    virtual void comment(const std::string& /*text*/) {}  // without the "#"
    virtual void problem(const TapProblem& /*problem*/) {}
    virtual void text(const std::string& /*line*/) {}  // a line that is not TAP
};

class TapParser {
public:
    explicit TapParser(TapListener& listener) : listener_(listener) {}

    // Bytes as the program wrote them; lines end at '\n' ("\r\n" too).
    void feed(const char* data, std::size_t size);
    // One line, without its end.
    void line(std::string text);
    // The end of the stream: a last unterminated line, open YAML blocks, subtests and plans.
    void finish();
    // The program was stopped half-way: what was read is given (a pending point, held lines),
    // nothing is checked (plans, open blocks). Nothing more is read after.
    void abandon();

    // A version line, a plan, a test point or a bail out was seen. Until then what the stream
    // said is held back (at most 64 KiB: older lines are let go as plain text), and given as
    // plain text if the stream ends without being TAP.
    bool isTap() const { return isTap_; }
    int version() const { return version_; }
    bool skipAll() const { return skipAll_; }  // "1..0 # SKIP reason" at the top level
    const std::string& skipReason() const { return skipReason_; }
    bool bailedOut() const { return bailedOut_; }
    const std::string& bailOutReason() const { return bailOutReason_; }
    unsigned int bailOutLine() const { return bailOutLine_; }
    // A failing point, a problem or a bail out (meaningful once the stream is TAP).
    bool failed() const { return bailedOut_ || failedPoints_ > 0 || problems_ > 0; }

private:
    struct Level {
        std::size_t indent = 0;
        std::string name;         // the subtest's name; empty at the top
        std::string nextSubtest;  // named by "# Subtest: name" for the next indented stream
        bool sawVersion = false;
        bool strict = false;  // "pragma +strict": a line that is not TAP fails the stream
        long planned = -1;    // how many points the plan says (end - start + 1)
        unsigned long planStart = 1;
        unsigned long planEnd = 0;
        unsigned int planLine = 0;
        unsigned int count = 0;
        unsigned int beforePlan = 0;
        unsigned int afterPlan = 0;
        bool numbered = false;            // a point gave its number
        unsigned long highestNumber = 0;  // of the numbered points
        unsigned long lowestNumber = 0;
        // The numbers given so far, to tell one given twice: numbers up to what the budget of
        // the whole stream allows (kMaxTrackedNumbers); beyond it a repeat is not told.
        std::vector<bool> seen;
    };
    // A line or an event from before the stream was known to be TAP.
    struct Held {
        enum class Kind { Line, Comment, Problem } kind;
        std::string raw;      // the line as printed, or the comment
        bool isText = false;  // a line that is plain output if the stream is TAP
        TapProblem problem;
    };

    void process(const std::string& text);
    // A line that is not TAP: plain output, and a problem where "pragma +strict" holds.
    void nonTap(const std::string& raw);
    // Notes `number` as given at the current level; false when it was given before.
    bool firstTimeNumbered(unsigned long number);
    bool endsSubtests(const std::string& content) const;
    void plan(const std::string& content);
    bool point(const std::string& content);
    void closeYaml(bool closed);
    void flushPending();
    void closeLevel();
    void decideTap();
    std::string path() const;

    void emitText(const std::string& raw);
    void emitComment(const std::string& comment);
    void emitProblem(unsigned int line, const std::string& message);
    void giveText(const std::string& raw);
    void end(bool check);

    TapListener& listener_;
    std::string partial_;  // an incomplete line from feed()
    std::size_t partialCut_ = 0;
    unsigned int lineNumber_ = 0;
    std::vector<Level> levels_{Level{}};

    bool havePending_ = false;  // a point whose YAML block may follow
    TapPoint pending_;
    std::size_t pendingIndent_ = 0;
    bool inYaml_ = false;
    unsigned int yamlLine_ = 0;

    bool isTap_ = false;
    std::deque<Held> held_;
    std::size_t lineItem_ = 0;  // the current line's entry in held_
    std::size_t heldBytes_ = 0;
    std::size_t heldBlankLines_ = 0;  // blank lines not yet given (dropped at the end)

    int version_ = 12;
    bool skipAll_ = false;
    std::string skipReason_;
    bool bailedOut_ = false;
    std::string bailOutReason_;
    unsigned int bailOutLine_ = 0;
    std::size_t trackedNumbers_ = 0;  // the sizes of every level's `seen`
    std::size_t failedPoints_ = 0;
    std::size_t problems_ = 0;
    bool finished_ = false;
};

// The whole stream at once, every point, comment and problem kept (for tests and small outputs).
struct TapStream {
    bool isTap = false;
    int version = 12;
    std::vector<TapPoint> points;        // every level, in stream order
    std::vector<std::string> comments;   // "# ..." lines, without the "#", in order
    std::vector<std::string> otherText;  // lines that are not TAP, in order
    std::vector<TapProblem> problems;
    bool skipAll = false;
    std::string skipReason;
    bool bailedOut = false;
    std::string bailOutReason;
    unsigned int bailOutLine = 0;

    bool failed() const;  // a failing point, a problem or a bail out
};

TapStream parseTap(const std::string& text);

}  // namespace languages
}  // namespace robottestingframework
