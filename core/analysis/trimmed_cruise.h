#pragma once
// The speed an AUV cruises at once the move has trimmed it, and what that
// does to the roll the plan must level (issue 11 item 8).
//
// A vehicle that flew its survey heavy or light, nose up or down, holds depth
// with its planes deflected and part of its weight along its path: at the same
// propeller speed it goes slower than it will when trimmed (identification
// truth 1107: 1.15 m/s at 137 rpm before the second move, 1.71 m/s after). The
// propeller's reaction torque falls with the advance ratio, so the roll the
// log measured at cruise is not the roll the trimmed vehicle flies: on the
// identification truths the roll after one move missed by 2 to 5 degrees per
// m/s of speed gained. The surge balance of the shared vehicle model
// (sim::Dynamics: thrust, hull and plane drag, weight along the path) at the
// logged cruise segments says how much drag the model misses there; with that
// drag the same balance in level flight at the state the plan aims for (its
// net buoyancy and CG x, the pitch and planes that hold them) gives the
// trimmed speed, and the torque law the change of torque between the two.
#include <optional>
#include <span>

#include "analysis/auv_trim_estimation.h"
#include "sim/vehicle_model.h"

namespace auv::analysis {

// Needs the cruise rpm, a fitted propeller torque (several propeller speeds
// in the log) and the model's propeller; nullopt otherwise or when the
// balance has no root between a third of the logged speed and twice it (at least 4 m/s).
// `net_after_kg`: the net buoyancy the plan aims for.
std::optional<TrimmedCruise> trimmedCruise(const sim::VehicleModel& model, std::span<const SteadySegmentMeans> segments,
                                           const AuvTrimEstimate& e, const AuvTrimContext& ctx, double net_after_kg);

}  // namespace auv::analysis
