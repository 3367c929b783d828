#include "pages/vehicle_page.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QRegularExpressionValidator>
#include <QVBoxLayout>

#include "common/input_error.h"
#include "vehicle/vehicle_catalog.h"
#include "wizard/operator_wizard.h"

namespace auv::ui {

VehiclePage::VehiclePage(WizardState& state) : state_(state) {
  setTitle(tr("Vehicle and configuration"));
  setSubTitle(tr("Choose the vehicle and name the payload configuration you are ballasting."));
  vehicle_ = new QComboBox;
  vehicle_->setObjectName("vehicle");
  vehicle_->setToolTip(tr("The vehicle profile: hull volume, centre of buoyancy, adjustment points and weight kit."));
  VehicleCatalog cat(state_.vehicles_dir);
  for (const auto& id : cat.ids()) vehicle_->addItem(QString::fromStdString(id));
  config_ = new QLineEdit(QString::fromStdString(state_.configuration_id));
  config_->setObjectName("configuration");
  config_->setPlaceholderText(tr("e.g. 01-02-03"));
  config_->setToolTip(tr("Configuration ID as on the vehicle's ballasting sheet (xx-xx-xx)."));
  config_->setValidator(new QRegularExpressionValidator(QRegularExpression("[0-9]{1,2}-[0-9]{1,2}-[0-9]{1,2}"), this));
  payload_ = new QLineEdit(QString::fromStdString(state_.payload_note));
  payload_->setObjectName("payload");
  payload_->setToolTip(tr("Which payload modules are fitted, in your words."));
  summary_ = new QLabel;
  summary_->setObjectName("summary");
  summary_->setWordWrap(true);
  error_ = new QLabel;
  error_->setObjectName("error");
  error_->setStyleSheet("color: #b00020;");

  auto* form = new QFormLayout;
  form->addRow(tr("&Vehicle:"), vehicle_);
  form->addRow(tr("&Configuration ID:"), config_);
  form->addRow(tr("&Payload:"), payload_);
  auto* lay = new QVBoxLayout(this);
  lay->addLayout(form);
  lay->addWidget(summary_);
  lay->addWidget(error_);
  lay->addStretch();
  if (state_.vehicle) vehicle_->setCurrentText(QString::fromStdString(state_.vehicle->id));
  connect(vehicle_, &QComboBox::currentTextChanged, this, [this] { showProfile(); });
  showProfile();
}

void VehiclePage::showProfile() {
  try {
    const VehicleProfile v = VehicleCatalog(state_.vehicles_dir).load(vehicle_->currentText().toStdString());
    summary_->setText(tr("%1: %2 kg in air, hull volume %3 m³, %4 adjustment points.")
                          .arg(QString::fromStdString(v.name))
                          .arg(v.mass_kg, 0, 'f', 1)
                          .arg(v.hull.volume_m3, 0, 'f', 4)
                          .arg(v.points.size()));
    error_->clear();
  } catch (const InputError& e) {
    summary_->clear();
    error_->setText(QString::fromStdString(e.what()));
  }
}

bool VehiclePage::validatePage() {
  try {
    state_.vehicle = VehicleCatalog(state_.vehicles_dir).load(vehicle_->currentText().toStdString());
  } catch (const InputError& e) {
    error_->setText(QString::fromStdString(e.what()));
    return false;
  }
  state_.configuration_id = config_->text().toStdString();
  state_.payload_note = payload_->text().toStdString();
  return true;
}

int VehiclePage::nextId() const { return OperatorWizard::kCraneWeighing; }

}  // namespace auv::ui
