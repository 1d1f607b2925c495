// markdown_html.h: the Markdown that pamsim's commands write (table5.md, bands.md,
// identify.md, ...) as HTML, for the pages of `pamsim report DIR --html`: CommonMark with
// GitHub's pipe tables, by cmark-gfm. Raw HTML in the text is left out: a page shows what the
// file says, never runs it.
#pragma once

#include <string>

namespace pamsim {

std::string markdown_to_html(const std::string& markdown);

}  // namespace pamsim
