#include "wizard/column_mapping_store.h"

#include <QDir>
#include <QFileInfo>

#include "common/input_error.h"
#include "wizard/app_paths.h"

namespace auv::ui {

QString columnMappingPath(const std::string& vehicle_id) {
  const QString dir = QFileInfo(historyFilePath()).absolutePath() + "/column-mappings";
  return dir + "/" + QString::fromStdString(vehicle_id.empty() ? std::string("unknown-vehicle") : vehicle_id) + ".json";
}

std::optional<ColumnMapping> loadSavedColumnMapping(const std::string& vehicle_id, QString* error) {
  const QString path = columnMappingPath(vehicle_id);
  if (!QFileInfo::exists(path)) return std::nullopt;
  try {
    return ColumnMapping::load(path.toStdString());
  } catch (const InputError& e) {
    if (error) *error = QString::fromStdString(e.what());
    return std::nullopt;
  }
}

void saveColumnMapping(const std::string& vehicle_id, const ColumnMapping& m) {
  const QString path = columnMappingPath(vehicle_id);
  QDir().mkpath(QFileInfo(path).absolutePath());
  m.save(path.toStdString());
}

}  // namespace auv::ui
