// SPDX-License-Identifier: MIT
// The run plan's errors, located where the case set the key.
#include "formflow/app/run_plan.hpp"

namespace formflow::app {

InputError KeyPlaces::error(const std::string& key, const std::string& message,
                            const std::string& hint) const {
  const auto where = places.find(key);
  if (where == places.end()) return InputError(source, 0, key, message, hint);
  return InputError(where->second.file, where->second.line, key, message, hint);
}

} // namespace formflow::app
