#pragma once
// Thesis §5.5.1: a configuration ID names one vehicle with one payload set in
// one water of operation, written "xx-xx-xx". The thesis's own examples are
// "1-2-3" (Fig. 5.14) and "sys-0-0" (Fig. 7.9), so a group is 1-8 letters or
// digits, not exactly two digits (docs/decisions/history-configuration-id.md).
#include <string>

namespace auv {

bool isValidConfigurationId(const std::string& id);
// Throws InputError("configuration ID", ...) naming the offending text.
void requireValidConfigurationId(const std::string& id);

}  // namespace auv
