#!/usr/bin/env python3
"""The timing table scripts/test prints after ctest: each test's time against its budget in tests/README.md.

Usage: scripts/test_times.py JUNIT_XML release|sanitize|studies WALL_S
       scripts/test_times.py --table RELEASE_JUNIT_XML[,...] SANITIZE_JUNIT_XML[,...]

JUNIT_XML is ctest's --output-junit file. The budgets are the table under "## Time budget" in tests/README.md
(columns: test, Release s, sanitizers s, budget Release s, budget sanitizers s; a dash where the test does not
run in that pass; the studies run in Release), its line "every other test: …" for the tests it does not list,
and its line "pass: …" for each pass's wall time. The table never fails the run: a test past its budget is
named, so the next change sees it.

With --table it writes that table's rows from the junit files of fresh-clone runs (comma-separated per pass):
each test's longest time per pass, and its budget, 1.5× the longer of those times rounded up to 5 s, at least
10 s in Release and 30 s under the sanitizers; the tests over 5 s in Release or 10 s under the sanitizers.
"""
import math
import re
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

README = Path(__file__).resolve().parent.parent / "tests" / "README.md"


# Per mode: the budget table's column, and the group of the "every other test" and "pass" lines.
COLUMNS = {"release": (3, 1, 1), "sanitize": (4, 2, 2), "studies": (3, 1, 3)}
PASS_NAMES = {"release": "Release", "sanitize": "sanitizer", "studies": "studies"}


def budgets(mode):
    """(per-test budget, budget of any other test, budget of the pass's wall time), in s, from tests/README.md."""
    col, other_group, pass_group = COLUMNS[mode]
    text = README.read_text()
    section = text.split("## Time budget", 1)[1].split("\n## ", 1)[0]
    per_test = {}
    for line in section.splitlines():
        cells = [c.strip().strip("`") for c in line.strip().strip("|").split("|")]
        if len(cells) == 5 and re.fullmatch(r"[\d.]+", cells[col]):
            per_test[cells[0]] = float(cells[col])
    other = re.search(r"every other test: (\d+) s in Release and (\d+) s under the sanitizers", section)
    total = re.search(r"pass: (\d+) s in Release, (\d+) s under the sanitizers and (\d+) s for the studies", section)
    if not other or not total:
        sys.exit("test_times.py: tests/README.md's \"## Time budget\" lacks its 'every other test' or 'pass' line")
    return per_test, float(other.group(other_group)), float(total.group(pass_group))


def times(junit):
    """(test name, seconds) of every test that ran in ctest's junit file."""
    for case in ET.parse(junit).getroot().iter("testcase"):
        if case.get("status") == "notrun" or case.find("skipped") is not None:
            continue
        # A parameterized test's name carries its parameter after "  # GetParam() = …": the table names the test.
        yield case.get("name").split("  #")[0].strip(), float(case.get("time", "0"))


def table(release_files, sanitize_files):
    """The budget table's rows (tests/README.md) from the runs' junit files, longest first."""
    longest = [{}, {}]
    for runs, files in zip(longest, (release_files, sanitize_files)):
        for junit in files.split(","):
            for name, seconds in times(junit):
                runs[name] = max(seconds, runs.get(name, 0))
    shown = [n for n in set(longest[0]) | set(longest[1]) if longest[0].get(n, 0) > 5 or longest[1].get(n, 0) > 10]
    shown.sort(key=lambda n: -max(longest[0].get(n, 0), longest[1].get(n, 0)))
    for name in shown:
        cells = [f"`{name}`"]
        cells += [f"{runs[name]:.1f}" if name in runs else "–" for runs in longest]
        for runs, least in zip(longest, (10, 30)):
            cells.append(str(max(least, 5 * math.ceil(1.5 * runs[name] / 5))) if name in runs else "–")
        print("| " + " | ".join(cells) + " |")


def main():
    if sys.argv[1] == "--table":
        table(sys.argv[2], sys.argv[3])
        return
    junit, mode, wall = sys.argv[1], sys.argv[2], float(sys.argv[3])
    per_test, other, total = budgets(mode)
    rows = [(seconds, name, per_test.get(name, other)) for name, seconds in times(junit)]
    rows.sort(reverse=True)
    over = [r for r in rows if r[0] > r[2]]
    print(f"\nTest times, {PASS_NAMES[mode]} pass (budgets: tests/README.md, \"Time budget\"); the ten longest and any past "
          "its budget:")
    print(f"  {'test':<72} {'s':>7} {'budget s':>9}")
    for rank, (seconds, name, budget) in enumerate(rows):
        if rank < 10 or seconds > budget:
            flag = "  past its budget" if seconds > budget else ""
            print(f"  {name:<72} {seconds:7.1f} {budget:9.0f}{flag}")
    summary = (f"  {len(rows)} tests, {sum(r[0] for r in rows):.0f} s in all; "
               f"the pass took {wall:.0f} s of its {total:.0f} s budget")
    if wall > total:
        summary += " (past it)"
    if len(over) == 1:
        summary += "; 1 test past its budget"
    elif over:
        summary += f"; {len(over)} tests past their budget"
    print(summary + ".")


if __name__ == "__main__":
    main()
