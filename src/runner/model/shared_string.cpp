#include "runner/model/shared_string.h"

#include <utility>

namespace robottestingframework {
namespace runner {

const std::string SharedString::empty_;

// An empty text holds nothing: the default SharedString already reads as "".
SharedString::SharedString(std::string text)
    : text_(text.empty() ? nullptr : std::make_shared<const std::string>(std::move(text))) {}

SharedString StringPool::intern(const std::string& text) {
    auto known = strings_.find(text);
    if (known == strings_.end()) {
        known = strings_.emplace(text, SharedString(text)).first;
    }
    return known->second;
}

}  // namespace runner
}  // namespace robottestingframework
