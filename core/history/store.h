#pragma once
// The ballasting history: one SQLite file, created and migrated by the app.
// Durability contract (docs/decisions/history-durability.md): WAL journal,
// synchronous=FULL, foreign keys on, every save one transaction. A crash or a
// kill at any moment leaves every committed save complete and no partial one.
//
// Every add*/save* below is one transaction of its own; called inside an open
// Transaction on database() it becomes part of that (outer) save instead.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "history/database.h"
#include "history/history_event.h"
#include "history/migrations.h"
#include "history/records.h"

namespace auv {

class HistoryStore {
 public:
  // Opens or creates the file and upgrades it to the latest schema. Throws
  // InputError naming the file for: not a SQLite file, a newer schema, a
  // read-only or missing location, a failed upgrade (file left unchanged).
  explicit HistoryStore(const std::string& path);
  // Test hook: use these migration steps instead of the standard ones.
  HistoryStore(const std::string& path, const std::vector<Migration>& steps);
  ~HistoryStore();
  HistoryStore(const HistoryStore&) = delete;
  HistoryStore& operator=(const HistoryStore&) = delete;

  const std::string& path() const { return db_->path(); }
  Database& database() { return *db_; }
  int schemaVersion();
  std::string integrityCheck();  // "ok" or SQLite's list of problems
  std::string quickCheck();      // the same, cheaper (run on every open)
  // Non-empty when the open check found damage; saves are then refused.
  const std::string& damage() const { return db_->damage(); }

  // --- saves ---
  RecordId ensureVehicle(const std::string& key, const std::string& name);
  // Validates the ID; creates the vehicle row if needed; InputError if the ID exists.
  RecordId addConfiguration(const Configuration& c);
  // BG (mm, CG below CB) of an existing configuration; nullopt = not measured.
  // InputError outside 0..500 mm or for an unknown configuration.
  void setConfigurationBg(const std::string& config_id, std::optional<double> bg_mm);
  // How closely the pitch sensor was checked level (deg, 1 sigma of its
  // bias); nullopt = not checked. InputError outside 0..5 deg or for an
  // unknown configuration.
  void setConfigurationPitchLevelCheck(const std::string& config_id, std::optional<double> deg);
  RecordId addWeighing(const std::string& config_id, const Weighing& w);
  RecordId addWaterCondition(const std::string& config_id, const WaterCondition& w);
  // InputError if the same content (sha256) is already in this configuration.
  RecordId addMission(const std::string& config_id, const Mission& m);
  // Hashes the file's content, then addMission.
  RecordId importMissionFile(const std::string& config_id, const std::string& file_path,
                             const nlohmann::json& summary, TimePoint imported_at);
  RecordId addAnalysisResult(const std::string& config_id, const AnalysisResult& a);
  RecordId addRecommendation(const std::string& config_id, const Recommendation& r);
  void setRecommendationAccepted(RecordId recommendation_id, bool accepted);
  RecordId addInstalledState(const std::string& config_id, const InstalledState& s);
  // `m.model` must hold a "profile" object (the vehicle profile with the terms).
  RecordId addModelTerms(const std::string& config_id, const ModelTerms& m);

  // Post-mission save: the mission, its analysis (linked to it) and the water
  // it measured, all or nothing.
  struct PostMissionIds {
    RecordId mission = 0, analysis = 0;
    std::optional<RecordId> water;
  };
  PostMissionIds savePostMission(const std::string& config_id, const Mission& m,
                                 AnalysisResult a, const std::optional<WaterCondition>& w);

  // --- queries ---
  std::optional<Configuration> configuration(const std::string& config_id);
  std::optional<ConfigurationState> lastState(const std::string& config_id, TimePoint now);
  std::vector<HistoryEvent> history(const std::string& config_id);  // oldest first
  std::vector<ConfigurationSummary> recentConfigurations(std::size_t limit);
  // Case-insensitive substring of the ID, payload note, area, water type or vehicle.
  std::vector<Configuration> search(const std::string& text);

  // Latest record at or before `t` (ties: the later-saved one).
  std::optional<WaterCondition> latestWater(const std::string& config_id, TimePoint t,
                                            bool with_temperature = false);
  std::optional<AnalysisResult> latestAnalysis(const std::string& config_id, TimePoint t);
  std::optional<InstalledState> latestInstalled(const std::string& config_id, TimePoint t);
  std::optional<ModelTerms> latestModelTerms(const std::string& config_id, TimePoint t);
  std::optional<Mission> missionBySha256(const std::string& config_id, const std::string& sha);

 private:
  void open(const std::vector<Migration>& steps);
  RecordId configRow(const std::string& config_id);
  // The configurations' columns as this file has them: a store opened with
  // fewer steps (an older program's schema, in tests) has no bg_mm or
  // pitch_level_check_deg.
  std::string configColumns() const;
  void readOptionalColumns();
  std::unique_ptr<Database> db_;
  bool has_bg_column_ = false, has_level_check_column_ = false;
};

}  // namespace auv
