#include "widgets/analysis_summary.h"

#include <QGridLayout>
#include <QLabel>
#include <QStringList>
#include <cmath>

#include "widgets/estimate_text.h"
#include "widgets/inputs.h"
#include "wizard/advice_text.h"

namespace auv::ui {
namespace {


QLabel* resultLabel(const char* name) {
  auto* l = new QLabel;
  l->setObjectName(name);
  l->setWordWrap(true);
  l->setTextFormat(Qt::RichText);
  l->setTextInteractionFlags(Qt::TextSelectableByMouse);
  return l;
}

// "mean ± 95 % half-width unit", or "n/a".
QString meanText(const analysis::MeanEstimate& m, int decimals, const QString& unit, bool sign = true) {
  if (!m.valid() || !std::isfinite(m.mean)) return AnalysisSummary::tr("n/a");
  decimals = EstimateText::decimalsFor(m.ci95, decimals);  // a small interval is not "± 0.00"
  const QString v = sign ? signedFixed(m.mean, decimals) : fixed(m.mean, decimals);
  const QString ci = std::isfinite(m.ci95) ? QStringLiteral(" ± %1").arg(fixed(m.ci95, decimals)) : QString();
  return v + ci + unit;
}

QString estimateText(const analysis::EstimatedValue& e, int decimals, const QString& unit) {
  return EstimateText::of(e, decimals, unit);
}

}  // namespace

AnalysisSummary::AnalysisSummary() {
  net_ = resultLabel("net_buoyancy");
  cg_ = resultLabel("cg_offset");
  errors_ = resultLabel("errors");
  water_ = resultLabel("water");
  source_ = resultLabel("plan_estimate_source");
  grid_ = new QGridLayout;
  grid_->setHorizontalSpacing(16);
  grid_->setVerticalSpacing(2);
  grid_->addWidget(net_, 0, 0);
  grid_->addWidget(cg_, 0, 1);
  grid_->addWidget(errors_, 1, 0, 1, 2);
  grid_->addWidget(water_, 2, 0, 1, 2);
  grid_->addWidget(source_, 3, 0, 1, 2);
  grid_->setColumnStretch(0, 3);
  grid_->setColumnStretch(1, 2);

  notes_ = new QLabel;
  notes_->setObjectName("analysis_notes");
  notes_->setWordWrap(true);
  notes_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  notes_->setTextFormat(Qt::RichText);
  notes_->setTextInteractionFlags(Qt::TextSelectableByMouse);
}

void AnalysisSummary::showPending(const QString& note) {
  source_->clear();
  source_->setVisible(false);
  net_->setStyleSheet(QString());
  net_->setText(note);
  cg_->clear();
  errors_->clear();
  water_->clear();
  notes_->clear();
}

void AnalysisSummary::show(const analysis::AnalysisReport* report, bool glider, const QString& error,
                           const QString& source) {
  source_->setText(report ? source : QString());
  source_->setVisible(report && !source.isEmpty());
  if (!report) {
    net_->setText(tr("<b>No analysis</b>: %1").arg(error.toHtmlEscaped()));
    net_->setStyleSheet("color: #b00020;");
    cg_->clear();
    errors_->clear();
    water_->clear();
    notes_->clear();
    return;
  }
  net_->setStyleSheet(QString());
  const analysis::AnalysisReport& r = *report;
  const bool g = glider;
  // A glider's net buoyancy line also carries the grams to add: it gets the
  // whole width, and the (short) CG line moves next to the errors.
  grid_->removeWidget(net_);
  grid_->removeWidget(cg_);
  grid_->removeWidget(errors_);
  grid_->addWidget(net_, 0, 0, 1, g ? 2 : 1);
  grid_->addWidget(errors_, 1, 0, 1, g ? 1 : 2);
  grid_->addWidget(cg_, g ? 1 : 0, 1);
  // Gliders are ballasted to the gram, AUVs to kit pieces of 0.1 kg and up.
  const int kg_dec = g ? 3 : 2;
  QString net = tr("Net buoyancy: <b>%1</b>").arg(estimateText(r.net_buoyancy_kg, kg_dec, tr(" kg")));
  if (r.net_buoyancy_kg.known && std::isfinite(r.net_buoyancy_kg.value)) {
    const double v = std::round(r.net_buoyancy_kg.value * std::pow(10.0, kg_dec));
    net += " " + (v > 0 ? tr("(too light, 1 σ)") : v < 0 ? tr("(too heavy, 1 σ)") : tr("(neutral, 1 σ)"));
  }
  if (r.mass_to_add_g.known && std::isfinite(r.mass_to_add_g.value))
    net += tr("; add %1 for neutral at %2 kg/m³")
               .arg(estimateText(r.mass_to_add_g, 0, tr(" g")))
               .arg(fixed(r.target_density_kgm3, 2));
  net_->setText(net);
  if (!r.cg_x_mm.known && !r.cg_y_mm.known)
    cg_->setText(tr("CG − CB: <b>%1</b> (see the notes)").arg(EstimateText::notKnown()));
  else
    cg_->setText(tr("CG − CB: x <b>%1</b>, y <b>%2</b>")
                     .arg(estimateText(r.cg_x_mm, 1, tr(" mm")), estimateText(r.cg_y_mm, 1, tr(" mm"))));
  errors_->setText(tr("Errors (95 %): depth %1 · pitch %2 · roll %3")
                       .arg(meanText(r.depth_error_m, 2, tr(" m")), meanText(r.pitch_error_deg, 2, tr("°")),
                            meanText(r.roll_deg, 2, tr("°"))));
  water_->setText(tr("Water at %1: %2 · %3 · %4 (95 %)")
                      .arg(meanText(r.depth_m, 1, tr(" m"), false), meanText(r.temperature_degC, 2, tr(" °C"), false),
                           meanText(r.salinity_psu, 2, tr(" PSU"), false),
                           meanText(r.density_kgm3, 2, tr(" kg/m³"), false)));
  QStringList lines;
  for (const auto& w : r.warnings) lines << QStringLiteral("⚠ %1").arg(adviceText(w).toHtmlEscaped());
  const std::pair<const char*, const analysis::EstimatedValue*> est[] = {
      {QT_TR_NOOP("Net buoyancy"), &r.net_buoyancy_kg}, {QT_TR_NOOP("CG x"), &r.cg_x_mm}, {QT_TR_NOOP("CG y"), &r.cg_y_mm}};
  for (const auto& [name, e] : est)
    if (!e->known && !e->why_not.empty()) lines << tr("<b>%1</b>: %2").arg(tr(name), adviceText(e->why_not).toHtmlEscaped());
  if (!r.pitch_error_basis.empty()) lines << tr("Pitch error: %1").arg(adviceText(r.pitch_error_basis).toHtmlEscaped());
  for (const auto& n : r.notes) lines << QStringLiteral("<span style='color:#555'>%1</span>").arg(adviceText(n).toHtmlEscaped());
  notes_->setText(lines.join("<br>"));
}

}  // namespace auv::ui
