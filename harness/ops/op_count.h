// harness/ops/op_count.h: counting kernels with mb::Counted and reporting the counts (table, JSON).
// Header-only so that tests and other commands can reuse it.
//
// A Kernel is one row of data: a name, a group, an optional claim (mul/add and who claims it)
// and a body that executes the kernel once on mb::Counted. To add rows (per-vertex pipeline
// transforms, ...), build more Kernels and pass them to measureAll(); to add a column (e.g. a
// SPIR-V count), fill Row::extra before formatTable()/toJson().
#pragma once
#include <algorithm>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "shaders/shim/counted.h"

namespace mb::ops {

struct Claim {
  int mul = 0, add = 0;
  std::string source;  // "paper" or "ref-src" (a comment in the reference implementation)
};

struct Kernel {
  std::string group;            // "pga", "matrix", ...
  std::string name;
  std::string what;             // one line: what it computes
  std::optional<Claim> claim;   // none: '-' in the table
  std::function<void()> run;    // executes the kernel once on mb::Counted
};

struct Row {
  Kernel kernel;
  OpCounts counts;
  std::vector<std::pair<std::string, std::string>> extra;  // (column, value), printed in order

  // "-" without a claim, "yes" when measured mul and add equal the claim, else "NO".
  std::string agree() const {
    if (!kernel.claim) return "-";
    return counts.mul == uint64_t(kernel.claim->mul) && counts.add == uint64_t(kernel.claim->add)
               ? "yes" : "NO";
  }
  std::string claimText() const {
    return kernel.claim ? std::to_string(kernel.claim->mul) + "/" + std::to_string(kernel.claim->add)
                        : "-";
  }
};

inline Row measure(const Kernel& k) {
  Row r{k, countOps(k.run), {}};
  return r;
}

inline std::vector<Row> measureAll(const std::vector<Kernel>& kernels) {
  std::vector<Row> rows;
  rows.reserve(kernels.size());
  for (const Kernel& k : kernels) rows.push_back(measure(k));
  return rows;
}

inline std::string formatTable(const std::vector<Row>& rows) {
  auto line = [](std::string& out, const char* fmt, auto... a) {
    char buf[512];
    std::snprintf(buf, sizeof buf, fmt, a...);
    out += buf;
  };
  std::string out;
  std::vector<std::string> extraCols;
  for (const Row& r : rows)
    for (const auto& [col, v] : r.extra)
      if (std::find(extraCols.begin(), extraCols.end(), col) == extraCols.end()) extraCols.push_back(col);
  line(out, "%-7s %-22s %5s %5s %4s %4s %5s %9s %-8s %-5s", "group", "kernel", "mul", "add", "div",
       "sqrt", "other", "claimed", "by", "agree");
  for (const auto& c : extraCols) line(out, " %10s", c.c_str());
  out += "  other calls\n";
  for (const Row& r : rows) {
    const OpCounts& c = r.counts;
    line(out, "%-7s %-22s %5llu %5llu %4llu %4llu %5llu %9s %-8s %-5s", r.kernel.group.c_str(),
         r.kernel.name.c_str(), (unsigned long long)c.mul, (unsigned long long)c.add,
         (unsigned long long)c.div, (unsigned long long)c.sqrt, (unsigned long long)c.other,
         r.claimText().c_str(), r.kernel.claim ? r.kernel.claim->source.c_str() : "-",
         r.agree().c_str());
    for (const auto& col : extraCols) {
      std::string v = "-";
      for (const auto& [k, val] : r.extra)
        if (k == col) v = val;
      line(out, " %10s", v.c_str());
    }
    out += "  " + c.otherCalls() + "\n";
  }
  return out;
}

inline nlohmann::json toJson(const Row& r) {
  nlohmann::json calls = nlohmann::json::object();
  for (size_t i = 0; i < r.counts.fn.size(); ++i)
    if (r.counts.fn[i]) calls[kOpFnNames[i]] = r.counts.fn[i];
  nlohmann::json j = {
      {"group", r.kernel.group},
      {"kernel", r.kernel.name},
      {"what", r.kernel.what},
      {"measured",
       {{"mul", r.counts.mul}, {"add", r.counts.add}, {"div", r.counts.div},
        {"sqrt", r.counts.sqrt}, {"other", r.counts.other}, {"calls", calls}}},
      {"claim", nullptr},
      {"agree", nullptr},
  };
  if (r.kernel.claim) {
    j["claim"] = {{"mul", r.kernel.claim->mul}, {"add", r.kernel.claim->add},
                  {"source", r.kernel.claim->source}};
    j["agree"] = r.agree() == "yes";
  }
  for (const auto& [col, v] : r.extra) j["extra"][col] = v;
  return j;
}

inline nlohmann::json toJson(const std::vector<Row>& rows) {
  nlohmann::json arr = nlohmann::json::array();
  for (const Row& r : rows) arr.push_back(toJson(r));
  return arr;
}

}  // namespace mb::ops
