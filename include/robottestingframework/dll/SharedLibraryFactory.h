// A factory function (SHLIBPP_DEFINE_SHARED_SUBCLASS) found in a shared library and checked
// before use (RTF 2.x's shlibpp). The check catches a wrong symbol, not a malicious library.
#pragma once

#include <string>

#include <robottestingframework/dll/SharedLibrary.h>
#include <robottestingframework/dll/SharedLibraryClassApi.h>
#include <robottestingframework/dll/Vocab.h>

namespace shlibpp {

class SharedLibraryFactory {
public:
    enum {
        STATUS_NONE,                                            // not opened yet
        STATUS_OK = VOCAB('o', 'k'),                            // ready to make objects
        STATUS_LIBRARY_NOT_FOUND = VOCAB('f', 'o', 'u', 'n'),   // no such file
        STATUS_LIBRARY_NOT_LOADED = VOCAB('l', 'o', 'a', 'd'),  // the loader refused it
        STATUS_FACTORY_NOT_FOUND = VOCAB('f', 'a', 'c', 't'),   // no such symbol
        STATUS_FACTORY_NOT_FUNCTIONAL = VOCAB('r', 'u', 'n')    // the symbol is no factory
    };

    explicit SharedLibraryFactory();
    // Opens at once (see open()).
    SharedLibraryFactory(const char* dll_name, const char* fn_name = nullptr);
    virtual ~SharedLibraryFactory();
    SharedLibraryFactory(const SharedLibraryFactory&) = delete;
    SharedLibraryFactory& operator=(const SharedLibraryFactory&) = delete;

    // Opens the library `dll_name` and checks its factory `fn_name` (SHLIBPP_DEFAULT_FACTORY_NAME
    // when nullptr). false on failure: getStatus() says what failed, getError() why.
    bool open(const char* dll_name, const char* fn_name = nullptr);
    bool isValid() const;
    int getStatus() const;
    std::string getError() const;
    // The hooks the factory filled in (valid only when isValid()).
    const SharedLibraryClassApi& getApi() const;

    // How many hold this factory: its maker (1 from the start) plus each SharedLibraryClass
    // using it. A factory is never deleted while its maker has not called removeRef().
    int getReferenceCount() const;
    int addRef();
    int removeRef();

    std::string getName() const;           // the factory's symbol name
    std::string getClassName() const;      // the class it makes
    std::string getBaseClassName() const;  // the class it hands out

    // Uses `factory` (a function with the signature of an SHLIBPP factory) instead of one
    // looked up in a library.
    bool useFactoryFunction(void* factory);

private:
    SharedLibrary library_;
    int status_ = STATUS_NONE;
    SharedLibraryClassApi api_{};
    int references_ = 1;
    std::string name_;
    std::string className_;
    std::string baseClassName_;
    std::string error_;
};

}  // namespace shlibpp
