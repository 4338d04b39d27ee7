// PostgresConnection: connecting, one transaction per call with retries where PostgreSQL asks for
// them, reconnection after a lost connection, and libpqxx's errors as one StoreError line.
#include "study/store/postgres_connection.hpp"

#include <cctype>
#include <chrono>
#include <cstdio>
#include <mutex>
#include <random>
#include <sstream>
#include <thread>

namespace tlab::study {

namespace {

constexpr int kRetries = 30;  // serialization failures and deadlocks of one call
constexpr unsigned kBoolOid = 16, kFloat8Oid = 701, kFloat4Oid = 700;

// libpq's messages span lines ("connection to server ... failed: FATAL:  ..."): one line, and
// never the URL with its password.
std::string oneLine(std::string text, const std::string& url, const std::string& location) {
  for (std::size_t at = text.find(url); !url.empty() && at != std::string::npos; at = text.find(url, at)) text.replace(at, url.size(), location);
  for (auto& c : text)
    if (c == '\n' || c == '\t') c = ' ';
  std::string out;
  for (const char c : text)
    if (c != ' ' || (!out.empty() && out.back() != ' ')) out += c;
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

// Connection-level SQLSTATEs: 08 (connection exception), 57P (server shut down or restarting).
bool connectionLost(const pqxx::sql_error& e) {
  const std::string state = e.sqlstate();
  return state.rfind("08", 0) == 0 || state.rfind("57P", 0) == 0;
}

// The SQL both stores share writes SQLite's ?N; PostgreSQL numbers its parameters $N.
std::string dollarPlaceholders(std::string sql) {
  for (std::size_t i = 0; i + 1 < sql.size(); ++i)
    if (sql[i] == '?' && std::isdigit(static_cast<unsigned char>(sql[i + 1]))) sql[i] = '$';
  return sql;
}

void backOff(int attempt) {
  thread_local std::minstd_rand random(std::random_device{}());
  const int ceiling = std::min(100, 2 << std::min(attempt, 6));
  std::this_thread::sleep_for(std::chrono::milliseconds(1 + int(random() % unsigned(ceiling))));
}

// One row of a result, read as the shared tables read SQLite's: REAL values in SQLite's text,
// booleans as 0 and 1.
class PgRow : public ResultRow {
 public:
  PgRow(const pqxx::row& row, const std::vector<unsigned>& types) : row_(row), types_(types) {}
  bool isNull(int column) const override { return row_[column].is_null(); }
  std::int64_t integer(int column) const override {
    if (types_[column] == kBoolOid) return row_[column].as<bool>() ? 1 : 0;
    if (types_[column] == kFloat8Oid || types_[column] == kFloat4Oid) return std::int64_t(row_[column].as<double>());
    return row_[column].as<std::int64_t>();
  }
  double real(int column) const override {
    if (types_[column] == kBoolOid) return row_[column].as<bool>() ? 1.0 : 0.0;
    return row_[column].as<double>();
  }
  std::string text(int column) const override {
    if (row_[column].is_null()) return "";
    if (types_[column] == kBoolOid) return row_[column].as<bool>() ? "1" : "0";
    if (types_[column] == kFloat8Oid || types_[column] == kFloat4Oid) return storedRealText(row_[column].as<double>());
    return std::string(row_[column].c_str(), row_[column].size());
  }

 private:
  const pqxx::row& row_;
  const std::vector<unsigned>& types_;
};

}  // namespace

std::string redactedUrl(const std::string& url) {
  std::string out = url;
  const auto scheme = out.find("://");
  if (scheme == std::string::npos) return out;
  const auto start = scheme + 3;
  const auto end = std::min(out.find_first_of("/?#", start), out.size());
  const auto at = end > start ? out.rfind('@', end - 1) : std::string::npos;
  if (at != std::string::npos && at >= start) {
    const auto colon = out.find(':', start);
    if (colon < at) out.erase(colon, at - colon);  // user:password@ → user@
  }
  const auto query = out.find('?');
  if (query == std::string::npos) return out;
  std::string kept, item;
  std::istringstream items(out.substr(query + 1));
  while (std::getline(items, item, '&'))
    if (item.rfind("password=", 0) != 0) kept += (kept.empty() ? "" : "&") + item;
  return out.substr(0, query) + (kept.empty() ? "" : "?" + kept);
}

std::optional<std::string> pgParam(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return std::string(buf);
}

pqxx::result PgTransaction::exec(const std::string& sql, const PgParams& params) {
  if (params.empty()) return t_.exec(dollarPlaceholders(sql));  // also several statements (the schema)
  std::vector<const char*> values;
  values.reserve(params.size());
  for (const auto& p : params) values.push_back(p ? p->c_str() : nullptr);
  return t_.exec_params(dollarPlaceholders(sql), pqxx::prepare::make_dynamic_params(values));
}

std::int64_t PgTransaction::integer(const std::string& sql, const PgParams& params) {
  const pqxx::result r = exec(sql, params);
  if (r.empty() || r[0][0].is_null()) throw StoreError("PostgreSQL returned no value for: " + sql.substr(0, 60));
  return r[0][0].as<std::int64_t>();
}

void PgTransaction::Tables::forEachRow(const std::string& sql, const std::string& parameter,
                                       const std::function<void(const ResultRow&)>& row) {
  const pqxx::result r = t_.exec(sql, sql.find("?1") != std::string::npos ? pgParams(parameter) : PgParams{});
  std::vector<unsigned> types;
  for (pqxx::row::size_type c = 0; c < r.columns(); ++c) types.push_back(unsigned(r.column_type(c)));
  for (const auto& each : r) row(PgRow(each, types));
}

PostgresConnection::PostgresConnection(std::string url, OpenMode mode)
    : url_(std::move(url)), location_(redactedUrl(url_)), mode_(mode) {
  connect();
}

void PostgresConnection::connect() {
  connection_.reset();
  try {
    auto connection = std::make_unique<pqxx::connection>(url_);
    // Readers: the server itself refuses any write of this connection.
    if (readOnly()) pqxx::nontransaction(*connection).exec("SET SESSION CHARACTERISTICS AS TRANSACTION READ ONLY");
    connection_ = std::move(connection);
  } catch (const std::exception& e) {
    throw StoreError("cannot connect to PostgreSQL at " + location_ + ": " + oneLine(e.what(), url_, location_));
  }
}

void PostgresConnection::transact(const std::string& what, const std::function<void(PgTransaction&)>& work) { run(what, true, work); }

void PostgresConnection::read(const std::function<void(PgTransaction&)>& work) {
  try {
    run("", false, work);
  } catch (const StoreError&) {
    if (connection_) throw;
    run("", false, work);  // the connection was lost: a read is simply asked again, once
  }
}

// Each libpqxx failure is told apart here, once, with what it means for the study.
void PostgresConnection::run(const std::string& what, bool write, const std::function<void(PgTransaction&)>& work) {
  const std::lock_guard<std::mutex> one(calls_);  // one connection: the calls of threads sharing a store take turns
  const std::string lost = what.empty() ? "" : ": " + what + " was not stored; the next call connects again";
  for (int attempt = 0;; ++attempt) {
    if (!connection_ || !connection_->is_open()) {
      try {
        connect();
      } catch (const StoreError& e) {
        throw StoreError(e.what() + lost);
      }
    }
    try {
      if (write) {
        pqxx::work tx(*connection_);
        PgTransaction t(tx);
        work(t);
        tx.commit();
      } else {
        pqxx::read_transaction tx(*connection_);
        PgTransaction t(tx);
        work(t);
        tx.commit();
      }
      return;
    } catch (const pqxx::statement_completion_unknown& e) {  // a transaction_rollback that must not be run again
      connection_.reset();
      throw StoreError(location_ + ": PostgreSQL cannot tell whether " + what + " was stored (" + oneLine(e.what(), url_, location_) +
                       "); check it with tlab export");
    } catch (const pqxx::in_doubt_error& e) {
      connection_.reset();
      throw StoreError(location_ + ": the connection to PostgreSQL was lost while committing " + what +
                       ": it may or may not be stored (" + oneLine(e.what(), url_, location_) + "); check it with tlab export");
    } catch (const pqxx::broken_connection& e) {
      connection_.reset();
      throw StoreError(location_ + ": lost the connection to PostgreSQL (" + oneLine(e.what(), url_, location_) + ")" + lost);
    } catch (const pqxx::transaction_rollback& e) {  // serialization failure, deadlock: PostgreSQL asks for a retry
      if (attempt >= kRetries)
        throw StoreError(location_ + ": " + oneLine(e.what(), url_, location_) + " (" + std::to_string(kRetries) +
                         " retries); " + (what.empty() ? "" : what + " was not stored; ") + "try again");
      backOff(attempt);
    } catch (const pqxx::sql_error& e) {
      if (connectionLost(e)) {
        connection_.reset();
        throw StoreError(location_ + ": lost the connection to PostgreSQL (" + oneLine(e.what(), url_, location_) + ")" + lost);
      }
      throw StoreError(location_ + ": " + oneLine(e.what(), url_, location_) + (what.empty() ? "" : "; " + what + " was not stored"));
    } catch (const pqxx::failure& e) {
      throw StoreError(location_ + ": " + oneLine(e.what(), url_, location_));
    }
  }
}

}  // namespace tlab::study
