#pragma once
// What was calibrated (issue 11): each vehicle constant the analysis or the
// model check fitted with the ballast state, by name, with its value ± σ,
// the profile's value and whether this log identified it or it stayed at
// its prior; and the calibration manoeuvre, when one is asked for. One
// table for the adjustment and model-check pages, the same lines for the
// work order.
#include <QCoreApplication>
#include <QString>
#include <QStringList>
#include <QTableWidget>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "discrepancy/model_check.h"

namespace auv::ui {

struct CalibrationRow {
  QString name, value, profile;
  QString unit_note;  // a long unit, said in the tooltip (and the work order) instead of the cell
  bool identified = false;
  bool from_analysis = false;  // held by the model check at the same log's analysis's value
  bool used = true;            // false: measured, but the estimate kept the profile's value (the hull law)
};

class CalibrationTable : public QTableWidget {
  Q_OBJECT

 public:
  explicit CalibrationTable(QWidget* parent = nullptr);
  // One row per constant; none: one row saying nothing was calibrated.
  void showRows(const std::vector<CalibrationRow>& rows);

  // From a report's `calibration` list (analysis or model check JSON).
  static std::vector<CalibrationRow> rowsFromJson(const nlohmann::json& list);
  static std::vector<CalibrationRow> rowsOf(const std::vector<discrepancy::CalibrationValue>& list);
  // The technician's name of a constant (never its id).
  static QString nameOf(const std::string& id);
  // "Heave lift of the hull: 0.93 ± 0.10 × the profile's (profile 1); from this log".
  static QStringList lines(const std::vector<CalibrationRow>& rows);
  // The manoeuvre {legs, expected_sigma} as lines: the legs (one line,
  // "; " between them), then the σ expected after it. Empty when `m` is not one.
  static QStringList manoeuvreLines(const nlohmann::json& m);
  // The plan's after_move_expected_sigma in one sentence (empty when unset):
  // the move itself calibrates the next mission's analysis.
  static QString afterMoveLine(std::optional<double> net_sigma_kg, std::optional<double> x_sigma_m);
  // The "From" column: this log, the prior, or (in the model check) the analysis's, held.
  static QString source(const CalibrationRow& r);
};

}  // namespace auv::ui
