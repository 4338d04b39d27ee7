#pragma once
// The study database's schema as numbered migrations. A new database runs them all; a database
// written by an older tlab runs the ones it lacks. Each migration is one transaction that also
// sets PRAGMA user_version, so a crash or a full disk leaves the previous version intact.
#include <string>
#include <vector>

#include "study/store/sqlite_database.hpp"

namespace tlab::study {

struct SchemaMigration {
  int version = 0;          // PRAGMA user_version after it ran
  std::string description;  // one line, stored in schema_migrations (version >= 2)
  std::string sql;
};

const std::vector<SchemaMigration>& schemaMigrations();
int latestSchemaVersion();

// Runs the migrations after the database's version up to `target`; returns how many ran.
// Safe against a second process migrating the same file at the same time.
int migrateSchema(Database& db, int target = latestSchemaVersion());

}  // namespace tlab::study
