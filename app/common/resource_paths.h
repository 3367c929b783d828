#pragma once
// Where the bundled resources (vehicle profiles, examples) are, for both the
// CLI and the GUI: $AUVBALLAST_RESOURCES, else <exe>/../share/auvballast/resources
// (installed package), else the source tree's resources/ (build tree).
#include <string>

namespace auv::app {

std::string resourceDir();
std::string vehiclesDir();
std::string examplesDir();

}  // namespace auv::app
