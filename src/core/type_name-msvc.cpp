// MSVC: type_info::name() is readable already ("class std::out_of_range"). Not verified here
// (no MSVC on these machines); docs/development/platforms.md.
#include "type_name.h"

namespace robottestingframework {

std::string typeName(const std::type_info& type) {
    return type.name();
}

}  // namespace robottestingframework
