// The hooks a plug-in library exports so that a program can make and delete objects of a class
// it does not know at build time (RTF 2.x's shlibpp, dll/SharedLibraryClassApi.h).
//
// SHLIBPP_DEFINE_SHARED_SUBCLASS(factory, Class, Base) exports an extern "C" function `factory`
// that fills a SharedLibraryClassApi; SharedLibraryFactory looks it up and checks it. The layout
// below is a binary contract with libraries built against RTF 2.x: do not change it.
#pragma once

#include <cstring>

#include <robottestingframework/dll/Vocab.h>

#if defined(_WIN32) || defined(__CYGWIN__)
#define SHLIBPP_EXPORT __declspec(dllexport)
#else
#define SHLIBPP_EXPORT __attribute__((visibility("default")))
#endif

#define SHLIBPP_POINTER_SIZE 8
// Spare room so that the structure keeps its size if hooks are added.
#define SHLIBPP_SHAREDLIBRARYCLASSAPI_PADDING (30 - 2 * (SHLIBPP_POINTER_SIZE / 4))

namespace shlibpp {

extern "C" {

struct SharedLibraryClassApi {
    int startCheck;     // VOCAB('S','H','P','P') when filled by a factory
    int structureSize;  // sizeof(SharedLibraryClassApi) as the library saw it
    int systemVersion;  // version of this contract (5)
    void* (*create)();
    void (*destroy)(void* object);
    int (*getVersion)(char* text, int length);
    int (*getAbi)(char* text, int length);
    int (*getClassName)(char* text, int length);
    int (*getBaseClassName)(char* text, int length);
    int roomToGrow[SHLIBPP_SHAREDLIBRARYCLASSAPI_PADDING];
    int endCheck;  // VOCAB('P','L','U','G')
};
}

// The version of the contract SHLIBPP_DEFINE_SHARED_SUBCLASS writes.
constexpr int kSharedLibraryClassApiVersion = 5;

// Copies `name` into `text` (at most `length` bytes); returns the room the name needs.
inline int copyClassName(const char* name, char* text, int length) {
    if (text != nullptr && length > 0) {
        std::strncpy(text, name, static_cast<std::size_t>(length));
    }
    return static_cast<int>(std::strlen(name)) + 1;
}

}  // namespace shlibpp

#define SHLIBPP_SHARED_CLASS_FN extern "C" SHLIBPP_EXPORT

// Exports `factoryname` (and factoryname_create, _destroy, ... beside it) making `classname`
// objects handed out as `basename*`. A class that is not a `basename` makes no object.
#define SHLIBPP_DEFINE_SHARED_SUBCLASS(factoryname, classname, basename)                 \
    SHLIBPP_SHARED_CLASS_FN void* factoryname##_create() {                               \
        classname* made = new classname;                                                 \
        basename* base = dynamic_cast<basename*>(made);                                  \
        if (base == nullptr) {                                                           \
            delete made;                                                                 \
        }                                                                                \
        return static_cast<void*>(base);                                                 \
    }                                                                                    \
    SHLIBPP_SHARED_CLASS_FN void factoryname##_destroy(void* object) {                   \
        delete dynamic_cast<classname*>(static_cast<basename*>(object));                 \
    }                                                                                    \
    SHLIBPP_SHARED_CLASS_FN int factoryname##_getVersion(char*, int) {                   \
        return 0;                                                                        \
    }                                                                                    \
    SHLIBPP_SHARED_CLASS_FN int factoryname##_getAbi(char*, int) {                       \
        return 0;                                                                        \
    }                                                                                    \
    SHLIBPP_SHARED_CLASS_FN int factoryname##_getClassName(char* text, int length) {     \
        return ::shlibpp::copyClassName(#classname, text, length);                       \
    }                                                                                    \
    SHLIBPP_SHARED_CLASS_FN int factoryname##_getBaseClassName(char* text, int length) { \
        return ::shlibpp::copyClassName(#basename, text, length);                        \
    }                                                                                    \
    SHLIBPP_SHARED_CLASS_FN int factoryname(void* space, int length) {                   \
        if (length < static_cast<int>(sizeof(::shlibpp::SharedLibraryClassApi))) {       \
            return -1;                                                                   \
        }                                                                                \
        auto* api = static_cast<::shlibpp::SharedLibraryClassApi*>(space);               \
        std::memset(api, 0, sizeof(::shlibpp::SharedLibraryClassApi));                   \
        api->startCheck = ::shlibpp::VOCAB('S', 'H', 'P', 'P');                          \
        api->structureSize = static_cast<int>(sizeof(::shlibpp::SharedLibraryClassApi)); \
        api->systemVersion = ::shlibpp::kSharedLibraryClassApiVersion;                   \
        api->create = factoryname##_create;                                              \
        api->destroy = factoryname##_destroy;                                            \
        api->getVersion = factoryname##_getVersion;                                      \
        api->getAbi = factoryname##_getAbi;                                              \
        api->getClassName = factoryname##_getClassName;                                  \
        api->getBaseClassName = factoryname##_getBaseClassName;                          \
        api->endCheck = ::shlibpp::VOCAB('P', 'L', 'U', 'G');                            \
        return api->startCheck;                                                          \
    }

#define SHLIBPP_DEFAULT_FACTORY_NAME "shlibpp_default_factory"
#define SHLIBPP_DEFINE_DEFAULT_SHARED_CLASS(classname) \
    SHLIBPP_DEFINE_SHARED_SUBCLASS(shlibpp_default_factory, classname, classname)
#define SHLIBPP_DEFINE_SHARED_CLASS(factoryname, classname) \
    SHLIBPP_DEFINE_SHARED_SUBCLASS(factoryname, classname, classname)
