#include "pages/vehicle_page.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QVBoxLayout>

#include "common/input_error.h"
#include "history/configuration_id.h"
#include "history/store.h"
#include "vehicle/vehicle_catalog.h"
#include "widgets/inputs.h"
#include "widgets/number_input.h"
#include "wizard/operator_wizard.h"

namespace auv::ui {
namespace {

QLineEdit* line(const char* name, const QString& tip) {
  auto* e = new QLineEdit;
  e->setObjectName(name);
  e->setToolTip(tip);
  e->setMinimumHeight(32);
  return e;
}

}  // namespace

VehiclePage::VehiclePage(WizardState& state) : state_(state) {
  setTitle(tr("Vehicle and configuration"));
  setSubTitle(tr("Choose the vehicle and name the payload configuration you are ballasting."));
  vehicle_ = new QComboBox;
  vehicle_->setObjectName("vehicle");
  vehicle_->setToolTip(tr("The vehicle profile: hull volume, centre of buoyancy, adjustment points and weight kit."));
  vehicle_->setMinimumHeight(32);
  VehicleCatalog cat(state_.vehicles_dir);
  // The vehicle's name as the technician knows it; the profile id stays behind it.
  for (const auto& id : cat.ids()) {
    QString name = QString::fromStdString(id);
    try {
      name = QString::fromStdString(cat.load(id).name);
    } catch (const InputError&) {
      // A damaged profile is listed by its id; choosing it shows the problem.
    }
    vehicle_->addItem(name, QString::fromStdString(id));
  }
  config_ = line("configuration", tr("Configuration ID as on the vehicle's ballasting sheet: three groups of "
                                     "letters or digits, e.g. 01-02-03 (vehicle, payload set, water)."));
  config_->setPlaceholderText(tr("e.g. 01-02-03"));
  payload_ = line("payload", tr("Which payload modules are fitted, in your words."));
  area_ = line("area", tr("Area of operation, e.g. the fjord or the survey site."));
  water_type_ = line("config_water_type", tr("Kind of water, e.g. fjord, coastal, open ocean."));
  bg_ = new NumberInput(tr("mm"));
  bg_->setObjectName("bg_mm");
  bg_->setRange(0.0, 499.0);
  bg_->setDecimals(1);
  bg_->setSpecialValueText(tr("not measured"));
  bg_->setMinimumHeight(32);
  bg_->setToolTip(tr("How far the centre of gravity is below the centre of buoyancy, from an inclining or roll "
                     "test. With it the analysis finds the sideways CG offset and the roll from the log; without "
                     "it they stay not known. Leave empty when not measured."));
  summary_ = new QLabel;
  summary_->setObjectName("summary");
  summary_->setWordWrap(true);
  id_hint_ = new QLabel;
  id_hint_->setObjectName("id_hint");
  id_hint_->setWordWrap(true);
  error_ = makeErrorLabel();

  auto* form = new QFormLayout;
  form->addRow(tr("&Vehicle:"), vehicle_);
  form->addRow(tr("&Configuration ID:"), config_);
  form->addRow(QString(), id_hint_);
  form->addRow(tr("&Payload:"), payload_);
  form->addRow(tr("&Area:"), area_);
  form->addRow(tr("Water &type:"), water_type_);
  bg_label_ = new QLabel(tr("B&G (CG below CB):"));
  bg_label_->setBuddy(bg_->lineEdit());
  form->addRow(bg_label_, bg_);
  auto* lay = new QVBoxLayout(this);
  lay->addLayout(form);
  lay->addWidget(summary_);
  lay->addWidget(error_);
  lay->addStretch();
  connect(vehicle_, &QComboBox::currentIndexChanged, this, [this] { showProfile(); });
  connect(config_, &QLineEdit::textChanged, this, [this] { checkId(); });
}

void VehiclePage::initializePage() {
  if (state_.vehicle) vehicle_->setCurrentIndex(vehicle_->findData(QString::fromStdString(state_.vehicle->id)));
  config_->setText(QString::fromStdString(state_.configuration_id));
  payload_->setText(QString::fromStdString(state_.payload_note));
  area_->setText(QString::fromStdString(state_.area));
  water_type_->setText(QString::fromStdString(state_.water_type));
  bg_->setValue(state_.bg_mm.value_or(0.0));
  // A configuration from the history is one vehicle with one ID: fixed.
  vehicle_->setEnabled(!state_.configuration_in_history);
  config_->setReadOnly(state_.configuration_in_history);
  showProfile();
  checkId();
}

void VehiclePage::checkId() {
  const std::string id = config_->text().trimmed().toStdString();
  if (state_.configuration_in_history) {
    id_hint_->setStyleSheet("color: #1b5e20;");
    id_hint_->setText(tr("From the history."));
  } else if (id.empty() || !isValidConfigurationId(id)) {
    id_hint_->setStyleSheet("color: #8a6d00;");
    id_hint_->setText(tr("Three groups of 1-8 letters or digits separated by '-', e.g. 01-02-03."));
  } else {
    id_hint_->setStyleSheet("color: #1b5e20;");
    id_hint_->setText(tr("A new configuration ID."));
  }
}

void VehiclePage::showProfile() {
  try {
    const VehicleProfile v = VehicleCatalog(state_.vehicles_dir).load(vehicle_->currentData().toString().toStdString());
    summary_->setText(tr("%1: %2 kg in air, hull volume %3 m³, %4 adjustment points; weighed by %5.")
                          .arg(QString::fromStdString(v.name))
                          .arg(fixed(v.mass_kg, 1))
                          .arg(fixed(v.hull.volume_m3, 4))
                          .arg(v.points.size())
                          .arg(v.kind == "glider" ? tr("the tank method (spring scales)") : tr("crane scales")));
    shown_kind_ = v.kind;
    // Gliders: the roll test is part of the tank weighing.
    bg_->setVisible(v.kind != "glider");
    bg_label_->setVisible(v.kind != "glider");
    error_->clear();
  } catch (const InputError& e) {
    shown_kind_.clear();
    summary_->clear();
    error_->setText(QString::fromStdString(e.what()));
  }
}

void VehiclePage::cleanupPage() {
  if (!state_.configuration_in_history) state_.configuration_id = config_->text().trimmed().toStdString();
  state_.payload_note = payload_->text().toStdString();
  state_.area = area_->text().toStdString();
  state_.water_type = water_type_->text().toStdString();
  storeBg();
  try {
    state_.vehicle = VehicleCatalog(state_.vehicles_dir).load(vehicle_->currentData().toString().toStdString());
  } catch (const InputError&) {
  }
}

bool VehiclePage::validatePage() {
  const std::string id = config_->text().trimmed().toStdString();
  try {
    state_.vehicle = VehicleCatalog(state_.vehicles_dir).load(vehicle_->currentData().toString().toStdString());
    requireValidConfigurationId(id);
    if (!bg_->commit())
      throw InputError("BG (CG below CB)", bg_->problem().toStdString(),
                       "enter the BG of an inclining or roll test in mm, or leave the field empty");
    if (!state_.configuration_in_history) {
      auto* wiz = qobject_cast<OperatorWizard*>(wizard());
      HistoryStore* store = wiz ? wiz->history() : nullptr;
      if (store && store->configuration(id)) {
        throw InputError("configuration ID", "'" + id + "' is already in the history",
                         "go back and pick it on the start page, or choose a new ID");
      }
    }
  } catch (const InputError& e) {
    error_->setText(QString::fromStdString(e.what()));
    return false;
  }
  error_->clear();
  state_.configuration_id = id;
  state_.payload_note = payload_->text().toStdString();
  state_.area = area_->text().toStdString();
  state_.water_type = water_type_->text().toStdString();
  storeBg();
  if (state_.isGlider()) {
    state_.tank.vehicle = state_.vehicle->id;
    if (state_.tank.readings.dry_mass_kg < 1.0) state_.tank.readings.dry_mass_kg = state_.vehicle->mass_kg;
  }
  return true;
}

void VehiclePage::storeBg() {
  bg_->commit();
  const double v = bg_->value();
  const std::optional<double> bg = v > 0.0 ? std::optional<double>(v) : std::nullopt;
  // Another BG is another CG y: the analysis must run again with it.
  if (bg != state_.bg_mm) state_.analysis.reset();
  state_.bg_mm = bg;
}

int VehiclePage::nextId() const {
  if (state_.mode == SessionMode::kPostMission) return OperatorWizard::kLogImport;
  if (state_.mode == SessionMode::kPreMission) return OperatorWizard::kPreMission;
  // The profile on screen decides (its kind), so the branch follows the combo at once.
  return shown_kind_ == "glider" ? OperatorWizard::kTankWeighing : OperatorWizard::kCraneWeighing;
}

}  // namespace auv::ui
