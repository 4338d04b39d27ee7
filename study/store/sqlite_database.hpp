#pragma once
// RAII handles for SQLite: a Database owns one sqlite3* connection, a Statement owns one prepared
// sqlite3_stmt*. Every value reaches SQL through bind(): participant ids, answers and free text
// never become part of an SQL string. Errors throw StoreError with SQLite's message.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "study/store/store_basics.hpp"

struct sqlite3;
struct sqlite3_stmt;

namespace tlab::study {

// How long a connection waits for another process's write lock before it gives up.
inline constexpr int kBusyTimeoutMs = 10000;

// The extended result code of the connection's last failure.
int sqliteCode(sqlite3* db);

class Statement;

class Database {
 public:
  // Opens the file. Read checks the SQLite header first, opens read-only, and where no write-ahead
  // log exists (a cleanly closed database) immutable, so no -wal/-shm files appear beside it and
  // read-only folders and media work. A connection that must wait for another process's lock waits up to
  // kBusyTimeoutMs (its busy handler records how long it waited, for honest messages).
  Database(const std::string& path, OpenMode mode);
  Database(const std::string& path, bool create) : Database(path, create ? OpenMode::Create : OpenMode::Write) {}
  ~Database();
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;

  const std::string& path() const { return path_; }
  // Runs statements without parameters (schema, pragmas). Never used with user data.
  void execute(const char* sql);
  Statement prepare(std::string_view sql);
  std::int64_t lastInsertId() const;
  int userVersion();
  bool readOnly() const { return mode_ == OpenMode::Read; }
  sqlite3* handle() const { return db_; }
  // What a failed call means, with a remedy (the busy message says how long it really waited).
  std::string explain() const;

 private:
  friend class Statement;
  static int onBusy(void* self, int count);
  std::string path_;
  OpenMode mode_ = OpenMode::Write;
  sqlite3* db_ = nullptr;
  long long busySinceNs_ = 0;   // steady clock when the current wait began
  long long busyWaitedNs_ = -1;  // how long the last wait lasted; -1: the last BUSY came without one
};

// Throws StoreError unless `path` exists and starts with the SQLite header ("not an SQLite
// database" for text or other files). Reads 16 bytes; writes nothing.
void requireSqliteFile(const std::string& path);

// BEGIN IMMEDIATE ... COMMIT; rolls back unless commit() was called. Inside another transaction
// it is a savepoint of it (RELEASE on commit, ROLLBACK TO otherwise), so a store method that
// writes in one transaction can be part of a larger one.
class Transaction {
 public:
  explicit Transaction(Database& db);
  ~Transaction();
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;
  void commit();

 private:
  Database& db_;
  bool nested_ = false;
  bool done_ = false;
};

class Statement {
 public:
  Statement(Database& db, std::string_view sql);
  ~Statement();
  Statement(Statement&& other) noexcept;
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;
  Statement& operator=(Statement&&) = delete;

  // 1-based parameter index. Text is bound byte for byte (any bytes, including invalid UTF-8).
  Statement& bind(int index, std::int64_t value);
  Statement& bind(int index, int value) { return bind(index, std::int64_t(value)); }
  Statement& bind(int index, double value);
  Statement& bind(int index, std::string_view text);
  Statement& bind(int index, const char* text) { return bind(index, std::string_view(text)); }
  Statement& bind(int index, const std::string& text) { return bind(index, std::string_view(text)); }
  Statement& bindNull(int index);
  Statement& bind(int index, const std::optional<double>& value);
  Statement& bind(int index, const std::optional<std::string>& value);

  // Steps once: true when a row is available.
  bool step();
  // Steps to completion (INSERT/UPDATE/DELETE) and resets for reuse.
  void run();
  void reset();

  bool isNull(int column) const;  // 0-based columns
  std::int64_t integer(int column) const;
  double real(int column) const;
  std::string text(int column) const;  // the stored bytes exactly
  std::optional<double> optionalReal(int column) const;
  std::optional<std::string> optionalText(int column) const;

 private:
  Database* db_;
  sqlite3_stmt* stmt_ = nullptr;
};

}  // namespace tlab::study
