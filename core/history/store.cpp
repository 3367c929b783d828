#include "history/store.h"

#include "common/input_error.h"

namespace auv {

HistoryStore::HistoryStore(const std::string& path) : HistoryStore(path, standardMigrations()) {}

HistoryStore::HistoryStore(const std::string& path, const std::vector<Migration>& steps)
    : db_(std::make_unique<Database>(path)) {
  open(steps);
}

HistoryStore::~HistoryStore() = default;

void HistoryStore::open(const std::vector<Migration>& steps) {
  Database& db = *db_;
  // Another auvballast (GUI and CLI at once) may hold the write lock briefly.
  db.exec("PRAGMA busy_timeout = 5000", "setting the busy timeout");
  // Reading the header first: a foreign file or a newer schema is refused
  // before the WAL switch below could write anything to it.
  requireNotNewer(db, steps);
  // A damaged page must not be written over (nor the damage spread by a
  // migration): read what can be read, refuse every save (Transaction).
  const std::string quick = quickCheck();
  if (quick != "ok") {
    db.refuseWrites(quick.substr(0, 300));
    // Only a file already at the current schema can be read as it is; one that
    // would need an upgrade cannot be upgraded without writing to it.
    const int known = steps.empty() ? 0 : steps.back().version;
    if (schemaVersionOf(db) != known) {
      throw InputError("history database", "'" + path() + "' is damaged (" + quick.substr(0, 300) + ")",
                       "restore the automatic backup: move '" + path() + "' aside and copy '" + db.backupPath() +
                           "' to '" + path() + "'");
    }
    readOptionalColumns();
    return;
  }
  // WAL: a save appends to the -wal file and the main file changes only at
  // checkpoints, so a killed writer cannot leave a torn main file and readers
  // (the GUI) never block the writer.
  const std::string mode = db.queryText("PRAGMA journal_mode = WAL");
  if (mode != "wal")
    throw InputError("history database",
                     "'" + path() + "' cannot use write-ahead logging (journal mode '" + mode +
                         "')",
                     "keep the history on a local disk, not a network share");
  // FULL: fsync the WAL at every commit, so a committed save also survives a
  // power cut or OS crash, not only a killed process (~ms per save; saves are rare).
  db.exec("PRAGMA synchronous = FULL", "setting synchronous mode");
  db.exec("PRAGMA foreign_keys = ON", "enabling foreign keys");
  migrate(db, steps);
  readOptionalColumns();
}

void HistoryStore::readOptionalColumns() {
  const auto has = [this](const char* column) {
    return db_->queryInt(std::string("SELECT count(*) FROM pragma_table_info('configurations') WHERE name = '") + column +
                         "'") > 0;
  };
  has_bg_column_ = has("bg_mm");
  has_level_check_column_ = has("pitch_level_check_deg");
}

int HistoryStore::schemaVersion() { return schemaVersionOf(*db_); }

namespace {
// "ok" or the problems a check pragma lists; SQLITE_CORRUPT while checking is
// itself the answer.
std::string runCheck(Database& db, const char* pragma) {
  try {
    auto st = db.prepare(pragma);
    std::string all;
    while (st.step()) {
      if (!all.empty()) all += "; ";
      all += st.text(0);
    }
    return all;
  } catch (const InputError& e) {
    if (e.problem().find("damaged") == std::string::npos) throw;
    return e.problem();
  }
}
}  // namespace

std::string HistoryStore::quickCheck() { return runCheck(*db_, "PRAGMA quick_check"); }

std::string HistoryStore::integrityCheck() { return runCheck(*db_, "PRAGMA integrity_check"); }

RecordId HistoryStore::configRow(const std::string& config_id) {
  auto st = db_->prepare("SELECT id FROM configurations WHERE config_id = ?1");
  st.bind(1, config_id);
  if (!st.step())
    throw InputError("configuration ID",
                     "'" + config_id + "' is not in the history '" + path() + "'",
                     "check the ID, or create the configuration first (first-mission mode)");
  return st.integer(0);
}

}  // namespace auv
