#include "runner/history/sqlite_statement.h"

#include "runner/history/sqlite_library.h"

#include "runner/history/history_error.h"

namespace robottestingframework {
namespace runner {

namespace {

[[noreturn]] void fail(sqlite3* db, const std::string& file) {
    throw HistoryError("--history " + file + ": " + sqlite().errmsg(db));
}

}  // namespace

SqliteStatement::SqliteStatement(sqlite3* db, const std::string& sql, const std::string& file)
    : db_(db), file_(file) {
    if (sqlite().prepare_v2(db, sql.c_str(), static_cast<int>(sql.size()), &statement_, nullptr) !=
        SQLITE_OK) {
        fail(db_, file_);
    }
}

SqliteStatement::~SqliteStatement() {
    if (statement_ != nullptr) {
        sqlite().finalize(statement_);
    }
}

SqliteStatement& SqliteStatement::bind(int index, const std::string& text) {
    if (sqlite().bind_text(statement_, index, text.data(), static_cast<int>(text.size()),
                           SQLITE_TRANSIENT) != SQLITE_OK) {
        fail(db_, file_);
    }
    return *this;
}

SqliteStatement& SqliteStatement::bind(int index, double value) {
    if (sqlite().bind_double(statement_, index, value) != SQLITE_OK) {
        fail(db_, file_);
    }
    return *this;
}

SqliteStatement& SqliteStatement::bind(int index, std::int64_t value) {
    if (sqlite().bind_int64(statement_, index, value) != SQLITE_OK) {
        fail(db_, file_);
    }
    return *this;
}

SqliteStatement& SqliteStatement::bindNull(int index) {
    if (sqlite().bind_null(statement_, index) != SQLITE_OK) {
        fail(db_, file_);
    }
    return *this;
}

bool SqliteStatement::step() {
    const int status = sqlite().step(statement_);
    if (status == SQLITE_ROW) {
        return true;
    }
    if (status == SQLITE_DONE) {
        return false;
    }
    fail(db_, file_);
}

void SqliteStatement::reset() {
    sqlite().reset(statement_);
    sqlite().clear_bindings(statement_);
}

std::string SqliteStatement::text(int column) const {
    const unsigned char* text = sqlite().column_text(statement_, column);
    return text == nullptr
               ? std::string()
               : std::string(reinterpret_cast<const char*>(text),
                             static_cast<std::size_t>(sqlite().column_bytes(statement_, column)));
}

double SqliteStatement::real(int column) const {
    return sqlite().column_double(statement_, column);
}

std::int64_t SqliteStatement::integer(int column) const {
    return sqlite().column_int64(statement_, column);
}

bool SqliteStatement::isNull(int column) const {
    return sqlite().column_type(statement_, column) == SQLITE_NULL;
}

void runSql(sqlite3* db, const std::string& sql, const std::string& file) {
    char* message = nullptr;
    if (sqlite().exec(db, sql.c_str(), nullptr, nullptr, &message) != SQLITE_OK) {
        const std::string text = message != nullptr ? message : sqlite().errmsg(db);
        sqlite().free(message);
        throw HistoryError("--history " + file + ": " + text);
    }
}

}  // namespace runner
}  // namespace robottestingframework
