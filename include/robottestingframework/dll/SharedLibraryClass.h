// Owns one object made by a SharedLibraryClassFactory and gives it back to the same factory
// (so to the library's own delete) when done (RTF 2.x's shlibpp).
#pragma once

#include <robottestingframework/dll/SharedLibraryClassFactory.h>

namespace shlibpp {

template <class T>
class SharedLibraryClass {
public:
    SharedLibraryClass() = default;
    explicit SharedLibraryClass(SharedLibraryClassFactory<T>& factory) { open(factory); }
    virtual ~SharedLibraryClass() { close(); }
    SharedLibraryClass(const SharedLibraryClass&) = delete;
    SharedLibraryClass& operator=(const SharedLibraryClass&) = delete;

    // Makes an object with `factory` (destroying the one held before). true when one was made.
    bool open(SharedLibraryClassFactory<T>& factory) {
        close();
        content_ = factory.create();
        if (content_ != nullptr) {
            factory_ = &factory;
            factory.addRef();
        }
        return content_ != nullptr;
    }

    // Destroys the object held, if any. A factory nobody holds any more (its maker gave up its
    // reference with removeRef()) is deleted with its last object, as in RTF 2.x.
    virtual bool close() {
        if (content_ != nullptr) {
            factory_->destroy(content_);
            if (factory_->removeRef() == 0) {
                delete factory_;
            }
        }
        content_ = nullptr;
        factory_ = nullptr;
        return true;
    }

    T& getContent() { return *content_; }
    bool isValid() const { return content_ != nullptr; }
    T& operator*() { return *content_; }
    T* operator->() { return content_; }

private:
    T* content_ = nullptr;
    SharedLibraryClassFactory<T>* factory_ = nullptr;
};

}  // namespace shlibpp
