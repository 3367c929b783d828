#pragma once
// How an estimate is written on every page and in the work order: value ±
// sigma, or "not known" when the log did not identify it. A zero or absent
// sigma is never shown as "± 0.00" (false confidence, issue 14 item 4).
#include <QCoreApplication>
#include <QString>
#include <optional>

#include "analysis/analysis_report.h"
#include "discrepancy/plan_estimate.h"
#include "planning/pre_mission_plan.h"

namespace auv::ui {

class EstimateText {
  Q_DECLARE_TR_FUNCTIONS(auv::ui::EstimateText)

 public:
  static QString notKnown();
  // True when a value with this sigma was identified (finite, sigma > 0).
  static bool identified(double value, double sigma);
  // "+1.23 ± 0.05 kg" (unit appended as given, e.g. " kg" or "°"), else "not
  // known"; more decimals when the sigma would round to 0 ("+0.012 ± 0.004").
  static QString valueSigma(bool known, double value, double sigma, int decimals, const QString& unit);
  static QString of(const analysis::EstimatedValue& e, int decimals, const QString& unit);
  static QString of(const std::optional<double>& value, double sigma, int decimals, const QString& unit);
  // Decimals that show a measured sigma (a 95 % half-width) as non-zero:
  // `decimals`, more (up to `max`) when it would round to 0.
  static int decimalsFor(double sigma, int decimals, int max = 4);
  // The sentence every page shows: which estimate the plan uses.
  static QString planUses(discrepancy::EstimateSource source);
  // Pitch / roll of a plan are known when the estimate identified CG x / CG y.
  static bool pitchKnown(const PreMissionPlan& p);
  static bool rollKnown(const PreMissionPlan& p);
};

}  // namespace auv::ui
