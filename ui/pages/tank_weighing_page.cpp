#include "pages/tank_weighing_page.h"

#include <QComboBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QVBoxLayout>

#include "common/input_error.h"
#include "firstmission/slocum_first_mission.h"
#include "weighing/tank_weighing_file.h"
#include "widgets/inputs.h"
#include "wizard/json_number.h"
#include "wizard/operator_wizard.h"

namespace auv::ui {
namespace {

// Labels in the order of SlocumItem.
const char* const kItemLabels[kSlocumItemCount] = {
    QT_TRANSLATE_NOOP("auv::ui::TankWeighingPage", "Bow bottle, &port:"),
    QT_TRANSLATE_NOOP("auv::ui::TankWeighingPage", "Bow bottle, &starboard:"),
    QT_TRANSLATE_NOOP("auv::ui::TankWeighingPage", "Aft bottle, &upper:"),
    QT_TRANSLATE_NOOP("auv::ui::TankWeighingPage", "Aft bottle, &lower:"),
    QT_TRANSLATE_NOOP("auv::ui::TankWeighingPage", "Wing rail, p&ort:"),
    QT_TRANSLATE_NOOP("auv::ui::TankWeighingPage", "Wing rail, s&tarboard:"),
};

}  // namespace

TankWeighingPage::TankWeighingPage(WizardState& state) : state_(state) {
  setTitle(tr("Slocum tank weighing"));
  setSubTitle(tr("Hang the glider submerged in the tank from the two spring scales over the bow and aft "
                 "ballast bottles; read both once it hangs still and level, with no air trapped."));

  glider_ = new QLineEdit;
  glider_->setObjectName("glider");
  glider_->setToolTip(tr("Glider serial number or name, for the record."));
  glider_->setMinimumHeight(32);
  dry_mass_ = makeNumber("dry_mass", 1, 1000, 3, tr(" kg"),
                       tr("Mass of the complete glider in air (wings and ballast as now), from a calibrated scale."));
  bow_scale_ = makeNumber("bow_scale", 0, 100000, 0, tr(" g"),
                        tr("Spring scale hanging directly above the bow ballast bottles, glider fully submerged "
                           "and still. Read it at eye level, in grams."));
  aft_scale_ = makeNumber("aft_scale", 0, 100000, 0, tr(" g"),
                        tr("Spring scale hanging directly above the aft ballast bottles, read at the same time."));
  auto* gBox = new QGroupBox(tr("Glider and spring scales"));
  auto* gf = new QFormLayout(gBox);
  gf->addRow(tr("Gl&ider:"), glider_);
  gf->addRow(tr("&Dry mass:"), dry_mass_);
  gf->addRow(tr("Bow s&cale:"), bow_scale_);
  gf->addRow(tr("&Aft scale:"), aft_scale_);

  tank_water_ = new QComboBox;
  tank_water_->setObjectName("tank_water");
  tank_water_->addItem(tr("Fresh water"), false);
  tank_water_->addItem(tr("Salt water"), true);
  tank_water_->setToolTip(tr("Fresh tank water is taken as 1000 kg/m³ unless you measured it; salt water needs "
                             "its measured density."));
  tank_water_->setMinimumHeight(32);
  tank_density_ = makeNumber("tank_density", 990, 1050, 2, tr(" kg/m³"),
                           tr("Density of the tank water (hydrometer or CTD)."));
  tank_temperature_ = makeNumber("tank_temperature", -2, 40, 1, tr(" °C"),
                               tr("Tank water temperature next to the glider, at mid depth."));
  target_density_ = makeNumber("target_density", 990, 1060, 2, tr(" kg/m³"),
                             tr("Density of the water the glider will fly in (from a CTD cast or the area's climatology)."));
  target_temperature_ = makeNumber("target_temperature", -2.5, 40, 1, tr(" °C"),
                                 tr("Temperature of the deployment water: the aluminium hull shrinks in cold water."));
  auto* wBox = new QGroupBox(tr("Water"));
  auto* wf = new QFormLayout(wBox);
  wf->addRow(tr("Tank &water:"), tank_water_);
  wf->addRow(tr("Tank d&ensity:"), tank_density_);
  wf->addRow(tr("Tank te&mperature:"), tank_temperature_);
  wf->addRow(tr("Ta&rget density:"), target_density_);
  wf->addRow(tr("Tar&get temperature:"), target_temperature_);

  auto* bBox = new QGroupBox(tr("Ballast in the glider now"));
  auto* bf = new QFormLayout(bBox);
  for (int i = 0; i < kSlocumItemCount; ++i) {
    const auto item = static_cast<SlocumItem>(i);
    auto* s = makeNumber(QString("ballast_%1").arg(slocumItemName(item)), 0, 5000, 0, tr(" g"),
                       i < 4 ? tr("Lead shot in this ballast bottle now, in grams (weigh the bottle contents).")
                             : tr("Brass in this wing rail now, in grams."));
    ballast_[static_cast<std::size_t>(i)] = s;
    bf->addRow(tr(kItemLabels[i]), s);
  }

  result_ = new QLabel;
  result_->setObjectName("tank_result");
  result_->setWordWrap(true);
  result_->setTextFormat(Qt::RichText);
  error_ = makeErrorLabel();

  auto* grid = new QGridLayout;
  grid->addWidget(gBox, 0, 0);
  grid->addWidget(wBox, 1, 0);
  grid->addWidget(bBox, 0, 1, 2, 1);
  auto* lay = new QVBoxLayout(this);
  lay->addLayout(grid);
  lay->addWidget(result_);
  lay->addWidget(error_);
  lay->addStretch();

  connect(tank_water_, &QComboBox::currentIndexChanged, this, [this] { applyWaterChoice(); });
  for (auto* s : {dry_mass_, bow_scale_, aft_scale_, tank_density_, tank_temperature_, target_density_,
                  target_temperature_}) {
    connect(s, &NumberInput::valueChanged, this, [this] { updatePreview(); });
  }
  for (auto* s : ballast_) connect(s, &NumberInput::valueChanged, this, [this] { updatePreview(); });
}

void TankWeighingPage::applyWaterChoice() {
  const bool salt = tank_water_->currentData().toBool();
  // Fresh water: the loader's range (990..1010) and the report's 1000 kg/m³.
  tank_density_->setRange(990, salt ? 1050 : 1010);
  if (!loading_) tank_density_->setValue(salt ? 1025.0 : kFreshTankDensityKgm3);
  updatePreview();
}

void TankWeighingPage::initializePage() {
  loading_ = true;
  const TankWeighing& w = state_.tank;
  glider_->setText(QString::fromStdString(w.glider));
  dry_mass_->setValue(w.readings.dry_mass_kg >= 1.0 ? w.readings.dry_mass_kg
                                                    : (state_.vehicle ? state_.vehicle->mass_kg : 1.0));
  bow_scale_->setValue(w.readings.bow_scale_kg * 1000.0);
  aft_scale_->setValue(w.readings.aft_scale_kg * 1000.0);
  tank_water_->setCurrentIndex(state_.tank_water_salt ? 1 : 0);
  tank_density_->setRange(990, state_.tank_water_salt ? 1050 : 1010);
  tank_density_->setValue(w.readings.tank.density_kgm3);
  tank_temperature_->setValue(w.readings.tank.temperature_degC);
  target_density_->setValue(w.readings.target.density_kgm3);
  target_temperature_->setValue(w.readings.target.temperature_degC);
  for (std::size_t i = 0; i < ballast_.size(); ++i) ballast_[i]->setValue(w.ballast.item_kg[i] * 1000.0);
  loading_ = false;
  updatePreview();
}

void TankWeighingPage::store(TankWeighing& w) const {
  if (state_.vehicle) w.vehicle = state_.vehicle->id;
  w.glider = glider_->text().toStdString();
  w.readings.dry_mass_kg = dry_mass_->value();
  w.readings.bow_scale_kg = bow_scale_->value() / 1000.0;
  w.readings.aft_scale_kg = aft_scale_->value() / 1000.0;
  w.readings.tank.density_kgm3 = tank_density_->value();
  w.readings.tank.temperature_degC = tank_temperature_->value();
  w.readings.target.density_kgm3 = target_density_->value();
  w.readings.target.temperature_degC = target_temperature_->value();
  for (std::size_t i = 0; i < ballast_.size(); ++i) w.ballast.item_kg[i] = ballast_[i]->value() / 1000.0;
}

void TankWeighingPage::updatePreview() {
  if (loading_ || !state_.vehicle) return;
  // The tank step alone: as weighed, before any roll test.
  TankWeighing w = state_.tank;
  store(w);
  w.bottles_after_tank_step_kg.reset();
  w.roll_test.reset();
  try {
    const FirstMissionReport r = slocumFirstMission(*state_.vehicle, w);
    const auto& d = r.details;
    QStringList changes;
    for (std::size_t i = 0; i < 4 && i < r.points.size(); ++i) {
      changes << QString("%1 %2").arg(QString::fromStdString(r.points[i].label), massText(r.points[i].add_kg, true, true));
    }
    result_->setText(
        tr("In the tank it displaces <b>%1 kg</b>; in the target water it is neutral at <b>%2 kg</b>. "
           "It weighs %3 kg, so it is <b>%4 %5</b>.<br>Tank step: %6.<br>"
           "With that done, the bow scale should read <b>%7 g</b> and the aft scale <b>%8 g</b>.")
            .arg(fixed(jnum(d, {"tank", "tank_neutral_mass_kg"}), 3))
            .arg(fixed(jnum(d, {"tank", "target_neutral_mass_kg"}), 3))
            .arg(fixed(r.weight_kg, 3))
            .arg(fixed(std::abs(r.net_buoyancy_kg) * 1000.0, 1))
            .arg(r.net_buoyancy_kg < 0 ? tr("g heavy") : tr("g light"))
            .arg(changes.join(", ").toHtmlEscaped())
            .arg(fixed(jnum(d, {"expected_tank_readings_g", "bow"}), 0))
            .arg(fixed(jnum(d, {"expected_tank_readings_g", "aft"}), 0)));
    error_->clear();
    ok_ = true;
  } catch (const InputError& e) {
    result_->clear();
    error_->setText(QString::fromStdString(e.what()));
    ok_ = false;
  }
  emit completeChanged();
}

bool TankWeighingPage::isComplete() const { return ok_; }

void TankWeighingPage::cleanupPage() {
  store(state_.tank);
  state_.tank_water_salt = tank_water_->currentData().toBool();
}

bool TankWeighingPage::validatePage() {
  store(state_.tank);
  state_.tank_water_salt = tank_water_->currentData().toBool();
  return ok_;
}

int TankWeighingPage::nextId() const { return OperatorWizard::kRollTest; }

}  // namespace auv::ui
