#include "widgets/column_mapping_dialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileInfo>
#include <QGridLayout>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <regex>

#include "common/input_error.h"
#include "missionlog/channel_aliases.h"
#include "missionlog/delimited_text_reader.h"
#include "missionlog/log_reader.h"
#include "missionlog/unit_conversion.h"
#include "widgets/inputs.h"

namespace auv::ui {
namespace {

constexpr std::size_t kHeadBytes = 65536;
constexpr int kPreviewRows = 8;

QString q(const std::string& s) { return QString::fromStdString(s); }

struct ChannelInfo {
  const char* name;
  const char* text;  // translated at use
  bool required;
};

// What the analysis and the model check read; depth or pressure is required.
const ChannelInfo kChannels[] = {
    {"time", QT_TRANSLATE_NOOP("auv::ui::ColumnMappingDialog", "&Time *"), true},
    {"depth", QT_TRANSLATE_NOOP("auv::ui::ColumnMappingDialog", "&Depth, measured *"), true},
    {"depth_cmd", QT_TRANSLATE_NOOP("auv::ui::ColumnMappingDialog", "Depth &command"), false},
    {"pitch", QT_TRANSLATE_NOOP("auv::ui::ColumnMappingDialog", "&Pitch"), false},
    {"pitch_cmd", QT_TRANSLATE_NOOP("auv::ui::ColumnMappingDialog", "Pitch c&ommand"), false},
    {"roll", QT_TRANSLATE_NOOP("auv::ui::ColumnMappingDialog", "&Roll"), false},
    {"speed", QT_TRANSLATE_NOOP("auv::ui::ColumnMappingDialog", "Speed through &water"), false},
    {"prop_rpm", QT_TRANSLATE_NOOP("auv::ui::ColumnMappingDialog", "Propeller sp&eed"), false},
    {"elevator", QT_TRANSLATE_NOOP("auv::ui::ColumnMappingDialog", "E&levator angle"), false},
    {"pressure", QT_TRANSLATE_NOOP("auv::ui::ColumnMappingDialog", "Press&ure (CTD)"), false},
    {"temperature", QT_TRANSLATE_NOOP("auv::ui::ColumnMappingDialog", "Water te&mperature"), false},
    {"salinity", QT_TRANSLATE_NOOP("auv::ui::ColumnMappingDialog", "Sali&nity"), false},
    {"pump_volume", QT_TRANSLATE_NOOP("auv::ui::ColumnMappingDialog", "Buoyancy pump &volume"), false},
};

bool isCommentLine(std::string_view t) {
  return !t.empty() && (t.front() == '#' || t.front() == '%' || t.substr(0, 2) == "//");
}

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

// Display only: the reader does its own (stricter) splitting.
QStringList splitCells(std::string_view line, char delim) {
  QStringList out;
  if (delim == 0) {
    std::string cur;
    for (char c : line) {
      if (c == ' ' || c == '\t') {
        if (!cur.empty()) out << QString::fromUtf8(cur.data(), static_cast<qsizetype>(cur.size()));
        cur.clear();
      } else {
        cur += c;
      }
    }
    if (!cur.empty()) out << QString::fromUtf8(cur.data(), static_cast<qsizetype>(cur.size()));
    return out;
  }
  std::string cur;
  bool quoted = false;
  for (char c : line) {
    if (c == '"') {
      quoted = !quoted;
    } else if (c == delim && !quoted) {
      const auto t = trimmed(cur);
      out << QString::fromUtf8(t.data(), static_cast<qsizetype>(t.size()));
      cur.clear();
    } else {
      cur += c;
    }
  }
  const auto t = trimmed(cur);
  out << QString::fromUtf8(t.data(), static_cast<qsizetype>(t.size()));
  return out;
}

char delimiterChar(Delimiter d) {
  switch (d) {
    case Delimiter::kComma: return ',';
    case Delimiter::kSemicolon: return ';';
    case Delimiter::kTab: return '\t';
    default: return 0;
  }
}

}  // namespace

std::vector<std::string> ColumnMappingDialog::channelNames() {
  std::vector<std::string> out;
  for (const auto& c : kChannels) out.emplace_back(c.name);
  return out;
}

ColumnMappingDialog::ColumnMappingDialog(const QString& file, const std::string& vehicle_id,
                                         const std::optional<ColumnMapping>& start, QWidget* parent)
    : QDialog(parent), file_(file), vehicle_(vehicle_id) {
  setObjectName("column_mapping_dialog");
  setWindowTitle(tr("Map the columns of %1").arg(QFileInfo(file).fileName()));
  readHead();

  auto* intro = new QLabel(tr("Say which column of the file holds each quantity. The first rows are shown below; "
                              "the choices are pre-filled with what the reader recognised."));
  intro->setWordWrap(true);
  preview_ = new QTableWidget;
  preview_->setObjectName("preview");
  preview_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  preview_->verticalHeader()->setDefaultSectionSize(22);
  preview_->setToolTip(tr("The first rows of the file, split at the chosen delimiter."));
  preview_->setMinimumHeight(150);

  delimiter_ = new QComboBox;
  delimiter_->setObjectName("delimiter");
  delimiter_->addItem(tr("recognise"), static_cast<int>(Delimiter::kAuto));
  delimiter_->addItem(tr("comma ,"), static_cast<int>(Delimiter::kComma));
  delimiter_->addItem(tr("semicolon ;"), static_cast<int>(Delimiter::kSemicolon));
  delimiter_->addItem(tr("tab"), static_cast<int>(Delimiter::kTab));
  delimiter_->addItem(tr("blanks"), static_cast<int>(Delimiter::kWhitespace));
  delimiter_->setToolTip(tr("What separates the columns. 'recognise' lets the reader decide from the file."));
  delimiter_->setMinimumHeight(32);
  decimal_ = new QComboBox;
  decimal_->setObjectName("decimal");
  decimal_->addItem(tr("recognise"), static_cast<int>(DecimalMark::kAuto));
  decimal_->addItem(tr("point 1.5"), static_cast<int>(DecimalMark::kPoint));
  decimal_->addItem(tr("comma 1,5"), static_cast<int>(DecimalMark::kComma));
  decimal_->setToolTip(tr("The decimal mark of the numbers (a comma is only possible when the columns are not "
                          "separated by commas)."));
  decimal_->setMinimumHeight(32);
  time_format_ = new QComboBox;
  time_format_->setObjectName("time_format");
  time_format_->addItem(tr("recognise"), static_cast<int>(TimeFormat::kAuto));
  time_format_->addItem(tr("seconds (or the unit)"), static_cast<int>(TimeFormat::kSeconds));
  time_format_->addItem(tr("seconds since 1970"), static_cast<int>(TimeFormat::kEpochSeconds));
  time_format_->addItem(tr("ISO 8601 (2026-05-14T08:12:00Z)"), static_cast<int>(TimeFormat::kIso8601));
  time_format_->addItem(tr("dd.mm.yyyy hh:mm:ss"), static_cast<int>(TimeFormat::kDayMonthYear));
  time_format_->addItem(tr("hh:mm:ss (date from a date column)"), static_cast<int>(TimeFormat::kTimeOfDay));
  time_format_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
  time_format_->setToolTip(tr("How the time column is written."));
  time_format_->setMinimumHeight(32);
  utc_offset_ = makeNumber("utc_offset", -14.5, 14.0, 1, tr(" h"),
                         tr("The logger clock runs at UTC + this many hours (e.g. 2 for CEST). Leave at "
                            "'not stated' when the times are UTC or carry their zone."));
  utc_offset_->setSingleStep(0.5);
  utc_offset_->setSpecialValueText(tr("not stated"));
  utc_offset_->setValue(utc_offset_->minimum());
  auto* layout_row = new QHBoxLayout;
  auto* dl = new QLabel(tr("Delim&iter:"));
  dl->setBuddy(delimiter_);
  auto* cl = new QLabel(tr("Decimal mar&k:"));
  cl->setBuddy(decimal_);
  auto* tl = new QLabel(tr("Time &format:"));
  tl->setBuddy(time_format_);
  layout_row->addWidget(dl);
  layout_row->addWidget(delimiter_);
  layout_row->addSpacing(12);
  layout_row->addWidget(cl);
  layout_row->addWidget(decimal_);
  layout_row->addSpacing(12);
  layout_row->addWidget(tl);
  layout_row->addWidget(time_format_);
  layout_row->addSpacing(12);
  auto* ul = new QLabel(tr("Lo&gger clock: UTC +"));
  ul->setBuddy(utc_offset_);
  layout_row->addWidget(ul);
  layout_row->addWidget(utc_offset_);
  layout_row->addStretch(1);

  auto* box = new QGroupBox(tr("Columns (* = required; depth may instead come from pressure)"));
  auto* grid = new QGridLayout(box);
  grid->setVerticalSpacing(2);
  grid->setHorizontalSpacing(6);
  // Two blocks side by side (quantity, column, unit), each row with its
  // error underneath, so the dialog fits a laptop screen.
  constexpr int kLeftRows = 7;
  for (int block = 0; block < 2; ++block) {
    grid->addWidget(new QLabel(tr("<b>Quantity</b>")), 0, block * 4);
    grid->addWidget(new QLabel(tr("<b>Column in the file</b>")), 0, block * 4 + 1);
    grid->addWidget(new QLabel(tr("<b>Unit</b>")), 0, block * 4 + 2);
  }
  int index = 0;
  for (const auto& c : kChannels) {
    Row row;
    row.channel = c.name;
    row.column = new QComboBox;
    row.column->setObjectName(QString("column_%1").arg(c.name));
    row.column->setMinimumHeight(32);
    row.column->setToolTip(tr("The column holding this quantity, or 'not in this file'."));
    row.unit = new QLineEdit;
    row.unit->setObjectName(QString("unit_%1").arg(c.name));
    row.unit->setMinimumHeight(32);
    row.unit->setMaximumWidth(80);
    row.unit->setToolTip(c.name == std::string("time")
                             ? tr("Unit of numeric times: s, ms, min or h. Empty = from the header, else s.")
                             : tr("Unit of the numbers in the file, e.g. m, ft, dbar, deg, rad, m/s, knots, rpm, "
                                  "degC. Empty = from the header, else the format's unit."));
    row.error = makeErrorLabel(QString("error_%1").arg(c.name));
    auto* label = new QLabel(tr(c.text));
    label->setBuddy(row.column);
    const int block = index < kLeftRows ? 0 : 1;
    const int r = 1 + 2 * (index - block * kLeftRows), col = block * 4;
    grid->addWidget(label, r, col);
    grid->addWidget(row.column, r, col + 1);
    grid->addWidget(row.unit, r, col + 2);
    grid->addWidget(row.error, r + 1, col, 1, 3);
    // Whatever was wrong with this row is old news once it is edited.
    QLabel* error = row.error;
    connect(row.column, &QComboBox::currentIndexChanged, error, &QLabel::clear);
    connect(row.unit, &QLineEdit::textChanged, error, &QLabel::clear);
    rows_.push_back(row);
    ++index;
  }
  grid->setColumnStretch(1, 1);
  grid->setColumnStretch(5, 1);
  grid->setColumnMinimumWidth(3, 16);

  save_ = new QCheckBox(tr("&Save this mapping for %1 (used for its next text logs)").arg(q(vehicle_)));
  save_->setObjectName("save_mapping");
  save_->setToolTip(tr("Keep the mapping so later logs of this vehicle are read the same way without asking."));
  save_->setChecked(!vehicle_.empty());
  save_->setEnabled(!vehicle_.empty());
  general_error_ = makeErrorLabel("mapping_error");
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  buttons->button(QDialogButtonBox::Ok)->setText(tr("Read with this m&apping"));
  buttons->button(QDialogButtonBox::Ok)->setObjectName("mapping_ok");
  buttons->button(QDialogButtonBox::Cancel)->setText(tr("Cancel"));
  connect(buttons, &QDialogButtonBox::accepted, this, &ColumnMappingDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &ColumnMappingDialog::reject);

  auto* lay = new QVBoxLayout(this);
  lay->addWidget(intro);
  lay->addLayout(layout_row);
  lay->addWidget(preview_, 1);
  lay->addWidget(box);
  lay->addWidget(save_);
  lay->addWidget(general_error_);
  lay->addWidget(buttons);

  prefill(start);
  fillPreview();
  connect(delimiter_, &QComboBox::currentIndexChanged, this, [this] { fillPreview(); });
  resize(1060, 760);
}

void ColumnMappingDialog::readHead() {
  try {
    head_ = readFirstBytes(file_.toStdString(), kHeadBytes);
  } catch (const InputError& e) {
    guess_problem_ = q(e.what());
    return;
  }
  // Only whole lines: the last one may be cut by the byte limit.
  const bool complete = QFileInfo(file_).size() <= static_cast<qint64>(head_.size());
  if (!complete) {
    const auto nl = head_.rfind('\n');
    if (nl != std::string::npos) head_.resize(nl + 1);
  }
  std::string_view h = head_;
  if (h.substr(0, 3) == "\xEF\xBB\xBF") h.remove_prefix(3);
  while (!h.empty() && lines_.size() < static_cast<std::size_t>(kPreviewRows) + 1) {
    const auto nl = h.find('\n');
    const std::string_view l = trimmed(h.substr(0, nl));
    h.remove_prefix(nl == std::string_view::npos ? h.size() : nl + 1);
    if (!l.empty() && !isCommentLine(l)) lines_.emplace_back(l);
  }
  try {
    guess_ = suggestColumnMapping(std::string_view(head_), file_.toStdString());
  } catch (const InputError& e) {
    guess_problem_ = q(e.what());
  }
}

char ColumnMappingDialog::effectiveDelimiter() const {
  const auto chosen = static_cast<Delimiter>(delimiter_->currentData().toInt());
  if (chosen != Delimiter::kAuto) return delimiterChar(chosen);
  if (guess_) return delimiterChar(guess_->delimiter);
  if (lines_.empty()) return ',';
  // The reader could not lay the file out: the separator the header line uses most.
  const std::string& h = lines_.front();
  char best = 0;
  long most = 0;
  for (char c : {'\t', ';', ','}) {
    const long n = std::count(h.begin(), h.end(), c);
    if (n > most) {
      most = n;
      best = c;
    }
  }
  return best;
}

std::vector<QStringList> ColumnMappingDialog::splitLines() const {
  std::vector<QStringList> out;
  const char d = effectiveDelimiter();
  for (const auto& l : lines_) out.push_back(splitCells(l, d));
  return out;
}

void ColumnMappingDialog::fillPreview() {
  const auto cells = splitLines();
  const QStringList old = headers_;
  headers_ = cells.empty() ? QStringList{} : cells.front();
  int cols = static_cast<int>(headers_.size());
  for (const auto& c : cells) cols = std::max(cols, static_cast<int>(c.size()));
  preview_->clear();
  preview_->setColumnCount(cols);
  preview_->setRowCount(std::max(0, static_cast<int>(cells.size()) - 1));
  preview_->setHorizontalHeaderLabels(headers_);
  for (std::size_t i = 1; i < cells.size(); ++i)
    for (int k = 0; k < cells[i].size(); ++k)
      preview_->setItem(static_cast<int>(i) - 1, k, new QTableWidgetItem(cells[i][k]));
  preview_->resizeColumnsToContents();
  if (old == headers_ && rows_.front().column->count() > 0) return;
  // New columns: keep each choice by its header text where it still exists.
  for (Row& row : rows_) {
    const QString was = row.column->currentIndex() > 0 ? old.value(row.column->currentData().toInt()) : QString();
    row.column->clear();
    row.column->addItem(tr("(not in this file)"), -1);
    for (int k = 0; k < headers_.size(); ++k) row.column->addItem(QString("%1: %2").arg(k + 1).arg(headers_[k]), k);
    if (!was.isEmpty()) choose(row.channel, was);
  }
}

void ColumnMappingDialog::prefill(const std::optional<ColumnMapping>& start) {
  const auto select = [](QComboBox* c, auto value) {
    const int i = c->findData(static_cast<int>(value));
    if (i >= 0) c->setCurrentIndex(i);
  };
  if (start) {
    select(delimiter_, start->delimiter);
    select(decimal_, start->decimal);
    select(time_format_, start->time.format);
  }
  fillPreview();
  // 1. what the reader recognises by itself (alias table, units in the header)
  for (int k = 0; k < headers_.size(); ++k) {
    const HeaderField f = parseHeaderField(headers_[k].toStdString());
    const auto alias = findChannelAlias(f.key);
    if (!alias) continue;
    const Row* r = row(alias->channel);
    if (!r || r->column->currentIndex() > 0) continue;
    r->column->setCurrentIndex(k + 1);
    const std::string unit = !f.unit.empty() ? f.unit : std::string(alias->unit);
    r->unit->setText(q(unit.empty() && alias->channel != "time" ? std::string(canonicalUnitFor(alias->channel)) : unit));
  }
  // 2. the reader's full guess, then 3. a saved mapping: each overrides the one before.
  for (const std::optional<ColumnMapping>* m : {static_cast<const std::optional<ColumnMapping>*>(&guess_), &start}) {
    if (!*m) continue;
    const ColumnMapping& cm = **m;
    if (!cm.time.column.empty()) choose("time", q(cm.time.column));
    if (!cm.time.unit.empty()) row("time")->unit->setText(q(cm.time.unit));
    if (cm.time.utc_offset_hours) utc_offset_->setValue(*cm.time.utc_offset_hours);
    for (const ColumnRule& rule : cm.columns) {
      if (rule.ignore) {
        for (Row& r : rows_) {
          if (r.column->currentIndex() > 0 &&
              ColumnMapping::matches(rule.header, parseHeaderField(headers_.value(r.column->currentData().toInt()).toStdString())))
            r.column->setCurrentIndex(0);
        }
        continue;
      }
      const Row* r = row(rule.channel);
      if (!r) continue;
      for (int k = 0; k < headers_.size(); ++k) {
        if (ColumnMapping::matches(rule.header, parseHeaderField(headers_[k].toStdString()))) {
          r->column->setCurrentIndex(k + 1);
          if (!rule.unit.empty()) r->unit->setText(q(rule.unit));
          break;
        }
      }
    }
  }
}

const ColumnMappingDialog::Row* ColumnMappingDialog::row(const std::string& channel) const {
  for (const Row& r : rows_)
    if (r.channel == channel) return &r;
  return nullptr;
}

QComboBox* ColumnMappingDialog::columnCombo(const std::string& channel) const {
  const Row* r = row(channel);
  return r ? r->column : nullptr;
}
QLineEdit* ColumnMappingDialog::unitEdit(const std::string& channel) const {
  const Row* r = row(channel);
  return r ? r->unit : nullptr;
}
QLabel* ColumnMappingDialog::errorLabel(const std::string& channel) const {
  const Row* r = row(channel);
  return r ? r->error : nullptr;
}

bool ColumnMappingDialog::choose(const std::string& channel, const QString& header) {
  const Row* r = row(channel);
  if (!r) return false;
  for (int k = 0; k < headers_.size(); ++k) {
    if (headers_[k] == header || ColumnMapping::matches(header.toStdString(), parseHeaderField(headers_[k].toStdString()))) {
      r->column->setCurrentIndex(k + 1);
      return true;
    }
  }
  return false;
}

int ColumnMappingDialog::previewRows() const { return preview_->rowCount(); }

bool ColumnMappingDialog::saveForVehicle() const { return save_->isEnabled() && save_->isChecked(); }

ColumnMapping ColumnMappingDialog::mapping() const {
  ColumnMapping m;
  m.vehicle = vehicle_;
  m.description = "set in the import wizard for " + QFileInfo(file_).fileName().toStdString();
  m.delimiter = static_cast<Delimiter>(delimiter_->currentData().toInt());
  m.decimal = static_cast<DecimalMark>(decimal_->currentData().toInt());
  m.time.format = static_cast<TimeFormat>(time_format_->currentData().toInt());
  if (utc_offset_->value() > utc_offset_->minimum()) m.time.utc_offset_hours = utc_offset_->value();
  std::vector<bool> used(static_cast<std::size_t>(headers_.size()), false);
  for (const Row& r : rows_) {
    const int k = r.column->currentData().toInt();
    if (k < 0 || k >= headers_.size()) continue;
    used[static_cast<std::size_t>(k)] = true;
    const std::string header = headers_[k].toStdString();
    const std::string unit = r.unit->text().trimmed().toStdString();
    if (r.channel == "time") {
      m.time.column = header;
      m.time.unit = unit;
      continue;
    }
    ColumnRule rule;
    rule.header = header;
    rule.channel = r.channel;
    rule.unit = unit;
    m.columns.push_back(rule);
  }
  // A column the aliases would read as one of these quantities but that the
  // technician left unassigned must not come back through the alias table.
  for (int k = 0; k < headers_.size(); ++k) {
    if (used[static_cast<std::size_t>(k)]) continue;
    const auto alias = findChannelAlias(parseHeaderField(headers_[k].toStdString()).key);
    if (!alias || alias->channel == "date" || !row(alias->channel)) continue;
    ColumnRule rule;
    rule.header = headers_[k].toStdString();
    rule.ignore = true;
    m.columns.push_back(rule);
  }
  return m;
}

bool ColumnMappingDialog::validate() {
  for (Row& r : rows_) r.error->clear();
  general_error_->clear();
  bool ok = true;
  if (row("time")->column->currentIndex() <= 0) {
    row("time")->error->setText(tr("Choose the time column."));
    ok = false;
  }
  if (row("depth")->column->currentIndex() <= 0 && row("pressure")->column->currentIndex() <= 0) {
    row("depth")->error->setText(tr("Choose the depth column (or a pressure column below)."));
    ok = false;
  }
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (rows_[i].column->currentIndex() > 0 && rows_[i].column->currentIndex() == rows_[j].column->currentIndex()) {
        rows_[i].error->setText(tr("Already chosen for %1.").arg(q(rows_[j].channel)));
        ok = false;
      }
    }
  }
  if (!ok) return false;
  const ColumnMapping m = mapping();
  // Core's own checks (units it can convert, decimal comma with commas, names).
  try {
    ColumnMapping::fromJson(m.toJson(), "column mapping");
  } catch (const InputError& e) {
    const std::string what = e.what();
    std::smatch hit;
    if (std::regex_search(what, hit, std::regex(R"(columns\[(\d+)\])"))) {
      const std::size_t k = std::stoul(hit[1].str());
      if (k < m.columns.size())
        if (const Row* r = row(m.columns[k].channel)) {
          // The JSON path means nothing here: the row says which column.
          const std::size_t cut = what.find(": ", static_cast<std::size_t>(hit.position(0)));
          r->error->setText(q(cut == std::string::npos ? what : what.substr(cut + 2)));
          return false;
        }
    }
    if (what.find("time") != std::string::npos) row("time")->error->setText(q(what));
    else general_error_->setText(q(what));
    return false;
  }
  // And that it reads the rows shown.
  try {
    ReadReport scratch;
    parseDelimitedText(head_, file_.toStdString(), m, ReadOptions{}, scratch);
  } catch (const InputError& e) {
    general_error_->setText(tr("The first rows cannot be read with this mapping: %1").arg(q(e.what())));
    return false;
  }
  return true;
}

void ColumnMappingDialog::accept() {
  if (validate()) QDialog::accept();
}

}  // namespace auv::ui
