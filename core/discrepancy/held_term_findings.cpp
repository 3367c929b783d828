#include "discrepancy/held_term_findings.h"

#include <cmath>

#include "analysis/calibration_parameter.h"
#include "discrepancy/rms_and_localisation.h"
#include "discrepancy/residual_statistics.h"

namespace auv::discrepancy::detail {
namespace {

// Simulation RMS per channel (SI) of the whole log at p.
std::vector<double> simulationRms(const CheckModel& m, const Params& p, std::size_t channels) {
  std::vector<double> e, sse, n;
  m.simulationError(p, e);
  rmsPerChannel(e, channels, sse, n);
  std::vector<double> out(channels);
  for (std::size_t c = 0; c < channels; ++c) out[c] = rmsOf(sse[c], n[c]);
  return out;
}

}  // namespace

void reportHeldTermFindings(const FitSetup& s, const std::vector<std::uint32_t>& fitRows,
                            const std::vector<std::size_t>& accepted, const Fit& fin, const std::vector<std::uint32_t>& all,
                            std::vector<MissingPhysics>& found, ModelCheckResult& R) {
  const CheckModel& m = s.m;
  const std::vector<Channel> simCh = m.simulationChannels();
  for (const HeldTermValue& h : m.heldTerms()) {
    const auto k = findTerm(h.id);
    if (!k || !(std::abs(h.value - h.profile_value) > 2.0 * h.sigma)) continue;
    const bool bias = h.id == "pitch_sensor_bias";  // held always, named only as large as a sensor's
    if (bias && std::abs(h.value - h.profile_value) < analysis::kNamedPitchBiasDeg) continue;
    const PhysicsTerm& t = termLibrary()[*k];
    const double increment = (h.value - h.profile_value) / t.display_scale;  // SI, inside the model's baseline
    // The profile's value: the held term cancelled, ballast and accepted terms refitted.
    FitSetup without = s;
    without.pinned_terms.push_back({*k, -increment});
    std::vector<std::size_t> terms = accepted;
    terms.push_back(*k);
    Params start = fin.params;
    start.terms[*k] = -increment;
    const Fit before = fit(without, fitRows, terms, start);
    const std::vector<double> rb = simulationRms(m, before.params, simCh.size());
    const std::vector<double> ra = simulationRms(m, fin.params, simCh.size());
    std::size_t best = 0;
    double gain = -1e300;
    for (std::size_t c = 0; c < simCh.size(); ++c)
      if (std::isfinite(rb[c]) && std::isfinite(ra[c]) && rb[c] > 0.0 && 1.0 - ra[c] / rb[c] > gain) {
        gain = 1.0 - ra[c] / rb[c];
        best = c;
      }
    MissingPhysics mp;
    mp.id = h.id;
    mp.unit = h.unit;
    mp.value = h.value;
    mp.sigma = h.sigma;
    mp.calibration_sigma = h.sigma;
    mp.profile_value = h.profile_value;
    if (!simCh.empty()) {
      mp.channel = simCh[best];
      mp.rms_before = rb[best] * channelDisplayScale(mp.channel);
      mp.rms_after = ra[best] * channelDisplayScale(mp.channel);
      mp.heldout_gain = gain;
    }
    mp.inclusion_probability = 1.0;
    mp.t_value = std::abs(h.value - h.profile_value) / h.sigma;
    mp.evidence = bias ? "found by the analysis beside the ballast state: the steady legs at their speeds and the "
                         "glides fit one balance only with the pitch reading this much more than the vehicle's "
                         "attitude; the check holds it"
                       : "fitted by the analysis from the steady legs' means at their depths, waters and times, which "
                         "separate the hull's compressibility, its thermal expansion and a mass drift; the check holds it";
    if (!h.rival.empty()) {
      mp.confused_with.push_back(h.rival);
      mp.evidence += "; but the legs explain a " + h.rival + " alone about as well (the temperature followed the depth): "
                     "legs at one depth in different water, or at two depths at one temperature, would tell them apart";
    }
    mp.where = locateContribution(s, before.params, fin.params, all);  // where it acts
    R.accepted[*k] = increment;  // for --accept (the check's model has it in its baseline)
    found.push_back(mp);
  }
}

}  // namespace auv::discrepancy::detail
