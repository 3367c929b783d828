#pragma once
// Reads a mission log in a worker thread so the UI never freezes: the
// registry picks the reader by content, the reader reports progress, and
// cancel() makes the next progress callback return false, which the reader
// turns into ReadCancelled (nothing partial is kept).
#include <QFutureWatcher>
#include <QObject>
#include <QStringList>
#include <QTimer>
#include <atomic>
#include <memory>
#include <optional>
#include <string>

#include "missionlog/column_mapping.h"
#include "missionlog/mission_log.h"
#include "missionlog/read_report.h"

namespace auv::ui {

// Several files of one mission in one path text (the wizard's line edit and
// its saved state hold one string): "a.dbd; a.ebd".
inline const QString kLogPathSeparator = QStringLiteral("; ");
// The paths in `text`: itself when it names an existing file or folder,
// else its `;`-separated parts.
QStringList splitLogPaths(const QString& text);

struct LogImportOutcome {
  enum class Status { kOk, kCancelled, kFailed } status = Status::kFailed;
  std::shared_ptr<const MissionLog> log;
  ReadReport report;
  std::string format;
  std::string error;  // InputError text when failed
  bool mapped = false;  // read through a column mapping
  double seconds = 0.0;
};

class LogImportJob : public QObject {
  Q_OBJECT
 public:
  explicit LogImportJob(QObject* parent = nullptr);
  ~LogImportJob() override;

  // Starts reading `path`; ignored while a read is running. With a column
  // mapping, a file the registry takes for vendor text (or does not
  // recognise at all) is read through it; other formats ignore it. A folder
  // or several files (splitLogPaths) are read as one mission (readMission).
  void start(const QString& path, std::optional<ColumnMapping> mapping = std::nullopt);
  void cancel();
  bool running() const;
  // Smaller blocks = more frequent progress (tests; the reader's default is 4 MiB).
  void setBlockBytes(std::size_t bytes) { block_bytes_ = bytes; }
  // Waits for the worker (tests and shutdown).
  void waitForFinished();

 signals:
  void progress(int percent);
  void finished(const auv::ui::LogImportOutcome& outcome);

 private:
  void poll();
  QFutureWatcher<LogImportOutcome> watcher_;
  bool busy_ = false;  // from start() until `finished` is emitted (ModelCheckJob::busy_)
  QTimer poll_timer_;
  std::shared_ptr<std::atomic<bool>> cancel_;
  std::shared_ptr<std::atomic<int>> permille_;
  std::size_t block_bytes_ = std::size_t{1} << 20;
  int last_percent_ = -1;
};

}  // namespace auv::ui
