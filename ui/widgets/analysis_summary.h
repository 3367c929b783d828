#pragma once
// The analysis results as text (core/analysis): net buoyancy and CG offset
// with their sigmas, depth/pitch/roll errors with 95 % intervals and the
// water at operating depth in a grid above the deviation charts, and the
// warnings, why-nots and notes in a label of their own. The strings keep the
// deviation plots page's translation context, where their nb translations are.
#include <QCoreApplication>
#include <QString>

#include "analysis/analysis_report.h"

class QGridLayout;
class QLabel;

namespace auv::ui {

class AnalysisSummary {
  Q_DECLARE_TR_FUNCTIONS(auv::ui::DeviationPlotsPage)

 public:
  // Creates the labels (object names net_buoyancy, cg_offset, errors, water,
  // analysis_notes) unparented: the page lays out grid() and notes().
  AnalysisSummary();
  QGridLayout* grid() const { return grid_; }
  QLabel* notes() const { return notes_; }

  // `report` null: says `error` in red instead. A glider's net buoyancy is
  // shown to the gram and gets the whole width. `source`: which estimate the
  // plan uses, in words (label plan_estimate_source). A quantity not identified
  // reads "not known", never ± 0.
  void show(const analysis::AnalysisReport* report, bool glider, const QString& error,
            const QString& source = QString());
  // No result yet (the analysis is running): `note` in plain words.
  void showPending(const QString& note);

 private:
  QGridLayout* grid_;
  QLabel* net_;
  QLabel* cg_;
  QLabel* errors_;
  QLabel* water_;
  QLabel* source_;
  QLabel* notes_;
};

}  // namespace auv::ui
