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
  // `id_or_path` is an id from ids() or a path to a .json profile. A profile
  // loaded by id also gets the sections of its companion file
  // <dir>/../sim/<id>_hydrodynamics.json when it has no "hydrodynamics" of its
  // own (docs/decisions/profile-companion-hydrodynamics.md).
  VehicleProfile load(const std::string& id_or_path) const;
  const std::string& directory() const { return dir_; }

 private:
  std::string dir_;
};

// Adds the object sections of `companion_file` that `v` lacks, if the file
// exists and `v` has no "hydrodynamics" section.
void mergeCompanionSections(VehicleProfile& v, const std::string& companion_file);

}  // namespace auv
