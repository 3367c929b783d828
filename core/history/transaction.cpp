#include "history/transaction.h"

#include <sqlite3.h>

#include "common/input_error.h"

namespace auv {
Transaction::Transaction(Database& db) : db_(db) {
  if (!db_.damage().empty()) {
    throw InputError("history database",
                     "'" + db_.path() + "' is damaged (" + db_.damage() + "); nothing is written to it",
                     "restore the automatic backup: move '" + db_.path() + "' aside, copy '" + db_.backupPath() +
                         "' to '" + db_.path() + "' and save again; 'auvballast history --check --history " +
                         db_.path() + "' lists the damage");
  }
  if (db_.inTransaction()) {
    // Nesting is strictly LIFO and SQLite resolves a repeated savepoint name
    // to the most recent one, so one fixed name is enough.
    savepoint_ = "auv_nested_save";
    db_.exec("SAVEPOINT " + savepoint_, "starting a nested save");
  } else {
    db_.exec("BEGIN IMMEDIATE", "starting a save");
  }
}

void Transaction::commit() {
  db_.exec(savepoint_.empty() ? "COMMIT" : "RELEASE " + savepoint_, "committing a save");
  done_ = true;
  if (savepoint_.empty()) db_.refreshBackup();
}

Transaction::~Transaction() {
  if (done_) return;
  // Errors here cannot be reported (we may be unwinding); SQLite has already
  // rolled back if the failure was fatal to the transaction.
  if (savepoint_.empty()) {
    if (db_.inTransaction()) sqlite3_exec(db_.handle(), "ROLLBACK", nullptr, nullptr, nullptr);
  } else {
    const std::string sql = "ROLLBACK TO " + savepoint_ + "; RELEASE " + savepoint_;
    sqlite3_exec(db_.handle(), sql.c_str(), nullptr, nullptr, nullptr);
  }
}

}  // namespace auv
