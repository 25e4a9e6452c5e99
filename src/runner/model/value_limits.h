// Repetitions and seconds, read by one rule whether they come from the command line or from a
// suite file. Each check returns an empty string when the text is valid (and sets `value`),
// else what is wrong with it and what is expected ("is too large: at most ..."), for the caller
// to put after the text it quotes.
#pragma once

#include <string>

namespace robottestingframework {
namespace runner {

// The most runs of one test: more would run for ever and count past what reports can hold.
constexpr unsigned long maxRepetition = 1000000000UL;

// The longest time limit, in seconds (about 11.5 days); 0 means none. Infinity is refused:
// 0 already says "no limit", and a clock cannot wait that long.
constexpr double maxTimeoutSeconds = 1000000;

// The most extra attempts of a failing test (--retries): enough for any flaky test.
constexpr unsigned long maxRetries = 100UL;

// A whole number of extra attempts, 0 to maxRetries.
std::string checkRetries(const std::string& text, unsigned int& value);

// A whole number of runs, 1 to maxRepetition.
std::string checkRepetition(const std::string& text, unsigned int& value);

// --repetition: as checkRepetition, and 0 (RTF 2.x's default, which its users write) gives 0,
// "not given": each test runs its own repetition, else once.
std::string checkRunnerRepetition(const std::string& text, unsigned int& value);

// A number of seconds, 0 to maxTimeoutSeconds.
std::string checkSeconds(const std::string& text, double& value);

}  // namespace runner
}  // namespace robottestingframework
