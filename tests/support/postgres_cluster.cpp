#include "tests/support/postgres_cluster.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <memory>
#include <stdexcept>
#include <vector>

#include <pqxx/pqxx>

#include "tests/support/run_command.hpp"

namespace tlab::testing {

namespace {

// The newest /usr/lib/postgresql/N/bin (Debian), or initdb's folder on PATH.
std::string postgresBinDir() {
  std::vector<std::filesystem::path> found;
  std::error_code ec;
  for (const auto& version : std::filesystem::directory_iterator("/usr/lib/postgresql", ec))
    if (std::filesystem::exists(version.path() / "bin" / "initdb")) found.push_back(version.path() / "bin");
  if (!found.empty()) {
    std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) {
      return std::stoi(a.parent_path().filename().string()) < std::stoi(b.parent_path().filename().string());
    });
    return found.back().string();
  }
  const auto onPath = runCommand("command -v initdb");
  if (onPath.exitCode == 0 && !onPath.out.empty()) return std::filesystem::path(onPath.out.substr(0, onPath.out.find('\n'))).parent_path();
  throw std::runtime_error("the PostgreSQL server programs (initdb, pg_ctl) are missing: run scripts/setup.sh "
                           "(it installs Debian's postgresql package)");
}

// Clusters of test processes that were killed (their destructor never ran): stopped and removed,
// so a CI machine does not collect servers.
void removeOrphanedClusters(const std::string& bin) {
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::temp_directory_path(), ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("tlabpg-", 0) != 0) continue;
    const std::string pid = name.substr(7, name.find('-', 7) - 7);
    if (pid.empty() || pid.find_first_not_of("0123456789") != std::string::npos || std::filesystem::exists("/proc/" + pid)) continue;
    const std::string user = ::geteuid() == 0 ? "runuser -u nobody -- " : "";
    runCommand(user + quoted(bin + "/pg_ctl") + " -D " + quoted((entry.path() / "data").string()) + " -m immediate stop >/dev/null 2>&1");
    std::filesystem::remove_all(entry.path(), ec);
  }
}

}  // namespace

PostgresCluster::PostgresCluster() : bin_(postgresBinDir()) {
  removeOrphanedClusters(bin_);
  static std::atomic<int> clusters{0};
  const int n = clusters++;
  // Short: a Unix socket path must stay under 108 bytes.
  dir_ = std::filesystem::temp_directory_path() / ("tlabpg-" + std::to_string(::getpid()) + "-" + std::to_string(n));
  std::filesystem::remove_all(dir_);
  std::filesystem::create_directories(dir_);
  port_ = 20000 + int((::getpid() * 7 + n) % 30000);
  if (::geteuid() == 0 && runCommand("chown nobody: " + quoted(dir_.string())).exitCode != 0)
    throw std::runtime_error("cannot hand " + dir_.string() + " to the user nobody");
  run("initdb", "-D " + quoted((dir_ / "data").string()) + " -U tlab --auth=trust -E UTF8 --locale=C --no-sync");
  start();
}

PostgresCluster::~PostgresCluster() {
  try {
    stop();
  } catch (...) {
  }
  std::error_code ec;
  std::filesystem::remove_all(dir_, ec);
}

void PostgresCluster::run(const std::string& program, const std::string& arguments) const {
  const std::string log = (dir_ / (program + ".out")).string();
  const std::string user = ::geteuid() == 0 ? "runuser -u nobody -- " : "";
  const auto r = runCommand("cd / && " + user + quoted(bin_ + "/" + program) + " " + arguments + " >" + quoted(log) + " 2>&1");
  if (r.exitCode != 0)
    throw std::runtime_error(program + " " + arguments + " failed (" + std::to_string(r.exitCode) + "): " + readText(log) +
                             readText((dir_ / "server.log").string()));
}

void PostgresCluster::start() {
  // -w: pg_ctl returns once the server accepts connections on its socket.
  run("pg_ctl", "-D " + quoted((dir_ / "data").string()) + " -l " + quoted((dir_ / "server.log").string()) + " -w -t 120 -o \"-c listen_addresses='' -c unix_socket_directories=" +
                    dir_.string() + " -p " + std::to_string(port_) + " -c max_connections=300\" start");
  running_ = true;
}

void PostgresCluster::stop() {
  if (!running_) return;
  running_ = false;
  run("pg_ctl", "-D " + quoted((dir_ / "data").string()) + " -w -m immediate stop");
}

std::string PostgresCluster::url(const std::string& database) const {
  return "postgresql:///" + database + "?host=" + dir_.string() + "&port=" + std::to_string(port_) + "&user=tlab";
}

std::string PostgresCluster::createDatabase(const std::string& name) {
  pqxx::connection admin(url("postgres"));
  pqxx::nontransaction(admin).exec("CREATE DATABASE " + admin.quote_name(name) + " ENCODING 'UTF8' TEMPLATE template0");
  return url(name);
}

PostgresCluster& sharedPostgresCluster() {
  static std::unique_ptr<PostgresCluster> cluster;
  if (!cluster) cluster = std::make_unique<PostgresCluster>();
  return *cluster;
}

}  // namespace tlab::testing
