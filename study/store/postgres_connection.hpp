#pragma once
// PostgresConnection: the one libpq connection (libpqxx) of a PostgresStore, and the one place that
// turns libpqxx's exceptions into StoreError lines. Every call runs as one transaction; a lost
// connection fails that call ("... was not stored") and the next call connects again, so a study
// goes on once the server is back. Readers connect with every transaction read-only. Threads may
// share one connection (their calls take turns); a server thread that wants its own opens a store.
// Only study/store/postgres_*.cpp include this header (libpqxx stays out of the rest of tlab).
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <pqxx/pqxx>

#include "study/store/store_basics.hpp"
#include "study/store/store_tables.hpp"

namespace tlab::study {

// `url` without its password ("postgresql://ann@host/db"), for messages and Store::location().
std::string redactedUrl(const std::string& url);

// A statement's parameters as text (nullopt: NULL); build them with pgParams(a, b, ...).
using PgParams = std::vector<std::optional<std::string>>;

inline std::optional<std::string> pgParam(const std::string& v) { return v; }
inline std::optional<std::string> pgParam(const char* v) { return std::string(v); }
inline std::optional<std::string> pgParam(std::int64_t v) { return std::to_string(v); }
inline std::optional<std::string> pgParam(int v) { return std::to_string(v); }
std::optional<std::string> pgParam(double v);  // "%.17g": read back exactly
template <class T>
std::optional<std::string> pgParam(const std::optional<T>& v) {
  return v ? pgParam(*v) : std::nullopt;
}
template <class... A>
PgParams pgParams(const A&... args) {
  return PgParams{pgParam(args)...};
}

// One transaction of a PostgresConnection: statements written with SQLite's ?N placeholders (the
// SQL both stores share) or PostgreSQL's $N.
class PgTransaction {
 public:
  explicit PgTransaction(pqxx::transaction_base& t) : t_(t) {}
  pqxx::result exec(const std::string& sql, const PgParams& params = {});
  // The first column of the first row as an integer (INSERT ... RETURNING id, count(*)).
  std::int64_t integer(const std::string& sql, const PgParams& params = {});
  // Runs a reading statement of the shared tables (study/store/store_tables.hpp).
  TableQueries& tables() { return tables_; }

 private:
  class Tables : public TableQueries {
   public:
    explicit Tables(PgTransaction& t) : t_(t) {}
    void forEachRow(const std::string& sql, const std::string& parameter, const std::function<void(const ResultRow&)>& row) override;

   private:
    PgTransaction& t_;
  };
  pqxx::transaction_base& t_;
  Tables tables_{*this};
};

class PostgresConnection {
 public:
  // Connects (StoreError: unreachable server, wrong credentials, no such database).
  PostgresConnection(std::string url, OpenMode mode);
  const std::string& location() const { return location_; }
  bool readOnly() const { return mode_ == OpenMode::Read; }

  // Runs `work` as one transaction and commits it. A serialization failure or deadlock runs it
  // again (it must only touch the database); a lost connection throws StoreError saying that
  // `what` was not stored, and the next call connects again.
  void transact(const std::string& what, const std::function<void(PgTransaction&)>& work);
  // A reading transaction (read-only on the server).
  void read(const std::function<void(PgTransaction&)>& work);

 private:
  void connect();
  void run(const std::string& what, bool write, const std::function<void(PgTransaction&)>& work);
  std::string url_;
  std::string location_;
  OpenMode mode_;
  std::unique_ptr<pqxx::connection> connection_;
  std::mutex calls_;
};

}  // namespace tlab::study
