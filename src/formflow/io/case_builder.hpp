// SPDX-License-Identifier: MIT
// The builder that turns case keys into a Case, internal to io/: io/case_file.cpp
// feeds it the keys of a document and of `--set`, io/case_builder.cpp sets them and
// blames, io/case_cross_checks.cpp checks the keys against each other.
#pragma once

#include "formflow/io/case.hpp"
#include "formflow/io/case_keys.hpp"
#include "formflow/io/toml_lines.hpp"

#include <toml.hpp>

#include <functional>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace formflow::io {

/// Accumulates keys into a Case (starting from the table's defaults), remembering
/// where each was set, so that cross-key errors can point at the key set last.
class CaseBuilder {
public:
  CaseBuilder();

  /// Sets `key` from `value`, found at `file`:`line`; `lines` places the entries of a table.
  void set(const CaseKey& key, const toml::value& value, const std::string& file, int line,
           TomlLines& lines);

  /// Gives `key` another default, `value`: checked as a value of `key` is, not counted
  /// as set (io::load_case's `defaults`).
  void set_default(const CaseKey& key, const toml::value& value);

  /// A bad entry of a table of strings is blamed on its own line, not on the
  /// table's header line, which may be far above it.
  static void check_table_entries(const CaseKey& key, const toml::value& table,
                                  const std::string& file, TomlLines& lines);

  // Run once every key is set, in this order (io/case_cross_checks.cpp).
  void resolve_dependent_defaults();
  void check_cross_keys() const;

  Case finish(std::string source);

private:
  /// Where a key got its current value; `order` tells which of two keys was set last.
  struct Origin {
    std::string file = "<default>";
    int line = 0;
    int order = 0;
  };

  Origin origin(const std::string& name) const;

  /// The key to blame for a problem found at `primary`: `primary` itself when
  /// the user set it, else whichever of `related` was set last (a key left at
  /// its default is not what the user should change).
  std::string responsible(const std::string& primary,
                          std::initializer_list<std::string> related) const;

  Real real_value(const std::string& name) const;

  /// Throws for the key (of `names`) that was set last: it is the one to change.
  [[noreturn]] void blame(const std::vector<std::string>& names, const std::string& message,
                          const std::string& hint) const;

  /// Throws for `name`, or (when `name` is at its default) for the key of
  /// `related` set last; the message then says which value of `name` is meant.
  [[noreturn]] void die_error(const std::string& name, const std::string& message,
                              const std::string& hint,
                              std::initializer_list<std::string> related = {}) const;

  // The checks check_cross_keys runs (io/case_cross_checks.cpp, each explained there).
  void check_order(const std::string& small, const std::string& large) const;
  void check_flow_law() const;
  std::optional<std::string> non_finite_law() const;
  void check_formulation() const;
  void check_linear_solver() const;
  void check_acceleration() const;
  void check_cells() const;
  void check_solid() const;
  void check_mesh_source() const;
  void check_verification() const;
  void check_stages(const std::string& stage_key) const;
  void check_thermal() const;
  void check_adapt() const;
  void check_mesh_memory() const;
  void check_die() const;
  void check_mesh_fits() const;

  Case case_;
  std::map<std::string, Origin, std::less<>> origins_;
  int n_set_ = 0;
};

} // namespace formflow::io
