#include "pages/start_page.h"

#include <QButtonGroup>
#include <QDir>
#include <QFileInfo>
#include <QFrame>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include "common/input_error.h"
#include "discrepancy/profile_update.h"
#include "history/store.h"
#include "vehicle/vehicle_catalog.h"
#include "weighing/slocum_layout.h"
#include "widgets/inputs.h"
#include "wizard/app_paths.h"
#include "wizard/operator_wizard.h"

namespace auv::ui {
namespace {

QString dateOf(TimePoint t) { return QString::fromStdString(toIsoUtc(t)).left(10); }
QString q(const std::string& s) { return QString::fromStdString(s); }

}  // namespace

StartPage::StartPage(WizardState& state) : state_(state) {
  setTitle(tr("Start: configuration and mode"));
  setSubTitle(tr("Continue a vehicle configuration from the history or start a new one, then choose what to do."));

  resume_box_ = new QFrame;
  resume_box_->setObjectName("resume_banner");
  resume_box_->setFrameShape(QFrame::StyledPanel);
  resume_box_->setStyleSheet("#resume_banner { background: #fff4cc; }");
  resume_text_ = new QLabel;
  resume_text_->setObjectName("resume_text");
  resume_text_->setWordWrap(true);
  resume_ = new QPushButton(tr("&Resume"));
  resume_->setObjectName("resume");
  resume_->setToolTip(tr("Continue the unfinished session where you left it."));
  resume_->setMinimumHeight(32);
  resume_->setAutoDefault(false);  // Enter means Next in a wizard, never a page button
  discard_ = new QPushButton(tr("&Discard"));
  discard_->setObjectName("discard");
  discard_->setToolTip(tr("Delete the unfinished session and start afresh."));
  discard_->setMinimumHeight(32);
  discard_->setAutoDefault(false);
  auto* rl = new QHBoxLayout(resume_box_);
  rl->addWidget(resume_text_, 1);
  rl->addWidget(resume_);
  rl->addWidget(discard_);
  resume_box_->hide();

  search_ = new QLineEdit;
  search_->setObjectName("search");
  search_->setPlaceholderText(tr("Search ID, payload, area, water type or vehicle"));
  search_->setToolTip(tr("Type part of a configuration ID, payload note, area, water type or vehicle name."));
  search_->setMinimumHeight(32);
  search_->setClearButtonEnabled(true);
  auto* searchLabel = new QLabel(tr("&Search:"));
  searchLabel->setBuddy(search_);

  table_ = new QTableWidget(0, 5);
  table_->setObjectName("configurations");
  table_->setHorizontalHeaderLabels({tr("Configuration"), tr("Vehicle"), tr("Payload"), tr("Area / water"),
                                     tr("Last activity")});
  table_->horizontalHeader()->setStretchLastSection(true);
  table_->verticalHeader()->hide();
  table_->verticalHeader()->setDefaultSectionSize(32);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::SingleSelection);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setToolTip(tr("Recent configurations, newest first. The first row starts a new configuration."));

  auto* stateBox = new QGroupBox(tr("Last state"));
  last_state_ = new QLabel;
  last_state_->setObjectName("last_state");
  last_state_->setWordWrap(true);
  temperature_ = new QLabel;
  temperature_->setObjectName("temperature_age");
  temperature_->setWordWrap(true);
  auto* sl = new QVBoxLayout(stateBox);
  sl->addWidget(last_state_);
  sl->addWidget(temperature_);

  auto* modeBox = new QGroupBox(tr("What do you want to do?"));
  mode_first_ = new QRadioButton(tr("&First mission: weigh the vehicle and compute the ballast change"));
  mode_first_->setObjectName("mode_first");
  mode_first_->setToolTip(tr("No mission flown yet with this configuration: crane weighing (AUV) or tank weighing (glider)."));
  mode_post_ = new QRadioButton(tr("&Post mission: import a mission log and look at the deviations"));
  mode_post_->setObjectName("mode_post");
  mode_post_->setToolTip(tr("You have a log of a mission flown with this configuration."));
  mode_pre_ = new QRadioButton(tr("Pre &mission: plan the next mission from the analysed log"));
  mode_pre_->setObjectName("mode_pre");
  mode_pre_->setToolTip(tr("Plan the next mission from the last analysed mission of this configuration: needs an "
                           "analysis in the history (post-mission mode) or in this session."));
  mode_pre_->setEnabled(false);
  for (auto* r : {mode_first_, mode_post_, mode_pre_}) r->setMinimumHeight(28);
  auto* group = new QButtonGroup(this);
  group->addButton(mode_first_);
  group->addButton(mode_post_);
  group->addButton(mode_pre_);
  auto* ml = new QVBoxLayout(modeBox);
  ml->addWidget(mode_first_);
  ml->addWidget(mode_post_);
  ml->addWidget(mode_pre_);

  error_ = makeErrorLabel();
  history_location_ = new QLabel;
  history_location_->setObjectName("history_location");
  history_location_->setWordWrap(true);
  history_location_->setTextInteractionFlags(Qt::TextSelectableByMouse);

  auto* searchRow = new QHBoxLayout;
  searchRow->addWidget(searchLabel);
  searchRow->addWidget(search_, 1);
  auto* lower = new QHBoxLayout;
  lower->addWidget(stateBox, 3);
  lower->addWidget(modeBox, 2);
  auto* lay = new QVBoxLayout(this);
  lay->addWidget(resume_box_);
  lay->addLayout(searchRow);
  lay->addWidget(table_, 1);
  lay->addLayout(lower);
  lay->addWidget(history_location_);
  lay->addWidget(error_);

  connect(search_, &QLineEdit::textChanged, this, [this] { refreshTable(); });
  connect(table_, &QTableWidget::itemSelectionChanged, this, [this] { showSelection(); });
  connect(resume_, &QPushButton::clicked, this, [this] {
    try {
      const SavedSession saved = readSessionFile(autosaveFilePath().toStdString(), state_.resource_dir);
      resume_box_->hide();
      wiz()->resume(saved);
    } catch (const InputError& e) {
      error_->setText(tr("Cannot resume: %1").arg(q(e.what())));
    }
  });
  connect(discard_, &QPushButton::clicked, this, [this] {
    wiz()->discardAutosave();
    resume_box_->hide();
  });
}

OperatorWizard* StartPage::wiz() const { return qobject_cast<OperatorWizard*>(wizard()); }

void StartPage::initializePage() {
  error_->clear();
  if (HistoryStore* store = wiz()->history(); !store) {
    history_location_->clear();
    error_->setText(tr("The history cannot be opened (%1); you can still work, but nothing will be saved.")
                        .arg(wiz()->historyError()));
  } else {
    history_location_->setText(tr("History: %1").arg(QDir::toNativeSeparators(historyFilePath())));
  }
  refreshTable();
  mode_first_->setChecked(state_.mode == SessionMode::kFirstMission);
  mode_post_->setChecked(state_.mode == SessionMode::kPostMission);
  if (state_.mode == SessionMode::kPreMission) (mode_pre_->isEnabled() ? mode_pre_ : mode_first_)->setChecked(true);
  showResumeOffer();
}

void StartPage::showResumeOffer() {
  const QString path = autosaveFilePath();
  if (!QFileInfo::exists(path)) {
    resume_box_->hide();
    return;
  }
  try {
    const SavedSession s = readSessionFile(path.toStdString(), state_.resource_dir);
    const QString where = wiz()->page(s.page_id) ? wiz()->page(s.page_id)->title() : QString();
    resume_text_->setText(tr("An unfinished session was found (saved %1): %2, configuration %3, at \"%4\".")
                              .arg(q(s.saved_at).replace('T', ' ').replace('Z', " UTC"))
                              .arg(s.state.vehicle ? q(s.state.vehicle->name) : tr("no vehicle yet"))
                              .arg(s.state.configuration_id.empty() ? tr("(no ID)") : q(s.state.configuration_id))
                              .arg(where));
    resume_->setEnabled(true);
  } catch (const InputError& e) {
    resume_text_->setText(tr("An unfinished session was found but cannot be read: %1").arg(q(e.what())));
    resume_->setEnabled(false);
  }
  resume_box_->show();
}

void StartPage::refreshTable() {
  rows_.clear();
  table_->blockSignals(true);
  table_->clearContents();
  std::vector<QString> activity;
  if (HistoryStore* store = wiz() ? wiz()->history() : nullptr) {
    try {
      const std::string text = search_->text().trimmed().toStdString();
      if (text.empty()) {
        for (const auto& s : store->recentConfigurations(50)) {
          rows_.push_back(s.configuration);
          activity.push_back(dateOf(s.last_activity));
        }
      } else {
        for (const auto& c : store->search(text)) {
          rows_.push_back(c);
          activity.push_back(tr("created %1").arg(dateOf(c.created_at)));
        }
      }
    } catch (const InputError& e) {
      error_->setText(q(e.what()));
    }
  }
  table_->setRowCount(static_cast<int>(rows_.size()) + 1);
  auto* fresh = new QTableWidgetItem(tr("+ New configuration"));
  QFont bold = fresh->font();
  bold.setBold(true);
  fresh->setFont(bold);
  table_->setItem(0, 0, fresh);
  table_->setSpan(0, 0, 1, 5);
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    const auto& c = rows_[i];
    const int r = static_cast<int>(i) + 1;
    table_->setItem(r, 0, new QTableWidgetItem(q(c.config_id)));
    table_->setItem(r, 1, new QTableWidgetItem(q(c.vehicle_name.empty() ? c.vehicle_key : c.vehicle_name)));
    table_->setItem(r, 2, new QTableWidgetItem(q(c.payload_note)));
    QString where = q(c.area);
    if (!c.water_type.empty()) where += (where.isEmpty() ? "" : " / ") + q(c.water_type);
    table_->setItem(r, 3, new QTableWidgetItem(where));
    table_->setItem(r, 4, new QTableWidgetItem(activity[i]));
  }
  table_->resizeColumnsToContents();
  // Keep the configuration of this session selected if it is listed.
  int select = 0;
  if (state_.configuration_in_history) {
    for (std::size_t i = 0; i < rows_.size(); ++i)
      if (rows_[i].config_id == state_.configuration_id) select = static_cast<int>(i) + 1;
  }
  table_->blockSignals(false);
  table_->selectRow(select);
  showSelection();
}

std::optional<Configuration> StartPage::selectedConfiguration() const {
  const auto sel = table_->selectionModel()->selectedRows();
  if (sel.isEmpty() || sel.first().row() == 0) return std::nullopt;
  const std::size_t i = static_cast<std::size_t>(sel.first().row() - 1);
  return i < rows_.size() ? std::optional<Configuration>(rows_[i]) : std::nullopt;
}

void StartPage::showSelection() {
  const auto c = selectedConfiguration();
  mode_post_->setEnabled(c.has_value());
  // Planning needs an analysed mission: this session's or the configuration's.
  bool can_plan = state_.analysis.has_value();
  if (c && !can_plan) {
    if (HistoryStore* store = wiz()->history()) {
      try {
        can_plan = store->latestAnalysis(c->config_id, wiz()->now()).has_value();
      } catch (const InputError&) {
      }
    }
  }
  mode_pre_->setEnabled(can_plan);
  if (!can_plan && mode_pre_->isChecked()) mode_first_->setChecked(true);
  if (can_plan && state_.mode == SessionMode::kPreMission) mode_pre_->setChecked(true);
  if (!c) {
    if (mode_post_->isChecked()) mode_first_->setChecked(true);
    last_state_->setText(tr("A new configuration: you name it and choose the vehicle on the next page. "
                            "Only the first-mission mode makes sense until it has flown."));
    temperature_->clear();
    return;
  }
  HistoryStore* store = wiz()->history();
  if (!store) return;
  try {
    const auto st = store->lastState(c->config_id, wiz()->now());
    if (!st) return;
    std::optional<VehicleProfile> profile;
    try {
      profile = VehicleCatalog(state_.vehicles_dir).load(c->vehicle_key);
    } catch (const InputError&) {
    }
    QStringList lines;
    lines << tr("<b>%1</b> - %2, %3").arg(q(c->config_id).toHtmlEscaped(), q(c->vehicle_name).toHtmlEscaped(),
                                         q(c->payload_note).toHtmlEscaped());
    if (st->installed) {
      QStringList pts;
      for (const auto& p : st->installed->points) {
        const AdjustmentPoint* ap = profile ? profile->findPoint(p.name) : nullptr;
        pts << QString("%1 %2").arg(ap ? q(ap->label) : q(p.name),
                                    massText(p.mass_kg, profile && profile->kind == "glider"));
      }
      lines << tr("Installed (%1): %2").arg(dateOf(st->installed->installed_at), pts.join(", "));
    } else {
      lines << tr("Installed: nothing recorded yet.");
    }
    if (st->last_mission) {
      lines << tr("Last mission: %1, imported %2")
                   .arg(QFileInfo(q(st->last_mission->file_path)).fileName().toHtmlEscaped(),
                        dateOf(st->last_mission->imported_at));
    } else {
      lines << tr("Last mission: none yet.");
    }
    if (st->last_analysis) lines << tr("Last analysis: %1").arg(dateOf(st->last_analysis->at));
    last_state_->setText(lines.join("<br>"));
    if (st->last_temperature && st->last_temperature->temperature_degC && st->temperature_age) {
      const long days = static_cast<long>(st->temperature_age->count() / 86400);
      const QString base = tr("Water temperature %1 °C measured %2 (%3 days ago)")
                               .arg(fixed(*st->last_temperature->temperature_degC, 1))
                               .arg(dateOf(st->last_temperature->measured_at))
                               .arg(days);
      if (st->temperature_stale) {
        temperature_->setStyleSheet("color: #b00020;");
        temperature_->setText(base + tr(": older than one month - measure it again before computing (thesis §5.5.3)."));
      } else {
        temperature_->setStyleSheet("color: #1b5e20;");
        temperature_->setText(base + tr(": less than a month old, it can be reused."));
      }
    } else {
      temperature_->setStyleSheet("color: #b00020;");
      temperature_->setText(tr("No water temperature in the history: measure it before computing."));
    }
  } catch (const InputError& e) {
    error_->setText(q(e.what()));
  }
}

void StartPage::applyConfiguration(const Configuration& c) {
  // A different configuration than the session's: take over its identity and
  // what the history knows (installed pieces, a temperature still valid).
  const bool switching = !state_.configuration_in_history || state_.configuration_id != c.config_id;
  state_.configuration_id = c.config_id;
  state_.payload_note = c.payload_note;
  state_.bg_mm = c.bg_mm;
  state_.pitch_alignment_sigma_deg = c.pitch_level_check_deg;
  state_.area = c.area;
  state_.water_type = c.water_type;
  state_.configuration_in_history = true;
  state_.vehicle = VehicleCatalog(state_.vehicles_dir).load(c.vehicle_key);
  // The configuration's vehicle model (terms accepted in earlier model checks).
  state_.history_model = nullptr;
  if (HistoryStore* hs = wiz()->history()) {
    if (const auto m = hs->latestModelTerms(c.config_id, makeUtc(9999, 12, 31, 23, 59, 59)); m && m->model.contains("profile")) {
      try {
        state_.vehicle = discrepancy::vehicleFromStoredProfile(m->model["profile"], *state_.vehicle, "history: " + c.config_id);
        state_.history_model = m->model["profile"];
      } catch (const InputError&) {
        // A stored model this version cannot read: the catalog's profile.
      }
    }
  }
  state_.model_profile = state_.history_model;
  if (!switching) return;
  // Installed pieces belong to a configuration: forget the previous one's.
  state_.crane.installed_kg.clear();
  state_.tank.ballast = SlocumBallast{};
  HistoryStore* store = wiz()->history();
  const auto st = store ? store->lastState(c.config_id, wiz()->now()) : std::nullopt;
  if (!st) return;
  if (st->installed) {
    const VehicleProfile& v = *state_.vehicle;
    if (v.kind == "glider") {
      for (const auto& p : st->installed->points) {
        for (int i = 0; i < kSlocumItemCount; ++i) {
          if (p.name == slocumItemName(static_cast<SlocumItem>(i))) state_.tank.ballast.item_kg[static_cast<std::size_t>(i)] = p.mass_kg;
        }
      }
    } else {
      state_.crane.installed_kg.assign(v.points.size(), 0.0);
      for (std::size_t i = 0; i < v.points.size(); ++i)
        for (const auto& p : st->installed->points)
          if (p.name == v.points[i].name) state_.crane.installed_kg[i] = p.mass_kg;
    }
  }
  if (st->last_temperature && st->last_temperature->temperature_degC && !st->temperature_stale) {
    state_.crane.water.temperature_degC = *st->last_temperature->temperature_degC;
    if (st->last_temperature->salinity_psu) state_.crane.water.salinity_psu = *st->last_temperature->salinity_psu;
  }
}

bool StartPage::validatePage() {
  try {
    if (const auto c = selectedConfiguration()) {
      applyConfiguration(*c);
    } else if (state_.configuration_in_history) {
      // Leaving a history configuration for a new one: the ID must be new too.
      state_.configuration_in_history = false;
      state_.configuration_id.clear();
    }
  } catch (const InputError& e) {
    error_->setText(q(e.what()));
    return false;
  }
  state_.mode = mode_post_->isChecked()  ? SessionMode::kPostMission
                : mode_pre_->isChecked() ? SessionMode::kPreMission
                                         : SessionMode::kFirstMission;
  return true;
}

int StartPage::nextId() const { return OperatorWizard::kVehicle; }

}  // namespace auv::ui
