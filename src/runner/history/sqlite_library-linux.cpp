// Linux: SQLite loaded with dlopen when the history is first opened, not at start-up.
#include <dlfcn.h>

#include <string>

#include "runner/history/history_error.h"
#include "runner/history/sqlite_library.h"

namespace robottestingframework {
namespace runner {

namespace {

// SQLite's library by its soname (the one the build linked against until issue 37).
constexpr const char* libraryName = "libsqlite3.so.0";

struct Loaded {
    SqliteLibrary functions{};
    std::string error;  // empty once every function is found
};

template <typename Function>
void find(void* handle, const char* name, Function& function, std::string& error) {
    function = reinterpret_cast<Function>(::dlsym(handle, name));
    if (function == nullptr && error.empty()) {
        error = std::string(libraryName) + " has no " + name;
    }
}

Loaded load() {
    Loaded loaded;
    void* handle = ::dlopen(libraryName, RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
        const char* why = ::dlerror();
        loaded.error = "cannot load SQLite (" + std::string(why != nullptr ? why : libraryName) +
                       "; Debian's package libsqlite3-0)";
        return loaded;
    }
    SqliteLibrary& f = loaded.functions;
    find(handle, "sqlite3_bind_double", f.bind_double, loaded.error);
    find(handle, "sqlite3_bind_int64", f.bind_int64, loaded.error);
    find(handle, "sqlite3_bind_null", f.bind_null, loaded.error);
    find(handle, "sqlite3_bind_text", f.bind_text, loaded.error);
    find(handle, "sqlite3_busy_timeout", f.busy_timeout, loaded.error);
    find(handle, "sqlite3_changes", f.changes, loaded.error);
    find(handle, "sqlite3_clear_bindings", f.clear_bindings, loaded.error);
    find(handle, "sqlite3_close", f.close, loaded.error);
    find(handle, "sqlite3_column_bytes", f.column_bytes, loaded.error);
    find(handle, "sqlite3_column_double", f.column_double, loaded.error);
    find(handle, "sqlite3_column_int64", f.column_int64, loaded.error);
    find(handle, "sqlite3_column_text", f.column_text, loaded.error);
    find(handle, "sqlite3_column_type", f.column_type, loaded.error);
    find(handle, "sqlite3_errmsg", f.errmsg, loaded.error);
    find(handle, "sqlite3_exec", f.exec, loaded.error);
    find(handle, "sqlite3_finalize", f.finalize, loaded.error);
    find(handle, "sqlite3_free", f.free, loaded.error);
    find(handle, "sqlite3_last_insert_rowid", f.last_insert_rowid, loaded.error);
    find(handle, "sqlite3_open_v2", f.open_v2, loaded.error);
    find(handle, "sqlite3_prepare_v2", f.prepare_v2, loaded.error);
    find(handle, "sqlite3_reset", f.reset, loaded.error);
    find(handle, "sqlite3_step", f.step, loaded.error);
    return loaded;  // the library stays loaded for the process's life
}

}  // namespace

const SqliteLibrary& sqlite() {
    static const Loaded loaded = load();
    if (!loaded.error.empty()) {
        throw HistoryError("--history: " + loaded.error);
    }
    return loaded.functions;
}

}  // namespace runner
}  // namespace robottestingframework
