#pragma once
// A log larger than the memory there is must end in an InputError naming the
// file, not in std::bad_alloc escaping to the user interface.
#include <new>
#include <string>

#include "common/input_error.h"

namespace auv::detail {

template <class F>
auto guardMemory(const std::string& name, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const std::bad_alloc&) {
    throw InputError("log", "not enough memory to hold this log", "split the file or use a larger machine",
                     {name, 0, 0});
  }
}

}  // namespace auv::detail
