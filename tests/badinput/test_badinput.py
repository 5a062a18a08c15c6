"""The bad-input suite: every case of cases.py run through the shadelab
command line. Each must fail with its exact one-line message and exit
status, leave the existing out.* files byte-identical and leave no other
file behind.

    SHADELAB_EXE=build/bin/shadelab /usr/bin/python3 tests/badinput/test_badinput.py
"""
import concurrent.futures
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from cases import CASES  # noqa: E402

SHADELAB = os.environ["SHADELAB_EXE"]
SEEDS = os.path.join(os.path.dirname(HERE), "fuzz", "seeds")
PREVIOUS = b"previous output, to be kept\n"


def write_inputs(folder, files):
    """Writes each input: bytes as they are, None as a folder, "skip" not at
    all, "seed:PATH:N" as the first N bytes of a fuzz seed."""
    for name, data in files.items():
        path = os.path.join(folder, name)
        if data is None:
            os.mkdir(path)
        elif isinstance(data, str) and data.startswith("seed:"):
            _, seed, length = data.split(":")
            with open(os.path.join(SEEDS, seed), "rb") as f:
                data = f.read()[:int(length)]
            with open(path, "wb") as f:
                f.write(data)
        elif data != "skip":
            with open(path, "wb") as f:
                f.write(data)


def run_case(args, files):
    """Runs one case in a fresh folder: (status, stderr, outputs kept, files added)."""
    with tempfile.TemporaryDirectory() as folder:
        write_inputs(folder, files)
        outputs = [a for a in args if a.startswith("out.")]
        for name in outputs:
            with open(os.path.join(folder, name), "wb") as f:
                f.write(PREVIOUS)
        before = set(os.listdir(folder))
        r = subprocess.run([SHADELAB, *args], cwd=folder, capture_output=True, timeout=120)
        kept = []
        for name in outputs:
            with open(os.path.join(folder, name), "rb") as f:
                kept.append(f.read() == PREVIOUS)
        added = sorted(set(os.listdir(folder)) - before)
        return r.returncode, r.stderr.decode("utf-8", "backslashreplace"), all(kept), added


class BadInputTest(unittest.TestCase):
    def test_case_count(self):
        self.assertGreaterEqual(len(CASES), 100)
        names = [c[0] for c in CASES]
        self.assertEqual(len(names), len(set(names)), "case names are unique")

    def test_cases(self):
        # Each case is its own process: run them side by side, check in order.
        with concurrent.futures.ThreadPoolExecutor(os.cpu_count()) as pool:
            results = list(pool.map(lambda case: run_case(case[1], case[2]), CASES))
        for (name, args, files, status, message), result in zip(CASES, results):
            with self.subTest(name):
                code, stderr, kept, added = result
                self.assertEqual(stderr, message)
                self.assertEqual(stderr.count("\n"), 1, "one line")
                self.assertEqual(code, status)
                self.assertTrue(kept, "the existing output is untouched")
                self.assertEqual(added, [], "no file left behind")


if __name__ == "__main__":
    if sys.argv[1:] == ["--print"]:
        # The actual results, for writing a new case's expectation (checked by eye).
        for name, args, files, status, message in CASES:
            code, stderr, kept, added = run_case(args, files)
            print(repr(name), code, repr(stderr), kept, added)
    else:
        unittest.main()
