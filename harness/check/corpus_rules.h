// `motorbench check --rules FILE|DIR...`: the corpus rules over a folder of glTF files. Every
// file is one `motorbench survey` worker (load once, every pipeline of the file's space at rest
// and at 1/3 and 2/3 of animation 0), --jobs at a time; a worker killed by a signal or by
// --timeout is recorded and the file's pipelines are retried one process each, so the crash is
// pinned on a pipeline and the run goes on. The rules judge each pipeline against its reference:
// rigid frames of the full-precision pipelines against matrix by PSNR outside the frame's tie
// pixels, the 16-byte pipelines by their position bound in the geometry view outside the int16-cell
// ties, skinned frames' drawn pixels against their own skinning method's reference
// (harness/render/skin_judgement.h), every drawable file drawn, every file loaded, no crash.
// Writes OUT/corpus-check.json (a row per file x pipeline, totals, the rules) and
// OUT/corpus-check.md (summary, fallback and per-file tables), prints the rules as PASS/FAIL
// lines; exit 0 when every rule passes, 1 when one fails, 2 for bad arguments.
//
// The judging is split in three: corpus_rows.h (a survey document -> a file's rows),
// corpus_verdicts.h (the rows -> the rules and totals), corpus_tables.h (the Markdown and JSON).
#pragma once
#include <string>
#include <vector>

// check's usage line for --rules and its options (one a line, each with its default), for
// check's help.
#define MB_CHECK_RULES_USAGE                                                                                  \
  " | --rules FILE|DIR... [--pipelines p,q] [--size WxH] [--jobs N] [--timeout S] [--min-psnr DB] "          \
  "[--max-drawn-diff F] [--out DIR] [--junit FILE] [--quiet] [--worker-exe PATH]"
#define MB_CHECK_RULES_HELP                                                                                   \
  "  --rules FILE|DIR...  instead of goldens, the corpus rules over these files and folders (searched\n"       \
  "                     recursively for .gltf/.glb): every pipeline of each file's space against its\n"        \
  "                     reference: rigid frames by PSNR against matrix outside their tie pixels, the 16-byte\n" \
  "                     pipelines by their position bound (geometry view, outside int16-cell ties), skinned\n"  \
  "                     frames' drawn pixels against their skinning method's reference; every file loads and\n" \
  "                     is drawn, no worker crashes. One `motorbench survey` worker per file; writes\n"         \
  "                     OUT/corpus-check.json and corpus-check.md, prints the rules as PASS/FAIL lines\n"      \
  "                     (exit 0 all pass, 1 a rule failed, 2 an error). With --rules:\n"                       \
  "    --pipelines p,q    the pipelines judged (default: every one of the file's space; matrix always)\n"      \
  "    --size WxH         image size (default 128x128)\n"                                                     \
  "    --jobs N           workers at a time (default: the CPUs)\n"                                            \
  "    --timeout S        seconds per worker before it is killed and the file's pipelines are retried\n"      \
  "                       one process each (default 300)\n"                                                   \
  "    --min-psnr DB      rigid frames of the full-precision pipelines against matrix (default 50)\n"         \
  "    --max-drawn-diff F skinned frames: drawn pixels at most this fraction apart from their method's\n"     \
  "                       reference (default 0.01, 1 %)\n"                                                    \
  "    --out DIR          corpus-check.json and corpus-check.md (default out/corpus-check)\n"                 \
  "    --junit FILE       JUnit XML, one test case per file x pipeline x frame (default: none written)\n"     \
  "    --quiet            the failing rules and one summary line only, no progress lines\n"                  \
  "    --worker-exe PATH  the program run as `PATH survey FILE ...` (default: this motorbench)\n"

namespace mb::check {

// argv: check's arguments (after "motorbench check"), --rules among them.
int runCheckRules(const std::vector<std::string>& argv);

}  // namespace mb::check
