#!/usr/bin/env python3
"""List the failed tests of a ctest JUnit file whose only fault is LeakSanitizer's own crash.

LeakSanitizer checks for leaks at exit by suspending every thread; while llvmpipe's worker
threads are alive its thread tracer intermittently crashes ("Tracer caught signal 11" then
"LeakSanitizer has encountered a fatal error", about 1 test process in 100 under load here;
google/sanitizers#1353) after the test itself passed. scripts/test.sh --sanitize runs such
tests once more; any other failure stands.

Usage: lsan_tracer_crashes.py JUNIT.xml
Prints the names of the failed tests, one per line, and exits 0 when every failed test is such
a crash (and there is at least one); exits 1 otherwise, naming the first real failure on stderr.
"""
import sys
import xml.etree.ElementTree as ET

TRACER_CRASH = ("Tracer caught signal", "LeakSanitizer has encountered a fatal error")
# Anything a sanitizer or the test itself reported: never retried.
REAL_FAULT = ("ERROR: AddressSanitizer", "ERROR: LeakSanitizer: detected memory leaks",
              "runtime error:", "[  FAILED  ]", "SUMMARY: UndefinedBehaviorSanitizer")


def main(path):
    failed = []
    for case in ET.parse(path).getroot().iter("testcase"):
        if case.get("status") != "fail" and case.find("failure") is None:
            continue
        out = case.findtext("system-out") or ""
        name = case.get("name", "?")
        crash = all(s in out for s in TRACER_CRASH) and "[  PASSED  ]" in out
        if not crash or any(s in out for s in REAL_FAULT):
            print(f"lsan_tracer_crashes: {name} failed for another reason", file=sys.stderr)
            return 1
        failed.append(name)
    for name in failed:
        print(name)
    return 0 if failed else 1


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    sys.exit(main(sys.argv[1]))
