#pragma once
// The PostgreSQL study database's schema: SqliteStore's tables (study/store/schema_migrations.cpp,
// version 4) in PostgreSQL types, created in one transaction; the version is the highest row of
// schema_migrations, as in SQLite (where PRAGMA user_version holds it too).
#include "study/store/postgres_connection.hpp"

namespace tlab::study {

inline constexpr int kPostgresSchemaVersion = 4;

// Writers: creates the schema in an empty database (one transaction, under a lock, so stations
// opening a new database together create it once). Everyone: refuses a database with other tables
// or a newer schema, and readers an empty one; nothing is changed then. Returns the version.
int preparePostgresSchema(PostgresConnection& connection);

}  // namespace tlab::study
