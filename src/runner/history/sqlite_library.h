// SQLite's functions, as the history calls them: sqlite().exec(...) is sqlite3_exec(...). On
// Linux the library is loaded when the history is first opened (sqlite_library-linux.cpp), so
// that a run without --history does not pay for loading and relocating it at start-up (about
// a tenth of a one-test run's time); elsewhere they are the linked functions
// (sqlite_library-portable.cpp).
#pragma once

#include <sqlite3.h>

namespace robottestingframework {
namespace runner {

struct SqliteLibrary {
    decltype(&::sqlite3_bind_double) bind_double;
    decltype(&::sqlite3_bind_int64) bind_int64;
    decltype(&::sqlite3_bind_null) bind_null;
    decltype(&::sqlite3_bind_text) bind_text;
    decltype(&::sqlite3_busy_timeout) busy_timeout;
    decltype(&::sqlite3_changes) changes;
    decltype(&::sqlite3_clear_bindings) clear_bindings;
    decltype(&::sqlite3_close) close;
    decltype(&::sqlite3_column_bytes) column_bytes;
    decltype(&::sqlite3_column_double) column_double;
    decltype(&::sqlite3_column_int64) column_int64;
    decltype(&::sqlite3_column_text) column_text;
    decltype(&::sqlite3_column_type) column_type;
    decltype(&::sqlite3_errmsg) errmsg;
    decltype(&::sqlite3_exec) exec;
    decltype(&::sqlite3_finalize) finalize;
    decltype(&::sqlite3_free) free;
    decltype(&::sqlite3_last_insert_rowid) last_insert_rowid;
    decltype(&::sqlite3_open_v2) open_v2;
    decltype(&::sqlite3_prepare_v2) prepare_v2;
    decltype(&::sqlite3_reset) reset;
    decltype(&::sqlite3_step) step;
};

// SQLite's functions; throws HistoryError when the library cannot be loaded.
const SqliteLibrary& sqlite();

}  // namespace runner
}  // namespace robottestingframework
