// SPDX-License-Identifier: MIT
// The pieces of a self-contained HTML page: escaped text, data URIs, the page shell.
#pragma once

#include <string>
#include <string_view>

namespace formflow::io {

/// `text` safe as HTML element content and as a quoted attribute value:
/// & < > " ' become character references. Every user-supplied string of a
/// report (case paths, key values, warnings) goes through this, so none can
/// open a tag or leave an attribute. Invalid UTF-8 is kept as bytes (the page
/// declares UTF-8; a browser shows U+FFFD), which cannot form markup either.
std::string html_escaped(std::string_view text);

/// `bytes` as an RFC 2397 data URI of `media_type` with base64 content: a
/// picture inside the page itself, no file or network access to show it.
std::string data_uri(std::string_view media_type, std::string_view bytes);

/// A whole HTML5 document: the title (escaped here), the report's own style
/// sheet and `body` (already HTML). No script, no external resource.
std::string html_page(std::string_view title, std::string_view body);

} // namespace formflow::io
