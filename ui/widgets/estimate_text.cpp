#include "widgets/estimate_text.h"

#include <cmath>

#include "widgets/inputs.h"

namespace auv::ui {

QString EstimateText::notKnown() { return tr("not known"); }

bool EstimateText::identified(double value, double sigma) {
  return std::isfinite(value) && std::isfinite(sigma) && sigma > 0.0;
}

QString EstimateText::valueSigma(bool known, double value, double sigma, int decimals, const QString& unit) {
  if (!known || !identified(value, sigma)) return notKnown();
  decimals = decimalsFor(sigma, decimals);  // a small sigma is shown, never "± 0.0"
  return tr("%1 ± %2%3").arg(signedFixed(value, decimals), fixed(sigma, decimals), unit);
}

QString EstimateText::of(const analysis::EstimatedValue& e, int decimals, const QString& unit) {
  return valueSigma(e.known, e.value, e.sigma, decimals, unit);
}

QString EstimateText::of(const std::optional<double>& value, double sigma, int decimals, const QString& unit) {
  return valueSigma(value.has_value(), value.value_or(NAN), sigma, decimals, unit);
}

int EstimateText::decimalsFor(double sigma, int decimals, int max) {
  int d = decimals;
  while (d < max && std::isfinite(sigma) && sigma > 0.0 && std::round(sigma * std::pow(10.0, d)) == 0.0) ++d;
  return d;
}

QString EstimateText::planUses(discrepancy::EstimateSource source) {
  switch (source) {
    case discrepancy::EstimateSource::kModelCheck:
      return tr("The plan uses the estimate with the model-check terms you accepted.");
    case discrepancy::EstimateSource::kModelCheckReplay:
      return tr("The plan uses the model check's fit of the whole log: the steady flight alone did not identify "
                "the ballast state.");
    case discrepancy::EstimateSource::kHistoryJoint:
      return tr("The plan uses the estimate calibrated from this log and the configuration's earlier mission "
                "(the weight change between them is known).");
    case discrepancy::EstimateSource::kAnalysis:
      break;
  }
  return tr("The plan uses the estimate calibrated from this log.");
}

bool EstimateText::pitchKnown(const PreMissionPlan& p) {
  return p.estimate.cg_x_m.has_value() && identified(p.predicted.pitch_deg, p.pitch_sigma_deg);
}

bool EstimateText::rollKnown(const PreMissionPlan& p) {
  return p.estimate.cg_y_m.has_value() && identified(p.predicted.roll_deg, p.roll_sigma_deg);
}

}  // namespace auv::ui
