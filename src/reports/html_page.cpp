#include "reports/html_page.hpp"

#include <fmt/format.h>

#include "io/format.hpp"

namespace sweetspot::reports {
namespace {

constexpr const char* kStyle = R"(
:root { --ink: #1b1f24; --muted: #5b6470; --line: #d5dae0; --accent: #0b5fa5; }
* { box-sizing: border-box; }
body { margin: 0; font-family: system-ui, -apple-system, "Segoe UI", Roboto, "DejaVu Sans", sans-serif;
       color: var(--ink); background: #fff; line-height: 1.5; }
main { max-width: 62rem; margin: 0 auto; padding: 1rem 1.2rem 3rem; }
h1 { font-size: 1.7rem; line-height: 1.25; margin: 0.6rem 0 0.2rem; }
h2 { font-size: 1.25rem; margin: 2.2rem 0 0.6rem; border-bottom: 2px solid var(--line); padding-bottom: 0.2rem; }
.lede { color: var(--muted); margin-top: 0; }
.answer { background: #f1f6fb; border-left: 5px solid var(--accent); padding: 0.4rem 1rem; font-size: 1.12rem; }
figure { margin: 1rem 0; }
figure svg { width: 100%; height: auto; display: block; }
figure.drawing-figure { max-width: 46rem; }
.narrow { display: none; }
.means { color: var(--muted); font-size: 0.88rem; }
.si { display: block; color: var(--muted); font-size: 0.78rem; }
.swatch { display: inline-block; width: 1.4em; height: 0.3em; vertical-align: middle; }
figcaption { color: var(--muted); font-size: 0.92rem; }
.drawing text { font-size: 1.6px; fill: var(--ink); }
.drawing .tick { font-size: 1.5px; text-anchor: middle; fill: var(--muted); }
.drawing .frame { fill: none; stroke: #2b3138; stroke-width: 1.2; }
.drawing .bed { fill: #eef3e2; stroke: #9aa58a; stroke-width: 0.15; }
.drawing .shaft { fill: #59616b; }
.drawing .hand { fill: #d99a6c; fill-opacity: 0.55; stroke: #a86a3e; stroke-width: 0.2; }
.drawing .tape { fill: #ef8a17; stroke: #9c5200; stroke-width: 0.15; }
.drawing .cop { fill: #d62728; stroke: #fff; stroke-width: 0.25; }
.drawing .node { fill: #1f5fbf; stroke: #fff; stroke-width: 0.2; }
.drawing .balance { fill: #2b3138; }
.drawing .ball { fill: #d4e157; fill-opacity: 0.6; stroke: #7c8a12; stroke-width: 0.2; stroke-dasharray: 0.6 0.4; }
.drawing .leader { stroke: var(--muted); stroke-width: 0.12; }
.drawing .ruler { stroke: var(--muted); stroke-width: 0.12; }
.table-wrap { overflow-x: auto; -webkit-overflow-scrolling: touch; }
table { border-collapse: collapse; margin: 0.6rem 0; min-width: 60%; }
th, td { padding: 0.3rem 0.6rem; border-bottom: 1px solid var(--line); text-align: left; vertical-align: top; }
th { background: #f6f8fa; }
td.num, th.num { text-align: right; font-variant-numeric: tabular-nums; }
td.num { white-space: nowrap; }
#positions td:first-child { min-width: 10rem; }
code { font-size: 0.9em; overflow-wrap: anywhere; }
details summary { cursor: pointer; color: var(--accent); }
.maps { display: grid; grid-template-columns: repeat(auto-fit, minmax(24rem, 1fr)); gap: 0 1.2rem; }
.missing { color: #9c2a00; }
footer { color: var(--muted); font-size: 0.88rem; margin-top: 2.5rem; }
@media (max-width: 640px) {
  main { padding: 0.6rem 0.7rem 2rem; }
  h1 { font-size: 1.35rem; }
  .answer { font-size: 1rem; padding: 0.3rem 0.7rem; }
  th, td { padding: 0.25rem 0.35rem; font-size: 0.9rem; }
  table { width: 100%; }
  #positions td:first-child { min-width: 8.5rem; }
  .drawing text { font-size: 2.4px; }
  .drawing .tick { font-size: 2.2px; }
  .side-by-side .means code { display: none; }
  .wide { display: none; }
  .narrow { display: block; }
}
)";

}  // namespace

std::string html_escape(std::string_view text) {
  const std::string chars = io::xml_chars(text);
  std::string out;
  out.reserve(chars.size());
  for (const char c : chars) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string html_with_code(std::string_view text) {
  std::string out;
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t open = text.find('`', at);
    const std::size_t close = open == std::string_view::npos ? open : text.find('`', open + 1);
    if (close == std::string_view::npos) {
      out += html_escape(text.substr(at));
      break;
    }
    out += html_escape(text.substr(at, open - at)) + "<code>" +
           html_escape(text.substr(open + 1, close - open - 1)) + "</code>";
    at = close + 1;
  }
  return out;
}

std::string plot_text_for_html(std::string_view text) {
  std::string out;
  for (const char c : text) {
    if (!((static_cast<unsigned char>(c) < 0x20 && c != '\t') || c == 0x7f)) out += c;
  }
  return io::xml_chars(out);
}

std::string html_cm(double metres, int decimals) {
  return fmt::format("{:.{}f}", metres * 100.0, decimals);
}

std::string html_page_open(std::string_view name, std::string_view lede) {
  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\"/>\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\"/>\n"
      "<meta name=\"generator\" content=\"sweetspot\"/>\n";
  html += "<title>" + html_escape(name) + " — sweetspot</title>\n<style>" + kStyle +
          "</style>\n</head>\n<body>\n<main>\n";
  html += "<h1 id=\"name\">" + html_escape(name) + "</h1>\n";
  if (!lede.empty()) html += "<p class=\"lede\">" + html_escape(lede) + "</p>\n";
  return html;
}

std::string html_page_close(std::string_view footer_html) {
  return "<footer>" + std::string(footer_html) + "</footer>\n</main>\n</body>\n</html>\n";
}

std::vector<io::SvgPlot> figure_svg_plots(const io::Plot& plot, const std::string& id) {
  return {{io::gnuplot_svg_script(plot, 960, 560), id + "-w-"},
          {io::gnuplot_svg_script(plot, 520, 460), id + "-n-"}};
}

std::string html_figure(const io::RenderedSvg& wide, const io::RenderedSvg& narrow,
                        const std::string& id, const std::string& caption) {
  const std::string body = wide.svg && narrow.svg
                               ? "<div class=\"wide\">" + *wide.svg +
                                     "</div><div class=\"narrow\">" + *narrow.svg + "</div>"
                               : "<p class=\"missing\">Plot not drawn: " +
                                     html_escape(wide.svg ? narrow.why : wide.why) + "</p>";
  return fmt::format("<figure id=\"{}\">{}<figcaption>{}</figcaption></figure>\n", id, body,
                     caption);
}

std::string html_figure(const io::Plot& plot, const std::string& id, const std::string& caption) {
  const std::vector<io::RenderedSvg> svgs = io::render_svgs(figure_svg_plots(plot, id));
  return html_figure(svgs[0], svgs[1], id, caption);
}

}  // namespace sweetspot::reports
