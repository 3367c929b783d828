#pragma once
// Pre-mission tests start from a real post-mission analysis: the bundled
// simulated HUGIN mission with a known ballast error
// (resources/examples/hugin1000_ballast_error.plan.json: 3 kg light, CG 5 mm
// forward, 7.2/7.2/25.2/25.2 kg installed), flown by core/sim and analysed
// by core/analysis exactly as scripts/run-example.sh does on the command line.
#include <QString>
#include <QStringList>
#include <QPaintDevice>
#include <QPaintEngine>
#include <QPainterPath>
#include <memory>
#include <vector>

#include "analysis/mission_analysis.h"
#include "common/units.h"
#include "sim/mission_plan.h"
#include "sim/sim_log.h"
#include "sim/simulator.h"
#include "vehicle/vehicle_catalog.h"

namespace auv::testing {

inline const std::vector<double>& exampleInstalledKg() {
  static const std::vector<double> kg{7.2, 7.2, 25.2, 25.2};
  return kg;
}

// Simulated once per test process (a fraction of a second).
inline const analysis::AnalysisReport& exampleHuginAnalysis() {
  static const analysis::AnalysisReport report = [] {
    const std::string res = AUV_RESOURCE_DIR;
    const sim::MissionPlan plan = sim::loadMissionPlan(res + "/examples/hugin1000_ballast_error.plan.json");
    const VehicleProfile v = VehicleCatalog(res + "/vehicles").load("hugin1000");
    const sim::SimVehicle sv = sim::loadSimVehicle(v, res);
    const sim::SimTrace tr = sim::simulate(sv.model, sv.autopilot, plan.water, sim::resolveScenario(plan, v), plan.options);
    const MissionLog log = sim::toMissionLog(
        tr, {v.id, "plan", "hugin1000_ballast_error.plan.json", plan.options.seed, sv.model.thruster_count, plan.installed_kg, {}});
    analysis::AnalysisOptions a;
    a.log_name = "hugin1000_mission.csv";
    a.installed_kg = exampleInstalledKg();
    a.bg_m = units::mmToM(20.0);  // as run-example.sh: --bg-mm 20
    return analysis::analyzeMission(log, v, a);
  }();
  return report;
}

// A paint device that keeps the text each drawText reaches the paint engine
// with: the check that a drawing shows the expected strings.
class TextRecorder : public QPaintDevice {
 public:
  TextRecorder(QSize size_px, int dpi) : size_(size_px), dpi_(dpi), engine_(std::make_unique<Engine>()) {}
  ~TextRecorder() override = default;
  QPaintEngine* paintEngine() const override { return engine_.get(); }
  const QStringList& texts() const { return engine_->texts; }
  QString joined() const { return engine_->texts.join("\n"); }

 protected:
  int metric(PaintDeviceMetric m) const override {
    switch (m) {
      case PdmWidth: return size_.width();
      case PdmHeight: return size_.height();
      case PdmWidthMM: return static_cast<int>(size_.width() * 25.4 / dpi_);
      case PdmHeightMM: return static_cast<int>(size_.height() * 25.4 / dpi_);
      case PdmDpiX:
      case PdmDpiY:
      case PdmPhysicalDpiX:
      case PdmPhysicalDpiY: return dpi_;
      case PdmDepth: return 32;
      case PdmNumColors: return 0x7fffffff;
      case PdmDevicePixelRatio: return 1;
      case PdmDevicePixelRatioScaled: return static_cast<int>(devicePixelRatioFScale());
      default: return 0;
    }
  }

 private:
  struct Engine : QPaintEngine {
    Engine() : QPaintEngine(QPaintEngine::AllFeatures) {}
    bool begin(QPaintDevice*) override { return true; }
    bool end() override { return true; }
    void updateState(const QPaintEngineState&) override {}
    void drawPixmap(const QRectF&, const QPixmap&, const QRectF&) override {}
    void drawPolygon(const QPointF*, int, PolygonDrawMode) override {}
    void drawPath(const QPainterPath&) override {}
    void drawTextItem(const QPointF&, const QTextItem& t) override { texts << t.text(); }
    Type type() const override { return QPaintEngine::User; }
    QStringList texts;
  };
  QSize size_;
  int dpi_;
  std::unique_ptr<Engine> engine_;
};

}  // namespace auv::testing
