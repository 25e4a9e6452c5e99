// RTF 2.x's shlibpp classes, on the framework's own SharedLibrary (shared_library.h), so that
// the platform code stays in shared_library-posix.cpp.
#include <robottestingframework/dll/SharedLibrary.h>
#include <robottestingframework/dll/SharedLibraryFactory.h>

#include <sys/stat.h>

#include "dll/shared_library.h"

namespace shlibpp {

namespace {

robottestingframework::plugin::SharedLibrary* library(void* implementation) {
    return static_cast<robottestingframework::plugin::SharedLibrary*>(implementation);
}

}  // namespace

SharedLibrary::SharedLibrary() : implementation(new robottestingframework::plugin::SharedLibrary) {}

SharedLibrary::SharedLibrary(const char* filename) : SharedLibrary() {
    open(filename);
}

SharedLibrary::~SharedLibrary() {
    delete library(implementation);
}

bool SharedLibrary::open(const char* filename) {
    close();
    if (filename == nullptr || *filename == '\0') {
        err_message = "no library name given";
        return false;
    }
    if (!library(implementation)->open(filename)) {
        err_message =
            "cannot load '" + std::string(filename) + "': " + library(implementation)->error();
        return false;
    }
    err_message.clear();
    return true;
}

bool SharedLibrary::close() {
    library(implementation)->close();
    return true;
}

std::string SharedLibrary::error() {
    return err_message;
}

void* SharedLibrary::getSymbol(const char* symbolName) {
    if (!isValid()) {
        err_message = "no library is open";
        return nullptr;
    }
    void* address = library(implementation)->symbol(symbolName);
    if (address == nullptr) {
        err_message = library(implementation)->error();
    }
    return address;
}

bool SharedLibrary::isValid() const {
    return library(implementation)->isOpen();
}

SharedLibraryFactory::SharedLibraryFactory() = default;

SharedLibraryFactory::SharedLibraryFactory(const char* dll_name, const char* fn_name) {
    open(dll_name, fn_name);
}

SharedLibraryFactory::~SharedLibraryFactory() = default;

bool SharedLibraryFactory::open(const char* dll_name, const char* fn_name) {
    status_ = STATUS_NONE;
    api_ = SharedLibraryClassApi{};
    name_ = fn_name != nullptr ? fn_name : SHLIBPP_DEFAULT_FACTORY_NAME;
    className_.clear();
    baseClassName_.clear();
    std::string file = dll_name != nullptr ? dll_name : "";
    if (!library_.open(file.c_str())) {
        // A path to nothing is "not found"; anything else is the loader's refusal.
        struct stat info {};
        bool isPath = file.find('/') != std::string::npos;
        status_ = isPath && ::stat(file.c_str(), &info) != 0 ? STATUS_LIBRARY_NOT_FOUND
                                                             : STATUS_LIBRARY_NOT_LOADED;
        error_ = library_.error();
        return false;
    }
    void* factory = library_.getSymbol(name_.c_str());
    if (factory == nullptr) {
        status_ = STATUS_FACTORY_NOT_FOUND;
        error_ = "'" + file + "' has no factory '" + name_ + "' (" + library_.error() + ")";
        return false;
    }
    if (!useFactoryFunction(factory)) {
        error_ = "'" + file + "': " + error_;
        return false;
    }
    return true;
}

bool SharedLibraryFactory::useFactoryFunction(void* factory) {
    using Factory = int (*)(void*, int);
    api_ = SharedLibraryClassApi{};
    if (factory == nullptr) {
        status_ = STATUS_FACTORY_NOT_FOUND;
        error_ = "no factory function given";
        return false;
    }
    int answer = reinterpret_cast<Factory>(factory)(&api_, sizeof(api_));
    bool sane = answer == VOCAB('S', 'H', 'P', 'P') && api_.startCheck == answer &&
                api_.endCheck == VOCAB('P', 'L', 'U', 'G') &&
                api_.structureSize == static_cast<int>(sizeof(api_)) &&
                api_.systemVersion == kSharedLibraryClassApiVersion && api_.create != nullptr &&
                api_.destroy != nullptr;
    if (!sane) {
        status_ = STATUS_FACTORY_NOT_FUNCTIONAL;
        error_ = "factory '" + name_ + "' does not answer as a shlibpp factory";
        api_ = SharedLibraryClassApi{};
        return false;
    }
    auto name = [](int (*get)(char*, int)) {
        if (get == nullptr) {
            return std::string();
        }
        std::string text(static_cast<std::size_t>(get(nullptr, 0)), '\0');
        get(text.data(), static_cast<int>(text.size()));
        return std::string(text.c_str());
    };
    className_ = name(api_.getClassName);
    baseClassName_ = name(api_.getBaseClassName);
    status_ = STATUS_OK;
    error_.clear();
    return true;
}

bool SharedLibraryFactory::isValid() const {
    return status_ == STATUS_OK;
}

int SharedLibraryFactory::getStatus() const {
    return status_;
}

std::string SharedLibraryFactory::getError() const {
    return error_;
}

const SharedLibraryClassApi& SharedLibraryFactory::getApi() const {
    return api_;
}

int SharedLibraryFactory::getReferenceCount() const {
    return references_;
}

int SharedLibraryFactory::addRef() {
    return ++references_;
}

int SharedLibraryFactory::removeRef() {
    return --references_;
}

std::string SharedLibraryFactory::getName() const {
    return name_;
}

std::string SharedLibraryFactory::getClassName() const {
    return className_;
}

std::string SharedLibraryFactory::getBaseClassName() const {
    return baseClassName_;
}

}  // namespace shlibpp
