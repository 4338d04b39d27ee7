#pragma once
// The store a command names: a postgresql:// or postgres:// URL opens the PostgreSQL store
// (study/store/postgres_store.hpp), anything else is a file path and opens the SQLite store
// (study/store/sqlite_store.hpp). Front ends and commands hold a Store and never know which one runs.
#include <memory>
#include <string>

#include "study/store/store.hpp"

namespace tlab::study {

// Whether `location` names a database server (a postgresql:// or postgres:// URL), not a file.
bool isServerLocation(const std::string& location);

std::unique_ptr<Store> openStore(const std::string& location, OpenMode mode = OpenMode::Create);

}  // namespace tlab::study
