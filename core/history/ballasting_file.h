#pragma once
// The thesis's per-configuration 'ballasting' text file (HUGIN thesis
// §5.5.2, Fig. 5.14 and 7.9); the accepted format is specified in
// docs/formats/thesis-ballasting-file.md. Eleven tab-separated columns per
// record, wrapped over any number of lines; "Unknown" for a value not known.
#include <optional>
#include <string>
#include <vector>

#include "history/timestamp.h"

namespace auv {

class HistoryStore;

struct BallastingRow {
  std::string config_id;
  TimePoint at{};            // dd.mm.yyyy-hh:mm, read as UTC (the file has no zone)
  std::string vehicle_type;  // e.g. "HUGIN1000"
  std::string area;          // "" for Unknown
  std::optional<double> salinity_psu;
  std::optional<double> temperature_degC;
  std::optional<double> total_weight_kg;  // vehicle mass including the added weight
  std::vector<double> added_kg;           // per point: FS, FP, AS, AP for HUGIN
  std::optional<double> depth_deviation_m;    // + = did not reach commanded depth (light)
  std::optional<double> pitch_deviation_deg;
  std::optional<double> roll_deviation_deg;
  long line = 0;  // where the record starts in the file read (0 when not read)
};

struct BallastingFile {
  std::vector<BallastingRow> rows;
  std::vector<std::string> warnings;  // "file:line:col: field: problem" of skipped records
};

// A broken header or a record cut short throws InputError with file, line and
// column; a record with a bad value is skipped with a warning, the rest kept.
BallastingFile parseBallastingFile(const std::string& text, const std::string& file_name);
BallastingFile readBallastingFile(const std::string& path);
// Writes the Fig. 5.14 layout (4 + 4 + 3 fields per record).
std::string formatBallastingFile(const std::vector<BallastingRow>& rows);

// Point names for the AddedWeight positions (thesis order for four points).
std::vector<std::string> ballastingPointNames(std::size_t count);
// Keys of an analysis result that the ballasting file carries.
inline constexpr const char* kDepthDeviationKey = "depth_deviation_m";
inline constexpr const char* kPitchDeviationKey = "pitch_deviation_deg";
inline constexpr const char* kRollDeviationKey = "roll_deviation_deg";

struct BallastingImport {
  int rows_imported = 0;
  int rows_already_present = 0;  // same configuration and minute already installed
  std::vector<std::string> warnings;
};
// All rows in ONE transaction: the file is imported completely or not at all.
// Each row becomes an installed state; its water and deviations are saved only
// when they differ from what the history already holds at that time (a
// pre-mission row repeats them), so the temperature keeps its true age.
BallastingImport importBallastingFile(HistoryStore& store, const BallastingFile& file,
                                      const std::string& file_name);
// One row per minute in which water, an analysis or an installed state was
// saved, from the first installed state on, values carried forward.
std::vector<BallastingRow> ballastingRowsFromHistory(HistoryStore& store,
                                                     const std::string& config_id);
std::string exportBallastingFile(HistoryStore& store, const std::string& config_id);

}  // namespace auv
