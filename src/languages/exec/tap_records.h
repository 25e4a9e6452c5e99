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

}  // namespace languages
}  // namespace robottestingframework
