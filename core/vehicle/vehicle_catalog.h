#pragma once
// The set of vehicle profiles shipped in resources/vehicles (or any folder),
// addressed by id ("hugin1000") or by a path to a profile file.
#include <string>
#include <vector>

#include "vehicle/vehicle_profile.h"

namespace auv {

class VehicleCatalog {
 public:
  explicit VehicleCatalog(std::string vehicles_dir);

  std::vector<std::string> ids() const;  // sorted
  // `id_or_path` is an id from ids() or a path to a .json profile.
  VehicleProfile load(const std::string& id_or_path) const;
  const std::string& directory() const { return dir_; }

 private:
  std::string dir_;
};

}  // namespace auv
