// SPDX-License-Identifier: MIT
// The resolved case as JSON, keyed exactly like the case file (summary.json "case").
#pragma once

#include "formflow/io/case.hpp"

#include <nlohmann/json.hpp>

namespace formflow::io {

/// Every resolved parameter, nested by section with the case-file key names
/// (e.g. j["penalty"]["dN"], j["friction"]["on"] = ["container", "die"]), in
/// the order of the key table (docs/case-reference.md), then "source".
nlohmann::ordered_json case_to_json(const Case& case_);

} // namespace formflow::io
