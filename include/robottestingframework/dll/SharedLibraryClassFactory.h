// A SharedLibraryFactory that makes objects of one base class T (RTF 2.x's shlibpp). That the
// library's factory really makes T objects is taken on trust: it is the library's contract.
#pragma once

#include <robottestingframework/dll/SharedLibraryFactory.h>

namespace shlibpp {

template <class T>
class SharedLibraryClassFactory : public SharedLibraryFactory {
public:
    SharedLibraryClassFactory() = default;
    SharedLibraryClassFactory(const char* dll_name, const char* fn_name = nullptr)
        : SharedLibraryFactory(dll_name, fn_name) {}

    // A new object, or nullptr when the factory is not valid or made nothing.
    T* create() { return isValid() ? static_cast<T*>(getApi().create()) : nullptr; }

    // Deletes `object` with the library's own delete.
    void destroy(T* object) {
        if (isValid() && object != nullptr) {
            getApi().destroy(object);
        }
    }
};

}  // namespace shlibpp
