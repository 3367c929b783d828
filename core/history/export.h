#pragma once
// The whole history of one configuration, oldest first, for people and other
// tools: JSON (every record complete) and CSV (one row per record, the
// common quantities in columns and the complete record as JSON in the last).
#include <nlohmann/json.hpp>
#include <string>

namespace auv {

class HistoryStore;

// {"format": "auvballast-history", "format_version": 1, "schema_version",
//  "configuration": {...}, "events": [{"at", "kind", "id", "record"}, ...]}
nlohmann::json exportHistoryJson(HistoryStore& store, const std::string& config_id);

// RFC 4180: comma-separated, CRLF line ends, fields with , " or line breaks
// quoted with "" doubled. Columns: see kHistoryCsvColumns in export.cpp and
// docs/formats/thesis-ballasting-file.md (section "History exports").
std::string exportHistoryCsv(HistoryStore& store, const std::string& config_id);

}  // namespace auv
