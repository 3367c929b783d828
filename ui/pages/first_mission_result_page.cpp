#include "pages/first_mission_result_page.h"

#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>

#include "common/input_error.h"
#include "common/units.h"
#include "firstmission/hugin_first_mission.h"
#include "widgets/weight_map_widget.h"

namespace auv::ui {
namespace {

QString piecesText(const PointRecommendation& p) {
  QStringList parts;
  for (const auto& pc : p.pieces) {
    if (pc.count == 0) continue;
    parts << QString("%1 %2 × %3 kg")
                 .arg(pc.count > 0 ? QObject::tr("add") : QObject::tr("remove"))
                 .arg(std::abs(pc.count))
                 .arg(pc.size_kg, 0, 'f', 1);
  }
  return parts.isEmpty() ? QObject::tr("no change") : parts.join(", ");
}

QString band(bool ok) { return ok ? QString("✓") : QString("✗"); }

}  // namespace

FirstMissionResultPage::FirstMissionResultPage(WizardState& state) : state_(state) {
  setTitle(tr("Ballast change before the first mission"));
  before_ = new QLabel;
  before_->setObjectName("before");
  before_->setWordWrap(true);
  predicted_ = new QLabel;
  predicted_->setObjectName("predicted");
  predicted_->setWordWrap(true);
  messages_ = new QLabel;
  messages_->setObjectName("messages");
  messages_->setWordWrap(true);
  table_ = new QTableWidget(0, 3);
  table_->setObjectName("changes");
  table_->setHorizontalHeaderLabels({tr("Point"), tr("Change"), tr("Pieces")});
  table_->horizontalHeader()->setStretchLastSection(true);
  table_->verticalHeader()->hide();
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  map_ = new WeightMapWidget;
  auto* lay = new QVBoxLayout(this);
  lay->addWidget(before_);
  lay->addWidget(table_, 1);
  lay->addWidget(map_, 2);
  lay->addWidget(predicted_);
  lay->addWidget(messages_);
}

void FirstMissionResultPage::initializePage() {
  state_.report.reset();
  state_.last_error.clear();
  try {
    state_.report = craneFirstMission(*state_.vehicle, state_.crane);
    showReport(*state_.report);
  } catch (const InputError& e) {
    state_.last_error = e.what();
    before_->setText(tr("Cannot compute: %1").arg(QString::fromStdString(e.what())));
    before_->setStyleSheet("color: #b00020;");
  }
}

void FirstMissionResultPage::showReport(const FirstMissionReport& r) {
  const Eigen::Vector3d d = r.cg_m - r.cb_m;
  before_->setStyleSheet(QString());
  before_->setText(tr("Weighed %1 kg; buoyancy %2 kg in %3 kg/m³ water → net buoyancy %4 kg (%5). "
                      "CG − CB: x %6 mm, y %7 mm; static pitch %8°, roll %9°.")
                       .arg(r.weight_kg, 0, 'f', 1)
                       .arg(r.buoyancy_kg, 0, 'f', 1)
                       .arg(r.density_kgm3, 0, 'f', 2)
                       .arg(r.net_buoyancy_kg, 0, 'f', 2)
                       .arg(r.net_buoyancy_kg >= 0 ? tr("too light") : tr("too heavy"))
                       .arg(units::mToMm(d.x()), 0, 'f', 1)
                       .arg(units::mToMm(d.y()), 0, 'f', 1)
                       .arg(r.pitch_before_deg, 0, 'f', 2)
                       .arg(r.roll_before_deg, 0, 'f', 2));
  table_->setRowCount(static_cast<int>(r.points.size()));
  for (int i = 0; i < static_cast<int>(r.points.size()); ++i) {
    const auto& p = r.points[static_cast<std::size_t>(i)];
    table_->setItem(i, 0, new QTableWidgetItem(QString::fromStdString(p.label)));
    table_->setItem(i, 1, new QTableWidgetItem(QString("%1%2 kg").arg(p.add_kg >= 0 ? "+" : "").arg(p.add_kg, 0, 'f', 1)));
    table_->setItem(i, 2, new QTableWidgetItem(piecesText(p)));
  }
  table_->resizeColumnsToContents();
  map_->setModel(makeWeightMapModel(*state_.vehicle, state_.crane.installed_kg, r));
  const auto& spec = state_.vehicle->spec;
  const bool nb_ok = r.predicted.net_buoyancy_kg >= spec.net_buoyancy_min_kg - 1e-9 &&
                     r.predicted.net_buoyancy_kg <= spec.net_buoyancy_max_kg + 1e-9;
  predicted_->setText(tr("After the change: net buoyancy %1 kg %2 (band %3..%4), pitch %5° %6 (±%7), "
                         "roll %8° %9 (±%10).")
                          .arg(r.predicted.net_buoyancy_kg, 0, 'f', 2)
                          .arg(band(nb_ok))
                          .arg(spec.net_buoyancy_min_kg, 0, 'f', 1)
                          .arg(spec.net_buoyancy_max_kg, 0, 'f', 1)
                          .arg(r.predicted.pitch_deg, 0, 'f', 2)
                          .arg(band(std::abs(r.predicted.pitch_deg) <= spec.pitch_tolerance_deg))
                          .arg(spec.pitch_tolerance_deg, 0, 'f', 1)
                          .arg(r.predicted.roll_deg, 0, 'f', 2)
                          .arg(band(std::abs(r.predicted.roll_deg) <= spec.roll_tolerance_deg))
                          .arg(spec.roll_tolerance_deg, 0, 'f', 1));
  QStringList msgs;
  for (const auto& w : r.warnings) msgs << tr("⚠ %1").arg(QString::fromStdString(w));
  for (const auto& n : r.notes) msgs << QString::fromStdString(n);
  messages_->setText(msgs.join("\n"));
}

}  // namespace auv::ui
