#include "wizard/model_words.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include "wizard/advice_text.h"

namespace auv::ui {
namespace {

struct Name {
  const char* id;
  const char* label;
};

constexpr Name kTerms[] = {
    {"hull_compressibility", QT_TRANSLATE_NOOP("ModelWords", "hull compressibility")},
    {"thermal_expansion", QT_TRANSLATE_NOOP("ModelWords", "hull thermal expansion")},
    {"propeller_torque", QT_TRANSLATE_NOOP("ModelWords", "propeller torque")},
    {"mass_drift", QT_TRANSLATE_NOOP("ModelWords", "mass drift")},
    {"pitch_sensor_bias", QT_TRANSLATE_NOOP("ModelWords", "pitch sensor bias")},
    {"roll_sensor_bias", QT_TRANSLATE_NOOP("ModelWords", "roll sensor bias")},
    {"depth_sensor_offset", QT_TRANSLATE_NOOP("ModelWords", "depth sensor offset")},
    {"quadratic_pitch_damping", QT_TRANSLATE_NOOP("ModelWords", "quadratic pitch damping")},
    {"vertical_current", QT_TRANSLATE_NOOP("ModelWords", "vertical current")},
};

QString words(const char* s) { return QCoreApplication::translate("ModelWords", s); }

}  // namespace

QString termLabel(const std::string& id) {
  for (const Name& n : kTerms)
    if (id == n.id) return words(n.label);
  return QString::fromStdString(id).replace('_', ' ');
}

QString channelLabel(discrepancy::Channel c) {
  using discrepancy::Channel;
  switch (c) {
    case Channel::kVerticalVelocity: return words(QT_TRANSLATE_NOOP("ModelWords", "vertical velocity"));
    case Channel::kVerticalForce: return words(QT_TRANSLATE_NOOP("ModelWords", "vertical force"));
    case Channel::kPitchMoment: return words(QT_TRANSLATE_NOOP("ModelWords", "pitch moment"));
    case Channel::kRollMoment: return words(QT_TRANSLATE_NOOP("ModelWords", "roll moment"));
    case Channel::kDepth: return words(QT_TRANSLATE_NOOP("ModelWords", "depth"));
    case Channel::kPitch: return words(QT_TRANSLATE_NOOP("ModelWords", "pitch"));
    case Channel::kRoll: return words(QT_TRANSLATE_NOOP("ModelWords", "roll"));
    case Channel::kSpeed: return words(QT_TRANSLATE_NOOP("ModelWords", "speed"));
    case Channel::kSurgeForce: return words(QT_TRANSLATE_NOOP("ModelWords", "surge force"));
  }
  return QString::fromLatin1(discrepancy::channelName(c)).replace('_', ' ');
}

QString readableModelText(const std::string& core_text) {
  QString s = QString::fromStdString(core_text);
  for (const Name& n : kTerms) s.replace(QString::fromLatin1(n.id), words(n.label));
  using discrepancy::Channel;
  for (Channel c : {Channel::kVerticalVelocity, Channel::kVerticalForce, Channel::kPitchMoment, Channel::kRollMoment,
                    Channel::kSurgeForce})
    s.replace(QString::fromLatin1(discrepancy::channelName(c)), channelLabel(c));
  s.replace("ballast_state", words(QT_TRANSLATE_NOOP("ModelWords", "ballast state")));
  s.replace("core/sim", words(QT_TRANSLATE_NOOP("ModelWords", "the simulator")));
  // Any other id or profile key left in core's English: its words.
  static const QRegularExpression id(R"(\b([A-Za-z0-9]+)_(?=[A-Za-z0-9]))");
  for (int i = 0; i < 8 && s.contains(id); ++i) s.replace(id, "\\1 ");
  static const QRegularExpression range(R"((\d)--(\d))");
  s.replace(range, "\\1 " + words(QT_TRANSLATE_NOOP("ModelWords", "to")) + " -\\2");
  return s;
}

QString readableModelMessage(const Message& m) {
  return readableModelText(m.id().empty() ? m.text() : adviceText(m).toStdString());
}

QString residualSourceLabel(const std::string& source) {
  if (source == "equation error") return words(QT_TRANSLATE_NOOP("ModelWords", "equation error"));
  if (source == "simulation error") return words(QT_TRANSLATE_NOOP("ModelWords", "simulation error"));
  if (source == "term contribution") return words(QT_TRANSLATE_NOOP("ModelWords", "term contribution"));
  return QString::fromStdString(source);
}

}  // namespace auv::ui
