// GCC and Clang (the Itanium C++ ABI, on Linux, macOS and MinGW): demangled with cxxabi.h,
// which MSVC does not have; type_name-msvc.cpp is its version.
#include <cxxabi.h>

#include <cstdlib>
#include <memory>

#include "type_name.h"

namespace robottestingframework {

std::string typeName(const std::type_info& type) {
    int status = 0;
    std::unique_ptr<char, void (*)(void*)> name(
        abi::__cxa_demangle(type.name(), nullptr, nullptr, &status), std::free);
    return (status == 0 && name) ? std::string(name.get()) : std::string(type.name());
}

}  // namespace robottestingframework
