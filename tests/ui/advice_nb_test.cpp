// Issue 14 item 7: the computed advice (core's notes, warnings and
// explanations, as message ids with arguments) is shown in the wizard's own
// words and, under Norwegian, in Norwegian: complete for every id, and on
// the analysis, model-check and adjustment pages of the post-mission demo
// no English advice sentence remains.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QLabel>
#include <QRegularExpression>
#include <set>

#include "analysis/analysis_messages.h"
#include "ballast/ballast_messages.h"
#include "firstmission/first_mission_messages.h"
#include "weighing/weighing_messages.h"
#include "history/store.h"
#include "widgets/inputs.h"
#include "page_walk.h"
#include "planning/planning_messages.h"
#include "ui_fixture.h"
#include "wizard/advice_text.h"
#include "wizard/demo_state.h"
#include "wizard/model_words.h"
#include "wizard/translations.h"

namespace auv::ui {
using auv::testing::find;

namespace {

// The %n a sentence uses.
std::set<int> placeholders(const QString& s) {
  std::set<int> out;
  static const QRegularExpression re("%(\\d+)");
  for (auto it = re.globalMatch(s); it.hasNext();) out.insert(it.next().captured(1).toInt());
  return out;
}

std::vector<const MessageFormat*> coreFormats() {
  std::vector<const MessageFormat*> all(std::begin(analysis::msg::kAll), std::end(analysis::msg::kAll));
  all.insert(all.end(), std::begin(planning::msg::kAll), std::end(planning::msg::kAll));
  all.insert(all.end(), std::begin(ballast::msg::kAll), std::end(ballast::msg::kAll));
  all.insert(all.end(), std::begin(firstmission::msg::kAll), std::end(firstmission::msg::kAll));
  all.insert(all.end(), std::begin(weighing::msg::kAll), std::end(weighing::msg::kAll));
  return all;
}

// Restores English whatever a test does.
struct Norwegian {
  Norwegian() { ok = installTranslation(QLocale(QLocale::NorwegianBokmal)); }
  ~Norwegian() { removeTranslation(); }
  bool ok = false;
};

}  // namespace

TEST(Advice, EveryCoreMessageHasAWizardSentenceWithoutInternalWords) {
  const QStringList ids = adviceIds();
  for (const MessageFormat* f : coreFormats()) {
    const QString id = QString::fromLatin1(f->id);
    ASSERT_TRUE(ids.contains(id)) << f->id << ": no wizard sentence";
    const QString mine = adviceSource(id);
    // The wizard may leave out an argument the page shows elsewhere, never use one core does not give.
    for (int n : placeholders(mine)) EXPECT_LE(n, messageArgCount(f->english)) << f->id;
    EXPECT_EQ(auv::testing::internalWordsIn(mine), QStringList()) << f->id << ": " << mine.toStdString();
  }
}

TEST(Advice, NorwegianIsCompleteForEveryId) {
  Norwegian nb;
  ASSERT_TRUE(nb.ok);
  for (const QString& id : adviceIds()) {
    const QByteArray src = adviceSource(id).toUtf8();
    const QString t = QCoreApplication::translate("Advice", src.constData());
    EXPECT_NE(t, adviceSource(id)) << id.toStdString() << " has no Norwegian";
    EXPECT_EQ(placeholders(t), placeholders(adviceSource(id))) << id.toStdString() << ": " << t.toStdString();
  }
  // A message as core builds it comes out Norwegian with its numbers (Norwegian decimal comma).
  const Message m(analysis::msg::kCgYNeedsBg, {"+9.90"});
  EXPECT_EQ(adviceText(m).toStdString(),
            "Kan ikke bestemmes fra denne loggen: en stødig rull gir y = BG tan(rull), og BG (tyngdepunktets høyde under "
            "oppdriftssenteret) kan ikke måles fra loggen. Legg inn BG fra en krengeprøve eller rulletest for denne "
            "konfigurasjonen (statisk rull +9,90°).");
  // Sentences the wizard builds in pieces: Norwegian in every piece.
  const Message band("ballast.band_unreachable", "pitch band ...",
                     {"pitch", "0.50°", "", "+0.64°", "piece", "0.6 kg", "", "2.0", "-0.31", "inside"});
  EXPECT_EQ(adviceText(band).toStdString(),
            "Stampbåndet ±0,50° kan ikke nås med dette vektsettet (i ro); beste er +0,64°; i planflyging ved 2,0 m/s "
            "stamper det -0,31°, innenfor båndet; et lodd på 0,6 kg ville nådd det.");
  for (const char* kind : {"out_of_reach", "none_tried", "none_tried_undecided"}) {
    const Message other("ballast.band_unreachable", "...", {"roll", "0.10°", "", "-0.63°", kind, "0.6 kg", "pitch_ok"});
    const QString s = adviceText(other);
    EXPECT_TRUE(s.startsWith("Rullbåndet ±0,10° kan ikke nås med dette vektsettet mens stampen")) << s.toStdString();
    EXPECT_EQ(s.indexOf(" would "), -1) << s.toStdString();
  }
  const Message point("plan.explain_point", "...",
                      {"Aft / port", "", "1 × 4.8 kg and 1 × 1.2 kg", "+6.00 kg", "6.00 kg", "-1.32", "-1.25", "lowers", "x", "back"});
  EXPECT_EQ(adviceText(point).toStdString(),
            "Aft / port: legg til 1 × 4,8 kg og 1 × 1,2 kg (+6,00 kg), som senker netto oppdrift med 6,00 kg og flytter "
            "tyngdepunktet 1,32 mm akterover og 1,25 mm mot babord, som flytter tyngdepunktet tilbake mot "
            "oppdriftssenteret forut-akter.");
  // The CLI keeps its English, word for word.
  EXPECT_EQ(m, "not identifiable from this log because a steady roll gives y = BG tan(roll) and BG (the CG height below "
               "the CB) cannot be measured from the log: give --bg-mm from an inclining or roll test (static roll "
               "+9.90 deg)");
}

// Numbers on pages follow the wizard's language (issue 14: "1025,4" typed
// under nb must not come back as "1025.4" beside it), never with group
// separators, and go back to the start locale with English.
TEST(Advice, NumbersFollowTheWizardLanguage) {
  {
    Norwegian nb;
    ASSERT_TRUE(nb.ok);
    EXPECT_EQ(fixed(1025.4, 1).toStdString(), "1025,4");
    EXPECT_EQ(signedFixed(0.004, 2).toStdString(), "0,00");
    EXPECT_EQ(signedFixed(1565.25, 2).toStdString(), "+1565,25");
    EXPECT_EQ(massText(52.2, false).toStdString(), "52,2 kg");
    EXPECT_TRUE(significant(4.797e-6, 4).startsWith("4,797")) << significant(4.797e-6, 4).toStdString();
  }
  EXPECT_EQ(fixed(1565.2, 1).toStdString(), QLocale().toString(1565.2, 'f', 1).remove(QLocale().groupSeparator()).toStdString());
  EXPECT_EQ(fixed(-0.001, 2).toStdString(), fixed(0.0, 2).toStdString()) << "never -0.00";
}

// Masses of kit pieces and installed weights with the decimals they need:
// Delphin2's 0.05 kg piece read "0.1 kg" and its optional 0.02 kg piece
// "0.0 kg" (seen in the real program under Xvfb).
TEST(Advice, MassesKeepTheDecimalsTheyNeed) {
  EXPECT_EQ(massText(0.05, false), fixed(0.05, 2) + " kg");
  EXPECT_EQ(massText(0.02, false), fixed(0.02, 2) + " kg");
  EXPECT_EQ(massText(24.05, false, true), "+" + fixed(24.05, 2) + " kg");
  EXPECT_EQ(massText(25.2, false), fixed(25.2, 1) + " kg");
  EXPECT_EQ(massText(1.0, false), fixed(1.0, 1) + " kg");
  EXPECT_EQ(massText(-1.2, false, true), fixed(-1.2, 1) + " kg");
  EXPECT_EQ(massText(0.1234, false), fixed(0.123, 3) + " kg");  // at most grams
  EXPECT_EQ(massText(0.0004, true), "0 g");
}

// The post-mission demo under Norwegian: the analysis notes and the
// adjustment page's warnings and explanations are Norwegian; none of core's
// English sentences and none of the wizard's English ones is left.
class AdviceNorwegian : public auv::testing::UiTest {};

TEST_F(AdviceNorwegian, AnalysisAndAdjustmentPagesHaveNoEnglishAdvice) {
  Norwegian nb;
  ASSERT_TRUE(nb.ok);
  {
    HistoryStore store(path("history.sqlite").toStdString());
    seedDemoHistory(store, AUV_RESOURCE_DIR, makeUtc(2026, 5, 10, 9, 0, 0));
  }
  OperatorWizard wiz(makePostMissionDemoState(AUV_RESOURCE_DIR, path("survey.csv").toStdString()));
  wiz.setClock(fixedNow);
  wiz.setAutosaveEnabled(false);
  wiz.resize(1000, 760);
  wiz.show();
  // English versions of every message shown: core's and the wizard's own.
  auto english = [](const Message& m) {
    QStringList e{QString::fromStdString(m)};
    if (!adviceSource(QString::fromStdString(m.id())).isEmpty()) {
      removeTranslation();
      e << adviceText(m);
      installTranslation(QLocale(QLocale::NorwegianBokmal));
    }
    return e;
  };
  auto checkNoEnglish = [&](const QString& shown, const std::vector<Message>& msgs, const char* where) {
    int translated = 0;
    for (const Message& m : msgs) {
      EXPECT_FALSE(m.id().empty()) << where << ": advice without an id: " << m;
      for (const QString& e : english(m))
        EXPECT_EQ(shown.indexOf(e.toHtmlEscaped()), -1) << where << ": English left: " << e.toStdString();
      const QString nbText = adviceText(m);
      EXPECT_NE(shown.indexOf(nbText.toHtmlEscaped()), -1) << where << ": not shown: " << nbText.toStdString();
      translated += !m.id().empty();
    }
    return translated;
  };
  int pages = 0;
  bool saw_check = false;
  while (wiz.currentId() != OperatorWizard::kSummary && pages++ < 12) {
    auv::testing::settlePage(wiz);
    if (wiz.currentId() == OperatorWizard::kDeviationPlots) {
      ASSERT_TRUE(wiz.state().analysis.has_value());
      const auto& r = *wiz.state().analysis;
      std::vector<Message> msgs = r.notes;
      msgs.insert(msgs.end(), r.warnings.begin(), r.warnings.end());
      for (const auto* e : {&r.net_buoyancy_kg, &r.cg_x_mm, &r.cg_y_mm})
        if (!e->known && !e->why_not.empty()) msgs.push_back(e->why_not);
      if (!r.pitch_error_basis.empty()) msgs.push_back(r.pitch_error_basis);
      const QString notes = find<QLabel>(*wiz.currentPage(), "analysis_notes")->text();
      EXPECT_GE(checkNoEnglish(notes, msgs, "analysis notes"), 3) << notes.toStdString();
      // Norwegian words a reader sees (the demo: CG y needs BG, the calibration notes).
      EXPECT_NE(notes.indexOf("Kan ikke bestemmes fra denne loggen"), -1) << notes.toStdString();
      EXPECT_NE(notes.indexOf("Stampavvik"), -1) << notes.toStdString();
      EXPECT_NE(find<QLabel>(wiz, "net_buoyancy")->text().indexOf("Netto oppdrift"), -1);
    }
    if (wiz.currentId() == OperatorWizard::kModelCheck) {
      // The model check's explanations: what the model is and where each
      // residual concentrates, in Norwegian words (check_messages.h).
      ASSERT_TRUE(wiz.state().model_check.has_value());
      saw_check = true;
      const auto& r = *wiz.state().model_check;
      std::vector<Message> msgs{r.model};
      for (const auto& l : r.localisation) msgs.push_back(l.summary);
      for (const auto& m : r.missing_physics) msgs.push_back(m.where);
      const QString shown = find<QLabel>(*wiz.currentPage(), "where")->text() + "\n" +
                            find<QLabel>(*wiz.currentPage(), "check_status")->text();
      int checked = 0;
      for (const Message& m : msgs) {
        if (m.empty()) continue;
        EXPECT_FALSE(m.id().empty()) << "model check: explanation without an id: " << m;
        removeTranslation();
        const QString en = readableModelMessage(m);
        installTranslation(QLocale(QLocale::NorwegianBokmal));
        const QString nbText = readableModelMessage(m);
        EXPECT_NE(en, nbText) << m;
        EXPECT_EQ(shown.indexOf(QString::fromStdString(m).toHtmlEscaped()), -1) << "core's English left: " << m;
        EXPECT_EQ(shown.indexOf(en.toHtmlEscaped()), -1) << "English left: " << en.toStdString();
        EXPECT_NE(shown.indexOf(nbText.toHtmlEscaped()), -1) << "not shown: " << nbText.toStdString();
        ++checked;
      }
      EXPECT_GE(checked, 3) << shown.toStdString();
      EXPECT_EQ(shown.indexOf(" concentrates at "), -1) << shown.toStdString();
      EXPECT_EQ(shown.indexOf("simulation error"), -1) << shown.toStdString();
    }
    if (wiz.currentId() == OperatorWizard::kAdjustment) {
      ASSERT_TRUE(wiz.state().plan.has_value());
      const auto& p = *wiz.state().plan;
      std::vector<Message> msgs = p.warnings;
      msgs.insert(msgs.end(), p.explanations.begin(), p.explanations.end());
      const QString shown = find<QLabel>(*wiz.currentPage(), "messages")->text();
      EXPECT_GE(checkNoEnglish(shown, msgs, "adjustment"), 1) << shown.toStdString();
      EXPECT_EQ(shown.indexOf("which lowers"), -1);
      EXPECT_EQ(shown.indexOf("which raises"), -1);
    }
    wiz.next();
  }
  EXPECT_EQ(wiz.currentId(), OperatorWizard::kSummary) << wiz.state().last_error;
  EXPECT_TRUE(saw_check);
}

// The first mission under Norwegian: the notes and warnings on the result
// page (HUGIN: what to do at each point, the priorities, the bands the kit
// cannot reach; Slocum: the tank, the bottles, the roll test and h-arm) are
// Norwegian, none of core's English is left.
namespace {
void expectNorwegianFirstMission(WizardState start, const std::vector<QString>& norwegian) {
  OperatorWizard wiz(std::move(start));
  wiz.setClock([] { return makeUtc(2026, 5, 20, 12, 0, 0); });
  wiz.setAutosaveEnabled(false);
  wiz.resize(1000, 760);
  wiz.show();
  for (int pages = 0; wiz.currentId() != OperatorWizard::kFirstMissionResult && pages < 8; ++pages) {
    auv::testing::settlePage(wiz);
    wiz.next();
  }
  ASSERT_EQ(wiz.currentId(), OperatorWizard::kFirstMissionResult) << wiz.state().last_error;
  ASSERT_TRUE(wiz.state().report.has_value());
  const FirstMissionReport& r = *wiz.state().report;
  std::vector<Message> msgs = r.notes;
  msgs.insert(msgs.end(), r.warnings.begin(), r.warnings.end());
  ASSERT_GE(msgs.size(), 3u);
  const QString shown = find<QLabel>(*wiz.currentPage(), "messages")->text();
  for (const Message& m : msgs) {
    EXPECT_FALSE(m.id().empty()) << "first mission: advice without an id: " << m;
    EXPECT_EQ(shown.indexOf(QString::fromStdString(m)), -1) << "core's English left: " << m;
  }
  for (const QString& w : norwegian) EXPECT_NE(shown.indexOf(w), -1) << w.toStdString() << "\n" << shown.toStdString();
  EXPECT_EQ(shown.indexOf("remove "), -1) << shown.toStdString();
  EXPECT_EQ(shown.indexOf("no change"), -1) << shown.toStdString();
}
}  // namespace

TEST_F(AdviceNorwegian, FirstMissionResultHasNoEnglishAdvice) {
  Norwegian nb;
  ASSERT_TRUE(nb.ok);
  expectNorwegianFirstMission(makeDemoState(AUV_RESOURCE_DIR), {"Prioriteringer", "Etter flyttingen"});
  expectNorwegianFirstMission(makeSlocumDemoState(AUV_RESOURCE_DIR), {"I tanken", "Den veier", "Rulletest"});
}

}  // namespace auv::ui
