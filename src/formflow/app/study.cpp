// SPDX-License-Identifier: MIT
// Ladder of runs over one key: planning (all validation first), running, differences, orders.
#include "formflow/app/study.hpp"

#include "formflow/app/simulation.hpp"
#include "formflow/core/error.hpp"
#include "formflow/io/case_keys.hpp"

#include <fmt/format.h>

#include <charconv>
#include <chrono>
#include <memory>

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

Real numeric_value(const io::CaseKey& key, const io::Case& case_) {
  const io::KeyValue value = key.get(case_);
  if (key.type == io::KeyType::Integer) return static_cast<Real>(std::get<std::int64_t>(value));
  return std::get<Real>(value);
}

bool same_mesh(const mesh::Mesh<2>& a, const mesh::Mesh<2>& b) {
  return a.order == b.order && a.nodes.cols() == b.nodes.cols() && a.nodes == b.nodes &&
         a.cells == b.cells;
}

/// ε̄̇ around the die corner (L_c, H_out) from ρ = 0.01 to the exit half height, 5 bins a decade.
post::CornerProfile die_corner_profile(const io::Case& case_, const Simulation& simulation) {
  const assembly::FormingProblem<2> problem(simulation.mesh, problem_settings(case_));
  const Point<2> corner(case_.geometry.container_length, case_.geometry.exit_half_height);
  return post::corner_profile<2>(problem, simulation.results.fields.velocity, corner, 0.01,
                                 case_.geometry.exit_half_height, 5);
}

} // namespace

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
    const Real number = numeric_value(*key, plan.cases.back());
    if (!(number > 0))
      throw InputError("--vary", 0, plan.key, fmt::format("value {} is not positive", value),
                       "study values are the x axis of a log-log plot: use values > 0");
  }
  plan.description = case_path.empty() ? "default case" : case_path;
  for (const io::Override& assignment : overrides)
    plan.description += fmt::format(", {}={}", assignment.first, assignment.second);
  return plan;
}

post::StudyTable run_study(const StudyPlan& plan, bool estimate_condition,
                           const std::function<void(const post::StudyRung&)>& on_rung) {
  const io::CaseKey* key = io::find_case_key(plan.key);
  FF_ASSERT(key, "plan_study checked the key");
  post::StudyTable table{plan.key, plan.description, {}, std::nullopt, std::nullopt};
  std::vector<Simulation> simulations;
  for (std::size_t k = 0; k < plan.cases.size(); ++k) {
    const auto start = std::chrono::steady_clock::now();
    Simulation simulation = simulate(plan.cases[k], {}, estimate_condition);
    post::StudyRung rung;
    rung.value_text = plan.values[k];
    rung.parameter = numeric_value(*key, plan.cases[k]);
    rung.dofs = simulation.results.n_dofs;
    rung.iterations = simulation.results.iterations;
    rung.stop_reason = simulation.results.stop_reason;
    rung.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    rung.pressure = simulation.results.pressure;
    rung.error = simulation.errors;
    rung.reciprocal_condition = simulation.reciprocal_condition;
    // The re-entrant corner (L_c, H_out) exists only for the square die of SPEC §4.
    if (plan.key == "mesh.size" &&
        plan.cases[k].manufactured == physics::ManufacturedSolution::None &&
        plan.cases[k].geometry.die == mesh::DieShape::Square)
      rung.corner = die_corner_profile(plan.cases[k], simulation);
    table.rungs.push_back(rung);
    if (on_rung) on_rung(table.rungs.back());
    simulations.push_back(std::move(simulation));
  }
  // Penalty and regularisation ladders keep the mesh: measure each rung
  // against the last one, which the user makes the reference (smallest d).
  const Simulation& last = simulations.back();
  bool common_mesh = true;
  for (const Simulation& simulation : simulations)
    common_mesh &= same_mesh(simulation.mesh, last.mesh);
  if (common_mesh) {
    const assembly::FormingProblem<2> problem(last.mesh, problem_settings(plan.cases.back()));
    for (std::size_t k = 0; k + 1 < simulations.size(); ++k)
      table.rungs[k].difference = post::difference_norms<2>(
          problem, simulations[k].results.fields.velocity, last.results.fields.velocity);
  }
  post::compute_orders(table);
  const io::Case& first = plan.cases.front();
  if (plan.key == "mesh.size" && first.manufactured != physics::ManufacturedSolution::None) {
    const int order = fem::element_order(first.element); // Theorem 4.1, smooth solution
    table.theory_order_v = order;
    table.theory_order_l2 = order + 1;
  } else if (plan.key == "penalty.d") { // Theorem 3.4
    table.theory_order_v = table.theory_order_l2 = 1.0;
  } else if (plan.key == "penalty.dT") { // Theorem 3.3 (a bound)
    table.theory_order_v = table.theory_order_l2 = 0.5;
  }
  return table;
}

} // namespace formflow::app
