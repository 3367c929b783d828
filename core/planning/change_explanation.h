#pragma once
// The sentences of a pre-mission plan: one per changed point saying what the
// change does to net buoyancy and CG (the parts add up to the whole move),
// a summary of where the vehicle goes, and every way the plan falls short
// of the spec or the safety rule, with the reason.
#include "ballast/ballast_problem.h"
#include "planning/pre_mission_plan.h"

namespace auv {

void explainPlan(const VehicleProfile& v, const BallastProblem& problem, PreMissionPlan& plan);

}  // namespace auv
