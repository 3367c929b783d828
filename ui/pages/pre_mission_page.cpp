#include "pages/pre_mission_page.h"

#include <QButtonGroup>
#include <QCheckBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QRadioButton>
#include <QVBoxLayout>
#include <cmath>

#include "common/input_error.h"
#include "common/units.h"
#include "firstmission/water_conditions.h"
#include "history/staleness.h"
#include "history/store.h"
#include "widgets/estimate_text.h"
#include "widgets/inputs.h"
#include "wizard/history_save.h"
#include "wizard/operator_wizard.h"

namespace auv::ui {

namespace {
double roundedTo(double v, int decimals) {
  const double f = std::pow(10.0, decimals);
  return std::round(v * f) / f;
}
}  // namespace

namespace {

QString q(const std::string& s) { return QString::fromStdString(s); }
QString dateOf(TimePoint t) { return q(toIsoUtc(t)).left(10); }

// The lowest value of the temperature box means "not entered yet".
constexpr double kNoTemperature = -3.0;

}  // namespace

PreMissionPage::PreMissionPage(WizardState& state) : state_(state) {
  setTitle(tr("Plan the next mission"));
  setSubTitle(tr("From what the last mission showed and the water of the next one: which pieces to add or remove."));

  auto* basisBox = new QGroupBox(tr("What the plan starts from"));
  estimate_ = new QLabel;
  estimate_->setObjectName("estimate");
  estimate_->setWordWrap(true);
  estimate_source_ = new QLabel;
  estimate_source_->setObjectName("estimate_source");
  estimate_source_->setWordWrap(true);
  installed_ = new QLabel;
  installed_->setObjectName("installed_now");
  installed_->setWordWrap(true);
  auto* bl = new QVBoxLayout(basisBox);
  bl->addWidget(estimate_);
  bl->addWidget(estimate_source_);
  bl->addWidget(installed_);

  auto* waterBox = water_box_ = new QGroupBox(tr("Next mission's water"));
  src_ctd_ = new QRadioButton(tr("&Last mission's CTD"));
  src_ctd_->setObjectName("water_ctd");
  src_ctd_->setToolTip(tr("Fly in the water the analysed mission measured: its temperature and salinity at its operating depth."));
  src_operator_ = new QRadioButton(tr("&Values I enter"));
  src_operator_->setObjectName("water_operator");
  src_operator_->setToolTip(tr("Another area, season or depth: enter the temperature and salinity you measured or expect."));
  auto* srcGroup = new QButtonGroup(this);
  srcGroup->addButton(src_ctd_);
  srcGroup->addButton(src_operator_);
  temperature_ = makeNumber("next_temperature", kNoTemperature, 40, 2, " °C",
                          tr("Water temperature at the operating depth (CTD cast), in °C."));
  temperature_->setSpecialValueText(tr("enter °C"));
  salinity_ = makeNumber("next_salinity", 0, 42, 2, " PSU", tr("Practical salinity at the operating depth (35 = open ocean)."));
  depth_ = makeNumber("next_depth", 0, 6000, 1, " m", tr("Depth where the vehicle spends most of the mission: the band applies there."));
  deepest_ = makeNumber("next_deepest", 0, 6000, 1, " m",
                        tr("Deepest depth the mission goes to (the analysed log's deepest by default): the vehicle "
                           "must not be heavy there either. At least the operating depth."));
  latitude_ = makeNumber("next_latitude", -90, 90, 1, " °", tr("Latitude of the area (gravity for depth to pressure)."));
  stale_label_ = makeErrorLabel("temperature_stale");
  density_ = new QLabel;
  density_->setObjectName("next_density");
  water_error_ = makeErrorLabel("water_error");
  auto* srcRow = new QHBoxLayout;
  srcRow->addWidget(src_ctd_);
  srcRow->addWidget(src_operator_);
  srcRow->addStretch();
  auto* wf = new QGridLayout;
  auto addField = [&](int row, int col, const QString& text, NumberInput* spin) {
    auto* l = new QLabel(text);
    l->setBuddy(spin);
    wf->addWidget(l, row, col);
    wf->addWidget(spin, row, col + 1);
  };
  addField(0, 0, tr("&Temperature:"), temperature_);
  addField(0, 2, tr("&Salinity:"), salinity_);
  addField(1, 0, tr("Operating &depth:"), depth_);
  addField(1, 2, tr("D&eepest depth:"), deepest_);
  addField(2, 0, tr("Lat&itude:"), latitude_);
  wf->addWidget(density_, 2, 2, 1, 2);
  wf->setColumnStretch(1, 1);
  wf->setColumnStretch(3, 1);
  auto* wl = new QVBoxLayout(waterBox);
  wl->addLayout(srcRow);
  wl->addWidget(stale_label_);
  wl->addLayout(wf);
  wl->addWidget(water_error_);

  auto* policyBox = policy_box_ = new QGroupBox(tr("Policy"));
  policy_exact_ = new QRadioButton(tr("E&xact: the whole change now"));
  policy_exact_->setObjectName("policy_exact");
  policy_exact_->setToolTip(tr("Pieces that bring net buoyancy, pitch and roll into the bands as well as the kit allows."));
  policy_half_ = new QRadioButton(tr("H&alf-way: about half the change"));
  policy_half_->setObjectName("policy_half");
  policy_half_->setToolTip(tr("When the estimate is uncertain: move about half way, still never heavy."));
  policy_classic_ = new QRadioButton(tr("&Classic: the thesis's table"));
  policy_classic_->setObjectName("policy_classic");
  policy_classic_->setToolTip(tr("The thesis's slow control loop (App. E): one smallest piece per point from the signs "
                                 "of the deviations. For comparison."));
  auto* polGroup = new QButtonGroup(this);
  for (auto* r : {policy_exact_, policy_half_, policy_classic_}) {
    polGroup->addButton(r);
    r->setMinimumHeight(28);
  }
  optional_ = new QCheckBox;
  optional_->setObjectName("optional_pieces");
  optional_->setToolTip(tr("Also use the kit's optional pieces (HUGIN: 0.5 kg, thesis §8.1) - only if you have them."));
  auto* pl = new QVBoxLayout(policyBox);
  pl->addWidget(policy_exact_);
  pl->addWidget(policy_half_);
  pl->addWidget(policy_classic_);
  pl->addWidget(optional_);
  pl->addStretch();

  preview_ = new QLabel;
  preview_->setObjectName("plan_preview");
  preview_->setWordWrap(true);
  error_ = makeErrorLabel();
  save_status_ = makeErrorLabel("save_status");

  auto* middle = new QHBoxLayout;
  middle->addWidget(waterBox, 3);
  middle->addWidget(policyBox, 2);
  auto* lay = new QVBoxLayout(this);
  lay->addWidget(basisBox);
  lay->addLayout(middle);
  lay->addWidget(preview_);
  lay->addWidget(error_);
  lay->addWidget(save_status_);
  lay->addStretch();

  connect(src_ctd_, &QRadioButton::toggled, this, [this] {
    applySource();
    updatePreview();
  });
  for (auto* s : {temperature_, salinity_, depth_, deepest_, latitude_}) {
    // The plan follows each entered value (Enter, Tab, arrows), not each keystroke.
    connect(s, &NumberInput::valueChanged, this, [this] { updatePreview(); });
  }
  for (auto* r : {policy_exact_, policy_half_, policy_classic_}) {
    connect(r, &QRadioButton::toggled, this, [this](bool on) {
      if (!on || loading_) return;
      store();
      loadBasis();  // the classic table may start from other records
      showBasis();
      updatePreview();
    });
  }
  connect(optional_, &QCheckBox::toggled, this, [this] { updatePreview(); });
}

OperatorWizard* PreMissionPage::wiz() const { return qobject_cast<OperatorWizard*>(wizard()); }

void PreMissionPage::loadBasis() {
  basis_.reset();
  basis_error_.clear();
  OperatorWizard* w = wiz();
  try {
    basis_ = planBasis(state_, w ? w->history() : nullptr, w ? w->now() : nowUtc(), state_.policy);
  } catch (const InputError& e) {
    basis_error_ = q(e.what());
  }
  stale_ = basis_ && basis_->measured_at && temperatureIsStale(*basis_->measured_at, w ? w->now() : nowUtc());
}

void PreMissionPage::initializePage() {
  save_status_->clear();
  loading_ = true;
  policy_exact_->setChecked(state_.policy == PlanPolicy::Exact);
  policy_half_->setChecked(state_.policy == PlanPolicy::HalfWay);
  policy_classic_->setChecked(state_.policy == PlanPolicy::Classic);
  const bool has_optional = state_.vehicle && !state_.vehicle->kit.optional_pieces_kg.empty();
  optional_->setVisible(has_optional);
  if (has_optional) {
    QStringList sizes;
    for (double s : state_.vehicle->kit.optional_pieces_kg) sizes << massText(s, state_.isGlider());
    optional_->setText(tr("Use the optional %1 &piece").arg(sizes.join(", ")));
  }
  optional_->setChecked(has_optional && state_.crane.use_optional_pieces);
  loadBasis();

  // The water: what this session entered, else the last mission's.
  const bool have_entered = state_.next_water.has_value();
  const bool operator_values = have_entered && state_.next_water_source == "operator";
  PlannedWater w = state_.next_water.value_or(PlannedWater{});
  double exact_depth_m = w.depth_m;
  if (!have_entered) {
    w.latitude_deg = state_.crane.water.latitude_deg;
    if (basis_) w = lastMissionWater(basis_->start.estimate, w.latitude_deg);
    exact_depth_m = w.depth_m;
    // Defaults from the last mission, shown (and, once the operator takes
    // them as theirs, used) to the CTD's resolution.
    w.temperature_degC = roundedTo(w.temperature_degC, 3);
    w.salinity_psu = roundedTo(w.salinity_psu, 3);
    w.depth_m = roundedTo(w.depth_m, 1);
  }
  temperature_->setValue(w.temperature_degC);
  salinity_->setValue(w.salinity_psu);
  depth_->setValue(w.depth_m);
  latitude_->setValue(w.latitude_deg);
  // The deepest depth: as entered, else as deep as the analysed log went,
  // never shallower than the operating depth (the check would then cover
  // the surface only).
  double deepest = state_.next_deepest_m;
  if (deepest <= 0.0 && state_.log) {
    for (const auto& c : state_.log->channels)
      if (c.name == "depth")
        for (double d : c.values)
          if (std::isfinite(d)) deepest = std::max(deepest, d);
  }
  // A default from the log shows to 0.1 m, rounded up: never shallower than it.
  deepest_->setValue(state_.next_deepest_m > 0.0 ? std::max(deepest, w.depth_m)
                                                 : std::ceil(std::max(deepest, exact_depth_m) * 10.0 - 1e-9) / 10.0);
  src_ctd_->setEnabled(basis_.has_value() && !stale_);
  if (stale_ || !basis_ || operator_values) {
    src_operator_->setChecked(true);
    // A temperature too old to reuse is not offered as a default either.
    if (stale_ && !operator_values) temperature_->setValue(kNoTemperature);
  } else {
    src_ctd_->setChecked(true);
  }
  loading_ = false;
  showBasis();
  applySource();
  updatePreview();
}

void PreMissionPage::showBasis() {
  water_box_->setEnabled(basis_.has_value());
  policy_box_->setEnabled(basis_.has_value() || !basis_error_.contains("report.net_buoyancy_kg"));
  if (!basis_) {
    estimate_->setText(saveOnly() ? tr("Nothing to plan from: %1 Finish saves the mission to the history; plan the "
                                       "next mission from a log that shows the net buoyancy.")
                                        .arg(basis_error_)
                                  : tr("Nothing to plan from: %1").arg(basis_error_));
    estimate_->setStyleSheet("color: #b00020;");
    estimate_source_->clear();
    installed_->clear();
    stale_label_->clear();
    return;
  }
  estimate_->setStyleSheet(QString());
  const TrimEstimate& e = basis_->start.estimate;
  const bool g = state_.isGlider();
  const QString state = std::abs(e.net_buoyancy_kg) < 5e-4 ? tr("neutral")
                        : e.net_buoyancy_kg > 0           ? tr("too light")
                                                          : tr("too heavy");
  QString text;
  if (basis_->start.physical) {
    text = tr("Net buoyancy <b>%1</b> (%2) in %3 kg/m³ water at %4 m (%5 °C, %6 PSU).")
               .arg(EstimateText::valueSigma(true, e.net_buoyancy_kg, e.net_buoyancy_sigma_kg, g ? 3 : 2, tr(" kg")), state)
               .arg(fixed(e.water.density_kgm3, 2))
               .arg(fixed(e.depth_m, 0))
               .arg(fixed(e.water.temperature_degC, 2))
               .arg(fixed(e.salinity_psu, 2));
  } else {
    text = tr("No net buoyancy was measured: the recorded weight against the buoyancy gives <b>%1 kg</b> (%2), "
              "and the classic table works from the deviations.")
               .arg(signedFixed(e.net_buoyancy_kg, 2), state);
  }
  auto cg = [&](const std::optional<double>& v, double sigma) {
    return EstimateText::of(v ? std::optional<double>(units::mToMm(*v)) : std::nullopt, units::mToMm(sigma), 1, tr(" mm"));
  };
  text += " " + tr("CG − CB: x %1, y %2").arg(cg(e.cg_x_m, e.cg_x_sigma_m), cg(e.cg_y_m, e.cg_y_sigma_m));
  if (e.cg_y_basis == "cruise" && e.cg_y_m) text += tr(" (y that levels it at %1 rpm)").arg(fixed(e.cruise_rpm, 0));
  text += ".";
  // Which estimate: this session's (analysis, or with the accepted
  // model-check terms) or the history's.
  if (basis_->from_session) text += "<br>" + EstimateText::planUses(basis_->source);
  estimate_->setText(text);

  OperatorWizard* w = wiz();
  QString source = tr("From %1").arg(q(basis_->analysis_name));
  if (basis_->measured_at) {
    const long days = static_cast<long>(((w ? w->now() : nowUtc()) - *basis_->measured_at).count() / 86400);
    source += tr("; its water measured %1 (%2 days ago)").arg(dateOf(*basis_->measured_at)).arg(days);
  }
  estimate_source_->setText(source + ".");
  QStringList pts;
  for (std::size_t i = 0; i < state_.vehicle->points.size() && i < basis_->installed_kg.size(); ++i) {
    pts << QString("%1 %2").arg(q(state_.vehicle->points[i].label), massText(basis_->installed_kg[i], g));
  }
  installed_->setText(tr("Installed now (%1): %2.").arg(q(basis_->installed_source), pts.join(", ")));
  if (stale_) {
    stale_label_->setText(tr("The last mission's water is older than one month (thesis §5.5.3): measure the "
                             "temperature again and enter it."));
  } else {
    stale_label_->clear();
  }
  stale_label_->setVisible(stale_);
}

void PreMissionPage::applySource() {
  const bool ctd = src_ctd_->isChecked();
  if (ctd && basis_) {
    // Shown to the CTD's resolution (a mean of thousands of samples would
    // show every digit: "7.542212 °C"); the plan takes the exact means (store).
    const PlannedWater w = lastMissionWater(basis_->start.estimate, latitude_->value());
    const bool was = loading_;
    loading_ = true;
    temperature_->setValue(roundedTo(w.temperature_degC, 3));
    salinity_->setValue(roundedTo(w.salinity_psu, 3));
    depth_->setValue(roundedTo(w.depth_m, 1));
    loading_ = was;
  }
  // The CTD's values are what they are; the operator's are typed.
  for (auto* s : {temperature_, salinity_, depth_}) s->setEnabled(!ctd);
}

bool PreMissionPage::temperatureEntered() const { return temperature_->value() > kNoTemperature; }

void PreMissionPage::store() {
  PlannedWater w;
  if (src_ctd_->isChecked() && basis_) {
    w = lastMissionWater(basis_->start.estimate, latitude_->value());
  } else {
    w.temperature_degC = temperature_->value();
    w.salinity_psu = salinity_->value();
    w.depth_m = depth_->value();
  }
  w.latitude_deg = latitude_->value();
  state_.next_water = w;
  state_.next_deepest_m = deepest_->value();
  state_.next_water_source = src_ctd_->isChecked() ? "last mission" : "operator";
  state_.policy = policy_classic_->isChecked() ? PlanPolicy::Classic
                  : policy_half_->isChecked()  ? PlanPolicy::HalfWay
                                               : PlanPolicy::Exact;
  if (optional_->isVisible()) state_.crane.use_optional_pieces = optional_->isChecked();
}

std::optional<PreMissionPlan> PreMissionPage::computePlan(QString& error) {
  if (!basis_) {
    error = basis_error_;
    return std::nullopt;
  }
  const double op_depth = state_.next_water ? state_.next_water->depth_m : depth_->value();  // exact (store)
  if (deepest_->value() < op_depth) {
    error = tr("Deepest depth: %1 m is shallower than the operating depth (%2 m); enter the deepest depth the "
               "mission goes to, at least %2 m.")
                .arg(fixed(deepest_->value(), 1))
                .arg(fixed(std::ceil(op_depth * 10.0 - 1e-9) / 10.0, 1));
    return std::nullopt;
  }
  if (!temperatureEntered()) {
    error = tr("Enter the next mission's water temperature.");
    return std::nullopt;
  }
  try {
    return planPreMission(*state_.vehicle, preMissionInput(state_, *basis_));
  } catch (const InputError& e) {
    error = q(e.what());
    return std::nullopt;
  }
}

void PreMissionPage::updatePreview() {
  if (loading_) return;
  store();
  water_error_->clear();
  density_->clear();
  if (temperatureEntered()) {
    try {
      const WaterState ws = resolveWater(*state_.next_water);
      density_->setText(tr("In-situ density %1 kg/m³").arg(fixed(ws.density_kgm3, 2)));
    } catch (const InputError& e) {
      water_error_->setText(q(e.what()));
    }
  } else {
    water_error_->setText(tr("Enter the next mission's water temperature."));
  }
  QString error;
  const auto plan = computePlan(error);
  const bool was_ok = plan_ok_;
  plan_ok_ = plan.has_value();
  error_->setText(plan_ok_ || !temperatureEntered() ? QString() : error);  // a missing temperature is said at the field
  if (plan) {
    const bool g = state_.isGlider();
    int pieces = 0;
    for (const auto& p : plan->points)
      for (const auto& pc : p.pieces) pieces += std::abs(pc.count);
    preview_->setText(tr("Plan: %1 piece(s) to handle; afterwards net buoyancy %2, pitch %3, roll %4 at %5 m.")
                          .arg(pieces)
                          .arg(EstimateText::valueSigma(true, plan->predicted.net_buoyancy_kg, plan->net_sigma_kg,
                                                        g ? 3 : 2, tr(" kg")),
                               EstimateText::valueSigma(EstimateText::pitchKnown(*plan), plan->predicted.pitch_deg,
                                                        plan->pitch_sigma_deg, 2, tr("°")),
                               EstimateText::valueSigma(EstimateText::rollKnown(*plan), plan->predicted.roll_deg,
                                                        plan->roll_sigma_deg, 2, tr("°")))
                          .arg(fixed(plan->at_points.front().water.depth_m, 0)));
  } else {
    preview_->clear();
  }
  if (plan_ok_ != was_ok) emit completeChanged();
}

bool PreMissionPage::isComplete() const { return plan_ok_ || saveOnly(); }

void PreMissionPage::cleanupPage() { store(); }

bool PreMissionPage::validatePage() {
  store();
  if (saveOnly()) {
    // Last page of this post-mission session: Finish saves the mission.
    OperatorWizard* w = wiz();
    HistoryStore* history = w ? w->history() : nullptr;
    if (!history) return !w || w->confirmCloseWithoutHistory();
    try {
      saveMissionToHistory(*history, state_, w->now());
    } catch (const InputError& e) {
      save_status_->setText(tr("Not saved: %1").arg(q(e.what())));
      return false;
    }
    w->reportSaved(tr("Saved configuration %1: the mission log and its analysis.").arg(q(state_.configuration_id)));
    return true;
  }
  QString error;
  auto plan = computePlan(error);
  if (!plan) {
    error_->setText(error);
    return false;
  }
  // A different move invalidates the checklist and the installed masses.
  const bool same = state_.plan && state_.plan->delta == plan->delta && state_.plan->piece_sizes_kg == plan->piece_sizes_kg;
  const bool resumed = !state_.plan && state_.actually_installed_kg.size() == plan->points.size();
  if (!same && !resumed) {
    state_.actually_installed_kg.clear();
    state_.checklist_done.clear();
  }
  state_.plan = std::move(plan);
  return true;
}

int PreMissionPage::nextId() const { return saveOnly() ? -1 : OperatorWizard::kAdjustment; }

}  // namespace auv::ui
