// One prepared SQLite statement, finalized when it goes: binds by position (from 1), steps,
// reads columns. Errors throw HistoryError naming the database file.
#pragma once

#include <cstdint>
#include <string>

struct sqlite3;
struct sqlite3_stmt;

namespace robottestingframework {
namespace runner {

class SqliteStatement {
public:
    // `file` names the database in errors.
    SqliteStatement(sqlite3* db, const std::string& sql, const std::string& file);
    ~SqliteStatement();
    SqliteStatement(const SqliteStatement&) = delete;
    SqliteStatement& operator=(const SqliteStatement&) = delete;

    SqliteStatement& bind(int index, const std::string& text);
    SqliteStatement& bind(int index, double value);
    SqliteStatement& bind(int index, std::int64_t value);
    SqliteStatement& bindNull(int index);
    // True while there is a row to read; false once done. Throws on an error.
    bool step();
    // Makes the statement ready to run again with new bindings.
    void reset();

    std::string text(int column) const;
    double real(int column) const;
    std::int64_t integer(int column) const;
    bool isNull(int column) const;

private:
    sqlite3* db_;
    sqlite3_stmt* statement_ = nullptr;
    std::string file_;
};

// Runs `sql` (one or more statements, no rows wanted); throws HistoryError naming `file`.
void runSql(sqlite3* db, const std::string& sql, const std::string& file);

}  // namespace runner
}  // namespace robottestingframework
