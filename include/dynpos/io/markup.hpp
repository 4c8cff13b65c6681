#pragma once
/// \file
/// Text for HTML and SVG (XML) documents.

#include <string>
#include <string_view>

namespace dynpos::io {

/// `text` with the five markup characters replaced by their entities (& < > " '), safe in
/// element content and in quoted attributes of HTML and XML alike.
std::string escape_markup(std::string_view text);

}  // namespace dynpos::io
