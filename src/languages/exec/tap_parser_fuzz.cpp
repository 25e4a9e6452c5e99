// Fuzz target: a TAP stream through TapParser (cmake/Fuzz.cmake, ./run.sh fuzz). The first byte
// chooses how the stream is cut into reads and whether the program ends or is stopped; the
// stream read in pieces must give what parseTap gives for it read at once.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>

#include "languages/exec/tap_parser.h"

using namespace robottestingframework::languages;

namespace {

struct Counter : TapListener {
    std::size_t points = 0, failed = 0, comments = 0, problems = 0, lines = 0;
    void point(const TapPoint& point) override {
        ++points;
        failed += point.failed() ? 1 : 0;
    }
    void comment(const std::string&) override { ++comments; }
    void problem(const TapProblem&) override { ++problems; }
    void text(const std::string&) override { ++lines; }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) {
        return 0;
    }
    const std::size_t piece = (data[0] & 0x3f) + 1;
    const bool stopped = (data[0] & 0x40) != 0;
    const std::string stream(reinterpret_cast<const char*>(data) + 1, size - 1);

    Counter counted;
    TapParser parser(counted);
    for (std::size_t at = 0; at < stream.size(); at += piece) {
        parser.feed(stream.data() + at, std::min(piece, stream.size() - at));
    }
    if (stopped) {
        parser.abandon();
        return 0;
    }
    parser.finish();

    const TapStream whole = parseTap(stream);
    if (whole.isTap != parser.isTap() || whole.points.size() != counted.points ||
        whole.problems.size() != counted.problems || whole.failed() != parser.failed() ||
        whole.comments.size() != counted.comments || whole.otherText.size() != counted.lines) {
        __builtin_trap();  // how the stream was cut into reads changed what it says
    }
    return 0;
}
