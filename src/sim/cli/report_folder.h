// report_folder.h: the page of a command's output folder (`pamsim report DIR --html`): a
// validation's tables, bands and sensitivity, an identification's parameters with their
// intervals, residuals and verdicts: every Markdown file the command wrote there as HTML
// (markdown_html.h), its figures embedded in the page, and what its provenance.json says of
// the run at the foot. One self-contained file, DIR/report.html, that requests nothing.
#pragma once

#include <string>

namespace pamsim {

// Throws InputError naming `dir` when it holds no Markdown file a pamsim command writes.
std::string folder_page_html(const std::string& dir);

}  // namespace pamsim
