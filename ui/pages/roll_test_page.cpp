#include "pages/roll_test_page.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include "common/input_error.h"
#include "firstmission/slocum_first_mission.h"
#include "weighing/slocum_layout.h"
#include "widgets/inputs.h"
#include "wizard/json_number.h"
#include "wizard/operator_wizard.h"

namespace auv::ui {
namespace {

const char* const kBottleLabels[4] = {
    QT_TRANSLATE_NOOP("auv::ui::RollTestPage", "Bow, port:"), QT_TRANSLATE_NOOP("auv::ui::RollTestPage", "Bow, starboard:"),
    QT_TRANSLATE_NOOP("auv::ui::RollTestPage", "Aft, upper:"), QT_TRANSLATE_NOOP("auv::ui::RollTestPage", "Aft, lower:")};

}  // namespace

RollTestPage::RollTestPage(WizardState& state) : state_(state) {
  setTitle(tr("Slocum roll test"));
  setSubTitle(tr("Wings off, glider hanging free from the nose hook and tail loop. Read the roll the glider reports with nothing hung, "
                 "then with each known mass hung on a wing rail."));

  after_step_ = new QCheckBox(tr("Bottles set after the tank st&ep"));
  after_step_->setObjectName("after_step");
  after_step_->setToolTip(tr("Tick when you have changed the bottles as the tank step said: the roll test then "
                             "refers to these contents."));
  auto* aBox = new QGroupBox(tr("Bottles now"));
  auto* af = new QFormLayout(aBox);
  af->addRow(after_step_);
  for (int i = 0; i < 4; ++i) {
    const auto item = static_cast<SlocumItem>(i);
    after_[static_cast<std::size_t>(i)] =
        makeNumber(QString("after_%1").arg(slocumItemName(item)), 0, 5000, 0, tr(" g"),
                 tr("Lead shot actually in this bottle after the tank step, in grams."));
    af->addRow(tr(kBottleLabels[i]), after_[static_cast<std::size_t>(i)]);
  }
  use_recommended_ = new QPushButton(tr("Fill in the tank-step &result"));
  use_recommended_->setObjectName("use_recommended");
  use_recommended_->setToolTip(tr("Copy the bottle contents the tank step recommended (edit them if you set "
                                  "something else)."));
  use_recommended_->setMinimumHeight(32);
  use_recommended_->setAutoDefault(false);
  af->addRow(use_recommended_);

  roll_done_ = new QCheckBox(tr("Roll &test done"));
  roll_done_->setObjectName("roll_done");
  roll_done_->setToolTip(tr("Untick to compute without a roll test (the CG height then comes from the profile)."));
  initial_roll_ = makeNumber("initial_roll", -1, 1, 3, tr(" rad"),
                           tr("The roll the glider reports with nothing hung, in radians (starboard down positive)."));
  lever_arm_ = makeNumber("lever_arm", 0.01, 1, 4, tr(" m"),
                        tr("Horizontal distance from the hull axis to where the mass hangs (the hull radius for a "
                           "mass on the rail)."));
  table_ = new QTableWidget(0, 3);
  table_->setObjectName("roll_table");
  table_->setHorizontalHeaderLabels({tr("Mass hung"), tr("Rail"), tr("Roll reading")});
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
  table_->verticalHeader()->setDefaultSectionSize(36);
  table_->setToolTip(tr("One row per applied mass: its submerged mass, the rail it hangs on and the roll the glider reports with it hanging."));
  add_row_ = new QPushButton(tr("&Add mass"));
  add_row_->setObjectName("add_row");
  add_row_->setToolTip(tr("Add a row for another applied mass."));
  add_row_->setMinimumHeight(32);
  add_row_->setAutoDefault(false);
  remove_row_ = new QPushButton(tr("Re&move last"));
  remove_row_->setObjectName("remove_row");
  remove_row_->setToolTip(tr("Remove the last applied mass."));
  remove_row_->setMinimumHeight(32);
  remove_row_->setAutoDefault(false);
  auto* rBox = new QGroupBox(tr("Roll readings"));
  auto* rl = new QVBoxLayout(rBox);
  auto* rf = new QFormLayout;
  rf->addRow(roll_done_);
  rf->addRow(tr("&Initial roll:"), initial_roll_);
  rf->addRow(tr("&Lever arm:"), lever_arm_);
  rl->addLayout(rf);
  rl->addWidget(table_, 1);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(add_row_);
  buttons->addWidget(remove_row_);
  buttons->addStretch();
  rl->addLayout(buttons);

  auto* dBox = new QGroupBox(tr("Disk weights and roll battery now"));
  auto* dg = new QGridLayout(dBox);
  const char* cols[3] = {"A", "B", "C"};
  dg->addWidget(new QLabel(tr("Top")), 1, 0);
  dg->addWidget(new QLabel(tr("Bottom")), 2, 0);
  for (int k = 0; k < 3; ++k) {
    dg->addWidget(new QLabel(tr("Column %1").arg(cols[k])), 0, k + 1);
    for (int b = 0; b < 2; ++b) {
      auto* s = makeNumber(QString("disk_%1_%2").arg(cols[k], b == 0 ? "top" : "bottom"), 0, 5000, 0, tr(" g"),
                         tr("Disk weight in this seat, in grams (0 = empty)."));
      disks_[static_cast<std::size_t>(2 * k + b)] = s;
      dg->addWidget(s, b + 1, k + 1);
    }
  }
  battery_angle_ = makeNumber("battery_angle", -1.5, 1.5, 4, tr(" rad"),
                            tr("Roll battery angle now; positive = swung to starboard."));
  dg->addWidget(new QLabel(tr("Battery:")), 3, 0);
  dg->addWidget(battery_angle_, 3, 1, 1, 3);
  dg->setRowStretch(4, 1);

  result_ = new QLabel;
  result_->setObjectName("roll_result");
  result_->setWordWrap(true);
  result_->setTextFormat(Qt::RichText);
  error_ = makeErrorLabel();

  auto* grid = new QGridLayout;
  grid->addWidget(aBox, 0, 0);
  grid->addWidget(rBox, 0, 1, 2, 1);
  grid->addWidget(dBox, 1, 0);
  grid->setColumnStretch(1, 1);
  auto* lay = new QVBoxLayout(this);
  lay->addLayout(grid, 1);
  lay->addWidget(result_);
  lay->addWidget(error_);

  auto refresh = [this] { updatePreview(); };
  connect(after_step_, &QCheckBox::toggled, this, [this] {
    for (auto* s : after_) s->setEnabled(after_step_->isChecked());
    use_recommended_->setEnabled(after_step_->isChecked());
    updatePreview();
  });
  connect(roll_done_, &QCheckBox::toggled, this, [this] {
    for (QWidget* w : std::initializer_list<QWidget*>{initial_roll_, lever_arm_, table_, add_row_, remove_row_})
      w->setEnabled(roll_done_->isChecked());
    updatePreview();
  });
  for (auto* s : after_) connect(s, &NumberInput::valueChanged, this, refresh);
  for (auto* s : disks_) connect(s, &NumberInput::valueChanged, this, refresh);
  for (auto* s : {initial_roll_, lever_arm_, battery_angle_}) connect(s, &NumberInput::valueChanged, this, refresh);
  connect(use_recommended_, &QPushButton::clicked, this, [this] { fillRecommended(); });
  connect(add_row_, &QPushButton::clicked, this, [this] {
    addRow(0.5, false, 0.0);
    updatePreview();
  });
  connect(remove_row_, &QPushButton::clicked, this, [this] {
    if (table_->rowCount() > 0) table_->removeRow(table_->rowCount() - 1);
    updatePreview();
  });
}

int RollTestPage::rowCount() const { return table_->rowCount(); }

void RollTestPage::addRow(double mass_kg, bool starboard, double roll_rad) {
  const int r = table_->rowCount();
  table_->insertRow(r);
  auto* mass = makeNumber(QString("roll_mass_%1").arg(r), 0.001, 20, 3, tr(" kg"),
                        tr("Submerged (apparent) mass of the weight you hung, in kg."));
  auto* rail = new QComboBox;
  rail->setObjectName(QString("roll_rail_%1").arg(r));
  rail->addItem(tr("Port"), false);
  rail->addItem(tr("Starboard"), true);
  rail->setToolTip(tr("The wing rail the mass hangs on."));
  rail->setMinimumHeight(32);
  auto* roll = makeNumber(QString("roll_reading_%1").arg(r), -1.5, 1.5, 3, tr(" rad"),
                        tr("The roll the glider reports with this mass hanging and the glider at rest, in radians."));
  mass->setValue(mass_kg);
  rail->setCurrentIndex(starboard ? 1 : 0);
  roll->setValue(roll_rad);
  table_->setCellWidget(r, 0, mass);
  table_->setCellWidget(r, 1, rail);
  table_->setCellWidget(r, 2, roll);
  connect(mass, &NumberInput::valueChanged, this, [this] { updatePreview(); });
  connect(roll, &NumberInput::valueChanged, this, [this] { updatePreview(); });
  connect(rail, &QComboBox::currentIndexChanged, this, [this] { updatePreview(); });
}

void RollTestPage::initializePage() {
  loading_ = true;
  const TankWeighing& w = state_.tank;
  const bool after = w.bottles_after_tank_step_kg.has_value();
  after_step_->setChecked(after);
  for (std::size_t i = 0; i < 4; ++i) {
    after_[i]->setValue((after ? (*w.bottles_after_tank_step_kg)[i] : w.ballast.item_kg[i]) * 1000.0);
    after_[i]->setEnabled(after);
  }
  use_recommended_->setEnabled(after);
  double hull_radius = 0.1065;
  try {
    if (state_.vehicle) hull_radius = slocumLayout(*state_.vehicle).hull_radius_m;
  } catch (const InputError&) {
  }
  table_->setRowCount(0);
  if (w.roll_test) {
    roll_done_->setChecked(true);
    initial_roll_->setValue(w.roll_test->initial_roll_rad);
    lever_arm_->setValue(w.roll_test->lever_arm_m.value_or(hull_radius));
    for (const auto& h : w.roll_test->applied) addRow(h.mass_kg, h.starboard, h.roll_rad);
  } else {
    roll_done_->setChecked(true);
    initial_roll_->setValue(0.0);
    lever_arm_->setValue(hull_radius);
    // The report's three applied masses.
    for (double m : {0.5, 0.6, 0.7}) addRow(m, false, 0.0);
  }
  for (std::size_t k = 0; k < 3; ++k) {
    disks_[2 * k]->setValue(w.ballast.disks[k].top_kg * 1000.0);
    disks_[2 * k + 1]->setValue(w.ballast.disks[k].bottom_kg * 1000.0);
  }
  battery_angle_->setValue(w.ballast.battery_angle_rad);
  loading_ = false;
  updatePreview();
}

void RollTestPage::store(TankWeighing& w) const {
  if (after_step_->isChecked()) {
    std::array<double, 4> b{};
    for (std::size_t i = 0; i < 4; ++i) b[i] = after_[i]->value() / 1000.0;
    w.bottles_after_tank_step_kg = b;
  } else {
    w.bottles_after_tank_step_kg.reset();
  }
  if (roll_done_->isChecked() && table_->rowCount() > 0) {
    RollTestRecord t;
    t.initial_roll_rad = initial_roll_->value();
    t.lever_arm_m = lever_arm_->value();
    for (int r = 0; r < table_->rowCount(); ++r) {
      RollTestRecord::Hang h;
      h.mass_kg = qobject_cast<NumberInput*>(table_->cellWidget(r, 0))->value();
      h.starboard = qobject_cast<QComboBox*>(table_->cellWidget(r, 1))->currentData().toBool();
      h.roll_rad = qobject_cast<NumberInput*>(table_->cellWidget(r, 2))->value();
      t.applied.push_back(h);
    }
    w.roll_test = t;
  } else {
    w.roll_test.reset();
  }
  for (std::size_t k = 0; k < 3; ++k) {
    w.ballast.disks[k].top_kg = disks_[2 * k]->value() / 1000.0;
    w.ballast.disks[k].bottom_kg = disks_[2 * k + 1]->value() / 1000.0;
  }
  w.ballast.battery_angle_rad = battery_angle_->value();
}

void RollTestPage::fillRecommended() {
  TankWeighing w = state_.tank;
  w.bottles_after_tank_step_kg.reset();
  w.roll_test.reset();
  try {
    const FirstMissionReport r = slocumFirstMission(*state_.vehicle, w);
    for (int i = 0; i < 4; ++i) {
      after_[static_cast<std::size_t>(i)]->setValue(
          jnum(r.details, {"tank", "recommended_bottles_g", slocumItemName(static_cast<SlocumItem>(i))}));
    }
  } catch (const InputError& e) {
    error_->setText(QString::fromStdString(e.what()));
  }
}

void RollTestPage::updatePreview() {
  if (loading_ || !state_.vehicle) return;
  TankWeighing w = state_.tank;
  store(w);
  try {
    const FirstMissionReport r = slocumFirstMission(*state_.vehicle, w);
    const auto& d = r.details;
    if (d.contains("roll_test")) {
      QStringList each;
      for (const auto& h : d["roll_test"]["h_each_mm"]) each << fixed(h.get<double>(), 2);
      const double y = jnum(d, {"roll_test", "cg_y_mm"});
      result_->setText(tr("h-arm <b>%1 mm</b> (each mass: %2 mm; spread %3 mm). G sits <b>%4 mm to %5</b> of the "
                          "hull axis and %6 mm below it. Target h-arm %7 mm.")
                           .arg(fixed(jnum(d, {"roll_test", "h_mm"}), 2))
                           .arg(each.join(", "))
                           .arg(fixed(jnum(d, {"roll_test", "spread_mm"}), 2))
                           .arg(fixed(std::abs(y), 2))
                           .arg(y >= 0 ? tr("starboard") : tr("port"))
                           .arg(fixed(jnum(d, {"roll_test", "cg_z_mm"}), 2))
                           .arg(fixed(jnum(d, {"h_arm", "target_mm"}), 2)));
    } else {
      result_->setText(tr("No roll test: the result will use the profile's CG height."));
    }
    error_->clear();
    ok_ = true;
  } catch (const InputError& e) {
    result_->clear();
    error_->setText(QString::fromStdString(e.what()));
    ok_ = false;
  }
  emit completeChanged();
}

bool RollTestPage::isComplete() const { return ok_; }

void RollTestPage::cleanupPage() { store(state_.tank); }

bool RollTestPage::validatePage() {
  store(state_.tank);
  return ok_;
}

int RollTestPage::nextId() const { return OperatorWizard::kFirstMissionResult; }

}  // namespace auv::ui
