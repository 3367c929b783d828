#pragma once
// Ordered schema steps. The schema version lives in the file header
// (PRAGMA user_version): 0 = empty file, N = steps 1..N applied.
// All pending steps run inside ONE outer transaction, each step in its own
// savepoint, and user_version moves with them: an upgrade either completes or
// leaves the file exactly as it was (docs/decisions/history-durability.md).
#include <functional>
#include <string>
#include <vector>

#include "history/database.h"

namespace auv {

struct Migration {
  int version = 0;  // this step brings the schema to `version`
  std::string name;
  std::function<void(Database&)> apply;
};

// The steps this program knows, in order.
const std::vector<Migration>& standardMigrations();
int latestSchemaVersion();

int schemaVersionOf(Database& db);
// InputError when the file's schema is newer than the last of `steps`.
void requireNotNewer(Database& db, const std::vector<Migration>& steps);
// Throws InputError when the file is newer than `steps` knows or a step fails;
// on failure nothing has been written.
void migrate(Database& db, const std::vector<Migration>& steps);

}  // namespace auv
