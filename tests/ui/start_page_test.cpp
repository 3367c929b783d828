// The start page against a history prepared with known dates: recent list,
// search, last state, the one-month temperature rule, and what a picked
// configuration carries into the session.
#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QRadioButton>
#include <QTableWidget>

#include "history/store.h"
#include "pages/start_page.h"
#include "screenshot.h"
#include "ui_fixture.h"
#include "wizard/demo_state.h"
#include "wizard/operator_wizard.h"

namespace auv::ui {
using auv::testing::find;
using auv::testing::shot;

class StartPageTest : public auv::testing::UiTest {
 protected:
  void SetUp() override {
    UiTest::SetUp();
    HistoryStore store(path("history.sqlite").toStdString());
    auto config = [&](const char* id, const char* vehicle, const char* name, const char* payload, const char* area,
                      TimePoint created) {
      Configuration c;
      c.config_id = id;
      c.vehicle_key = vehicle;
      c.vehicle_name = name;
      c.payload_note = payload;
      c.area = area;
      c.water_type = "fjord";
      c.created_at = created;
      store.addConfiguration(c);
    };
    auto water = [&](const char* id, TimePoint at, double t) {
      WaterCondition w;
      w.measured_at = at;
      w.temperature_degC = t;
      w.salinity_psu = 34.0;
      w.source = "ctd";
      store.addWaterCondition(id, w);
    };
    config("01-02-03", "hugin1000", "HUGIN 1000", "multibeam + SAS", "Horten", makeUtc(2026, 3, 1));
    // 48 days before "now" (2026-05-20 12:00): older than one month.
    water("01-02-03", makeUtc(2026, 4, 2, 12, 0, 0), 6.5);
    InstalledState inst;
    inst.installed_at = makeUtc(2026, 4, 3, 9, 0, 0);
    inst.points = {{"fore_starboard", 14.4, {4.8, 4.8, 4.8}}, {"fore_port", 14.4, {}},
                   {"aft_starboard", 19.2, {}}, {"aft_port", 19.2, {}}};
    store.addInstalledState("01-02-03", inst);
    config("02-01-01", "slocum_g2", "Slocum G2", "CTD only", "Bedford Basin", makeUtc(2026, 4, 1));
    water("02-01-01", makeUtc(2026, 5, 10, 8, 0, 0), 3.5);  // 10 days: fine
    // Exactly one calendar month old (2026-04-20 12:00 -> 2026-05-20 12:00): may still be reused.
    config("03-01-01", "delphin2", "Delphin2", "sonar", "Solent", makeUtc(2026, 1, 5));
    water("03-01-01", makeUtc(2026, 4, 20, 12, 0, 0), 12.0);
    // One second more: stale.
    config("04-01-01", "delphin2", "Delphin2", "camera", "Solent", makeUtc(2026, 1, 6));
    water("04-01-01", makeUtc(2026, 4, 20, 11, 59, 59), 12.0);
  }

  static int rowOf(QTableWidget* t, const QString& id) {
    for (int r = 0; r < t->rowCount(); ++r)
      if (t->item(r, 0) && t->item(r, 0)->text() == id) return r;
    return -1;
  }
};

TEST_F(StartPageTest, ListsRecentConfigurationsAndTheirLastState) {
  OperatorWizard wiz(makeEmptyState(AUV_RESOURCE_DIR));
  wiz.setClock(fixedNow);
  wiz.resize(1000, 760);
  wiz.show();
  auto* table = find<QTableWidget>(wiz, "configurations");
  ASSERT_EQ(table->rowCount(), 5);  // new + 4
  // Newest activity first: 02-01-01 (water 2026-05-10) heads the list.
  EXPECT_EQ(table->item(1, 0)->text(), "02-01-01");
  EXPECT_EQ(table->item(1, 4)->text(), "2026-05-10");
  // A new configuration may only do a first mission.
  EXPECT_FALSE(find<QRadioButton>(wiz, "mode_post")->isEnabled());
  EXPECT_FALSE(find<QRadioButton>(wiz, "mode_pre")->isEnabled());

  table->selectRow(rowOf(table, "01-02-03"));
  shot(wiz, "00_start_history");
  const QString st = find<QLabel>(wiz, "last_state")->text();
  EXPECT_NE(st.indexOf("Fore / starboard 14.4 kg"), -1) << st.toStdString();
  EXPECT_NE(st.indexOf("Aft / port 19.2 kg"), -1);
  EXPECT_NE(st.indexOf("Last mission: none yet."), -1);
  const QString temp = find<QLabel>(wiz, "temperature_age")->text();
  EXPECT_NE(temp.indexOf("6.5 °C measured 2026-04-02 (48 days ago)"), -1) << temp.toStdString();
  EXPECT_NE(temp.indexOf("older than one month"), -1);
  EXPECT_TRUE(find<QRadioButton>(wiz, "mode_post")->isEnabled());

  table->selectRow(rowOf(table, "02-01-01"));
  EXPECT_NE(find<QLabel>(wiz, "temperature_age")->text().indexOf("10 days ago): less than a month old"), -1);
  EXPECT_NE(find<QLabel>(wiz, "last_state")->text().indexOf("Installed: nothing recorded yet."), -1);
}

TEST_F(StartPageTest, OneMonthRuleAtItsBoundary) {
  OperatorWizard wiz(makeEmptyState(AUV_RESOURCE_DIR));
  wiz.setClock(fixedNow);
  wiz.show();
  auto* table = find<QTableWidget>(wiz, "configurations");
  table->selectRow(rowOf(table, "03-01-01"));  // exactly one month
  EXPECT_NE(find<QLabel>(wiz, "temperature_age")->text().indexOf("can be reused"), -1)
      << find<QLabel>(wiz, "temperature_age")->text().toStdString();
  table->selectRow(rowOf(table, "04-01-01"));  // one month and one second
  EXPECT_NE(find<QLabel>(wiz, "temperature_age")->text().indexOf("older than one month"), -1);
}

TEST_F(StartPageTest, SearchFindsByVehicleAreaAndId) {
  OperatorWizard wiz(makeEmptyState(AUV_RESOURCE_DIR));
  wiz.setClock(fixedNow);
  wiz.show();
  auto* table = find<QTableWidget>(wiz, "configurations");
  auto* search = find<QLineEdit>(wiz, "search");
  search->setText("slocum");
  ASSERT_EQ(table->rowCount(), 2);
  EXPECT_EQ(table->item(1, 0)->text(), "02-01-01");
  search->setText("SOLENT");  // case-insensitive, by area
  EXPECT_EQ(table->rowCount(), 3);
  search->setText("01-02");
  ASSERT_EQ(table->rowCount(), 2);
  EXPECT_EQ(table->item(1, 0)->text(), "01-02-03");
  search->setText("nothing like this");
  EXPECT_EQ(table->rowCount(), 1);
  search->clear();
  EXPECT_EQ(table->rowCount(), 5);
}

TEST_F(StartPageTest, PickedConfigurationFixesIdentityAndCarriesInstalledPieces) {
  OperatorWizard wiz(makeEmptyState(AUV_RESOURCE_DIR));
  wiz.setClock(fixedNow);
  wiz.show();
  auto* table = find<QTableWidget>(wiz, "configurations");
  table->selectRow(rowOf(table, "01-02-03"));
  wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kVehicle);
  EXPECT_EQ(find<QLineEdit>(wiz, "configuration")->text(), "01-02-03");
  EXPECT_TRUE(find<QLineEdit>(wiz, "configuration")->isReadOnly());
  EXPECT_FALSE(find<QComboBox>(wiz, "vehicle")->isEnabled());
  EXPECT_EQ(find<QComboBox>(wiz, "vehicle")->currentData().toString(), "hugin1000");
  const auto& s = wiz.state();
  ASSERT_EQ(s.crane.installed_kg.size(), 4u);
  EXPECT_DOUBLE_EQ(s.crane.installed_kg[0], 14.4);
  EXPECT_DOUBLE_EQ(s.crane.installed_kg[3], 19.2);
  // The 48-day-old temperature is not carried over (thesis §5.5.3).
  EXPECT_DOUBLE_EQ(s.crane.water.temperature_degC, 10.0);
  wiz.next();
  EXPECT_EQ(wiz.currentId(), OperatorWizard::kCraneWeighing);

  // A fresh temperature is carried over.
  wiz.back();
  wiz.back();
  table->selectRow(rowOf(table, "02-01-01"));
  wiz.next();
  EXPECT_EQ(find<QComboBox>(wiz, "vehicle")->currentData().toString(), "slocum_g2");
  EXPECT_DOUBLE_EQ(wiz.state().crane.water.temperature_degC, 3.5);
}

TEST_F(StartPageTest, NewConfigurationMustNotReuseAnId) {
  WizardState s = makeDemoState(AUV_RESOURCE_DIR);  // its ID 01-02-03 is in the history already
  OperatorWizard wiz(s);
  wiz.setClock(fixedNow);
  wiz.show();
  wiz.next();
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kVehicle);
  wiz.next();
  EXPECT_EQ(wiz.currentId(), OperatorWizard::kVehicle);
  EXPECT_NE(find<QLabel>(*wiz.currentPage(), "error")->text().indexOf("already in the history"), -1);
  find<QLineEdit>(wiz, "configuration")->setText("not an id");
  wiz.next();
  EXPECT_EQ(wiz.currentId(), OperatorWizard::kVehicle);
  EXPECT_NE(find<QLabel>(*wiz.currentPage(), "error")->text().indexOf("configuration ID"), -1);
  find<QLineEdit>(wiz, "configuration")->setText("01-02-09");
  wiz.next();
  EXPECT_EQ(wiz.currentId(), OperatorWizard::kCraneWeighing);
}

}  // namespace auv::ui
