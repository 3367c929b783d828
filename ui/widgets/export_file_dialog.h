#pragma once
// The save dialog of the page exports: starts in the folder of the last
// export (QSettings "paths/last_export_folder"), proposes a file named after
// the log, and remembers the folder chosen.
#include <QString>
#include <string>

class QWidget;

namespace auv::ui {

// Proposes "<log base name><suffix>" (e.g. "_plots.png"). Empty when cancelled.
QString askExportFile(QWidget* parent, const QString& title, const std::string& log_file, const QString& suffix,
                      const QString& filter);

}  // namespace auv::ui
