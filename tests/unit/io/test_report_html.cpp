// SPDX-License-Identifier: MIT
// report.html: escaping (no markup from a case can reach the page), data URIs, the sections.
#include "formflow/io/case_keys.hpp"
#include "formflow/io/html_text.hpp"
#include "formflow/io/report_html.hpp"
#include "support/synthetic_run.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace formflow::testing {

namespace {

std::size_t count(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

TEST(HtmlText, EscapesEveryCharacterThatCanMakeMarkup) {
  EXPECT_EQ(io::html_escaped("<a href=\"x\" title='y'>&</a>"),
            "&lt;a href=&quot;x&quot; title=&#39;y&#39;&gt;&amp;&lt;/a&gt;");
  EXPECT_EQ(io::html_escaped("plain text, σ_H ≥ 0"), "plain text, σ_H ≥ 0");
}

TEST(HtmlText, DataUriIsBase64OfTheBytes) {
  // RFC 4648 §10 test vectors: every padding case.
  const std::vector<std::pair<std::string, std::string>> vectors = {{"", ""},
                                                                    {"f", "Zg=="},
                                                                    {"fo", "Zm8="},
                                                                    {"foo", "Zm9v"},
                                                                    {"foob", "Zm9vYg=="},
                                                                    {"fooba", "Zm9vYmE="},
                                                                    {"foobar", "Zm9vYmFy"}};
  for (const auto& [bytes, encoded] : vectors)
    EXPECT_EQ(io::data_uri("text/plain", bytes), "data:text/plain;base64," + encoded) << bytes;
  EXPECT_EQ(io::data_uri("a/b", std::string("\xff\x00\x10", 3)), "data:a/b;base64,/wAQ");
}

TEST(ReportHtml, NothingACaseSuppliesCanOpenATag) {
  io::Case case_;
  mesh::Mesh<2> mesh;
  post::Results results;
  make_synthetic_run(2, 2.5, case_, mesh, results);
  // The case path and a warning (which quotes it) carry markup; so does a picture's name.
  const std::string hostile = "<script>alert(1)</script><img src=x onerror=alert(2)>\"'.toml";
  case_ =
      io::load_case_text("[mesh]\nelement = \"Q1\"\n[integration]\nvolumetric = 2\n", hostile, {});
  ASSERT_FALSE(case_.warnings.empty()); // the complete rule with Q1 locks: a warning
  const std::vector<io::ReportPicture> pictures = {{"<b>bold</b>", "<svg></svg>"}};
  const std::string page = io::report_html(case_, results, pictures);
  EXPECT_EQ(count(page, "<script"), 0u);
  EXPECT_EQ(count(page, "<b>"), 0u);
  EXPECT_EQ(count(page, "<svg"), 0u);       // the picture is inside a data URI
  EXPECT_EQ(count(page, "<img src=x"), 0u); // its text stays, escaped, but opens no tag
  EXPECT_GE(count(page, "&lt;script&gt;alert(1)&lt;/script&gt;"), 3u); // title, source, warning
  // The only images are the data URIs of the pictures: nothing is fetched.
  EXPECT_EQ(count(page, "<img "), 1u);
  EXPECT_EQ(count(page, "src=\"data:image/svg+xml;base64,"), 1u);
  EXPECT_EQ(count(page, "http://"), 0u);
  EXPECT_EQ(count(page, "https://"), 0u);
}

TEST(ReportHtml, ListsEveryKeyAndMarksTheNonDefaults) {
  io::Case case_;
  mesh::Mesh<2> mesh;
  post::Results results;
  make_synthetic_run(2, 2.5, case_, mesh, results);
  case_ = io::load_case("", {{"friction.mu", "0.1"}, {"penalty.d", "0.001"}});
  const std::string page = io::report_html(case_, results, {});
  for (const io::CaseKey& key : io::case_keys())
    EXPECT_EQ(count(page, "<td><code>" + std::string(key.name) + "</code></td>"), 1u) << key.name;
  // friction.mu differs from its default; penalty.d was set to its default: not marked.
  EXPECT_EQ(count(page, "<tr class=\"set\"><td><code>friction.mu</code>"), 1u);
  EXPECT_EQ(count(page, "<tr class=\"set\">"), 1u);
  EXPECT_NE(page.find("<td><code>penalty.d</code></td><td>0.001</td><td>0.001</td><td>--set</td>"),
            std::string::npos);
}

TEST(ReportHtml, ShowsTheLoadsAndTheOutcome) {
  io::Case case_;
  mesh::Mesh<2> mesh;
  post::Results results;
  make_synthetic_run(2, 2.5, case_, mesh, results);
  results.pressure = {2.5, 2.4, 2.5, 2.0};
  results.stop_reason = solvers::StopReason::Converged;
  std::string page = io::report_html(case_, results, {});
  EXPECT_NE(page.find("status converged"), std::string::npos);
  EXPECT_NE(page.find("<td class=\"number\">2.4</td><td class=\"number\">4 %</td>"),
            std::string::npos); // the power balance 4 % below the reaction
  EXPECT_NE(page.find("<td class=\"number\">2</td><td class=\"number\">20 %</td>"),
            std::string::npos);
  EXPECT_EQ(count(page, "<tr><td class=\"number\">"), results.history.size());
  results.stop_reason = solvers::StopReason::Diverged;
  page = io::report_html(case_, results, {});
  EXPECT_NE(page.find("NOT CONVERGED (diverged)"), std::string::npos);
}

} // namespace

} // namespace formflow::testing
