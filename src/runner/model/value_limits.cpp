#include "runner/model/value_limits.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace robottestingframework {
namespace runner {

namespace {

std::string trim(const std::string& text) {
    const char* space = " \t\r\n";
    std::size_t first = text.find_first_not_of(space);
    if (first == std::string::npos) {
        return {};
    }
    return text.substr(first, text.find_last_not_of(space) - first + 1);
}

}  // namespace

std::string checkRepetition(const std::string& text, unsigned int& value) {
    const std::string digits = trim(text);
    const bool whole = !digits.empty() && std::all_of(digits.begin(), digits.end(),
                                                      [](char c) { return c >= '0' && c <= '9'; });
    if (!whole) {
        return "is not a whole number of runs >= 1";
    }
    errno = 0;
    const unsigned long long number = std::strtoull(digits.c_str(), nullptr, 10);
    if (number == 0) {
        return "is not a whole number of runs >= 1";
    }
    if (errno == ERANGE || number > maxRepetition) {
        return "is too large: at most " + std::to_string(maxRepetition) + " runs";
    }
    value = static_cast<unsigned int>(number);
    return {};
}

std::string checkRunnerRepetition(const std::string& text, unsigned int& value) {
    const std::string digits = trim(text);
    if (!digits.empty() && digits.find_first_not_of('0') == std::string::npos) {
        value = 0;
        return {};
    }
    return checkRepetition(text, value);
}

std::string checkRetries(const std::string& text, unsigned int& value) {
    const std::string digits = trim(text);
    const bool whole = !digits.empty() && std::all_of(digits.begin(), digits.end(),
                                                      [](char c) { return c >= '0' && c <= '9'; });
    if (!whole) {
        return "is not a whole number of retries from 0 to " + std::to_string(maxRetries);
    }
    errno = 0;
    const unsigned long long number = std::strtoull(digits.c_str(), nullptr, 10);
    if (errno == ERANGE || number > maxRetries) {
        return "is too large: at most " + std::to_string(maxRetries) + " retries";
    }
    value = static_cast<unsigned int>(number);
    return {};
}

std::string checkSeconds(const std::string& text, double& value) {
    const std::string number = trim(text);
    char* end = nullptr;
    const double seconds = number.empty() ? -1 : std::strtod(number.c_str(), &end);
    if (number.empty() || end == nullptr || *end != '\0' || !std::isfinite(seconds) ||
        seconds < 0) {
        return "is not a number of seconds >= 0 (e.g. 30 or 2.5; 0 for no limit)";
    }
    if (seconds > maxTimeoutSeconds) {
        return "is too large: at most " + std::to_string(static_cast<long>(maxTimeoutSeconds)) +
               " seconds (0 for no limit)";
    }
    value = seconds;
    return {};
}

}  // namespace runner
}  // namespace robottestingframework
