"""The tally of the python run tests (tests/app/test_*.py), as check_lib.sh is the shell
tests': a check that does not hold prints FAIL and its name; finish() prints the tally
and exits with its status. Not a test itself (not test_*.py)."""
import sys


class Checks:
    def __init__(self, show_passed=False):
        self.show_passed = show_passed  # also print the checks that hold (their measured values)
        self.passed, self.failed = 0, []

    def __call__(self, name, ok):
        if ok:
            self.passed += 1
            if self.show_passed:
                print("ok:  ", name)
        else:
            self.failed.append(name)
            print("FAIL:", name)

    def finish(self, label):
        print(f"{label}: {self.passed} passed, {len(self.failed)} failed")
        sys.exit(1 if self.failed else 0)
