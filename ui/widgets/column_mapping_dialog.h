#pragma once
// "Which column is which?" for a vendor text log the reader cannot map on its
// own (no recognised time column, headers in another language, a depth under
// a name no alias knows). Shows the first rows of the file, one combo per
// channel the analysis uses, pre-filled with what the reader guesses
// (suggestColumnMapping, else the alias table), the unit of each, and
// "save this mapping for this vehicle". The result is a core ColumnMapping
// (docs/formats/column-mapping.md); accept() refuses one that core would
// refuse or that cannot read the file's first rows, with the reason next to
// the field.
#include <QDialog>
#include <optional>
#include <string>
#include <vector>

#include "missionlog/column_mapping.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QTableWidget;

namespace auv::ui {

class NumberInput;

class ColumnMappingDialog : public QDialog {
  Q_OBJECT
 public:
  // `start`: a saved mapping to begin from (its choices win over the guess).
  ColumnMappingDialog(const QString& file, const std::string& vehicle_id, const std::optional<ColumnMapping>& start,
                      QWidget* parent = nullptr);

  // Channels offered, in display order ("time" first).
  static std::vector<std::string> channelNames();
  QComboBox* columnCombo(const std::string& channel) const;  // item data = header index, -1 = not in the file
  QLineEdit* unitEdit(const std::string& channel) const;
  QLabel* errorLabel(const std::string& channel) const;
  // Selects a header column by its text for a channel; false if the file has no such column.
  bool choose(const std::string& channel, const QString& header);
  QStringList headers() const { return headers_; }
  int previewRows() const;
  bool saveForVehicle() const;
  // What the widgets say now, as a mapping (not validated).
  ColumnMapping mapping() const;
  // The reader's own guess could not be made (e.g. no time column): why.
  QString guessProblem() const { return guess_problem_; }

  void accept() override;

 private:
  struct Row {
    std::string channel;
    QComboBox* column = nullptr;
    QLineEdit* unit = nullptr;
    QLabel* error = nullptr;
  };
  void readHead();
  void fillPreview();
  void prefill(const std::optional<ColumnMapping>& start);
  std::vector<QStringList> splitLines() const;
  char effectiveDelimiter() const;  // ',', ';', '\t' or 0 = blanks
  const Row* row(const std::string& channel) const;
  bool validate();

  QString file_;
  std::string vehicle_;
  std::string head_;       // the first bytes of the file, cut at the last line end
  std::vector<std::string> lines_;  // non-blank, non-comment lines of head_
  std::optional<ColumnMapping> guess_;
  QString guess_problem_;
  QStringList headers_;
  QComboBox* delimiter_;
  QComboBox* decimal_;
  QComboBox* time_format_;
  NumberInput* utc_offset_;  // minimum = not stated (UTC assumed)
  QTableWidget* preview_;
  std::vector<Row> rows_;
  QCheckBox* save_;
  QLabel* general_error_;
};

}  // namespace auv::ui
