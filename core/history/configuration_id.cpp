#include "history/configuration_id.h"

#include "common/input_error.h"

namespace auv {

bool isValidConfigurationId(const std::string& id) {
  int groups = 1;
  std::size_t group_len = 0;
  for (char c : id) {
    if (c == '-') {
      if (group_len == 0) return false;
      ++groups;
      group_len = 0;
    } else if ((c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z')) {
      if (++group_len > 8) return false;
    } else {
      return false;
    }
  }
  return groups == 3 && group_len > 0;
}

void requireValidConfigurationId(const std::string& id) {
  if (!isValidConfigurationId(id))
    throw InputError("configuration ID", "'" + id + "' is not an xx-xx-xx code",
                     "use three groups of 1-8 letters or digits joined by '-', "
                     "e.g. 01-02-03 or sys-0-0");
}

}  // namespace auv
