#include "analysis/water_at_depth.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/series_tools.h"
#include "analysis/window_samples.h"
#include "seawater/seawater.h"

namespace auv::analysis {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool inRange(double v, const seawater::ValidRange& r) { return v >= r.min && v <= r.max; }

}  // namespace

WaterAtDepth waterProperties(const MissionLog& log, const std::vector<Segment>& win, const TimeSeries& depth,
                             double latitude, double min_depth_m, SeriesModel model,
                             const std::vector<bool>* in_overall) {
  WaterAtDepth out;
  const bool hasT = hasSamples(log, "temperature"), hasS = hasSamples(log, "salinity"),
             hasC = hasSamples(log, "conductivity"), hasP = hasSamples(log, "pressure"),
             hasRho = hasSamples(log, "density");
  const char* base = hasT ? "temperature" : (hasRho ? "density" : nullptr);
  if (!base) return out;
  const TimeSeries b = log.series(base);
  const TimeSeries sS = hasS ? log.series("salinity") : TimeSeries{};
  const TimeSeries sC = hasC ? log.series("conductivity") : TimeSeries{};
  const TimeSeries sP = hasP ? log.series("pressure") : TimeSeries{};
  const TimeSeries sR = hasRho && hasT ? log.series("density") : TimeSeries{};
  const double gap = 60.0;
  SeriesCursor cS(sS, false, gap), cC(sC, false, gap), cP(sP, false, gap), cR(sR, false, gap), cZ(depth, false, gap);
  MeanAccumulator aT, aS, aR, aP, aZ;
  std::vector<double> nR(win.size(), 0.0), sR_(win.size(), 0.0), nT(win.size(), 0.0), sT(win.size(), 0.0),
      nP(win.size(), 0.0), sP_(win.size(), 0.0);
  std::size_t last = static_cast<std::size_t>(-1);
  out.salinity_source = hasS ? "log" : (hasC ? "PSS-78 from conductivity" : "");
  out.density_source = hasRho ? "log" : "EOS-80 from temperature, salinity and pressure";
  forEachInWindows(b, win, [&](std::size_t w, double t, double v) {
    double p = hasP ? cP.at(t) : kNaN;
    double z = cZ.at(t);
    if (std::isnan(p) && !std::isnan(z)) p = seawater::pressureFromDepth(std::clamp(z, 0.0, 10600.0), latitude);
    if (std::isnan(z) && !std::isnan(p)) z = seawater::depthFromPressure(std::clamp(p, 0.0, 11000.0), latitude);
    if (!(z >= min_depth_m)) return;
    const bool all = !in_overall || (*in_overall)[w];
    if (w != last) {
      for (MeanAccumulator* a : {&aT, &aS, &aR, &aP, &aZ}) a->endBlock();
      last = w;
    }
    if (all) aZ.add(z);
    if (!std::isnan(p)) {
      if (all) aP.add(p);
      nP[w] += 1, sP_[w] += p;
    }
    if (!hasT) {  // density-only log
      if (all) aR.add(v);
      nR[w] += 1, sR_[w] += v;
      return;
    }
    const double T = v;
    double S = hasS ? cS.at(t) : kNaN;
    if (std::isnan(S) && hasC) {
      const double C = cC.at(t);
      if (inRange(C, seawater::kConductivityRange) && C > 0 && inRange(T, seawater::kTemperatureRange) &&
          inRange(p, seawater::kPressureRange))
        S = seawater::salinityFromConductivity(C, T, p);
    }
    if (all) aT.add(T);
    nT[w] += 1, sT[w] += T;
    if (!std::isnan(S) && all) aS.add(S);
    double rho = hasRho ? cR.at(t) : kNaN;
    if (!hasRho) {
      if (inRange(S, seawater::kSalinityRange) && inRange(T, seawater::kTemperatureRange) &&
          inRange(p, seawater::kPressureRange))
        rho = seawater::density(S, T, p);
      else
        ++out.skipped;
    }
    if (!std::isnan(rho)) {
      if (all) aR.add(rho);
      nR[w] += 1, sR_[w] += rho;
    }
  });
  auto meanOf = [](const std::vector<double>& n, const std::vector<double>& sum) {
    std::vector<double> m(n.size(), kNaN);
    for (std::size_t i = 0; i < n.size(); ++i)
      if (n[i] > 0) m[i] = sum[i] / n[i];
    return m;
  };
  out.win_rho = meanOf(nR, sR_);
  out.win_T = meanOf(nT, sT);
  out.win_p = meanOf(nP, sP_);
  out.T = aT.result(model);
  out.S = aS.result(model);
  out.rho = aR.result(model);
  out.p = aP.result(model);
  out.z = aZ.result(model);
  return out;
}

}  // namespace auv::analysis
