#!/usr/bin/env python3
"""Judges the sanitizer reports that scripts/sanitize.sh collected.

Usage: sanitizer_reports.py REPORTS_DIR MARK_REGEX REPO

Reads every log file REPORTS_DIR/<run>.<pid> (the sanitizers' log_path) and every run's output
REPORTS_DIR/<run>.out (GCC's UndefinedBehaviorSanitizer writes to stderr even with a log_path
when it runs with AddressSanitizer; measured with GCC 12), splits them into reports
(ThreadSanitizer warnings, AddressSanitizer errors, each leak of a LeakSanitizer report,
UndefinedBehaviorSanitizer runtime errors), and prints one line per report: IN DSLAM when one of
its stacks has a frame that names `dslam::` or a file under REPO, OUTSIDE otherwise. For
ThreadSanitizer the stacks of "Thread T.. created at" and "Location is" do not count (they say
where a thread or a variable came from, not who accessed it). Suppressions that matched are
printed. Exit status 1 when a report lies in dslam code.
"""
import glob
import os
import re
import sys


def split_reports(text, mark):
    """Report blocks of one log: from a line matching `mark` to its SUMMARY / ===== line."""
    blocks = []
    lines = text.splitlines()
    i = 0
    while i < len(lines):
        if not re.search(mark, lines[i]):
            i += 1
            continue
        j = i + 1
        while j < len(lines) and not re.match(r"(SUMMARY: |={10,})", lines[j]):
            if re.search(mark, lines[j]):
                break
            j += 1
        end = j + 1 if j < len(lines) and not re.search(mark, lines[j]) else j
        blocks.append("\n".join(lines[i:end]))
        i = end
    return blocks


def paragraphs_of(block):
    """The parts of a report judged one by one: each leak of a LeakSanitizer report, else the
    whole report."""
    if "LeakSanitizer: detected memory leaks" in block:
        return [p for p in re.split(r"\n\s*\n", block) if re.match(r"\s*(Direct|Indirect) leak", p)]
    return [block]


def access_stacks(report):
    """The stacks that say who did it (ThreadSanitizer: not thread creation or locations)."""
    parts = re.split(r"\n\s*\n", report)
    return [p for p in parts if not re.match(r"\s*(Thread T\d+|Location is|SUMMARY)", p)]


def main():
    reports, mark, repo = sys.argv[1], sys.argv[2], sys.argv[3]
    in_dslam = other = 0
    logs = glob.glob(os.path.join(reports, "*.[0-9]*")) + glob.glob(os.path.join(reports, "*.out"))
    for path in sorted(logs):
        if path.endswith(".xml"):
            continue
        text = open(path, errors="replace").read()
        name = os.path.basename(path)
        for line in re.findall(r"^ThreadSanitizer: Matched.*$|^ *\d+ +\S+:\S+$|^ *\d+ +\d+ +leak:\S+$", text, re.M):
            print("suppression " + name + ": " + line.strip())
        for block in split_reports(text, mark):
            for report in paragraphs_of(block):
                ours = any("dslam::" in p or repo in p for p in access_stacks(report))
                in_dslam += ours
                other += not ours
                summary = re.search(r"SUMMARY: .*", block)
                first = report.strip().splitlines()[0]
                print(("IN DSLAM " if ours else "OUTSIDE  ") + name + ": " + first[:200] +
                      ("" if not summary or summary.group(0) in first else
                       " | " + summary.group(0)[:200]))
    print(f"[sanitize] reports in dslam code: {in_dslam}; elsewhere (listed, not failing): {other}")
    return 1 if in_dslam else 0


if __name__ == "__main__":
    sys.exit(main())
