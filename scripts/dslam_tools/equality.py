"""Compares the status CSV and summary JSON files of two dslam_run_dataset runs for
scripts/equality_check.sh: the CSV's column names and order and the JSON's keys and order must be
the same, and so must every value that does not depend on timing. Timing values are the CSV
columns and JSON keys that name milliseconds (`_ms`). JSON keys of reported quantiles
(`median_*`, `p95_*`) are told apart, so that a change of the quantile rule can be counted
without hiding other differences."""

import csv
import json
import sys


def is_timing(name):
    """A column or key whose value is a measured time (ms), different from run to run."""
    return name.endswith("_ms") or "_ms_" in name


def is_quantile(name):
    """A summary key that reports a quantile (its value depends on the quantile rule)."""
    return name.startswith("median_") or name.startswith("p95_")


def compare_csv(before_path, after_path):
    """Differences (strings) between two status CSV files: header, row count, timing-free cells."""
    with open(before_path, newline="") as f:
        before = list(csv.reader(f))
    with open(after_path, newline="") as f:
        after = list(csv.reader(f))
    if not before or not after:
        return [] if before == after else ["one file is empty"]
    if before[0] != after[0]:
        return ["columns differ: %s | %s" % (",".join(before[0]), ",".join(after[0]))]
    if len(before) != len(after):
        return ["%d rows against %d" % (len(before) - 1, len(after) - 1)]
    header, out = before[0], []
    for number, (b, a) in enumerate(zip(before[1:], after[1:]), 1):
        for name, x, y in zip(header, b, a):
            if x != y and not is_timing(name):
                out.append("row %d %s: %s -> %s" % (number, name, x, y))
    return out


def compare_json(before_path, after_path):
    """(differences, quantile differences) between two summary JSON files: keys and their order,
    and every value whose key is not a timing."""
    with open(before_path) as f:
        before = json.load(f)
    with open(after_path) as f:
        after = json.load(f)
    if list(before) != list(after):
        return ["keys differ: %s | %s" % (" ".join(before), " ".join(after))], []
    out, quantiles = [], []
    for key in before:
        if before[key] != after[key] and not is_timing(key):
            (quantiles if is_quantile(key) else out).append(
                "%s: %s -> %s" % (key, before[key], after[key]))
    return out, quantiles


def main(argv):
    """equality.py csv|json BEFORE AFTER: prints the differences; exit 1 with any (quantile
    differences of a JSON file: exit 3, so that the caller can count them apart)."""
    kind, before, after = argv[1], argv[2], argv[3]
    if kind == "csv":
        differences, quantiles = compare_csv(before, after), []
    else:
        differences, quantiles = compare_json(before, after)
    for line in differences[:10] + ["quantile " + q for q in quantiles[:10]]:
        print("    " + line)
    if len(differences) > 10:
        print("    ... %d differences in all" % len(differences))
    return 1 if differences else (3 if quantiles else 0)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
