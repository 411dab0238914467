#!/usr/bin/python3
"""CI's closing report (.ci/run): the slowest tests of each ctest suite and one closing line.

Reads the JUnit files ctest wrote (--output-junit) for each leg and the fuzz harnesses' table
(tests/fuzz/run_fuzzers.sh: one row per harness, its last word "ok" or a failure). Prints, per
suite, its N slowest tests with their times, then "ci: P passed, F failed[, S skipped]" over every
test and harness of the run. Exits 1 when a suite's report is missing (its leg did not get as far
as its tests) or anything failed.

usage: ci_report.py [--slowest N] NAME=JUNIT.xml ... [--fuzz TABLE]
"""
import argparse
import pathlib
import sys
import xml.etree.ElementTree as ET


def read_suite(path):
    """[(name, seconds, outcome)] with outcome passed, failed or skipped."""
    cases = []
    for case in ET.parse(path).getroot().iter("testcase"):
        status = case.get("status", "run")
        if case.find("failure") is not None or case.find("error") is not None or status == "fail":
            outcome = "failed"
        elif case.find("skipped") is not None or status in ("notrun", "disabled"):
            outcome = "skipped"
        else:
            outcome = "passed"
        cases.append((case.get("name", "?"), float(case.get("time", "0") or 0), outcome))
    return cases


def read_fuzz(path):
    """[(harness, outcome)] from run_fuzzers.sh's table (the header row starts with 'harness')."""
    rows = []
    for line in pathlib.Path(path).read_text().splitlines():
        words = line.split()
        if len(words) >= 6 and words[0].startswith("fuzz_"):
            rows.append((words[0], "passed" if words[-1] == "ok" else "failed"))
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("suites", nargs="+", help="NAME=JUNIT.xml")
    parser.add_argument("--slowest", type=int, default=20)
    parser.add_argument("--fuzz", help="run_fuzzers.sh's table")
    args = parser.parse_args()
    totals = {"passed": 0, "failed": 0, "skipped": 0}
    complete = True
    for spec in args.suites:
        name, _, path = spec.partition("=")
        if not pathlib.Path(path).is_file():
            print(f"ci: {name}: no test report (the leg stopped before its tests)")
            complete = False
            continue
        cases = read_suite(path)
        print(f"ci: {name}: {len(cases)} tests, {sum(t for _, t, _ in cases):.0f} s of test time; "
              f"the {min(args.slowest, len(cases))} slowest:")
        for case_name, seconds, outcome in sorted(cases, key=lambda c: -c[1])[: args.slowest]:
            print(f"  {seconds:8.1f} s  {case_name}{'' if outcome == 'passed' else '  (' + outcome + ')'}")
        for _, _, outcome in cases:
            totals[outcome] += 1
        for case_name, _, outcome in cases:
            if outcome == "failed":
                print(f"ci: {name}: FAILED {case_name}")
    if args.fuzz:
        if pathlib.Path(args.fuzz).is_file():
            harnesses = read_fuzz(args.fuzz)
            print(f"ci: fuzz: {len(harnesses)} harnesses")
            for harness, outcome in harnesses:
                totals[outcome] += 1
                if outcome == "failed":
                    print(f"ci: fuzz: FAILED {harness}")
            complete &= len(harnesses) > 0
        else:
            print("ci: fuzz: no results (the leg stopped before fuzzing)")
            complete = False
    skipped = f", {totals['skipped']} skipped" if totals["skipped"] else ""
    print(f"ci: {totals['passed']} passed, {totals['failed']} failed{skipped}")
    return 0 if complete and totals["failed"] == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
