#include "pages/crane_weighing_page.h"

#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QVBoxLayout>
#include <cmath>

#include "common/input_error.h"
#include "weighing/crane_weighing.h"
#include "widgets/crane_side_view.h"
#include "widgets/inputs.h"
#include "wizard/operator_wizard.h"

namespace auv::ui {

CraneWeighingPage::CraneWeighingPage(WizardState& state) : state_(state) {
  setTitle(tr("Weighing with crane scales"));
  setSubTitle(tr("Hang the vehicle from two ropes, fore and aft, with a crane scale at each rope end, "
                 "and read the hook scale for the total."));
  const QString names[4] = {tr("Fore / &starboard:"), tr("Fore / &port:"), tr("Aft / s&tarboard:"),
                            tr("Aft / p&ort:")};
  const char* ids[4] = {"scale_fs", "scale_fp", "scale_as", "scale_ap"};
  auto* scalesBox = new QGroupBox(tr("Scale readings"));
  auto* sf = new QFormLayout(scalesBox);
  for (int i = 0; i < 4; ++i) {
    scales_[static_cast<std::size_t>(i)] =
        makeNumber(ids[i], 0, 5000, 1, " kg",
             tr("Reading of the crane scale at this rope end, in kg, with the vehicle hanging still."));
    sf->addRow(names[i], scales_[static_cast<std::size_t>(i)]);
  }
  total_ = makeNumber("total", 0, 10000, 1, " kg", tr("Reading of the scale on the crane hook (the whole vehicle)."));
  sf->addRow(tr("Hoo&k (total):"), total_);
  sum_check_ = new QLabel;
  sum_check_->setObjectName("sum_check");
  sf->addRow(QString(), sum_check_);

  auto* ropeBox = new QGroupBox(tr("Rope positions"));
  auto* rf = new QFormLayout(ropeBox);
  rope_fore_ = makeNumber("rope_fore", -20, 20, 4, " m",
                    tr("x of the fore rope from the vehicle origin, forward positive (measure along the hull)."));
  rope_aft_ = makeNumber("rope_aft", -20, 20, 4, " m", tr("x of the aft rope from the vehicle origin, forward positive."));
  rope_y_ = makeNumber("rope_y", 0.01, 5, 3, " m", tr("Half the lateral distance between the two ends of one rope."));
  rf->addRow(tr("&Fore rope x:"), rope_fore_);
  rf->addRow(tr("&Aft rope x:"), rope_aft_);
  rf->addRow(tr("Rope end &y (±):"), rope_y_);

  auto* instBox = new QGroupBox(tr("Adjustment weight installed now"));
  auto* inf = new QFormLayout(instBox);
  for (int i = 0; i < 4; ++i) {
    installed_[static_cast<std::size_t>(i)] =
        makeNumber(QString("installed_%1").arg(i), 0, 200, 1, " kg", tr("Kit pieces already in this point, in kg."));
    // The scales own the shortcut letters of these names.
    inf->addRow(QString(names[i]).remove('&'), installed_[static_cast<std::size_t>(i)]);
  }
  error_ = new QLabel;
  error_->setObjectName("error");
  error_->setWordWrap(true);
  error_->setStyleSheet("color: #b00020;");

  side_view_ = new CraneSideView;

  auto* grid = new QGridLayout;
  grid->addWidget(scalesBox, 0, 0, 2, 1);
  grid->addWidget(ropeBox, 0, 1);
  grid->addWidget(instBox, 1, 1);
  auto* lay = new QVBoxLayout(this);
  lay->addLayout(grid);
  lay->addWidget(error_);
  lay->addWidget(side_view_, 1);

  for (auto* s : scales_) connect(s, &NumberInput::valueChanged, this, [this] { updateSumCheck(); });
  connect(total_, &NumberInput::valueChanged, this, [this] { updateSumCheck(); });
  for (auto* s : {rope_fore_, rope_aft_, rope_y_}) {
    connect(s, &NumberInput::valueChanged, this, [this] {
      updateSideView();
      emit completeChanged();
    });
  }
}

void CraneWeighingPage::updateSideView() {
  CraneSideViewData d;
  if (state_.vehicle) {
    d.length_m = state_.vehicle->hull.length_m;
    d.diameter_m = state_.vehicle->hull.diameter_m;
    d.cb_x_m = state_.vehicle->cb_m.x();
  }
  CraneWeighing w = state_.crane.weighing;
  for (std::size_t i = 0; i < 4; ++i) {
    d.scales_kg[i] = scales_[i]->value();
    w.scales_kg[i] = scales_[i]->value();
  }
  d.total_kg = total_->value();
  d.rope_fore_x_m = rope_fore_->value();
  d.rope_aft_x_m = rope_aft_->value();
  w.total_kg = d.total_kg;
  w.rope_x_fore_m = d.rope_fore_x_m;
  w.rope_x_aft_m = d.rope_aft_x_m;
  w.rope_y_m = rope_y_->value();
  try {
    d.cg_x_m = weighCrane(w).mass.cg_m.x();  // core: the CG the readings give
  } catch (const InputError&) {
    // Readings that do not weigh yet (e.g. mid-typing): no CG marker.
  }
  side_view_->setData(d);
}

void CraneWeighingPage::initializePage() {
  const auto& w = state_.crane.weighing;
  for (std::size_t i = 0; i < 4; ++i) {
    scales_[i]->setValue(w.scales_kg[i]);
    installed_[i]->setValue(i < state_.crane.installed_kg.size() ? state_.crane.installed_kg[i] : 0.0);
    // One row per adjustment point of the profile, named by its label (a
    // Delphin2 has two; the four scales stay).
    const bool used = !state_.vehicle || i < state_.vehicle->points.size();
    installed_[i]->setVisible(used);
    if (auto* form = qobject_cast<QFormLayout*>(installed_[i]->parentWidget()->layout())) {
      if (auto* l = qobject_cast<QLabel*>(form->labelForField(installed_[i]))) {
        l->setVisible(used);
        if (used && state_.vehicle) l->setText(QString::fromStdString(state_.vehicle->points[i].label) + ":");
      }
    }
    if (state_.vehicle && i < state_.vehicle->points.size()) {
      installed_[i]->setToolTip(tr("Kit pieces already in '%1', in kg.")
                                    .arg(QString::fromStdString(state_.vehicle->points[i].label)));
    }
  }
  total_->setValue(w.total_kg);
  rope_fore_->setValue(w.rope_x_fore_m);
  rope_aft_->setValue(w.rope_x_aft_m);
  rope_y_->setValue(w.rope_y_m);
  updateSumCheck();
}

void CraneWeighingPage::updateSumCheck() {
  double parts = 0;
  for (auto* s : scales_) parts += s->value();
  const double diff = parts - total_->value();
  const double tol = state_.crane.weighing.sum_tolerance_kg;
  sum_ok_ = total_->value() > 0 && std::abs(diff) <= 5 * tol;
  QString text = tr("Parts add up to %1 kg (%2 kg against the hook)").arg(fixed(parts, 1)).arg(fixed(diff, 1));
  if (std::abs(diff) <= tol) {
    sum_check_->setStyleSheet("color: #1b5e20;");
  } else if (sum_ok_) {
    sum_check_->setStyleSheet("color: #8a6d00;");
    text += tr(": more than %1 kg, check the readings").arg(fixed(tol, 1));
  } else {
    sum_check_->setStyleSheet("color: #b00020;");
    text += tr(": re-read the scales");
  }
  sum_check_->setText(text);
  updateSideView();
  emit completeChanged();
}

// The CG comes from the moment of the rope forces about the ropes' stations:
// with the fore rope not forward of the aft one (both still 0 on a new
// page) there is no lever, so Next waits for the rope positions too.
bool CraneWeighingPage::isComplete() const { return sum_ok_ && rope_fore_->value() > rope_aft_->value(); }

void CraneWeighingPage::cleanupPage() { store(); }

void CraneWeighingPage::store() {
  auto& w = state_.crane.weighing;
  for (std::size_t i = 0; i < 4; ++i) w.scales_kg[i] = scales_[i]->value();
  w.total_kg = total_->value();
  w.rope_x_fore_m = rope_fore_->value();
  w.rope_x_aft_m = rope_aft_->value();
  w.rope_y_m = rope_y_->value();
  state_.crane.installed_kg.clear();
  const std::size_t points = state_.vehicle ? std::min<std::size_t>(state_.vehicle->points.size(), 4) : 4;
  for (std::size_t i = 0; i < points; ++i) state_.crane.installed_kg.push_back(installed_[i]->value());
}

bool CraneWeighingPage::validatePage() {
  store();
  try {
    CraneWeighing w = state_.crane.weighing;
    weighCrane(w);  // field-level checks; the numbers are computed on the result page
  } catch (const InputError& e) {
    error_->setText(QString::fromStdString(e.what()));
    return false;
  }
  error_->clear();
  return true;
}

int CraneWeighingPage::nextId() const { return OperatorWizard::kWater; }

}  // namespace auv::ui
