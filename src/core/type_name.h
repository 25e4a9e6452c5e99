// The readable name of a C++ type, for "unexpected exception std::out_of_range: ...".
#pragma once

#include <string>
#include <typeinfo>

namespace robottestingframework {

// "std::out_of_range", not the mangled "St12out_of_range" (GCC and Clang's ABI); as the
// compiler names it where it is readable already (MSVC).
std::string typeName(const std::type_info& type);

}  // namespace robottestingframework
