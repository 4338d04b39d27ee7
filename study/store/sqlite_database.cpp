#include "study/store/sqlite_database.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>

#include <sqlite3.h>

namespace tlab::study {

namespace {

long long steadyNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string seconds(long long ns) {
  char buf[32];
  std::snprintf(buf, sizeof buf, ns >= 1000000000LL ? "%.0f s" : "%.1f s", double(ns) / 1e9);
  return buf;
}

// What the user can do about a failed SQLite call, by its primary result code ("" when SQLite's
// own message says enough). `waitedNs` is how long the busy handler waited (-1: it was not asked).
std::string remedy(int code, long long waitedNs) {
  switch (code & 0xff) {
    case SQLITE_FULL:
      return "the disk (or the database's size limit) is full: free space, then continue with --resume";
    case SQLITE_READONLY:
      return "the database is read-only (file permissions, an immutable file or a read-only mount): make it writable, "
             "then continue with --resume";
    case SQLITE_BUSY:
    case SQLITE_LOCKED:
      if (waitedNs < 0)
        return "another process holds a conflicting lock and SQLite refused at once, without waiting (extended code " +
               std::to_string(code) + "): let it finish, then continue with --resume";
      return "the database is locked by another process (waited " + seconds(waitedNs) +
             "): let it finish, then continue with --resume";
    case SQLITE_CORRUPT:
    case SQLITE_NOTADB:  // the header was checked first (requireSqliteFile): what follows it is damaged
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

bool fileHasBytes(const std::string& path) {
  std::error_code ec;
  return std::filesystem::exists(path, ec) && std::filesystem::file_size(path, ec) > 0;
}

}  // namespace

int sqliteCode(sqlite3* db) { return db ? sqlite3_extended_errcode(db) : SQLITE_NOMEM; }

namespace {
[[noreturn]] void fail(const Database& db, const std::string& what) {
  throw StoreError(what + ": " + db.explain(), sqliteCode(db.handle()));
}
}  // namespace

void requireSqliteFile(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw StoreError(path + ": no such database", SQLITE_CANTOPEN);
  if (std::filesystem::is_directory(path, ec)) throw StoreError(path + ": is a folder, not a study database", SQLITE_CANTOPEN);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw StoreError(path + ": cannot be read (permissions?)", SQLITE_CANTOPEN);
  char header[16] = {};
  in.read(header, sizeof header);
  if (in.gcount() == 0) throw StoreError(path + ": the file is empty, not a tlab study database", SQLITE_NOTADB);
  if (in.gcount() < 16 || std::memcmp(header, "SQLite format 3", 16) != 0)
    throw StoreError(path + ": not an SQLite database (it is some other kind of file), so not a tlab study database", SQLITE_NOTADB);
}

int Database::onBusy(void* self, int count) {
  auto* db = static_cast<Database*>(self);
  const long long now = steadyNs();
  if (count == 0) db->busySinceNs_ = now;
  db->busyWaitedNs_ = now - db->busySinceNs_;
  if (db->busyWaitedNs_ >= kBusyTimeoutMs * 1000000LL) return 0;
  // 1, 2, 4 ... up to 50 ms between tries, like SQLite's own handler.
  std::this_thread::sleep_for(std::chrono::milliseconds(std::min(50, 1 << std::min(count, 6))));
  return 1;
}

std::string Database::explain() const {
  if (!db_) return "out of memory";
  const int code = sqlite3_extended_errcode(db_);
  const bool busy = (code & 0xff) == SQLITE_BUSY || (code & 0xff) == SQLITE_LOCKED;
  const std::string hint = remedy(code, busy ? busyWaitedNs_ : 0);
  return std::string(sqlite3_errmsg(db_)) + (hint.empty() ? "" : " - " + hint);
}

Database::Database(const std::string& path, OpenMode mode) : path_(path), mode_(mode) {
  std::string name = path;
  int flags = SQLITE_OPEN_NOMUTEX;
  if (mode == OpenMode::Read) {
    requireSqliteFile(path);
    // No write-ahead log beside it: nothing to replay, and immutable keeps SQLite from creating
    // -wal/-shm files. With a log, the normal read-only open reads it.
    const bool log = fileHasBytes(path + "-wal");
    char* uri = sqlite3_mprintf("file:%s?mode=ro%s", path.c_str(), log ? "" : "&immutable=1");
    name = uri;
    sqlite3_free(uri);
    flags |= SQLITE_OPEN_READONLY | SQLITE_OPEN_URI;
  } else {
    flags |= SQLITE_OPEN_READWRITE | (mode == OpenMode::Create ? SQLITE_OPEN_CREATE : 0);
  }
  if (sqlite3_open_v2(name.c_str(), &db_, flags, nullptr) != SQLITE_OK) {
    const std::string message = explain();
    const int code = sqliteCode(db_);
    sqlite3_close(db_);
    db_ = nullptr;
    throw StoreError(path + ": cannot open the database: " + message, code);
  }
  sqlite3_busy_handler(db_, &Database::onBusy, this);
  sqlite3_extended_result_codes(db_, 1);
}

Database::~Database() { sqlite3_close_v2(db_); }

void Database::execute(const char* sql) {
  busyWaitedNs_ = -1;
  char* message = nullptr;
  if (sqlite3_exec(db_, sql, nullptr, nullptr, &message) != SQLITE_OK) {
    sqlite3_free(message);
    throw StoreError(path_ + ": " + explain(), sqliteCode(db_));
  }
}

Statement Database::prepare(std::string_view sql) { return Statement(*this, sql); }

std::int64_t Database::lastInsertId() const { return sqlite3_last_insert_rowid(db_); }

int Database::userVersion() {
  Statement s(*this, "PRAGMA user_version");
  return s.step() ? int(s.integer(0)) : 0;
}

Transaction::Transaction(Database& db) : db_(db), nested_(sqlite3_get_autocommit(db.handle()) == 0) {
  db_.execute(nested_ ? "SAVEPOINT tlab_nested" : "BEGIN IMMEDIATE");
}

Transaction::~Transaction() {
  if (!done_)
    sqlite3_exec(db_.handle(), nested_ ? "ROLLBACK TO tlab_nested; RELEASE tlab_nested" : "ROLLBACK", nullptr, nullptr, nullptr);
}

void Transaction::commit() {
  db_.execute(nested_ ? "RELEASE tlab_nested" : "COMMIT");
  done_ = true;
}

Statement::Statement(Database& db, std::string_view sql) : db_(&db) {
  if (sqlite3_prepare_v2(db.handle(), sql.data(), int(sql.size()), &stmt_, nullptr) != SQLITE_OK)
    fail(db, db.path() + ": preparing '" + std::string(sql.substr(0, 60)) + "'");
}

Statement::~Statement() { sqlite3_finalize(stmt_); }

Statement::Statement(Statement&& other) noexcept : db_(other.db_), stmt_(other.stmt_) { other.stmt_ = nullptr; }

Statement& Statement::bind(int index, std::int64_t value) {
  if (sqlite3_bind_int64(stmt_, index, value) != SQLITE_OK) fail(*db_, db_->path() + ": bind");
  return *this;
}

Statement& Statement::bind(int index, double value) {
  if (sqlite3_bind_double(stmt_, index, value) != SQLITE_OK) fail(*db_, db_->path() + ": bind");
  return *this;
}

Statement& Statement::bind(int index, std::string_view text) {
  if (sqlite3_bind_text64(stmt_, index, text.data(), text.size(), SQLITE_TRANSIENT, SQLITE_UTF8) != SQLITE_OK)
    fail(*db_, db_->path() + ": bind");
  return *this;
}

Statement& Statement::bindNull(int index) {
  if (sqlite3_bind_null(stmt_, index) != SQLITE_OK) fail(*db_, db_->path() + ": bind");
  return *this;
}

Statement& Statement::bind(int index, const std::optional<double>& value) {
  return value ? bind(index, *value) : bindNull(index);
}

Statement& Statement::bind(int index, const std::optional<std::string>& value) {
  return value ? bind(index, std::string_view(*value)) : bindNull(index);
}

bool Statement::step() {
  db_->busyWaitedNs_ = -1;
  const int rc = sqlite3_step(stmt_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  fail(*db_, db_->path());
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
