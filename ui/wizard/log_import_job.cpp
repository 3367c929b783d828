#include "wizard/log_import_job.h"

#include <QElapsedTimer>
#include <QFileInfo>
#include <QtConcurrent/QtConcurrent>

#include "common/input_error.h"
#include "wizard/worker_pool.h"
#include "missionlog/delimited_text_reader.h"
#include "missionlog/log_reader.h"
#include "missionlog/mission_files.h"
#include "missionlog/read_options.h"

namespace auv::ui {

QStringList splitLogPaths(const QString& text) {
  if (text.trimmed().isEmpty() || QFileInfo::exists(text)) return {text};
  QStringList out;
  for (const QString& part : text.split(';'))
    if (!part.trimmed().isEmpty()) out << part.trimmed();
  return out;
}

LogImportJob::LogImportJob(QObject* parent) : QObject(parent) {
  // The worker only stores its progress; the UI thread polls it. A signal per
  // callback would flood the event queue on a fast read.
  poll_timer_.setInterval(30);
  connect(&poll_timer_, &QTimer::timeout, this, [this] { poll(); });
  connect(&watcher_, &QFutureWatcher<LogImportOutcome>::finished, this, [this] {
    busy_ = false;
    poll_timer_.stop();
    poll();
    emit finished(watcher_.result());
  });
}

LogImportJob::~LogImportJob() {
  cancel();
  waitForFinished();
}

bool LogImportJob::running() const { return busy_; }

void LogImportJob::cancel() {
  if (cancel_) cancel_->store(true);
}

void LogImportJob::waitForFinished() { watcher_.waitForFinished(); }

void LogImportJob::poll() {
  if (!permille_) return;
  const int percent = permille_->load() / 10;
  if (percent != last_percent_) {
    last_percent_ = percent;
    emit progress(percent);
  }
}

void LogImportJob::start(const QString& path, std::optional<ColumnMapping> mapping) {
  if (running()) return;
  cancel_ = std::make_shared<std::atomic<bool>>(false);
  permille_ = std::make_shared<std::atomic<int>>(0);
  last_percent_ = -1;
  const std::string file = path.toStdString();
  std::vector<std::filesystem::path> mission;
  const QStringList parts = splitLogPaths(path);
  if (parts.size() > 1 || QFileInfo(path).isDir())
    for (const QString& p : parts) mission.emplace_back(p.toStdString());
  const std::size_t block = block_bytes_;
  auto cancel = cancel_;
  auto permille = permille_;
  busy_ = true;
  watcher_.setFuture(QtConcurrent::run(workerPool(), [file, mission, block, cancel, permille, mapping = std::move(mapping)]() {
    lowerWorkerPriority();
    LogImportOutcome out;
    QElapsedTimer clock;
    clock.start();
    try {
      const LogReaderRegistry registry = LogReaderRegistry::withBuiltinReaders();
      ReadOptions options;
      options.block_bytes = block;
      options.progress = [cancel, permille](double fraction) {
        permille->store(static_cast<int>(fraction * 1000.0));
        return !cancel->load();
      };
      if (!mission.empty()) {  // a folder or several files: one mission, no column mapping
        out.log = std::make_shared<MissionLog>(readMission(mission, options, out.report, registry));
        out.format = out.report.format;
        out.status = LogImportOutcome::Status::kOk;
        out.seconds = static_cast<double>(clock.nsecsElapsed()) * 1e-9;
        return out;
      }
      const LogReader* reader = registry.find(file);
      std::optional<DelimitedTextReader> mapped;
      if (mapping && (!reader || reader->formatName() == DelimitedTextReader().formatName())) {
        mapped.emplace(*mapping);
        reader = &*mapped;
        out.mapped = true;
      }
      if (!reader) {
        std::string known;
        for (const auto& n : registry.formatNames()) known += (known.empty() ? "" : ", ") + n;
        throw InputError("mission log", "format not recognised", "convert it to one of: " + known,
                         {file, 0, 0});
      }
      out.format = reader->formatName();
      auto log = std::make_shared<MissionLog>(reader->read(file, options, out.report));
      out.log = std::move(log);
      out.status = LogImportOutcome::Status::kOk;
    } catch (const ReadCancelled&) {
      out.status = LogImportOutcome::Status::kCancelled;
      out.report = ReadReport{};
    } catch (const InputError& e) {
      out.status = LogImportOutcome::Status::kFailed;
      out.error = e.what();
    } catch (const std::exception& e) {
      out.status = LogImportOutcome::Status::kFailed;
      out.error = e.what();
    }
    out.seconds = static_cast<double>(clock.nsecsElapsed()) * 1e-9;
    return out;
  }));
  poll_timer_.start();
  emit progress(0);
}

}  // namespace auv::ui
