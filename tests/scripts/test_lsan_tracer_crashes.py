#!/usr/bin/env python3
"""scripts/lsan_tracer_crashes.py: only a passed test killed by LeakSanitizer's tracer is retried."""
import os
import subprocess
import sys
import tempfile
import unittest
from xml.sax.saxutils import escape

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts", "lsan_tracer_crashes.py")

PASSED = "[ RUN      ] A.B\n[       OK ] A.B (1 ms)\n[  PASSED  ] 1 test.\n"
TRACER = ("Tracer caught signal 11: addr=0x2c10 pc=0x7f4ce34e80f0 sp=0x7f4cb91ffd10\n"
          "==3230==LeakSanitizer has encountered a fatal error.\n")


def junit(*cases):
    body = ""
    for name, status, out in cases:
        failure = '<failure message=""/>' if status == "fail" else ""
        body += (f'<testcase name="{escape(name)}" status="{status}">{failure}'
                 f"<system-out>{escape(out)}</system-out></testcase>")
    return f'<?xml version="1.0"?><testsuite tests="{len(cases)}">{body}</testsuite>'


def run(xml):
    with tempfile.NamedTemporaryFile("w", suffix=".xml", delete=False) as f:
        f.write(xml)
    try:
        p = subprocess.run([sys.executable, SCRIPT, f.name], capture_output=True, text=True)
    finally:
        os.unlink(f.name)
    return p.returncode, p.stdout.split()


class Classifier(unittest.TestCase):
    def test_tracer_crash_after_pass_is_listed(self):
        rc, names = run(junit(("Ok.Test", "run", PASSED), ("Crashed.Test", "fail", PASSED + TRACER)))
        self.assertEqual((rc, names), (0, ["Crashed.Test"]))

    def test_tracer_crash_after_a_sanitizer_error_stands(self):
        out = PASSED + "==1==ERROR: AddressSanitizer: heap-use-after-free\n" + TRACER
        self.assertEqual(run(junit(("Bad.Test", "fail", out)))[0], 1)

    def test_tracer_crash_after_a_failed_test_stands(self):
        out = "[  FAILED  ] A.B\n" + TRACER
        self.assertEqual(run(junit(("Bad.Test", "fail", out)))[0], 1)

    def test_one_real_failure_beside_a_crash_stands(self):
        rc, _ = run(junit(("Crashed.Test", "fail", PASSED + TRACER), ("Bad.Test", "fail", "[  FAILED  ] A.B\n")))
        self.assertEqual(rc, 1)

    def test_nothing_failed_means_nothing_to_retry(self):
        self.assertEqual(run(junit(("Ok.Test", "run", PASSED)))[0], 1)


if __name__ == "__main__":
    unittest.main()
