// SQLite's functions as the history calls them (runner/history/sqlite_library.h): loaded on
// Linux when first asked for (the runner does not link SQLite, issue 37), linked elsewhere.
#include <gtest/gtest.h>

#include "runner/history/sqlite_library.h"

using robottestingframework::runner::sqlite;

TEST(SqliteLibrary, EveryFunctionIsFoundAndOneIsTheSameEachTime) {
    const auto& library = sqlite();
    EXPECT_EQ(&library, &sqlite());
    const void* functions[] = {
        reinterpret_cast<const void*>(library.bind_double),
        reinterpret_cast<const void*>(library.bind_int64),
        reinterpret_cast<const void*>(library.bind_null),
        reinterpret_cast<const void*>(library.bind_text),
        reinterpret_cast<const void*>(library.busy_timeout),
        reinterpret_cast<const void*>(library.changes),
        reinterpret_cast<const void*>(library.clear_bindings),
        reinterpret_cast<const void*>(library.close),
        reinterpret_cast<const void*>(library.column_bytes),
        reinterpret_cast<const void*>(library.column_double),
        reinterpret_cast<const void*>(library.column_int64),
        reinterpret_cast<const void*>(library.column_text),
        reinterpret_cast<const void*>(library.column_type),
        reinterpret_cast<const void*>(library.errmsg),
        reinterpret_cast<const void*>(library.exec),
        reinterpret_cast<const void*>(library.finalize),
        reinterpret_cast<const void*>(library.free),
        reinterpret_cast<const void*>(library.last_insert_rowid),
        reinterpret_cast<const void*>(library.open_v2),
        reinterpret_cast<const void*>(library.prepare_v2),
        reinterpret_cast<const void*>(library.reset),
        reinterpret_cast<const void*>(library.step),
    };
    for (const void* function : functions) {
        EXPECT_NE(function, nullptr);
    }
}

TEST(SqliteLibrary, ADatabaseInMemoryWorksThroughIt) {
    const auto& library = sqlite();
    sqlite3* db = nullptr;
    ASSERT_EQ(library.open_v2(":memory:", &db, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr),
              SQLITE_OK);
    ASSERT_EQ(
        library.exec(db, "CREATE TABLE t(x); INSERT INTO t VALUES (42)", nullptr, nullptr, nullptr),
        SQLITE_OK);
    EXPECT_EQ(library.last_insert_rowid(db), 1);
    EXPECT_EQ(library.changes(db), 1);
    EXPECT_EQ(library.close(db), SQLITE_OK);
}
