#include "pages/glider_pre_mission_page.h"

#include <QButtonGroup>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QRadioButton>
#include <QScrollArea>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "analysis/profile_constants.h"
#include "seawater/depth_pressure.h"
#include "common/input_error.h"
#include "history/store.h"
#include "wizard/history_save.h"
#include "wizard/model_words.h"
#include "widgets/inputs.h"
#include "wizard/operator_wizard.h"

namespace auv::ui {
namespace {

QString q(const std::string& s) { return QString::fromStdString(s); }

QString grams(double g, double sigma) {
  const QString v = signedFixed(g, 0);
  return std::isfinite(sigma) ? GliderPreMissionPage::tr("%1 ± %2 g").arg(v, fixed(sigma, 0)) : GliderPreMissionPage::tr("%1 g").arg(v);
}

double number(const nlohmann::json& j, const char* k) {
  return j.contains(k) && j[k].is_number() ? j[k].get<double>() : NAN;
}

}  // namespace

GliderPreMissionPage::GliderPreMissionPage(WizardState& state) : state_(state) {
  setTitle(tr("Glider: the next deployment's water"));
  setSubTitle(tr("What the log showed, and the water where the glider must be neutral with its pump at zero."));

  auto* logBox = new QGroupBox(tr("What the log showed"));
  log_answer_ = new QLabel;
  log_answer_->setObjectName("log_answer");
  log_answer_->setWordWrap(true);
  terms_ = new QLabel;
  terms_->setObjectName("terms_used");
  terms_->setWordWrap(true);
  installed_ = new QLabel;
  installed_->setObjectName("glider_installed_now");
  installed_->setWordWrap(true);
  auto* ll = new QVBoxLayout(logBox);
  ll->addWidget(log_answer_);
  ll->addWidget(terms_);
  ll->addWidget(installed_);

  auto* targetBox = new QGroupBox(tr("Target water"));
  kind_log_ = new QRadioButton(tr("The &log's own water at its deepest yo"));
  kind_log_->setObjectName("target_log");
  kind_log_->setToolTip(tr("Neutral where the recorded mission went deepest: its CTD's temperature and salinity there."));
  kind_density_ = new QRadioButton(tr("A densit&y"));
  kind_density_->setObjectName("target_density_choice");
  kind_density_->setToolTip(tr("The in-situ density of the next deployment's water (pressure and temperature from the log's deepest water)."));
  kind_pt_ = new QRadioButton(tr("&Pressure and temperature"));
  kind_pt_->setObjectName("target_pt_choice");
  kind_pt_->setToolTip(tr("Pressure and temperature of the next deployment's water; with a salinity the density follows "
                          "from EOS-80, else the log's salinity is used."));
  kind_depth_ = new QRadioButton(tr("&A depth in the log's CTD profile"));
  kind_depth_->setObjectName("target_depth_choice");
  kind_depth_->setToolTip(tr("Temperature, salinity and pressure at this depth as the log's own CTD measured them."));
  auto* group = new QButtonGroup(this);
  for (auto* r : {kind_log_, kind_density_, kind_pt_, kind_depth_}) {
    group->addButton(r);
    r->setMinimumHeight(28);
    connect(r, &QRadioButton::toggled, this, [this](bool on) {
      if (on) applyKind();
    });
  }
  density_ = makeNumber("glider_target_density", 990, 1080, 2, " kg/m³", tr("In-situ density of the target water, kg/m³ (990 .. 1080)."));
  pressure_ = makeNumber("glider_target_pressure", 0, 7000, 1, " dbar", tr("Pressure where the glider must be neutral, dbar."));
  temperature_ = makeNumber("glider_target_temperature", -2.5, 40, 2, " °C", tr("Water temperature there, °C."));
  salinity_ = makeNumber("glider_target_salinity", 0, 42, 3, " PSU",
                         tr("Practical salinity there; leave it at 'not given' to use the log's own salinity."));
  salinity_->setSpecialValueText(tr("not given"));
  depth_ = makeNumber("glider_target_depth", 0, 7000, 1, " m", tr("A depth the log reached: its CTD there gives T, S and p."));
  auto* grid = new QGridLayout;
  auto addField = [&](int row, int col, const QString& text, NumberInput* in) {
    auto* l = new QLabel(text);
    l->setBuddy(in);
    grid->addWidget(l, row, col);
    grid->addWidget(in, row, col + 1);
  };
  grid->addWidget(kind_log_, 0, 0, 1, 4);
  grid->addWidget(kind_density_, 1, 0, 1, 2);
  addField(1, 2, tr("&Density:"), density_);
  grid->addWidget(kind_pt_, 2, 0, 1, 2);
  addField(2, 2, tr("P&ressure:"), pressure_);
  addField(3, 2, tr("&Temperature:"), temperature_);
  addField(4, 2, tr("&Salinity:"), salinity_);
  grid->addWidget(kind_depth_, 5, 0, 1, 2);
  addField(5, 2, tr("D&epth:"), depth_);
  grid->setColumnStretch(1, 1);
  grid->setColumnStretch(3, 1);
  target_ = new QLabel;
  target_->setObjectName("target_resolved");
  target_->setWordWrap(true);
  auto* tl = new QVBoxLayout(targetBox);
  tl->addLayout(grid);
  tl->addWidget(target_);

  result_ = new QLabel;
  result_->setObjectName("glider_result");
  result_->setWordWrap(true);
  result_->setTextFormat(Qt::RichText);
  error_ = makeErrorLabel();

  for (NumberInput* in : {density_, pressure_, temperature_, salinity_, depth_})
    connect(in, &NumberInput::valueChanged, this, [this] { update(); });

  auto* content = new QWidget;
  auto* cl = new QVBoxLayout(content);
  cl->setContentsMargins(0, 0, 0, 0);
  cl->addWidget(logBox);
  cl->addWidget(targetBox);
  cl->addWidget(result_);
  cl->addWidget(error_);
  cl->addStretch();
  // Fits 1366 x 768; a smaller window scrolls.
  auto* scroll = new QScrollArea;
  scroll->setWidget(content);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(scroll);
}

GliderTargetChoice GliderPreMissionPage::choice() const {
  GliderTargetChoice c;
  using K = GliderTargetChoice::Kind;
  c.kind = kind_density_->isChecked() ? K::kDensity
           : kind_pt_->isChecked()    ? K::kPressureTemperature
           : kind_depth_->isChecked() ? K::kDepth
                                      : K::kLogDeepest;
  c.density_kgm3 = density_->value();
  c.pressure_dbar = pressure_->value();
  c.temperature_degC = temperature_->value();
  c.salinity_psu = salinity_->value() > salinity_->minimum() ? salinity_->value() : NAN;
  c.depth_m = depth_->value();
  return c;
}

void GliderPreMissionPage::initializePage() {
  loading_ = true;
  loadInstalled();
  showLogAnswer();
  // The fields start at the log's own deepest water, so a change is typed over it.
  const GliderAnswer def = gliderAnswer(state_, {});
  if (def.ok) {
    // Shown to the field's decimals (typing over them starts from what is seen).
    auto shown = [](double v, int decimals) { return std::round(v * std::pow(10.0, decimals)) / std::pow(10.0, decimals); };
    density_->setValue(shown(def.target.density_kgm3, density_->decimals()));
    pressure_->setValue(shown(def.target.pressure_dbar, pressure_->decimals()));
    temperature_->setValue(shown(def.target.temperature_degC, temperature_->decimals()));
    const double lat = state_.log ? analysis::latitudeFromMetadata(*state_.log).value_or(seawater::kDefaultLatitude_deg)
                                  : seawater::kDefaultLatitude_deg;
    depth_->setValue(std::round(seawater::depthFromPressure(def.target.pressure_dbar, lat)));
  }
  salinity_->setValue(salinity_->minimum());
  if (!kind_density_->isChecked() && !kind_pt_->isChecked() && !kind_depth_->isChecked()) kind_log_->setChecked(true);
  loading_ = false;
  applyKind();
}

void GliderPreMissionPage::loadInstalled() {
  if (!state_.vehicle) return;
  const auto& pts = state_.vehicle->points;
  // A glider's import page has no installed fields (its fit needs none), so
  // what the bottles hold comes from the configuration's latest installed
  // state in the history: what they held during the mission just analysed.
  state_.mission_installed_kg.clear();
  QString source;
  auto* w = qobject_cast<OperatorWizard*>(wizard());
  std::optional<InstalledState> st;
  if (HistoryStore* h = w ? w->history() : nullptr) {
    try {
      st = h->latestInstalled(state_.configuration_id, w->now());
    } catch (const InputError&) {
      // A configuration not in the history yet (saved at Finish): nothing installed is known.
    }
  }
  if (st) {
    std::vector<double> kg(pts.size(), 0.0);
    bool all = true;
    for (const InstalledPoint& p : st->points) {
      const auto it = std::find_if(pts.begin(), pts.end(), [&](const AdjustmentPoint& a) { return a.name == p.name; });
      if (it == pts.end()) all = false;
      else kg[static_cast<std::size_t>(it - pts.begin())] = p.mass_kg;
    }
    if (all) state_.mission_installed_kg = kg;
    source = tr("history, %1").arg(q(toIsoUtc(st->installed_at)).left(10));
  }
  if (state_.mission_installed_kg.size() != pts.size()) {
    installed_->setText(tr("What the bottles hold now is not in the history: capacities are checked against half-full bottles."));
    return;
  }
  QStringList now;
  for (std::size_t i = 0; i < pts.size(); ++i) now << QString("%1 %2").arg(q(pts[i].label), massText(state_.mission_installed_kg[i], true));
  installed_->setText(tr("Installed now (%1): %2.").arg(source, now.join(", ")));
}

void GliderPreMissionPage::showLogAnswer() {
  if (!state_.analysis) {
    log_answer_->setText(tr("No analysis: go back and import the mission's log."));
    terms_->clear();
    return;
  }
  const analysis::AnalysisReport& r = *state_.analysis;
  if (!r.mass_to_add_g.known) {
    log_answer_->setText(tr("The log does not show the glider's net buoyancy: %1. Finish saves the mission to the history; "
                            "plan the next deployment from a log with steady glides.")
                             .arg(q(r.mass_to_add_g.why_not)));
    terms_->clear();
    return;
  }
  QString text = tr("The analysis (steady-glide fit): add <b>%1</b> at the log's own deepest water.")
                     .arg(grams(r.mass_to_add_g.value, r.mass_to_add_g.sigma));
  const GliderAnswer def = gliderAnswer(state_, {});
  if (def.ok && def.joint)
    text += " " + tr("The model check, fitted jointly with its terms: add <b>%1</b>.")
                      .arg(grams(number(def.report, "mass_to_add_g"), number(def.report, "mass_to_add_sigma_g")));
  log_answer_->setText(text);
  QStringList used;
  if (state_.model_check)
    for (const auto& m : state_.model_check->missing_physics)
    {
      QString line = tr("%1 = %2 ± %3 %4 (profile %5)")
                         .arg(termLabel(m.id))
                         .arg(significant(m.value, 4))
                         .arg(significant(m.sigma, 2))
                         .arg(q(m.unit))
                         .arg(significant(m.profile_value, 4));
      // A term the log preferred over a rival: say so, the sigma above carries it.
      for (const auto& rv : m.rivals) line += " " + tr("(or %1: this log cannot tell them apart for certain)").arg(termLabel(rv.id));
      used << line;
    }
  QString t = !state_.model_check ? tr("The model check did not run: the answer uses the profile's compressibility and thermal expansion.")
              : used.isEmpty()    ? tr("The model check found no missing physics: the answer uses the profile's constants.")
                                  : tr("Terms the answer uses: %1.").arg(used.join("; "));
  if (def.ok && def.mass_drift_g_per_h != 0.0)
    t += " " + tr("Mass drift %1 g/h: the answer is the mass at the end of the log; add the drift until the deployment day.")
                   .arg(signedFixed(def.mass_drift_g_per_h, 2));
  terms_->setText(t);
}

void GliderPreMissionPage::applyKind() {
  if (loading_) return;
  density_->setEnabled(kind_density_->isChecked());
  for (auto* in : {pressure_, temperature_, salinity_}) in->setEnabled(kind_pt_->isChecked());
  depth_->setEnabled(kind_depth_->isChecked());
  update();
}

void GliderPreMissionPage::update() {
  if (loading_) return;
  const bool was = answer_.ok;
  answer_ = gliderAnswer(state_, choice());
  error_->setText(answer_.ok ? QString() : q(answer_.error));
  if (answer_.ok) {
    const auto& t = answer_.target;
    QString basis = q(t.basis);
    if (kind_log_->isChecked()) basis = tr("default: %1").arg(basis);
    target_->setText(tr("Target: %1 kg/m³ at %2 dbar, %3 °C (%4).")
                         .arg(fixed(t.density_kgm3, 2))
                         .arg(fixed(t.pressure_dbar, 0))
                         .arg(fixed(t.temperature_degC, 2))
                         .arg(basis));
    const double add = number(answer_.plan, "mass_to_add_g"), sigma = number(answer_.plan, "mass_to_add_sigma_g");
    result_->setText(tr("For neutral with the pump at zero in this water: add <b>%1</b>%2. Next: where the grams go.")
                         .arg(grams(add, sigma))
                         .arg(add < 0 ? tr(" (remove %1 g)").arg(fixed(-add, 0)) : QString()));
  } else {
    target_->clear();
    result_->clear();
  }
  if (was != answer_.ok) emit completeChanged();
}

bool GliderPreMissionPage::isComplete() const { return answer_.ok || saveOnly(); }

void GliderPreMissionPage::cleanupPage() {}

bool GliderPreMissionPage::validatePage() {
  if (saveOnly()) {
    auto* w = qobject_cast<OperatorWizard*>(wizard());
    HistoryStore* store = w ? w->history() : nullptr;
    if (!store) return !w || w->confirmCloseWithoutHistory();
    try {
      saveMissionToHistory(*store, state_, w->now());
    } catch (const InputError& e) {
      error_->setText(tr("Not saved: %1").arg(q(e.what())));
      return false;
    }
    w->reportSaved(tr("Saved configuration %1: the mission log and its analysis.").arg(q(state_.configuration_id)));
    return true;
  }
  update();
  if (!answer_.ok) return false;
  state_.glider_plan = answer_.plan;
  return true;
}

int GliderPreMissionPage::nextId() const { return saveOnly() ? -1 : OperatorWizard::kGliderBallast; }

}  // namespace auv::ui
