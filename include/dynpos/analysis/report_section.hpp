#pragma once
/// \file
/// A section of the `dynpos demo` report, one per analysis.

#include <string>

namespace dynpos::analysis {

/// An analysis section of the campaign report: a title and the same content as HTML (a
/// fragment, links relative to the report folder) and as Markdown. An empty title means the
/// analysis has nothing to add.
struct ReportSection {
  std::string title;
  std::string html;
  std::string markdown;
};

}  // namespace dynpos::analysis
