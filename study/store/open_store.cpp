#include "study/store/open_store.hpp"

#include "study/store/sqlite_store.hpp"

namespace tlab::study {

std::unique_ptr<Store> openStore(const std::string& location, OpenMode mode) { return std::make_unique<SqliteStore>(location, mode); }

}  // namespace tlab::study
