#include "runner/cli/world_protocol.h"

namespace robottestingframework {
namespace runner {

namespace {

const char* stateWord(WorldStatus::State state) {
    switch (state) {
        case WorldStatus::State::Starting:
            return "starting";
        case WorldStatus::State::Up:
            return "up";
        case WorldStatus::State::Collapsed:
            return "collapsed";
        case WorldStatus::State::Stopping:
            return "stopping";
    }
    return "starting";
}

// The first line of `packet` and the rest after it.
void splitFirstLine(const std::string& packet, std::string& first, std::string& rest) {
    const std::size_t end = packet.find('\n');
    first = packet.substr(0, end);
    rest = end == std::string::npos ? std::string() : packet.substr(end + 1);
}

}  // namespace

std::string worldSocketPath(const std::string& folder) {
    return folder + "/keeper.sock";
}

std::string worldLogPath(const std::string& folder) {
    return folder + "/keeper.log";
}

std::string worldFailedPath(const std::string& folder) {
    return folder + "/world-failed";
}

WorldRequest parseWorldRequest(const std::string& packet) {
    if (packet == "status") {
        return WorldRequest::Status;
    }
    if (packet == "down") {
        return WorldRequest::Down;
    }
    return WorldRequest::Unknown;
}

std::string worldRequestText(WorldRequest request) {
    return request == WorldRequest::Down ? "down" : "status";
}

std::string worldStatusText(const WorldStatus& status) {
    std::string suite = status.suite;
    for (char& c : suite) {
        c = c == '\n' || c == '\r' ? ' ' : c;
    }
    return std::string("rtf-world ") + stateWord(status.state) + " " +
           std::to_string(status.networkDescriptors) + " " + suite + "\n" + status.reason;
}

bool parseWorldStatus(const std::string& packet, WorldStatus& status) {
    std::string first, rest;
    splitFirstLine(packet, first, rest);
    const std::string prefix = "rtf-world ";
    if (first.compare(0, prefix.size(), prefix) != 0) {
        return false;
    }
    const std::string words = first.substr(prefix.size());
    const std::size_t space = words.find(' ');
    if (space == std::string::npos) {
        return false;
    }
    const std::string state = words.substr(0, space);
    const std::size_t afterCount = words.find(' ', space + 1);
    const std::string count = words.substr(space + 1, afterCount - space - 1);
    if (count != "0" && count != "1" && count != "2") {
        return false;
    }
    WorldStatus parsed;
    bool known = false;
    for (auto candidate : {WorldStatus::State::Starting, WorldStatus::State::Up,
                           WorldStatus::State::Collapsed, WorldStatus::State::Stopping}) {
        if (state == stateWord(candidate)) {
            parsed.state = candidate;
            known = true;
        }
    }
    if (!known) {
        return false;
    }
    parsed.networkDescriptors = static_cast<unsigned int>(count[0] - '0');
    parsed.reason = rest;
    parsed.suite = afterCount == std::string::npos ? std::string() : words.substr(afterCount + 1);
    status = parsed;
    return true;
}

std::string worldOutcomeText(const WorldOutcome& outcome) {
    return std::string(outcome.passed ? "rtf-world passed" : "rtf-world failed") + "\n" +
           outcome.text;
}

bool parseWorldOutcome(const std::string& packet, WorldOutcome& outcome) {
    std::string first, rest;
    splitFirstLine(packet, first, rest);
    if (first != "rtf-world passed" && first != "rtf-world failed") {
        return false;
    }
    outcome.passed = first == "rtf-world passed";
    outcome.text = rest;
    return true;
}

}  // namespace runner
}  // namespace robottestingframework
