#pragma once
// RAII handles for SQLite: a Database owns one sqlite3* connection, a Statement owns one prepared
// sqlite3_stmt*. Every value reaches SQL through bind(): participant ids, answers and free text
// never become part of an SQL string. Errors throw StoreError with SQLite's message.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

struct sqlite3;
struct sqlite3_stmt;

namespace tlab::study {

// How long a connection waits for another process's write lock before it gives up.
inline constexpr int kBusyTimeoutMs = 10000;

// A storage failure. Messages from SQLite say what happened and what to do ("... is full: free
// space, then continue with --resume"); `code` is SQLite's extended result code (0: not SQLite's).
class StoreError : public std::runtime_error {
 public:
  explicit StoreError(const std::string& message, int code = 0) : std::runtime_error(message), code_(code) {}
  int code() const { return code_; }

 private:
  int code_ = 0;
};

// The extended result code of the connection's last failure.
int sqliteCode(sqlite3* db);

class Statement;

class Database {
 public:
  // Opens (creating if `create`) the file; sets a busy timeout so concurrent readers wait.
  Database(const std::string& path, bool create);
  ~Database();
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;

  const std::string& path() const { return path_; }
  // Runs statements without parameters (schema, pragmas). Never used with user data.
  void execute(const char* sql);
  Statement prepare(std::string_view sql);
  std::int64_t lastInsertId() const;
  int userVersion();
  sqlite3* handle() const { return db_; }

 private:
  std::string path_;
  sqlite3* db_ = nullptr;
};

// BEGIN IMMEDIATE ... COMMIT; rolls back unless commit() was called.
class Transaction {
 public:
  explicit Transaction(Database& db);
  ~Transaction();
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;
  void commit();

 private:
  Database& db_;
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
