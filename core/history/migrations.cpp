#include "history/migrations.h"

#include <stdexcept>

#include "common/input_error.h"
#include "history/transaction.h"

namespace auv {
namespace {

// v1: who and what was weighed, in which water, which logs came back.
const char* kSchemaV1 = R"sql(
CREATE TABLE vehicles (
  id INTEGER PRIMARY KEY,
  key TEXT NOT NULL UNIQUE,
  name TEXT NOT NULL
);
CREATE TABLE configurations (
  id INTEGER PRIMARY KEY,
  config_id TEXT NOT NULL UNIQUE COLLATE NOCASE,
  vehicle_id INTEGER NOT NULL REFERENCES vehicles(id),
  payload_note TEXT NOT NULL DEFAULT '',
  area TEXT NOT NULL DEFAULT '',
  water_type TEXT NOT NULL DEFAULT '',
  created_at TEXT NOT NULL
);
CREATE TABLE weighings (
  id INTEGER PRIMARY KEY,
  configuration_id INTEGER NOT NULL REFERENCES configurations(id),
  at TEXT NOT NULL,
  method TEXT NOT NULL CHECK (method IN ('crane', 'tank')),
  inputs_json TEXT NOT NULL CHECK (json_valid(inputs_json)),
  results_json TEXT NOT NULL CHECK (json_valid(results_json))
);
CREATE TABLE water_conditions (
  id INTEGER PRIMARY KEY,
  configuration_id INTEGER NOT NULL REFERENCES configurations(id),
  measured_at TEXT NOT NULL,
  temperature_degc REAL,
  salinity_psu REAL,
  depth_m REAL,
  density_kg_m3 REAL,
  source TEXT NOT NULL DEFAULT ''
);
CREATE TABLE missions (
  id INTEGER PRIMARY KEY,
  configuration_id INTEGER NOT NULL REFERENCES configurations(id),
  imported_at TEXT NOT NULL,
  file_path TEXT NOT NULL,
  sha256 TEXT NOT NULL CHECK (length(sha256) = 64),
  summary_json TEXT NOT NULL CHECK (json_valid(summary_json)),
  UNIQUE (configuration_id, sha256),
  UNIQUE (id, configuration_id)
);
)sql";

// v2: what we concluded, what we advised and what was actually installed.
// The composite foreign keys keep a link inside one configuration.
const char* kSchemaV2 = R"sql(
CREATE TABLE analysis_results (
  id INTEGER PRIMARY KEY,
  configuration_id INTEGER NOT NULL REFERENCES configurations(id),
  at TEXT NOT NULL,
  mission_id INTEGER,
  result_json TEXT NOT NULL CHECK (json_valid(result_json)),
  UNIQUE (id, configuration_id),
  FOREIGN KEY (mission_id, configuration_id) REFERENCES missions(id, configuration_id)
);
CREATE TABLE recommendations (
  id INTEGER PRIMARY KEY,
  configuration_id INTEGER NOT NULL REFERENCES configurations(id),
  at TEXT NOT NULL,
  analysis_id INTEGER,
  policy TEXT NOT NULL,
  recommendation_json TEXT NOT NULL CHECK (json_valid(recommendation_json)),
  accepted INTEGER NOT NULL DEFAULT 0 CHECK (accepted IN (0, 1)),
  UNIQUE (id, configuration_id),
  FOREIGN KEY (analysis_id, configuration_id) REFERENCES analysis_results(id, configuration_id)
);
CREATE TABLE installed_states (
  id INTEGER PRIMARY KEY,
  configuration_id INTEGER NOT NULL REFERENCES configurations(id),
  installed_at TEXT NOT NULL,
  recommendation_id INTEGER,
  pieces_json TEXT NOT NULL CHECK (json_valid(pieces_json)),
  total_mass_kg REAL,
  note TEXT NOT NULL DEFAULT '',
  FOREIGN KEY (recommendation_id, configuration_id) REFERENCES recommendations(id, configuration_id)
);
CREATE INDEX weighings_by_time ON weighings(configuration_id, at);
CREATE INDEX water_by_time ON water_conditions(configuration_id, measured_at);
CREATE INDEX missions_by_time ON missions(configuration_id, imported_at);
CREATE INDEX analysis_by_time ON analysis_results(configuration_id, at);
CREATE INDEX recommendations_by_time ON recommendations(configuration_id, at);
CREATE INDEX installed_by_time ON installed_states(configuration_id, installed_at);
)sql";

// v3: the vehicle model each configuration has accepted from model checks.
const char* kSchemaV3 = R"sql(
CREATE TABLE model_terms (
  id INTEGER PRIMARY KEY,
  configuration_id INTEGER NOT NULL REFERENCES configurations(id),
  at TEXT NOT NULL,
  analysis_id INTEGER,
  model_json TEXT NOT NULL CHECK (json_valid(model_json)),
  FOREIGN KEY (analysis_id, configuration_id) REFERENCES analysis_results(id, configuration_id)
);
CREATE INDEX model_terms_by_time ON model_terms(configuration_id, at);
)sql";

// v4: BG (CG below CB) of each configuration from an inclining or roll test;
// NULL = not measured. Existing rows keep every value and get NULL.
const char* kSchemaV4 = R"sql(
ALTER TABLE configurations ADD COLUMN bg_mm REAL CHECK (bg_mm IS NULL OR (bg_mm > 0 AND bg_mm < 500));
)sql";

// v5: how closely the configuration's pitch sensor was checked level on the
// dock (1 sigma of its bias, deg); NULL = not checked. Existing rows get NULL.
const char* kSchemaV5 = R"sql(
ALTER TABLE configurations ADD COLUMN pitch_level_check_deg REAL
  CHECK (pitch_level_check_deg IS NULL OR (pitch_level_check_deg > 0 AND pitch_level_check_deg <= 5));
)sql";

std::vector<Migration> makeStandard() {
  return {
      {1, "vehicles, configurations, weighings, water, missions",
       [](Database& db) { db.exec(kSchemaV1, "creating schema v1"); }},
      {2, "analyses, recommendations, installed states",
       [](Database& db) { db.exec(kSchemaV2, "creating schema v2"); }},
      {3, "accepted vehicle-model terms", [](Database& db) { db.exec(kSchemaV3, "creating schema v3"); }},
      {4, "BG of each configuration", [](Database& db) { db.exec(kSchemaV4, "adding configurations.bg_mm"); }},
      {5, "pitch sensor level check of each configuration",
       [](Database& db) { db.exec(kSchemaV5, "adding configurations.pitch_level_check_deg"); }},
  };
}
}  // namespace

const std::vector<Migration>& standardMigrations() {
  static const std::vector<Migration> steps = makeStandard();
  return steps;
}

int latestSchemaVersion() { return standardMigrations().back().version; }

int schemaVersionOf(Database& db) { return int(db.queryInt("PRAGMA user_version")); }

void requireNotNewer(Database& db, const std::vector<Migration>& steps) {
  const int known = steps.empty() ? 0 : steps.back().version;
  const int current = schemaVersionOf(db);
  if (current > known)
    throw InputError("history database",
                     "'" + db.path() + "' was written by a newer auvballast (schema version " +
                         std::to_string(current) + "; this program knows up to " +
                         std::to_string(known) + ")",
                     "update auvballast to open it; the file was left untouched");
}

void migrate(Database& db, const std::vector<Migration>& steps) {
  requireNotNewer(db, steps);
  const std::string file = db.path();
  const int known = steps.empty() ? 0 : steps.back().version;
  const int current = schemaVersionOf(db);
  if (current == known) return;

  Transaction upgrade(db);
  int reached = current;
  for (const Migration& step : steps) {
    if (step.version <= current) continue;
    if (step.version != reached + 1)
      throw std::logic_error("migration steps must be numbered 1, 2, 3, ...");
    try {
      Transaction one(db);
      step.apply(db);
      db.exec("PRAGMA user_version = " + std::to_string(step.version),
              "recording schema version");
      one.commit();
    } catch (const std::exception& e) {
      throw InputError("history database",
                       "could not upgrade '" + file + "' from schema version " +
                           std::to_string(current) + " to " + std::to_string(known) +
                           ": step " + std::to_string(step.version) + " (" + step.name +
                           ") failed: " + e.what(),
                       "the file was left exactly as it was; keep using the previous "
                       "auvballast version and report this error");
    }
    reached = step.version;
  }
  upgrade.commit();
}

}  // namespace auv
