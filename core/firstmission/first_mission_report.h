#pragma once
// What a first-mission computation hands to every front end (CLI text, JSON,
// GUI). Vehicle-specific weighing methods (HUGIN crane, Slocum tank) fill the
// same structure; their extra details go in `details`.
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/message.h"

namespace auv {

struct PieceCount {
  double size_kg = 0.0;
  int count = 0;  // negative = remove that many installed pieces
};

struct PointRecommendation {
  std::string name;  // adjustment point id from the vehicle profile
  std::string label;
  double add_kg = 0.0;  // signed: negative = remove
  std::vector<PieceCount> pieces;
};

struct PredictedTrim {
  double net_buoyancy_kg = 0.0;  // positive = too light
  Eigen::Vector2d cg_offset_m = Eigen::Vector2d::Zero();  // CG - CB, x and y
  double pitch_deg = 0.0;
  double roll_deg = 0.0;
};

struct FirstMissionReport {
  std::string vehicle_id;
  std::string method;  // "crane" or "tank"
  double weight_kg = 0.0;
  double buoyancy_kg = 0.0;
  double net_buoyancy_kg = 0.0;  // positive = too light
  Eigen::Vector3d cg_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d cg_sigma_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d cb_m = Eigen::Vector3d::Zero();
  double temperature_degC = 0.0;
  double salinity_psu = 0.0;
  double depth_m = 0.0;
  double pressure_dbar = 0.0;
  double density_kgm3 = 0.0;
  double pitch_before_deg = 0.0;
  double roll_before_deg = 0.0;
  std::vector<PointRecommendation> points;
  PredictedTrim predicted;
  std::vector<Message> warnings;  // e.g. band not reachable with this kit (ids: first_mission_messages.h, ...)
  std::vector<Message> notes;     // one-sentence explanations
  nlohmann::json details = nlohmann::json::object();
};

// The stable JSON contract (issue #2): weight_kg, buoyancy_kg, net_buoyancy_kg,
// cg_mm, cb_mm, recommendation.points[{name, add_kg, pieces}], predicted{...}.
nlohmann::json toJson(const FirstMissionReport& r);
std::string toText(const FirstMissionReport& r);

}  // namespace auv
