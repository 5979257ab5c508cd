#include "harness/options/shard.h"

#include <algorithm>
#include <cstdio>
#include <numeric>

namespace mb::options {

std::optional<Shard> parseShard(const std::string& text, std::string* error) {
  Shard s;
  char slash = 0, extra = 0;
  const int n = std::sscanf(text.c_str(), "%d%c%d%c", &s.index, &slash, &s.count, &extra);
  if (n != 3 || slash != '/' || s.count < 1 || s.count > 100000 || s.index < 1 || s.index > s.count) {
    *error = "--shard " + text + ": expected I/N with 1 <= I <= N, e.g. 2/8";
    return std::nullopt;
  }
  return s;
}

std::vector<size_t> shardPositions(const std::vector<std::string>& items, const Shard& shard) {
  std::vector<size_t> order(items.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return items[a] < items[b]; });
  std::vector<size_t> mine;
  for (size_t k = size_t(shard.index - 1); k < order.size(); k += size_t(shard.count)) mine.push_back(order[k]);
  std::sort(mine.begin(), mine.end());
  return mine;
}

std::string emptyShardNote(const Shard& shard, size_t inputs, size_t mine) {
  if (mine > 0 || inputs == 0) return "";
  return "shard " + std::to_string(shard.index) + "/" + std::to_string(shard.count) + " holds none of the " +
         std::to_string(inputs) + " input(s) (more shards than inputs): nothing to do; its (empty) output still " +
         "goes to merge with the others";
}

}  // namespace mb::options

namespace mb::options {

std::string checkShardSet(const std::vector<ShardPart>& parts) {
  if (parts.empty()) return "no shard outputs given";
  const ShardPart& first = parts.front();
  std::vector<std::string> seen(size_t(std::max(first.count, 0)) + 1);
  for (const ShardPart& p : parts) {
    if (p.count != first.count || p.count < 1)
      return p.source + " is a shard of " + std::to_string(p.count) + " parts, " + first.source + " of " +
             std::to_string(first.count);
    if (p.inputs != first.inputs) return p.source + " and " + first.source + " were cut from different input lists";
    if (p.index < 1 || p.index > p.count) return p.source + ": shard index " + std::to_string(p.index) + " out of range";
    std::string& slot = seen[size_t(p.index)];
    if (!slot.empty())
      return "shard " + std::to_string(p.index) + "/" + std::to_string(p.count) + " given twice: " + slot + " and " + p.source;
    slot = p.source;
  }
  std::string missing;
  for (int i = 1; i <= first.count; ++i)
    if (seen[size_t(i)].empty()) missing += (missing.empty() ? "" : ", ") + std::to_string(i) + "/" + std::to_string(first.count);
  if (!missing.empty()) return "shard " + missing + " missing: a merge would lack its inputs";
  return "";
}

}  // namespace mb::options
