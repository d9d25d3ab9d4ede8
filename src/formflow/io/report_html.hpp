// SPDX-License-Identifier: MIT
// report.html: one self-contained page that says what a run (or a study) was and gave.
#pragma once

#include "formflow/io/case.hpp"
#include "formflow/post/results.hpp"
#include "formflow/post/study_table.hpp"

#include <span>
#include <string>

namespace formflow::io {

/// A picture of the report: its file stem ("strain_rate") and its SVG document.
struct ReportPicture {
  std::string name;
  std::string svg;
};

/// report.html of a run: the outcome; the load three ways (ram reaction,
/// power balance, total discrete power) and the mean −σ_H near the ram, each
/// with its relative difference from the ram reaction; warnings; the pictures
/// (each SVG inside the page as a data URI); the iteration history; timings;
/// the mesh; every case key with its value, those not at their defaults
/// marked with where they were set. Self-contained: no script, no file or
/// network access (a Content-Security-Policy says so to the browser), every
/// user-supplied string escaped.
std::string report_html(const Case& case_, const post::Results& results,
                        std::span<const ReportPicture> pictures);

/// report.html of a study: the table of study.csv, the study plot and, when
/// there is one, the die-corner plot; `csv` is study.csv's text.
std::string study_report_html(const post::StudyTable& table, const std::string& csv,
                              std::span<const ReportPicture> pictures);

} // namespace formflow::io
