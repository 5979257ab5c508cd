#!/usr/bin/env bash
# scripts/corpus-check.sh [DIR|FILE ...] [--jobs N] [--size WxH] [--out DIR] [--timeout S] [--exe PATH]
# Every glTF file (default: ../shared/corpus-wide, recursively) x every pipeline of its space, one
# `motorbench survey` worker per file, --jobs at a time; writes OUT/corpus-check.md and .json
# (default OUT: build/corpus-check), prints the summary and the rules as PASS/FAIL lines (the rigid
# and 16-byte rules judged outside each frame's tie pixels; frames that pass only so are listed as
# "PASS (ties: ...)"), exits 1 when a rule fails. The work is scripts/corpus_check.py (README:
# Corpus check).
set -euo pipefail
exec python3 "$(dirname "$0")/corpus_check.py" "$@"
