// A small document model (headings, paragraphs, tables whose cells may hold a thumbnail or a
// link, figures, code) so that report.md, report.html and claims.md are laid out once
// (report_layout.cpp, claims_layout.cpp) and written by two renderers (report_markdown.cpp,
// report_html.cpp). Image and link targets are relative paths, so the folder is browsable on
// the repository page as well as from disk.
#pragma once
#include <string>
#include <vector>

namespace mb::document {

struct Cell {
  std::string text;
  std::string image;  // relative path of a thumbnail shown in the cell ("" = none)
  std::string link;   // relative path the cell links to ("" = none)
};

struct Block {
  enum class Kind { Heading, Paragraph, Bullets, Table, Figure, Code, Gallery };
  Kind kind = Kind::Paragraph;
  int level = 2;                          // Heading: 1..4
  std::string text;                       // Heading, Paragraph, Code; Figure: caption
  std::string anchor;                     // Heading: id to link to ("" = none)
  std::vector<std::string> items;         // Bullets
  std::vector<std::string> header;        // Table
  std::vector<std::vector<Cell>> rows;    // Table; Gallery: one card per row, its title cell
                                          // then the images stacked under it
  std::string image, title;               // Figure
};

struct Document {
  std::string title;
  std::vector<Block> blocks;

  void heading(int level, std::string text, std::string anchor = "") {
    Block b{Block::Kind::Heading, level, std::move(text), std::move(anchor)};
    blocks.push_back(std::move(b));
  }
  void paragraph(std::string text) { blocks.push_back({Block::Kind::Paragraph, 0, std::move(text)}); }
  void code(std::string text) { blocks.push_back({Block::Kind::Code, 0, std::move(text)}); }
  void bullets(std::vector<std::string> items) {
    Block b{Block::Kind::Bullets};
    b.items = std::move(items);
    blocks.push_back(std::move(b));
  }
  void table(std::vector<std::string> header, std::vector<std::vector<Cell>> rows) {
    Block b{Block::Kind::Table};
    b.header = std::move(header);
    b.rows = std::move(rows);
    blocks.push_back(std::move(b));
  }
  // Small multiples that wrap to the page width (HTML) or rows of a few cards (Markdown).
  void gallery(std::vector<std::vector<Cell>> cards) {
    Block b{Block::Kind::Gallery};
    b.rows = std::move(cards);
    blocks.push_back(std::move(b));
  }
  void figure(std::string image, std::string title, std::string caption) {
    Block b{Block::Kind::Figure, 0, std::move(caption)};
    b.image = std::move(image);
    b.title = std::move(title);
    blocks.push_back(std::move(b));
  }
};

// The two renderers.
std::string toMarkdown(const Document& doc);
std::string toHtml(const Document& doc);

}  // namespace mb::document
