// The printed work order with the top-down weight map (issue 14 item 10):
// the first mission gets the same one-page PDF as the pre-mission summary,
// for a HUGIN crane weighing and a Slocum tank session; the numbers on the
// page are core's report for the same weighing, computed here; the map's
// labels reach the paint engine and its green/red squares the image; the
// page never runs into the bottom margin. Also: the pinned fonts (only
// Debian's DejaVu folder is visible, italic is a real oblique face) and
// `auvballast-gui --render-pages` (every demo page saved as an image).
#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QFontDatabase>
#include <QFontInfo>
#include <QImage>
#include <QLabel>
#include <QPainter>

#include "firstmission/hugin_first_mission.h"
#include "firstmission/slocum_first_mission.h"
#include "pages/first_mission_result_page.h"
#include "pre_mission_fixture.h"
#include "screenshot.h"
#include "ui_fixture.h"
#include "widgets/inputs.h"
#include "wizard/advice_text.h"
#include "wizard/demo_state.h"
#include "wizard/operator_wizard.h"
#include "wizard/page_renderer.h"
#include "wizard/point_labels.h"
#include "wizard/pinned_fonts.h"
#include "wizard/work_order.h"

namespace auv::ui {
using auv::testing::colourFraction;
using auv::testing::find;

namespace {

QString drawnText(const WorkOrder& order) {
  auv::testing::TextRecorder rec(QSize(794, 1123), 96);
  {
    QPainter p(&rec);
    drawWorkOrder(p, rec, order);
  }
  return rec.joined();
}

// Rows of the image (96 dpi) below the page's 15 mm bottom margin that hold
// anything but white: text or map that ran off the page.
double inkBelowTheMargin(const QImage& img) {
  const int margin_px = static_cast<int>(15 * 96 / 25.4) - 2;
  return 1.0 - colourFraction(img.copy(0, img.height() - margin_px, img.width(), margin_px), Qt::white, 8);
}

// The map's squares: kit pieces to add (green) and to remove (red), in the
// colours of weight_map_widget.cpp, as a fraction of the page.
double green(const QImage& img) { return colourFraction(img, QColor(46, 160, 67), 12); }
double red(const QImage& img) { return colourFraction(img, QColor(210, 50, 50), 12); }

}  // namespace

class WorkOrders : public auv::testing::UiTest {};

TEST_F(WorkOrders, OnlyDebiansDejaVuFontsAreVisibleAndItalicIsARealObliqueFace) {
  // Whatever else is installed (URW, Noto, Droid fallbacks on a development
  // machine), the rendering sees DejaVu only, so goldens match a fresh Debian.
  const QStringList families = QFontDatabase::families();
  ASSERT_FALSE(families.isEmpty());
  for (const QString& f : families) {  // Qt's generic names map onto DejaVu too
    if (f == "Sans Serif" || f == "Serif" || f == "Monospace") continue;
    EXPECT_TRUE(f.startsWith("DejaVu")) << f.toStdString();
  }
  EXPECT_EQ(QFontInfo(QFontDatabase::systemFont(QFontDatabase::FixedFont)).family(), "DejaVu Sans Mono");
  // fonts-dejavu-extra: without it italic page text is a slanted regular
  // face (the 415 px difference of issue 14 on a fresh machine).
  EXPECT_TRUE(QFontDatabase::styles("DejaVu Sans").contains("Oblique")) << QFontDatabase::styles("DejaVu Sans").join(", ").toStdString();
  QFont italic("DejaVu Sans", 10);
  italic.setItalic(true);
  EXPECT_EQ(QFontInfo(italic).styleName(), "Oblique");
  EXPECT_EQ(QFontInfo(italic).family(), "DejaVu Sans");
  QFont bold("DejaVu Sans", 10);
  bold.setBold(true);
  EXPECT_EQ(QFontInfo(bold).styleName(), "Bold");
  EXPECT_EQ(qgetenv("FONTCONFIG_FILE").endsWith("fonts.conf"), true);
}

TEST_F(WorkOrders, HuginFirstMissionWorkOrderHasTheWeighingsChangesAndTheMap) {
  WizardState s = makeDemoState(AUV_RESOURCE_DIR);
  EXPECT_THROW(makeFirstMissionWorkOrder(s, fixedNow()), InputError);  // nothing computed yet
  // The oracle: core's report for the same weighing, computed here.
  const FirstMissionReport r = craneFirstMission(*s.vehicle, s.crane);
  s.report = r;
  const WorkOrder order = makeFirstMissionWorkOrder(s, fixedNow());
  const QString drawn = drawnText(order);
  for (const QString& t : {QString("Ballast work order: first mission"), QString("HUGIN 1000"), QString("01-02-03"),
                           QString("2026-05-20 12:00:00 UTC"), QString("From: the crane weighing"),
                           QString("Where (top view, bow to the right)"), QString("Signature")}) {
    EXPECT_NE(drawn.indexOf(t), -1) << t.toStdString() << "\n" << drawn.toStdString();
  }
  ASSERT_EQ(r.points.size(), 4u);
  ASSERT_EQ(s.crane.installed_kg.size(), 4u);
  int changed = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    const double now = s.crane.installed_kg[i], after = now + r.points[i].add_kg;
    // The table row (installed now, the change, after) and the map label
    // "<point>: <change> (<now> → <after>)" with one decimal.
    EXPECT_NE(drawn.indexOf(massText(after, false)), -1) << i;
    EXPECT_NE(drawn.indexOf(massText(r.points[i].add_kg, false, true)), -1) << i;
    const QString label = QString("%1: %2 (%3 → %4)")
                              .arg(QString::fromStdString(r.points[i].label), massText(r.points[i].add_kg, false, true))
                              .arg(now, 0, 'f', 1)
                              .arg(after, 0, 'f', 1);
    EXPECT_NE(drawn.indexOf(label), -1) << label.toStdString() << "\n" << drawn.toStdString();
    changed += std::abs(r.points[i].add_kg) > 1e-6;
  }
  ASSERT_GT(changed, 0) << "the demo weighing must ask for a change, else the map shows no squares";
  EXPECT_NE(drawn.indexOf(QString("Net buoyancy %1 kg").arg(signedFixed(r.predicted.net_buoyancy_kg, 2))), -1);
  EXPECT_NE(drawn.indexOf(QString("Weighed %1 kg").arg(fixed(r.weight_kg, 1))), -1);
  EXPECT_NE(drawn.indexOf(QString("density %1 kg/m³").arg(r.density_kgm3, 0, 'f', 2)), -1);
  // In the wizard's words (the start: a long warning wraps).
  for (const auto& w : r.warnings) EXPECT_NE(drawn.indexOf(adviceText(w).left(40)), -1) << w;

  const QImage img = renderWorkOrder(order, 96);
  ASSERT_EQ(img.size(), QSize(794, 1123));
  img.save(QString(AUV_SCREENSHOT_DIR) + "/54_first_mission_work_order.png");
  const QString problem = auv::testing::checkGolden(img, "54_first_mission_work_order");
  EXPECT_TRUE(problem.isEmpty()) << problem.toStdString();
  EXPECT_GT(green(img) + red(img), 2e-4) << "no pieces drawn on the map";
  EXPECT_EQ(inkBelowTheMargin(img), 0.0);
  const QString pdf = path("first_mission.pdf");
  EXPECT_EQ(writeWorkOrderPdf(order, pdf), "");
  EXPECT_GT(QFile(pdf).size(), 1024);
}

TEST_F(WorkOrders, SlocumFirstMissionWorkOrderKeepsEveryStepOnOnePage) {
  WizardState s = makeSlocumDemoState(AUV_RESOURCE_DIR);
  const FirstMissionReport r = slocumFirstMission(*s.vehicle, s.tank);
  s.report = r;
  const WorkOrder order = makeFirstMissionWorkOrder(s, fixedNow());
  const QString drawn = drawnText(order);
  EXPECT_NE(drawn.indexOf("From: the tank weighing"), -1);
  // Grams for a glider, as on the result page: "+0.8 g", not "+0.001 kg".
  EXPECT_NE(drawn.indexOf(QString("Net buoyancy %1 g").arg(signedFixed(r.predicted.net_buoyancy_kg * 1000.0, 1))), -1)
      << drawn.toStdString();
  EXPECT_NE(drawn.indexOf(QString("net buoyancy %1 g before").arg(signedFixed(r.net_buoyancy_kg * 1000.0, 1))), -1);
  // Installed "ballast now" in grams per point, as core reports it.
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const double now_g = r.details["ballast_now_g"].value(s.vehicle->points[i].name, 0.0);
    EXPECT_NE(drawn.indexOf(massText(now_g / 1000.0 + r.points[i].add_kg, true)), -1) << r.points[i].label;
  }
  // The battery, rail and disk steps are the glider's work: all on the page
  // (wrapped text reaches the engine line by line, so look for its start).
  ASSERT_FALSE(r.notes.empty());
  QString flat = drawn;
  flat.replace('\n', ' ');
  // In the wizard's words, with the points' labels for their ids.
  for (const auto& n : r.notes) {
    const QString shown = withPointLabels(adviceText(n), *s.vehicle).left(25);
    EXPECT_NE(flat.indexOf(shown), -1) << shown.toStdString();
  }
  EXPECT_EQ(flat.indexOf("fore_port"), -1) << "point ids on the work order";
  const QImage img = renderWorkOrder(order, 96);
  img.save(QString(AUV_SCREENSHOT_DIR) + "/55_slocum_work_order.png");
  const QString problem = auv::testing::checkGolden(img, "55_slocum_work_order");
  EXPECT_TRUE(problem.isEmpty()) << problem.toStdString();
  EXPECT_EQ(inkBelowTheMargin(img), 0.0) << "the notes ran off the page";
  EXPECT_GT(green(img) + red(img), 1e-4);
}

TEST_F(WorkOrders, FirstMissionResultPageExportsItsWorkOrder) {
  OperatorWizard wiz(makeDemoState(AUV_RESOURCE_DIR));
  wiz.setClock(fixedNow);
  wiz.resize(1000, 760);
  wiz.show();
  for (int i = 0; i < 4; ++i) wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kFirstMissionResult);
  auto* page = qobject_cast<FirstMissionResultPage*>(wiz.currentPage());
  ASSERT_NE(page, nullptr);
  EXPECT_TRUE(find<QAbstractButton>(wiz, "export_work_order")->isVisible());
  const QString pdf = path("order.pdf");
  EXPECT_EQ(page->exportPdf(pdf), "");
  EXPECT_GT(QFile(pdf).size(), 1024);
  EXPECT_NE(find<QLabel>(wiz, "work_order_status")->text().indexOf("Work order written to"), -1);
  EXPECT_NE(page->exportPdf(path("no/such/folder/order.pdf")), "");
  EXPECT_NE(find<QLabel>(wiz, "work_order_status")->text().indexOf("Not exported"), -1);
}

TEST_F(WorkOrders, RenderPagesSavesEveryDemoPageAndTheWorkOrders) {
  const QString out = path("wizard");
  const RenderedPages r = renderDemoPages(AUV_RESOURCE_DIR, out, path("scratch"), fixedNow());
  EXPECT_EQ(r.error, "");
  // HUGIN: 5 pages, Slocum: 5, post to pre mission: 7, glider post to pre
  // mission: 3; 4 work orders as PNG and PDF.
  EXPECT_EQ(r.files.size(), 28) << r.files.join("\n").toStdString();
  for (const QString& f : r.files) {
    ASSERT_TRUE(QFileInfo::exists(f)) << f.toStdString();
    if (!f.endsWith(".png")) continue;
    const QImage img(f);
    // Wizard pages are 1000 px wide; the Slocum result page with its
    // installed-now fields and export row needs 788 px of height (issue 14
    // note: make that page scroll on 768 px screens). Work orders are A4.
    const bool page = img.width() == 1000 && img.height() >= 760 && img.height() <= 800;
    EXPECT_TRUE(page || img.size() == QSize(794, 1123)) << f.toStdString() << " " << img.width() << "x" << img.height();
    EXPECT_LT(colourFraction(img, img.pixelColor(0, 0), 4), 0.97) << f.toStdString() << " is blank";
  }
  for (const char* name : {"05_first_mission_result.png", "14_slocum_result.png", "22_deviation_plots.png",
                           "26_summary.png", "27_work_order.pdf", "32_glider_ballast.png", "33_glider_work_order.pdf"}) {
    EXPECT_TRUE(r.files.contains(out + "/" + name)) << name;
  }
}

}  // namespace auv::ui
