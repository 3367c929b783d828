#pragma once
// `auvballast-gui --demo --render-pages DIR`: walks the wizard through the
// three demo sessions (HUGIN crane weighing, Slocum tank weighing, post
// mission on the simulated survey and on to the next mission's plan) exactly
// as the Next button does, and saves every page as DIR/<nn>_<page>.png, plus
// each work order as PNG and PDF, so a newcomer without a display sees the
// program (scripts/run-example.sh).
#include <QString>
#include <QStringList>

#include "history/timestamp.h"

namespace auv::ui {

struct RenderedPages {
  QStringList files;  // written, in page order
  QString error;      // empty when every page rendered
};

// Needs a QApplication (offscreen is fine; pinned_fonts.h for stable
// images). The demo histories go into `scratch_dir`, never the user's.
RenderedPages renderDemoPages(const std::string& resource_dir, const QString& out_dir, const QString& scratch_dir,
                              TimePoint now);

}  // namespace auv::ui
