#include "widgets/export_file_dialog.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QSettings>

namespace auv::ui {

QString askExportFile(QWidget* parent, const QString& title, const std::string& log_file, const QString& suffix,
                      const QString& filter) {
  QSettings settings;
  const QString dir = settings.value("paths/last_export_folder").toString();
  const QString base = QFileInfo(QString::fromStdString(log_file)).completeBaseName();
  const QString file = QFileDialog::getSaveFileName(parent, title, dir + "/" + base + suffix, filter);
  if (file.isEmpty()) return file;
  settings.setValue("paths/last_export_folder", QFileInfo(file).absolutePath());
  return file;
}

}  // namespace auv::ui
