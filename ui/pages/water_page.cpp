#include "pages/water_page.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QVBoxLayout>

#include "common/input_error.h"
#include "firstmission/water_conditions.h"
#include "widgets/inputs.h"
#include "wizard/operator_wizard.h"

namespace auv::ui {
namespace {

struct WaterType {
  const char* name;
  double salinity_psu;  // middle of the thesis Table 2.1 range
};
constexpr WaterType kWaterTypes[] = {
    {QT_TRANSLATE_NOOP("auv::ui::WaterPage", "Fresh water (about 0.5)"), 0.5},
    {QT_TRANSLATE_NOOP("auv::ui::WaterPage", "Brackish, mildly (1-5)"), 3.0},
    {QT_TRANSLATE_NOOP("auv::ui::WaterPage", "Brackish, moderately (5-15)"), 10.0},
    {QT_TRANSLATE_NOOP("auv::ui::WaterPage", "Brackish, heavily (15-30)"), 22.5},
    {QT_TRANSLATE_NOOP("auv::ui::WaterPage", "Sea water (about 35)"), 35.0},
};

}  // namespace

WaterPage::WaterPage(WizardState& state) : state_(state) {
  setTitle(tr("Mission water"));
  setSubTitle(tr("Where will the vehicle fly? Density includes pressure at the operating depth."));
  temperature_ = makeNumber("temperature", -2, 40, 2, " °C",
                      tr("Water temperature at the operating depth if you know it (CTD cast), else at the surface."));
  water_type_ = new QComboBox;
  water_type_->setObjectName("water_type");
  water_type_->addItem(tr("Measured salinity"), -1.0);
  for (const auto& t : kWaterTypes) water_type_->addItem(tr(t.name), t.salinity_psu);
  water_type_->setToolTip(tr("Pick a water type if you have no salinity measurement (thesis Table 2.1)."));
  water_type_->setMinimumHeight(32);
  salinity_ = makeNumber("salinity", 0, 42, 2, " PSU", tr("Practical salinity of the mission water."));
  depth_ = makeNumber("depth", 0, 6000, 1, " m", tr("Depth where the vehicle spends most of the mission."));
  latitude_ = makeNumber("latitude", -90, 90, 1, " °", tr("Latitude of the area (gravity for depth to pressure)."));
  density_ = new QLabel;
  density_->setObjectName("density");
  error_ = new QLabel;
  error_->setObjectName("error");
  error_->setStyleSheet("color: #b00020;");
  auto* form = new QFormLayout;
  form->addRow(tr("&Temperature:"), temperature_);
  form->addRow(tr("Water t&ype:"), water_type_);
  form->addRow(tr("&Salinity:"), salinity_);
  form->addRow(tr("Operating &depth:"), depth_);
  form->addRow(tr("&Latitude:"), latitude_);
  form->addRow(tr("In-situ density:"), density_);
  auto* lay = new QVBoxLayout(this);
  lay->addLayout(form);
  lay->addWidget(error_);
  lay->addStretch();
  connect(water_type_, &QComboBox::currentIndexChanged, this, [this] {
    const double s = water_type_->currentData().toDouble();
    if (s >= 0) salinity_->setValue(s);
  });
  for (auto* s : {temperature_, salinity_, depth_, latitude_}) {
    connect(s, &NumberInput::valueChanged, this, [this] { updateDensity(); });
  }
}

void WaterPage::initializePage() {
  const auto& w = state_.crane.water;
  temperature_->setValue(w.temperature_degC);
  salinity_->setValue(w.salinity_psu);
  depth_->setValue(w.depth_m);
  latitude_->setValue(w.latitude_deg);
  updateDensity();
}

void WaterPage::updateDensity() {
  PlannedWater w{temperature_->value(), salinity_->value(), depth_->value(), latitude_->value()};
  try {
    const WaterState s = resolveWater(w);
    density_->setText(tr("%1 kg/m³ at %2 dbar").arg(fixed(s.density_kgm3, 3)).arg(fixed(s.pressure_dbar, 1)));
    error_->clear();
  } catch (const InputError& e) {
    density_->clear();
    error_->setText(QString::fromStdString(e.what()));
  }
}

void WaterPage::cleanupPage() {
  state_.crane.water = {temperature_->value(), salinity_->value(), depth_->value(), latitude_->value()};
}

bool WaterPage::validatePage() {
  state_.crane.water = {temperature_->value(), salinity_->value(), depth_->value(), latitude_->value()};
  try {
    resolveWater(state_.crane.water);
  } catch (const InputError& e) {
    error_->setText(QString::fromStdString(e.what()));
    return false;
  }
  return true;
}

int WaterPage::nextId() const { return OperatorWizard::kFirstMissionResult; }

}  // namespace auv::ui
