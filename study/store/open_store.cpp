#include "study/store/open_store.hpp"

#include "study/store/postgres_store.hpp"
#include "study/store/sqlite_store.hpp"

namespace tlab::study {

bool isServerLocation(const std::string& location) {
  return location.rfind("postgresql://", 0) == 0 || location.rfind("postgres://", 0) == 0;
}

std::unique_ptr<Store> openStore(const std::string& location, OpenMode mode) {
  if (isServerLocation(location)) return std::make_unique<PostgresStore>(location, mode);
  return std::make_unique<SqliteStore>(location, mode);
}

}  // namespace tlab::study
