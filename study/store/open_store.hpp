#pragma once
// The store a command names: a file path opens the SQLite store (study/store/sqlite_store.hpp). Front
// ends and commands hold a Store and never know which one runs.
#include <memory>
#include <string>

#include "study/store/store.hpp"

namespace tlab::study {

std::unique_ptr<Store> openStore(const std::string& location, OpenMode mode = OpenMode::Create);

}  // namespace tlab::study
