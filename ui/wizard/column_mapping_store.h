#pragma once
// Where the wizard keeps each vehicle's column mapping for vendor text logs
// (docs/formats/column-mapping.md): <folder of the history>/column-mappings/
// <vehicle id>.json. Next to the history because a mapping belongs to the
// vehicles that history describes (and tests get their own folder with it).
#include <QString>
#include <optional>
#include <string>

#include "missionlog/column_mapping.h"

namespace auv::ui {

QString columnMappingPath(const std::string& vehicle_id);
// The saved mapping, nullopt when there is none. A damaged file is reported
// in `error` (InputError text) and treated as none.
std::optional<ColumnMapping> loadSavedColumnMapping(const std::string& vehicle_id, QString* error = nullptr);
// Throws InputError when the file cannot be written.
void saveColumnMapping(const std::string& vehicle_id, const ColumnMapping& m);

}  // namespace auv::ui
