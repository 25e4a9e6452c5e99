#include "runner/suites/parametrize.h"

#include "runner/model/test_id.h"

#include <unordered_set>

namespace robottestingframework {
namespace runner {

namespace {

std::string trimmed(const std::string& text) {
    const char* space = " \t\r\n";
    const std::size_t first = text.find_first_not_of(space);
    if (first == std::string::npos) {
        return {};
    }
    return text.substr(first, text.find_last_not_of(space) - first + 1);
}

}  // namespace

std::vector<std::string> parameterValues(const std::string& text) {
    std::vector<std::string> values;
    std::size_t begin = 0;
    while (begin <= text.size()) {
        std::size_t end = text.find(',', begin);
        if (end == std::string::npos) {
            end = text.size();
        }
        std::string value = trimmed(text.substr(begin, end - begin));
        if (!value.empty()) {
            values.push_back(std::move(value));
        }
        begin = end + 1;
    }
    return values;
}

std::vector<ParameterInstance> instancesOf(const std::vector<ParameterAxis>& axes) {
    std::vector<ParameterInstance> instances(1);
    for (const auto& axis : axes) {
        std::vector<ParameterInstance> next;
        next.reserve(instances.size() * axis.values.size());
        for (const auto& before : instances) {
            for (const auto& value : axis.values) {
                next.push_back(before);
                next.back().emplace_back(axis.name, value);
            }
        }
        instances = std::move(next);
    }
    return instances;
}

std::string substituteAxes(const std::string& text, const ParameterInstance& instance) {
    std::string out;
    std::size_t at = 0;
    while (at < text.size()) {
        const std::size_t open = text.find("${", at);
        if (open == std::string::npos) {
            break;
        }
        const std::size_t close = text.find('}', open + 2);
        if (close == std::string::npos) {
            break;
        }
        const std::string name = text.substr(open + 2, close - open - 2);
        const std::string* value = nullptr;
        for (const auto& given : instance) {
            if (given.first == name) {
                value = &given.second;
            }
        }
        if (value == nullptr) {
            out.append(text, at, close + 1 - at);
        } else {
            out.append(text, at, open - at).append(*value);
        }
        at = close + 1;
    }
    return out.append(text, at, std::string::npos);
}

bool usesAxis(const std::string& text, const ParameterInstance& instance) {
    for (const auto& given : instance) {
        if (text.find("${" + given.first + "}") != std::string::npos) {
            return true;
        }
    }
    return false;
}

std::vector<std::string> instanceLabels(const std::vector<std::string>& params,
                                        const std::vector<ParameterInstance>& instances) {
    std::vector<std::string> labels;
    std::unordered_set<std::string> seen;
    bool byParam = true;
    for (const auto& param : params) {
        labels.push_back(oneLine(param));
        byParam = byParam && !labels.back().empty() && seen.insert(labels.back()).second;
    }
    if (byParam) {
        return labels;
    }
    labels.clear();
    for (const auto& instance : instances) {
        std::string label;
        for (const auto& given : instance) {
            label += (label.empty() ? "" : ",") + given.first + "=" + oneLine(given.second);
        }
        labels.push_back(label);
    }
    return labels;
}

}  // namespace runner
}  // namespace robottestingframework
