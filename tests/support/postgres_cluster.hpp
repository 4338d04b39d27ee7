#pragma once
// PostgresCluster: a throw-away PostgreSQL server for one test process. initdb into a fresh
// temporary folder, pg_ctl start listening only on a Unix socket in that folder (no TCP port is
// opened; the port number only names the socket), one database per test, and in the destructor
// pg_ctl stop -m immediate and the folder removed. PostgreSQL refuses to run as root: as root, the
// server runs as the unprivileged user `nobody` (runuser) and owns the folder; the test connects
// over the socket as the cluster's superuser "tlab" (trust authentication on the socket only).
// Missing PostgreSQL binaries throw, naming scripts/setup.sh, so the test fails and never skips.
#include <filesystem>
#include <string>

namespace tlab::testing {

class PostgresCluster {
 public:
  PostgresCluster();
  ~PostgresCluster();
  PostgresCluster(const PostgresCluster&) = delete;
  PostgresCluster& operator=(const PostgresCluster&) = delete;

  // A new, empty database (UTF8) and its URL: postgresql:///NAME?host=SOCKETDIR&port=PORT&user=tlab.
  std::string createDatabase(const std::string& name);
  std::string url(const std::string& database) const;
  // The server goes away (pg_ctl stop -m immediate, as a crash would) and comes back.
  void stop();
  void start();

 private:
  // Runs a PostgreSQL program (as `nobody` when this process is root); throws with its log on failure.
  void run(const std::string& program, const std::string& arguments) const;
  std::filesystem::path dir_;
  std::string bin_;
  int port_ = 0;
  bool running_ = false;
};

// The one cluster of this test process, started on first use (each ctest test is a process).
PostgresCluster& sharedPostgresCluster();

}  // namespace tlab::testing
