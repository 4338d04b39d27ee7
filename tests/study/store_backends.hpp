#pragma once
// The stores the Store contract tests run on: SQLite (a file in a fresh folder) and PostgreSQL (a
// fresh database in this test process's throw-away cluster, tests/support/postgres_cluster.hpp).
// peek() reads one value straight from the database, around the Store, to check what it wrote.
#include <cctype>
#include <filesystem>
#include <memory>
#include <string>

#include <pqxx/pqxx>

#include "study/store/sqlite_database.hpp"
#include "tests/support/postgres_cluster.hpp"
#include "tests/support/run_command.hpp"

namespace tlab::testing {

class StoreBackend {
 public:
  virtual ~StoreBackend() = default;
  // A fresh, empty database for the test `name`: its location for openStore.
  virtual std::string freshLocation(const std::string& name) = 0;
  // The first column of the first row of `sql` as text ("" for NULL or no row).
  virtual std::string peek(const std::string& location, const std::string& sql) = 0;
  virtual void execute(const std::string& location, const std::string& sql) = 0;
};

class SqliteBackend : public StoreBackend {
 public:
  std::string freshLocation(const std::string& name) override { return (freshDir(name) / "s.db").string(); }
  std::string peek(const std::string& location, const std::string& sql) override {
    study::Database db(location, false);
    study::Statement s = db.prepare(sql);
    return s.step() && !s.isNull(0) ? s.text(0) : "";
  }
  void execute(const std::string& location, const std::string& sql) override {
    study::Database db(location, false);
    db.execute(sql.c_str());
  }
};

class PostgresBackend : public StoreBackend {
 public:
  std::string freshLocation(const std::string& name) override {
    std::string db;
    for (const char c : name) db += std::isalnum(static_cast<unsigned char>(c)) ? char(std::tolower(c)) : '_';
    return sharedPostgresCluster().createDatabase(db);
  }
  std::string peek(const std::string& location, const std::string& sql) override {
    pqxx::connection c(location);
    const auto r = pqxx::nontransaction(c).exec(sql);
    return r.empty() || r[0][0].is_null() ? "" : std::string(r[0][0].c_str(), r[0][0].size());
  }
  void execute(const std::string& location, const std::string& sql) override {
    pqxx::connection c(location);
    pqxx::nontransaction(c).exec(sql);
  }
};

inline StoreBackend& storeBackend(const std::string& name) {
  static SqliteBackend sqlite;
  static PostgresBackend postgres;
  return name == "postgres" ? static_cast<StoreBackend&>(postgres) : sqlite;
}

}  // namespace tlab::testing
