#include "harness/report/report_folder.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace mb::report {
namespace {

namespace fs = std::filesystem;

bool owned(const std::string& name) {
  const auto& n = reportOwnedNames();
  return std::find(n.begin(), n.end(), name) != n.end();
}

// An input the run reads, or the console text beside one (bench.txt beside --bench-json
// DIR/bench.json, isa.txt beside --isa-json DIR/isa.json: written by the same earlier command).
bool isKept(const fs::path& p, const std::vector<std::string>& keep) {
  std::error_code ec;
  for (const std::string& k : keep) {
    if (k.empty()) continue;
    if (fs::equivalent(p, k, ec)) return true;
    const fs::path input(k);
    if (p.extension() == ".txt" && (input.filename() == "bench.json" || input.filename() == "isa.json") &&
        fs::equivalent(p.parent_path(), input.parent_path().empty() ? fs::path(".") : input.parent_path(), ec) &&
        p.stem() == input.stem())
      return true;
  }
  return false;
}

std::string listed(const std::vector<std::string>& names) {
  std::string s;
  const size_t shown = std::min<size_t>(names.size(), 8);
  for (size_t i = 0; i < shown; ++i) s += (s.empty() ? "" : ", ") + names[i];
  if (names.size() > shown) s += " and " + std::to_string(names.size() - shown) + " more";
  return s;
}

}  // namespace

const std::vector<std::string>& reportOwnedNames() {
  static const std::vector<std::string> names = {"report.json", "report.md", "report.html", "images", "plots",
                                                 "bench.json",  "bench.txt", "isa.json",    "isa.txt", kPartialMarker};
  return names;
}

Status clearOldReport(const std::string& dir, const std::vector<std::string>& keep) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return Status();
  std::vector<std::string> others, mine;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (isKept(e.path(), keep)) continue;
    (owned(name) ? mine : others).push_back(name + (e.is_directory(ec) ? "/" : ""));
  }
  std::sort(others.begin(), others.end());
  const bool earlierReport = fs::exists(fs::path(dir) / "report.json", ec) || fs::exists(fs::path(dir) / kPartialMarker, ec);
  if (!others.empty() && !earlierReport)
    return Status::fail("-o " + dir + ": the folder holds files that are not a report's: " + listed(others) +
                        " (give a new or empty folder, or one an earlier report wrote)");
  for (std::string name : mine) {
    if (!name.empty() && name.back() == '/') name.pop_back();
    fs::remove_all(fs::path(dir) / name, ec);
    if (ec) return Status::fail("-o " + dir + ": cannot remove the earlier report's " + name + ": " + ec.message());
  }
  if (!others.empty())
    std::fprintf(stderr, "report: %s: the earlier report's files removed; kept what is not a report's: %s\n",
                 dir.c_str(), listed(others).c_str());
  return Status();
}

Status markPartial(const std::string& dir, const std::string& text) {
  const fs::path p = fs::path(dir) / kPartialMarker;
  std::ofstream out(p);
  out << text << "\n";
  if (!out.flush()) return Status::fail(p.string() + ": cannot write");
  return Status();
}

void clearPartialMark(const std::string& dir) {
  std::error_code ec;
  fs::remove(fs::path(dir) / kPartialMarker, ec);
}

}  // namespace mb::report
