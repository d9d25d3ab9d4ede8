// SPDX-License-Identifier: MIT
// The files of a parameter study: study.csv and the log-log picture study.png/.svg.
#pragma once

#include "formflow/core/stop_request.hpp"
#include "formflow/post/study_table.hpp"

#include <span>
#include <string>

namespace formflow::io {

/// study.csv: one row per rung, header
/// `key,value,parameter,dofs,iterations,stop_reason,seconds,ram_reaction,power_balance,
/// total_power,mean_hydrostatic_near_ram,error_V,error_L2,error_hydrostatic_L2,
/// difference_V,difference_L2,order_V,order_L2,pressure_order,pressure_extrapolated,rcond,
/// load_error_estimate`.
/// Reals as `{:.10g}`; a cell is empty where the quantity does not apply or is not finite.
std::string study_csv(const post::StudyTable& table);

/// corner.csv: header `key,value,radius,mean_rate,max_rate`, the die-corner
/// profile of every rung that has one.
std::string corner_csv(const post::StudyTable& table);

/// adaptive.csv: header `series,index,dofs,load,estimate,estimate_predicted,refined_mesh`,
/// the uniform rungs (series "uniform") and the adaptive run's cycles ("adaptive"):
/// the data of load_error_dofs.png.
std::string adaptive_csv(const post::StudyTable& table);

/// Every file write_study may write: study.csv/.png/.svg, corner.csv/.png/.svg,
/// adaptive.csv, load_error_dofs.png/.svg, report.html.
std::span<const std::string> study_file_names();

/// Writes study.csv, study.png, study.svg and report.html (the table and the
/// plots in one page) into `directory` (created if missing), with corner
/// profiles also corner.csv, corner.png and corner.svg, with load error estimates
/// also adaptive.csv, load_error_dofs.png and load_error_dofs.svg,
/// as one set (io/result_set.hpp, study.csv last); corner files of an older
/// study that this one lacks are removed with the commit. `stop_requested`
/// is asked between files (throws Stopped, directory unchanged). Throws
/// OutputError if the disk refuses the files (directory unchanged).
void write_study(const std::string& directory, const post::StudyTable& table,
                 const StopRequested& stop_requested = {});

} // namespace formflow::io
