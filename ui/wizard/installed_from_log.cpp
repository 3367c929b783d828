#include "wizard/installed_from_log.h"

#include <QRegularExpression>
#include <QString>
#include <QStringList>

namespace auv::ui {
namespace {

QString initials(const std::string& id) {
  QString out;
  for (const QString& part : QString::fromStdString(id).split('_', Qt::SkipEmptyParts)) out += part.front();
  return out.toLower();
}

}  // namespace

std::optional<std::vector<double>> installedFromLogHeader(const MissionLog& log, const VehicleProfile& v) {
  const std::string* line = log.metadataValue("configuration");
  if (!line) return std::nullopt;
  std::vector<double> kg(v.points.size(), 0.0);
  bool any = false;
  static const QRegularExpression sep("[\\s,;]+");
  for (const QString& token : QString::fromStdString(*line).split(sep, Qt::SkipEmptyParts)) {
    const qsizetype eq = token.indexOf('=');
    if (eq <= 0) return std::nullopt;
    const QString key = token.left(eq).toLower();
    QString number = token.mid(eq + 1);
    if (number.endsWith("kg", Qt::CaseInsensitive)) number.chop(2);
    bool ok = false;
    const double value = number.toDouble(&ok);
    if (!ok) return std::nullopt;
    bool matched = false;
    for (std::size_t i = 0; i < v.points.size(); ++i) {
      if (key == QString::fromStdString(v.points[i].name).toLower() || key == initials(v.points[i].name)) {
        kg[i] = value;
        matched = any = true;
      }
    }
    if (!matched) return std::nullopt;  // a name this vehicle does not have: not our line
  }
  if (!any) return std::nullopt;
  return kg;
}

}  // namespace auv::ui
