// Windows and the portable POSIX build: SQLite is linked (a static library built from Debian's
// source on Windows, the system's elsewhere), its functions taken as they are.
#include "runner/history/sqlite_library.h"

namespace robottestingframework {
namespace runner {

const SqliteLibrary& sqlite() {
    static const SqliteLibrary functions{
        &::sqlite3_bind_double,    &::sqlite3_bind_int64,   &::sqlite3_bind_null,
        &::sqlite3_bind_text,      &::sqlite3_busy_timeout, &::sqlite3_changes,
        &::sqlite3_clear_bindings, &::sqlite3_close,        &::sqlite3_column_bytes,
        &::sqlite3_column_double,  &::sqlite3_column_int64, &::sqlite3_column_text,
        &::sqlite3_column_type,    &::sqlite3_errmsg,       &::sqlite3_exec,
        &::sqlite3_finalize,       &::sqlite3_free,         &::sqlite3_last_insert_rowid,
        &::sqlite3_open_v2,        &::sqlite3_prepare_v2,   &::sqlite3_reset,
        &::sqlite3_step,
    };
    return functions;
}

}  // namespace runner
}  // namespace robottestingframework
