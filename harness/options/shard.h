// `--shard I/N`: one of N independent parts of a run over many inputs, for existing schedulers
// (a Slurm array task, a Kubernetes Indexed Job, GNU parallel). Every shard sees the same full
// input list, sorts it the same way and keeps every N-th entry starting at I-1, so shards need no
// coordination and `motorbench merge` can check that together they cover the list exactly once.
#pragma once
#include <optional>
#include <string>
#include <vector>

namespace mb::options {

struct Shard {
  int index = 1;  // 1-based
  int count = 1;
};

// Parses "I/N" (1 <= I <= N <= 100000). On failure returns nullopt and sets `error` to a message
// naming the option and the value.
std::optional<Shard> parseShard(const std::string& text, std::string* error);

// Positions (into `items`) of the shard's part: `items` sorted by value (ties by position),
// then every count-th from index-1. Deterministic for a given list.
std::vector<size_t> shardPositions(const std::vector<std::string>& items, const Shard& shard);

// The note an empty shard prints (more shards than inputs): "shard 3/3 holds none of the 2
// inputs (more shards than inputs): nothing to do; its (empty) output still goes to merge";
// "" when the shard holds some input. An empty shard exits 0: it is a valid part of the set.
std::string emptyShardNote(const Shard& shard, size_t inputs, size_t mine);

}  // namespace mb::options

namespace mb::options {

// What one shard's output says about itself, for merging.
struct ShardPart {
  std::string source;               // the folder or file it came from
  int index = 0, count = 0;
  std::vector<std::string> inputs;  // the whole input list the shard was cut from
};

// "" when `parts` are the shards 1..N of one input list, each exactly once; else the reason,
// naming the sources ("shard 2/3 missing", "shard 1/3 given twice: a and b", "a and b were cut
// from different input lists").
std::string checkShardSet(const std::vector<ShardPart>& parts);

}  // namespace mb::options
