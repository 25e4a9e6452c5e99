// A shared library opened at run time, and the symbols in it (RTF 2.x's shlibpp, kept for the
// programs that load their own plug-ins with it). The framework's own loaders use the same code.
#pragma once

#include <string>

namespace shlibpp {

class SharedLibrary {
public:
    SharedLibrary();
    // Opens `filename` at once (see open()).
    explicit SharedLibrary(const char* filename);
    virtual ~SharedLibrary();  // closes the library
    SharedLibrary(const SharedLibrary&) = delete;
    SharedLibrary& operator=(const SharedLibrary&) = delete;

    // Opens `filename`: a path, or a bare name the platform's loader searches for. Closes the
    // library opened before. false on failure, with the loader's words in error().
    bool open(const char* filename);
    // Lets the library go. true when nothing was open or it was closed.
    bool close();
    // What went wrong last, naming the file.
    std::string error();
    // The address of `symbolName` in the library, or nullptr (error() says why).
    void* getSymbol(const char* symbolName);
    bool isValid() const;

private:
    void* implementation;
    std::string err_message;
};

}  // namespace shlibpp
