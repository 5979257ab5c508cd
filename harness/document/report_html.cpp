// HTML renderer of the report document model: one self-contained page (inline CSS, one inline
// script that only counts images, nothing fetched from the network), images by relative path so
// the folder can be opened from disk or a repository.
#include <algorithm>

#include "harness/document/report_format.h"
#include "harness/document/report_model.h"

namespace mb::document {
namespace {

const char* kStyle = R"(
body { font: 14px/1.45 system-ui, sans-serif; margin: 1.5em auto; max-width: 1300px; color: #222; padding: 0 1em; }
h1 { font-size: 1.7em; } h2 { border-bottom: 1px solid #ccc; margin-top: 1.6em; } h3 { margin-top: 1.3em; }
table { border-collapse: collapse; margin: 0.6em 0 1.2em; font-size: 13px; display: block; overflow-x: auto; max-width: 100%; }
th, td { border: 1px solid #ccc; padding: 3px 7px; text-align: left; vertical-align: top; }
th { background: #f0f0f3; } tr:nth-child(even) td { background: #fafafa; }
td img { display: block; max-width: 256px; height: auto; image-rendering: pixelated; }
figure { margin: 1em 0; } figure img { max-width: 100%; border: 1px solid #ddd; }
figcaption { font-size: 12px; color: #555; max-width: 900px; }
pre { background: #f5f5f5; padding: 0.6em; overflow-x: auto; font-size: 12px; }
.small { font-size: 12px; color: #555; }
.gallery { display: flex; flex-wrap: wrap; gap: 6px 10px; margin: 0.4em 0 1em; }
.card { width: 200px; font-size: 12px; } .card img { display: block; width: 200px; height: auto; image-rendering: pixelated; }
.card b { display: block; }
#answer-table { font-size: 13px; } #answer-table td:first-child { white-space: nowrap; }
#answer-table td:last-child { width: 30%; }
#design-space { margin: 0.4em 0; } #design-space img { max-width: 480px; }
)";

// Once the page has loaded, the <body> says how many images it shows and how many failed to
// decode (data-images, data-broken-images): the browser test (tests/cli/test_cli_browser.cpp)
// reads them back from headless Chromium. No network, no external script.
const char* kImageCheck =
    "<script>window.addEventListener('load', function () {\n"
    "  var imgs = document.images, broken = 0;\n"
    "  for (var i = 0; i < imgs.length; ++i) if (!imgs[i].complete || imgs[i].naturalWidth === 0) ++broken;\n"
    "  document.body.setAttribute('data-images', imgs.length);\n"
    "  document.body.setAttribute('data-broken-images', broken);\n"
    // Where the answer block ends and whether the page scrolls sideways (the browser test:
    // above the fold at 1400x900, no horizontal scroll).
    "  var layout = [];\n"
    "  ['answer', 'answer-table', 'design-space'].forEach(function (id) {\n"
    "    var e = document.getElementById(id);\n"
    "    if (e) { var b = e.getBoundingClientRect(); layout.push(id + ':' + Math.round(b.bottom + window.scrollY)); }\n"
    "  });\n"
    "  document.body.setAttribute('data-layout', layout.join(' '));\n"
    "  document.body.setAttribute('data-viewport', window.innerWidth + 'x' + window.innerHeight);\n"
    "  document.body.setAttribute('data-scroll-width', document.documentElement.scrollWidth);\n"
    "});</script>\n";

std::string cellHtml(const Cell& c) {
  std::string inner;
  if (!c.image.empty()) inner = "<img src=\"" + html(c.image) + "\" alt=\"" + html(c.text) + "\">";
  const std::string text = html(c.text);
  if (!c.link.empty()) inner = "<a href=\"" + html(c.link) + "\">" + (inner.empty() ? text : inner) + "</a>";
  else if (inner.empty()) inner = text;
  if (!c.image.empty() && !c.text.empty()) inner += "<span class=\"small\">" + text + "</span>";
  return inner;
}

}  // namespace

std::string toHtml(const Document& doc) {
  std::string out = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
                    html(doc.title) + "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n<h1>" +
                    html(doc.title) + "</h1>\n";
  for (const Block& b : doc.blocks) {
    switch (b.kind) {
      case Block::Kind::Heading: {
        const std::string h = "h" + std::to_string(std::max(1, std::min(b.level, 6)));
        out += "<" + h + (b.anchor.empty() ? "" : " id=\"" + html(b.anchor) + "\"") + ">" + html(b.text) +
               "</" + h + ">\n";
        break;
      }
      case Block::Kind::Paragraph:
        out += "<p>" + html(b.text) + "</p>\n";
        break;
      case Block::Kind::Code:
        out += "<pre>" + html(b.text) + "</pre>\n";
        break;
      case Block::Kind::Bullets:
        out += "<ul>\n";
        for (const std::string& i : b.items) out += "<li>" + html(i) + "</li>\n";
        out += "</ul>\n";
        break;
      case Block::Kind::Table:
        out += "<table" + (b.anchor.empty() ? "" : " id=\"" + html(b.anchor) + "\"") + ">\n<tr>";
        for (const std::string& h : b.header) out += "<th>" + html(h) + "</th>";
        out += "</tr>\n";
        for (const auto& row : b.rows) {
          out += "<tr>";
          for (size_t i = 0; i < b.header.size(); ++i) out += "<td>" + (i < row.size() ? cellHtml(row[i]) : "") + "</td>";
          out += "</tr>\n";
        }
        out += "</table>\n";
        break;
      case Block::Kind::Gallery:
        out += "<div class=\"gallery\">\n";
        for (const auto& card : b.rows) {
          out += "<div class=\"card\">";
          for (size_t i = 0; i < card.size(); ++i) out += i == 0 ? "<b>" + cellHtml(card[i]) + "</b>" : cellHtml(card[i]);
          out += "</div>\n";
        }
        out += "</div>\n";
        break;
      case Block::Kind::Figure:
        out += "<figure" + (b.anchor.empty() ? "" : " id=\"" + html(b.anchor) + "\"") + "><img src=\"" + html(b.image) + "\" alt=\"" + html(b.title) + "\"><figcaption><b>" +
               html(b.title) + "</b>. " + html(b.text) + "</figcaption></figure>\n";
        break;
    }
  }
  return figureMarksAsSpans(out) + kImageCheck + "</body>\n</html>\n";
}

}  // namespace mb::document
