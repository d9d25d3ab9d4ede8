// SPDX-License-Identifier: MIT
// The files of a parameter study: study.csv and the log-log picture study.png/.svg.
#pragma once

#include "formflow/post/study_table.hpp"

#include <string>

namespace formflow::io {

/// study.csv: one row per rung, header
/// `key,value,parameter,dofs,iterations,stop_reason,seconds,ram_reaction,power_balance,
/// total_power,mean_hydrostatic_near_ram,error_V,error_L2,error_hydrostatic_L2,
/// difference_V,difference_L2,order_V,order_L2,pressure_order,pressure_extrapolated,rcond`.
/// Reals as `{:.10g}`; a cell is empty where the quantity does not apply or is not finite.
std::string study_csv(const post::StudyTable& table);

/// corner.csv: header `key,value,radius,mean_rate,max_rate`, the die-corner
/// profile of every rung that has one.
std::string corner_csv(const post::StudyTable& table);

/// Writes study.csv, study.png and study.svg into `directory` (created if
/// missing), each through a temporary file and a rename; with corner
/// profiles also corner.csv, corner.png and corner.svg.
void write_study(const std::string& directory, const post::StudyTable& table);

} // namespace formflow::io
