// The measurements and attachments an exec test gives in a TAP point's YAML diagnostics
// (docs/tutorial/other-languages.md):
//
//   ok 1 - arm tracks
//     ---
//     measurements:
//       - name: tracking error
//         value: 0.012
//         unit: rad
//         low: 0
//         high: 0.05
//     attachments:
//       - path: plot.svg
//         description: joint 3 tracking
//     ...
//
// Only this subset of YAML is read (block lists of flat maps, plain or quoted scalars); the
// rest of the diagnostics stays the point's detail.
#pragma once

#include <string>
#include <vector>

#include <robottestingframework/Measurement.h>
#include <robottestingframework/TestMessage.h>

namespace robottestingframework {
namespace languages {

struct TapAttachment {
    std::string path;
    std::string description;
};

struct TapRecords {
    std::vector<Measurement> measurements;
    std::vector<TapAttachment> attachments;
    // What could not be read ("measurements item 2: value 'fast' is not a number"): each an
    // error of the test.
    std::vector<std::string> problems;
};

TapRecords readTapRecords(const std::string& diagnostics);

// The diagnostics without their top-level `measurements:` and `attachments:` keys (each with
// its indented lines), which readTapRecords turns into measurements and attachments: the rest
// is the point's detail ("" when nothing is left).
std::string withoutTapRecords(const std::string& diagnostics);

// The top-level keys of a point's YAML block (what withoutTapRecords leaves), in order, each
// with its value as text: a scalar unquoted (`message: "the gripper is open"` gives `the
// gripper is open`), a block scalar (`|`, `>`) or a nested block (a map, a list: `at:` with
// its `file:` and `line:`) as its lines, unindented to the block's first line. Lines that are
// no `key:` of the top level stay with the key before them; before any key, they are the
// value of a key "yaml". Comments and blank lines between keys are dropped; a key given twice
// keeps its last value, in its first place.
TestMessage::Diagnostics tapDiagnostics(const std::string& diagnostics);

}  // namespace languages
}  // namespace robottestingframework
