// Markdown renderer of the report document model (GitHub-flavoured: pipe tables, images in
// cells, fenced code).
#include <algorithm>

#include "harness/document/report_format.h"
#include "harness/document/report_model.h"

namespace mb::document {
namespace {

std::string cellText(const Cell& c) {
  std::string t = cell(c.text);
  if (!c.image.empty()) {
    const std::string img = "![" + t + "](" + c.image + ")";
    return c.link.empty() ? img : "[" + img + "](" + c.link + ")";
  }
  return c.link.empty() ? t : "[" + t + "](" + c.link + ")";
}

}  // namespace

std::string toMarkdown(const Document& doc) {
  std::string out = "# " + doc.title + "\n\n";
  for (const Block& b : doc.blocks) {
    switch (b.kind) {
      case Block::Kind::Heading:
        // An explicit anchor keeps in-page links (#scene-x) working on repository pages too.
        if (!b.anchor.empty()) out += "<a id=\"" + b.anchor + "\"></a>\n\n";
        out += std::string(size_t(std::max(1, std::min(b.level, 6))), '#') + " " + b.text + "\n\n";
        break;
      case Block::Kind::Paragraph:
        out += b.text + "\n\n";
        break;
      case Block::Kind::Code:
        out += "```\n" + b.text + (b.text.empty() || b.text.back() == '\n' ? "" : "\n") + "```\n\n";
        break;
      case Block::Kind::Bullets:
        for (const std::string& i : b.items) out += "- " + i + "\n";
        out += "\n";
        break;
      case Block::Kind::Table: {
        std::string head = "|", rule = "|";
        for (const std::string& h : b.header) head += " " + cell(h) + " |", rule += "---|";
        out += head + "\n" + rule + "\n";
        for (const auto& row : b.rows) {
          std::string line = "|";
          for (size_t i = 0; i < b.header.size(); ++i)
            line += " " + (i < row.size() ? cellText(row[i]) : std::string()) + " |";
          out += line + "\n";
        }
        out += "\n";
        break;
      }
      case Block::Kind::Gallery:  // rows of up to 5 cards: titles, then each image under its title
        for (size_t first = 0; first < b.rows.size(); first += 5) {
          const size_t end = std::min(b.rows.size(), first + 5);
          size_t depth = 0;
          std::string head = "|", rule = "|";
          for (size_t k = first; k < end; ++k) {
            head += " " + (b.rows[k].empty() ? std::string() : cellText(b.rows[k][0])) + " |", rule += "---|";
            depth = std::max(depth, b.rows[k].size());
          }
          out += head + "\n" + rule + "\n";
          for (size_t i = 1; i < depth; ++i) {
            std::string line = "|";
            for (size_t k = first; k < end; ++k) line += " " + (i < b.rows[k].size() ? cellText(b.rows[k][i]) : std::string()) + " |";
            out += line + "\n";
          }
          out += "\n";
        }
        break;
      case Block::Kind::Figure:
        out += "**" + b.title + "**\n\n![" + b.title + "](" + b.image + ")\n\n";
        if (!b.text.empty()) out += "*" + b.text + "*\n\n";
        break;
    }
  }
  return figureMarksAsSpans(out);
}

}  // namespace mb::document
