// SPDX-License-Identifier: MIT
// HTML escaping, base64 data URIs and the page shell shared by the reports.
#include "formflow/io/html_text.hpp"

#include <algorithm>
#include <array>
#include <cstdint>

namespace formflow::io {

std::string html_escaped(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char character : text) {
    switch (character) {
    case '&': out += "&amp;"; break;
    case '<': out += "&lt;"; break;
    case '>': out += "&gt;"; break;
    case '"': out += "&quot;"; break;
    case '\'': out += "&#39;"; break;
    default: out += character;
    }
  }
  return out;
}

std::string data_uri(std::string_view media_type, std::string_view bytes) {
  static constexpr std::string_view alphabet =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out = "data:" + std::string(media_type) + ";base64,";
  out.reserve(out.size() + (bytes.size() + 2) / 3 * 4);
  for (std::size_t k = 0; k < bytes.size(); k += 3) {
    std::array<std::uint32_t, 3> octets{};
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - k);
    for (std::size_t j = 0; j < n; ++j) octets[j] = static_cast<unsigned char>(bytes[k + j]);
    const std::uint32_t group = (octets[0] << 16) | (octets[1] << 8) | octets[2];
    out += alphabet[(group >> 18) & 63];
    out += alphabet[(group >> 12) & 63];
    out += n > 1 ? alphabet[(group >> 6) & 63] : '=';
    out += n > 2 ? alphabet[group & 63] : '=';
  }
  return out;
}

std::string html_page(std::string_view title, std::string_view body) {
  // The style sheet is the page's own: nothing is fetched to show it. No
  // script at all, so the report shows the same wherever it is opened.
  std::string out = R"(<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<meta http-equiv="Content-Security-Policy" content="default-src 'none'; img-src data:; style-src 'unsafe-inline'">
<title>)";
  out += html_escaped(title);
  out += R"(</title>
<style>
body { font-family: "DejaVu Sans", sans-serif; margin: 1.5em auto; max-width: 960px;
       padding: 0 1em; color: #1a1a1a; line-height: 1.4; }
h1 { font-size: 1.5em; margin-bottom: 0.2em; }
h2 { font-size: 1.2em; border-bottom: 1px solid #ccc; margin-top: 1.6em; }
table { border-collapse: collapse; margin: 0.5em 0; font-size: 0.9em; }
th, td { border: 1px solid #ccc; padding: 0.2em 0.6em; text-align: left; vertical-align: top; }
th { background: #f0f0f0; }
td.number { text-align: right; font-variant-numeric: tabular-nums; }
tr.set td { background: #fff6d5; }
.status { font-weight: bold; padding: 0.3em 0.6em; display: inline-block; }
.converged { background: #dff3df; color: #145214; }
.failed { background: #fbdcdc; color: #8b0000; }
.warning { background: #fff3cd; border-left: 4px solid #e0a800; padding: 0.4em 0.8em; }
figure { margin: 1em 0; }
figure img { width: 100%; max-width: 900px; height: auto; border: 1px solid #ddd; }
figcaption { font-size: 0.9em; color: #444; }
.note { font-size: 0.85em; color: #555; }
</style>
</head>
<body>
)";
  out += body;
  out += "</body>\n</html>\n";
  return out;
}

} // namespace formflow::io
