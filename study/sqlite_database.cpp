#include "study/sqlite_database.hpp"

#include <sqlite3.h>

namespace tlab::study {

namespace {

// What the user can do about a failed SQLite call, by its primary result code ("" when SQLite's
// own message says enough).
std::string remedy(int code) {
  switch (code & 0xff) {
    case SQLITE_FULL:
      return "the disk (or the database's size limit) is full: free space, then continue with --resume";
    case SQLITE_READONLY:
      return "the database is read-only (file permissions, an immutable file or a read-only mount): make it writable, "
             "then continue with --resume";
    case SQLITE_BUSY:
    case SQLITE_LOCKED:
      return "the database is locked by another process (waited " + std::to_string(kBusyTimeoutMs / 1000) +
             " s): let it finish, then continue with --resume";
    case SQLITE_CORRUPT:
    case SQLITE_NOTADB:
      return "the database file is damaged (corrupt or truncated); tlab does not write to it: restore it from a backup "
             "(or salvage with 'sqlite3 FILE .recover'), then continue with --resume";
    case SQLITE_IOERR:
      return "the disk reported an I/O error (is it full or failing?): check it, then continue with --resume";
    case SQLITE_CANTOPEN:
      return "the file or its folder cannot be opened or created (missing folder, permissions, read-only mount)";
    default:
      return "";
  }
}

std::string explain(sqlite3* db) {
  if (!db) return "out of memory";
  const std::string hint = remedy(sqlite3_extended_errcode(db));
  return std::string(sqlite3_errmsg(db)) + (hint.empty() ? "" : " - " + hint);
}

[[noreturn]] void fail(sqlite3* db, const std::string& what) { throw StoreError(what + ": " + explain(db), sqliteCode(db)); }

}  // namespace

int sqliteCode(sqlite3* db) { return db ? sqlite3_extended_errcode(db) : SQLITE_NOMEM; }

Database::Database(const std::string& path, bool create) : path_(path) {
  const int flags = SQLITE_OPEN_READWRITE | (create ? SQLITE_OPEN_CREATE : 0) | SQLITE_OPEN_NOMUTEX;
  if (sqlite3_open_v2(path.c_str(), &db_, flags, nullptr) != SQLITE_OK) {
    const std::string message = explain(db_);
    const int code = sqliteCode(db_);
    sqlite3_close(db_);
    db_ = nullptr;
    throw StoreError(path + ": cannot open the database: " + message, code);
  }
  sqlite3_busy_timeout(db_, kBusyTimeoutMs);
  sqlite3_extended_result_codes(db_, 1);
}

Database::~Database() { sqlite3_close_v2(db_); }

void Database::execute(const char* sql) {
  char* message = nullptr;
  if (sqlite3_exec(db_, sql, nullptr, nullptr, &message) != SQLITE_OK) {
    sqlite3_free(message);
    throw StoreError(path_ + ": " + explain(db_), sqliteCode(db_));
  }
}

Statement Database::prepare(std::string_view sql) { return Statement(*this, sql); }

std::int64_t Database::lastInsertId() const { return sqlite3_last_insert_rowid(db_); }

int Database::userVersion() {
  Statement s(*this, "PRAGMA user_version");
  return s.step() ? int(s.integer(0)) : 0;
}

Transaction::Transaction(Database& db) : db_(db) { db_.execute("BEGIN IMMEDIATE"); }

Transaction::~Transaction() {
  if (!done_) sqlite3_exec(db_.handle(), "ROLLBACK", nullptr, nullptr, nullptr);
}

void Transaction::commit() {
  db_.execute("COMMIT");
  done_ = true;
}

Statement::Statement(Database& db, std::string_view sql) : db_(&db) {
  if (sqlite3_prepare_v2(db.handle(), sql.data(), int(sql.size()), &stmt_, nullptr) != SQLITE_OK)
    fail(db.handle(), db.path() + ": preparing '" + std::string(sql.substr(0, 60)) + "'");
}

Statement::~Statement() { sqlite3_finalize(stmt_); }

Statement::Statement(Statement&& other) noexcept : db_(other.db_), stmt_(other.stmt_) { other.stmt_ = nullptr; }

Statement& Statement::bind(int index, std::int64_t value) {
  if (sqlite3_bind_int64(stmt_, index, value) != SQLITE_OK) fail(db_->handle(), db_->path() + ": bind");
  return *this;
}

Statement& Statement::bind(int index, double value) {
  if (sqlite3_bind_double(stmt_, index, value) != SQLITE_OK) fail(db_->handle(), db_->path() + ": bind");
  return *this;
}

Statement& Statement::bind(int index, std::string_view text) {
  if (sqlite3_bind_text64(stmt_, index, text.data(), text.size(), SQLITE_TRANSIENT, SQLITE_UTF8) != SQLITE_OK)
    fail(db_->handle(), db_->path() + ": bind");
  return *this;
}

Statement& Statement::bindNull(int index) {
  if (sqlite3_bind_null(stmt_, index) != SQLITE_OK) fail(db_->handle(), db_->path() + ": bind");
  return *this;
}

Statement& Statement::bind(int index, const std::optional<double>& value) {
  return value ? bind(index, *value) : bindNull(index);
}

Statement& Statement::bind(int index, const std::optional<std::string>& value) {
  return value ? bind(index, std::string_view(*value)) : bindNull(index);
}

bool Statement::step() {
  const int rc = sqlite3_step(stmt_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  fail(db_->handle(), db_->path());
}

void Statement::run() {
  while (step()) {
  }
  reset();
}

void Statement::reset() {
  sqlite3_reset(stmt_);
  sqlite3_clear_bindings(stmt_);
}

bool Statement::isNull(int column) const { return sqlite3_column_type(stmt_, column) == SQLITE_NULL; }
std::int64_t Statement::integer(int column) const { return sqlite3_column_int64(stmt_, column); }
double Statement::real(int column) const { return sqlite3_column_double(stmt_, column); }

std::string Statement::text(int column) const {
  const auto* bytes = static_cast<const char*>(sqlite3_column_blob(stmt_, column));
  const int n = sqlite3_column_bytes(stmt_, column);
  return bytes ? std::string(bytes, std::size_t(n)) : std::string();
}

std::optional<double> Statement::optionalReal(int column) const {
  if (isNull(column)) return std::nullopt;
  return real(column);
}

std::optional<std::string> Statement::optionalText(int column) const {
  if (isNull(column)) return std::nullopt;
  return text(column);
}

}  // namespace tlab::study
