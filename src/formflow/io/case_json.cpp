// SPDX-License-Identifier: MIT
// The resolved case as nested JSON, generated from the case-key table.
#include "formflow/io/case_json.hpp"

#include "formflow/io/case_keys.hpp"

#include <variant>

namespace formflow::io {

nlohmann::ordered_json case_to_json(const Case& case_) {
  // Ordered: the echo reads like the case reference, section by section.
  nlohmann::ordered_json json = nlohmann::ordered_json::object();
  for (const CaseKey& key : case_keys()) {
    nlohmann::ordered_json& slot = json[std::string(key.section())][std::string(key.leaf())];
    std::visit([&slot](const auto& value) { slot = value; }, key.get(case_));
    // A switch (an enum of exactly false/true, e.g. thermal.enabled) is a JSON boolean.
    if (key.type == KeyType::Enum && key.choices.size() == 2 && key.choices[0] == "false" &&
        key.choices[1] == "true")
      slot = slot.get<std::string>() == "true";
  }
  json["source"] = case_.source;
  return json;
}

} // namespace formflow::io
