#pragma once
// Reading a number out of a saved session or weighing document for display:
// a missing or non-numeric field shows as 0 (validation happens in core).
#include <initializer_list>
#include <nlohmann/json.hpp>

namespace auv::ui {

inline double jnum(const nlohmann::json& j, std::initializer_list<const char*> path) {
  const nlohmann::json* p = &j;
  for (const char* k : path) {
    if (!p->is_object() || !p->contains(k)) return 0.0;
    p = &(*p)[k];
  }
  return p->is_number() ? p->get<double>() : 0.0;
}

}  // namespace auv::ui
