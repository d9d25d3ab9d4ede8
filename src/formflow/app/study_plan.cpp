// SPDX-License-Identifier: MIT
// Planning a study: parsing --vary and loading every rung's case before anything runs.
#include "formflow/app/study.hpp"

#include "formflow/core/error.hpp"
#include "formflow/io/case_keys.hpp"

#include <fmt/format.h>

#include <charconv>

namespace formflow::app {

namespace {

std::string trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return std::string(text.substr(first, text.find_last_not_of(" \t") - first + 1));
}

/// "10/6" → "1.6666666666666667"; anything else unchanged (load_case judges it).
std::string resolve_fraction(const std::string& text) {
  const auto slash = text.find('/');
  if (slash == std::string::npos) return text;
  double numerator = 0, denominator = 0;
  const std::string top = text.substr(0, slash), bottom = text.substr(slash + 1);
  const auto a = std::from_chars(top.data(), top.data() + top.size(), numerator);
  const auto b = std::from_chars(bottom.data(), bottom.data() + bottom.size(), denominator);
  if (a.ec != std::errc{} || a.ptr != top.data() + top.size() || b.ec != std::errc{} ||
      b.ptr != bottom.data() + bottom.size() || denominator == 0)
    throw InputError("--vary", 0, text, "not a number or a fraction n/m", "e.g. 0.5 or 10/6");
  return fmt::format("{:.17g}", numerator / denominator);
}

} // namespace

Real numeric_key_value(const io::CaseKey& key, const io::Case& case_) {
  const io::KeyValue value = key.get(case_);
  if (key.type == io::KeyType::Integer) return static_cast<Real>(std::get<std::int64_t>(value));
  return std::get<Real>(value);
}

StudyPlan plan_study(const std::string& case_path, const std::string& vary,
                     const std::vector<io::Override>& overrides) {
  const auto equals = vary.find('=');
  if (equals == std::string::npos || equals == 0)
    throw InputError("--vary", 0, vary, "expected key=v1,v2,...",
                     "e.g. --vary mesh.size=1,0.5,0.25");
  StudyPlan plan;
  plan.key = trimmed(vary.substr(0, equals));
  const io::CaseKey* key = io::find_case_key(plan.key);
  if (!key) throw InputError("--vary", 0, plan.key, "unknown key", io::unknown_key_hint(plan.key));
  if (key->type != io::KeyType::Real && key->type != io::KeyType::Integer)
    throw InputError("--vary", 0, plan.key, "a study varies a numeric key",
                     "e.g. mesh.size, penalty.d, penalty.dT, friction.radius");
  std::string_view list = std::string_view(vary).substr(equals + 1);
  while (true) {
    const auto comma = list.find(',');
    const std::string value = trimmed(list.substr(0, comma));
    if (value.empty())
      throw InputError("--vary", 0, plan.key, "empty value in the list",
                       "separate values by single commas: key=v1,v2,v3");
    plan.values.push_back(value);
    if (plan.values.size() > max_study_rungs)
      throw InputError("--vary", 0, plan.key, fmt::format("more than {} values", max_study_rungs),
                       "a ladder needs a handful of rungs: each one is a whole solve");
    if (comma == std::string_view::npos) break;
    list.remove_prefix(comma + 1);
  }
  if (plan.values.size() < 2)
    throw InputError("--vary", 0, plan.key, "a study needs at least two values",
                     "e.g. --vary mesh.size=1,0.5,0.25");
  for (const std::string& value : plan.values) {
    std::vector<io::Override> rung = overrides;
    rung.emplace_back(plan.key, resolve_fraction(value));
    plan.cases.push_back(io::load_case(case_path, rung));
    const Real number = numeric_key_value(*key, plan.cases.back());
    if (!(number > 0))
      throw InputError("--vary", 0, plan.key, fmt::format("value {} is not positive", value),
                       "study values are the x axis of a log-log plot: use values > 0");
  }
  plan.description = case_path.empty() ? "default case" : case_path;
  for (const io::Override& assignment : overrides)
    plan.description += fmt::format(", {}={}", assignment.first, assignment.second);
  return plan;
}

} // namespace formflow::app
