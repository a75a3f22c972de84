#pragma once

// The pieces every HTML page of sweetspot shares (the design's page, a
// comparison's, a study's): the escaping of user text, the page's skeleton
// with its one inline stylesheet, and gnuplot's SVG inlined as a figure.
// Internal to src/reports: the pages are built in html_report.cpp,
// comparison.cpp and optimization_report.cpp.

#include <string>
#include <string_view>
#include <vector>

#include "io/plot.hpp"

namespace sweetspot::reports {

// `text` safe inside HTML text and attribute values: & < > " ' as
// entities, every character XML 1.0 does not allow (or HTML calls a control)
// as U+FFFD (io::xml_chars).
std::string html_escape(std::string_view text);

// `text` escaped, each `code` span between backticks set as <code>code</code>
// (the Markdown reports' sentences, shown on a page). An unpaired backtick
// stays as it is.
std::string html_with_code(std::string_view text);

// `text` (a name from a user's file) fit to be a plot's title or key in
// gnuplot's SVG: control characters, which XML cannot hold, dropped, other
// characters XML does not allow as U+FFFD (xml_chars; '&' and '<' are
// escaped by render_svg and gnuplot).
std::string plot_text_for_html(std::string_view text);

// A length in metres as centimetres with `decimals` decimals: "31.2".
std::string html_cm(double metres, int decimals = 1);

// The page's opening: doctype, head (charset, viewport, the title "`name` —
// sweetspot", the one inline stylesheet), <body><main>, the heading
// <h1 id="name"> and, when not empty, `lede` under it. Both are escaped here.
std::string html_page_open(std::string_view name, std::string_view lede);

// `footer_html` (already markup) in the page's footer, and the closing tags.
std::string html_page_close(std::string_view footer_html);

// `plot` as gnuplot's SVG twice, laid out for a wide screen and for a phone
// (the stylesheet shows one of them), in <figure id="`id`"> with
// `caption_html` (markup) under it; without gnuplot, a sentence saying why
// the plot is missing in its place.
std::string html_figure(const io::Plot& plot, const std::string& id,
                        const std::string& caption_html);

// The two layouts of `plot` that html_figure() draws, wide then narrow, for a
// page that draws all its plots with one io::render_svgs().
std::vector<io::SvgPlot> figure_svg_plots(const io::Plot& plot, const std::string& id);

// The figure of html_figure() from its two layouts as drawn.
std::string html_figure(const io::RenderedSvg& wide, const io::RenderedSvg& narrow,
                        const std::string& id, const std::string& caption_html);

}  // namespace sweetspot::reports
